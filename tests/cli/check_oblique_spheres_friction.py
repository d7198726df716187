"""Checks the coarse oblique spheres of prm/oblique_spheres_3d.prm with friction mu = 0.3 (issue 29:
friction between two bodies in 3D, node-to-surface pairs, on the default mass-redistribution).

Usage: check_oblique_spheres_friction.py DIRECTORY

- the impact is over at the end (no active pair);
- the contact slides (some step has a sliding pair) and dissipates: frictional_dissipation ends
  above 1e-3 of the initial energy (measured 3.6e-2) and never decreases by more than 1e-12 of
  it (round-off of a stuck pair's zero slip: measured 1.0e-15);
- the algorithmic energy plus the dissipation never rises above its initial value by more than
  1e-6 of it (the energy guard's tolerance is 1e-4; measured: it never rises);
- the total momentum along x and z is constant to 1e-10 of |p_z| (measured 1.2e-12): the
  tangential forces balance between the bodies as the normal ones do;
- at most 20 linear solves in a step (measured 15, at the first contact step; issue 29 F asks 15
  of its cases B and C, which the Newton limit of 25 would let pass unnoticed).
"""
import sys

from history_checks import Checks, read_history

rows = read_history(sys.argv[1])
checks = Checks()
check = checks.bound


first, last = rows[0], rows[-1]
check("active pairs at the end (the impact is over)", last["active_constraints"], 0)
energy = first["algorithmic_energy"]
check("most sliding pairs in a step", max(r["sliding_pairs"] for r in rows), 1, above=True)
check("frictional dissipation at the end / E_0", last["frictional_dissipation"] / energy, 1e-3, above=True)
drops = [a["frictional_dissipation"] - b["frictional_dissipation"] for a, b in zip(rows, rows[1:])]
check("largest decrease of frictional_dissipation / E_0", max(0.0, max(drops)) / energy, 1e-12)
check("largest rise of E + D / E_0", max(r["algorithmic_energy"] + r["frictional_dissipation"] - energy for r in rows) / energy, 1e-6)
scale = abs(first["momentum_z"])
for axis in "xz":
    check(f"largest change of the momentum along {axis} / |p_z|", max(abs(r[f"momentum_{axis}"] - first[f"momentum_{axis}"]) for r in rows) / scale, 1e-10)
check("largest linear solves in a step", max(r["newton_iterations"] for r in rows), 20)
checks.finish()
