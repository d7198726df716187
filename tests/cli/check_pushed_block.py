"""Checks the block of prm/sliding_block.prm pushed along its plane by a Dirichlet boundary on its
side (issue 29: friction with a prescribed displacement; the side's bottom corner is a contact
node prescribed across the plane's normal).

Usage: check_pushed_block.py DIRECTORY MU N SLIP

The block's weight N presses it on the plane with friction coefficient MU; its left side (x only)
is moved by SLIP from rest to rest, so the block slides by SLIP and friction dissipates
MU N SLIP, less the share of the corner node, whose x is prescribed and carries no friction (a
fixed direction carries none): D between 0.9 and 1 times MU N SLIP (measured 0.969). The external
work is the side's reaction's and the weight's: the algorithmic energy plus D minus it never rises
above its value at the start by more than 1e-12 of the final work (generalized-alpha with spectral
radius 0 dissipates; the energy guard's own test).
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
checks.bound("D / (mu N slip)", last["frictional_dissipation"] / (mu * normal_force * slip), 1.0)
checks.bound("D / (mu N slip), at least", last["frictional_dissipation"] / (mu * normal_force * slip),
             0.9, above=True)
balance = [r["algorithmic_energy"] + r["frictional_dissipation"] - r["external_work"] for r in rows]
checks.bound("max rise of E_alg + D - W_ext / W_ext", (max(balance) - balance[0]) / work, 1e-12)
checks.finish()
