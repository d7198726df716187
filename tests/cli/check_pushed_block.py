"""Checks the block of prm/sliding_block.prm pushed along its plane by a Dirichlet boundary on its
side (issue 29: friction with a prescribed displacement; the side's bottom corner is a contact
node prescribed across the plane's normal).

Usage: check_pushed_block.py DIRECTORY MU N SLIP [--bouncing]

The block's weight N presses it on the plane with friction coefficient MU; its left side (x only)
is moved by SLIP from rest to rest, so the block slides by SLIP and friction dissipates
MU N SLIP, less the share of the corner node, whose x is prescribed and carries no friction (a
fixed direction carries none): D between 0.9 and 1 times MU N SLIP (measured 0.969). The external
work is the side's reaction's and the weight's: the algorithmic energy plus D minus it never rises
above its value at the start by more than 1e-12 of the final work (generalized-alpha with spectral
radius 0 dissipates; the energy guard's own test).

--bouncing: the block on a step that resolves its vertical vibration (Newmark at dt = 0.05: placed
unloaded under its weight, it bounces, and the push rocks it; its pairs open and close, and it
leaves the plane at times), so N is not its weight at every moment and MU N SLIP no exact value:
its mean over the run is the weight, less the flights and the corner's share, so D at least
0.5 MU N SLIP (measured 0.87); D never decreasing by more than 1e-6 of itself in a step; and the
energy balance as above (Newmark with gamma > 1/2 dissipates as well).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from history_checks import Checks, read_history  # noqa: E402

directory = sys.argv[1]
mu, normal_force, slip = map(float, sys.argv[2:5])
rows = read_history(directory)
checks = Checks()
last = rows[-1]
work = last["external_work"]
if "--bouncing" in sys.argv[5:]:
    checks.bound("D / (mu N slip), at least", last["frictional_dissipation"] / (mu * normal_force * slip),
                 0.5, above=True)
    # A stuck pair's slip is zero to Newton's tolerance only, and so is its work (measured 1.2e-7).
    checks.bound("largest decrease of D in a step / D", max(
        a["frictional_dissipation"] - b["frictional_dissipation"] for a, b in zip(rows, rows[1:]))
        / last["frictional_dissipation"], 1e-6)
else:
    checks.bound("D / (mu N slip)", last["frictional_dissipation"] / (mu * normal_force * slip), 1.0)
    checks.bound("D / (mu N slip), at least",
                 last["frictional_dissipation"] / (mu * normal_force * slip), 0.9, above=True)
balance = [r["algorithmic_energy"] + r["frictional_dissipation"] - r["external_work"] for r in rows]
checks.bound("max rise of E_alg + D - W_ext / W_ext", (max(balance) - balance[0]) / work, 1e-12)
checks.finish()
