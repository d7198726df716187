"""Checks the rate constraints in stick (issue 29, E) on a run of
tests/cases/oblique_blocks_friction.prm.

Usage: check_stick_rates.py DIRECTORY taylor-papadopoulos|none SPEED DT

taylor-papadopoulos: after the correction, at every stuck pair the tangential relative velocity
and acceleration (stick_velocity_jump, stick_acceleration_jump) and at every active pair the
normal ones (velocity_jump, acceleration_jump) are at most 1e-10 of SPEED and of SPEED / DT (the
correction solves them to round-off: measured 7e-16 and 1.2e-15 relative); the total momentum
along x and y stays at its initial value to 1e-10 of its magnitude (each row of the correction
has coefficients summing to zero: measured 2.8e-15); and some step has stuck pairs (active pairs
minus sliding_pairs), so that the tangential bound was tested.
none: the classical rates, whose tangential jump at a stuck pair is of the order of the
tangential speed (0.1 of SPEED measured): above 1e-2 of SPEED, so that the check above can fail.
"""
import sys

from history_checks import Checks, read_history

directory, mode = sys.argv[1], sys.argv[2]
speed, dt = float(sys.argv[3]), float(sys.argv[4])
rows = read_history(directory)
checks = Checks()
check = checks.bound


stuck = max(r["active_constraints"] - r["sliding_pairs"] for r in rows)
stick_velocity = max(r["stick_velocity_jump"] for r in rows)
if mode == "none":
    check("largest stick velocity jump / speed", stick_velocity / speed, 1e-2, above=True)
else:
    check("most stuck pairs in a step", stuck, 1, above=True)
    check("largest stick velocity jump / speed", stick_velocity / speed, 1e-10)
    check("largest stick acceleration jump / (speed / dt)", max(r["stick_acceleration_jump"] for r in rows) * dt / speed, 1e-10)
    check("largest normal velocity jump / speed", max(r["velocity_jump"] for r in rows) / speed, 1e-10)
    check("largest normal acceleration jump / (speed / dt)", max(r["acceleration_jump"] for r in rows) * dt / speed, 1e-10)
    first = rows[0]
    scale = abs(first["momentum_1_x"] + first["momentum_2_x"]) + abs(first["momentum_1_y"] + first["momentum_2_y"])
    for axis in "xy":
        start = first[f"momentum_1_{axis}"] + first[f"momentum_2_{axis}"]
        drift = max(abs(r[f"momentum_1_{axis}"] + r[f"momentum_2_{axis}"] - start) for r in rows)
        check(f"largest change of the momentum along {axis} / |p|", drift / scale, 1e-10)
checks.finish()
