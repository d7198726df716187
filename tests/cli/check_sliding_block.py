"""Checks a run of prm/sliding_block.prm (issue 29, A) against the exact rigid-body references.

Usage: check_sliding_block.py DIRECTORY slip|stick MU TX G RHO WIDTH HEIGHT

The block (WIDTH x HEIGHT, density RHO, plane strain, per unit depth) carries the body force
(TX, -G) on a rigid plane with friction coefficient MU: its weight N = RHO G V, the tangential load
T = RHO TX V, its mass m = RHO V. Every row from t >= T_SETTLED on is checked; before it the
elastic transient of the suddenly applied loads (the normal force first overshoots by 50 %) is
still decaying (generalized-alpha, spectral radius 0: measured 2e-10 of the load at t = 5.5,
1e-12 from t = 7).

slip (T > MU N):
  - contact force = N to 1e-8 (relative);
  - the acceleration of the centre, the step's change of momentum_1_x over m dt, equals
    (T - MU N) / m to 1e-8 (relative; measured about 5e-12);
  - the step's frictional dissipation equals MU N times the step's slip, the displacement of the
    rigidly moving block, v_n dt + a dt^2 / 2 (exact for a constant acceleration on any Newmark or
    generalized-alpha member), to 1e-8 (relative).
stick (T < MU N): every bottom node (y = 0) of the last VTU frame moved along the plane by less
  than 1e-12 of the block's width (measured 1e-15), and momentum_1_x is below 1e-10 of T t.
Both, on the energy scale (T + MU N) WIDTH of the loads over the block's width:
frictional_dissipation never decreases by more than 1e-12 of it (a stuck pair's slip is zero to
  round-off: measured 2.5e-16), and the algorithmic energy plus the dissipation minus the external
  work never rises above its value at the start (generalized-alpha with spectral radius 0
  dissipates) by more than 1e-10 of it (measured 0).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu  # noqa: E402
from history_checks import Checks, read_history  # noqa: E402

T_SETTLED = 7.0
directory, mode = sys.argv[1], sys.argv[2]
mu, tx, g, rho, width, height = map(float, sys.argv[3:9])
volume = width * height
mass, weight, load = rho * volume, rho * g * volume, rho * tx * volume
rows = read_history(directory)
checks = Checks()
check = checks.relative


scale = (load + mu * weight) * width
drops = [a["frictional_dissipation"] - b["frictional_dissipation"] for a, b in zip(rows, rows[1:])]
check("largest decrease of frictional_dissipation / energy scale", max(0.0, max(drops)) / scale, 0.0, 1e-12)
balance = [r["algorithmic_energy"] + r["frictional_dissipation"] - r["external_work"] for r in rows]
check("largest rise of E + D - W above its start / energy scale", max(0.0, max(balance) - balance[0]) / scale, 0.0, 1e-10)

if mode == "slip":
    acceleration = (load - mu * weight) / mass
    for a, b in zip(rows, rows[1:]):
        if b["time"] < T_SETTLED:
            continue
        dt = b["time"] - a["time"]
        t = b["time"]
        check(f"t = {t:g}: contact force", b["contact_force"], weight, 1e-8)
        check(f"t = {t:g}: acceleration", (b["momentum_1_x"] - a["momentum_1_x"]) / (mass * dt), acceleration, 1e-8)
        slip = a["momentum_1_x"] / mass * dt + 0.5 * acceleration * dt * dt
        check(f"t = {t:g}: dissipation of the step", b["frictional_dissipation"] - a["frictional_dissipation"], mu * weight * slip, 1e-8)
else:
    frames = vtu.pvd_frames(f"{directory}/solution.pvd")
    last = vtu.read_record(os.path.join(directory, frames[-1][1]))
    displacement = last["fields"]["displacement"]
    bottom = [u for p, u in zip(last["points"], displacement) if abs(p[1]) < 1e-12]
    if len(bottom) < 2:
        checks.failures.append("bottom nodes")
    check(f"t = {frames[-1][0]:g}: largest slip of a bottom node / width", max(abs(u[0]) for u in bottom) / width, 0.0, 1e-12)
    check(f"t = {rows[-1]['time']:g}: momentum_1_x / (T t)", rows[-1]["momentum_1_x"] / (load * rows[-1]["time"]), 0.0, 1e-10)

checks.finish()
