"""Checks a block pressed through a Dirichlet boundary (tests/cases/pressed_block.prm and its 3D
variant; issue 29, point 4) against the exact quasi-static state and the energy balance.

Usage: check_prescribed_press.py DIRECTORY E D AREA HEIGHT exact|dissipative

A block of height HEIGHT and cross-section AREA (per unit depth in plane strain), Young's modulus
E, Poisson's ratio 0, clamped at its bottom and pushed down by D at its top by a prescribed
displacement ramped smoothly from rest to rest, ends in uniaxial strain D / HEIGHT:
  - the strain energy at the end is E D^2 AREA / (2 HEIGHT) to 1e-6 (relative). The ramp is 16
    periods of the lowest mode long, so what is left of the dynamic response is of the order of
    the kinetic energy, measured 5e-8 of it at the end; 1e-6 also bounds the kinetic energy
    fraction, which is printed;
  - the energy balance: the external work counts the work of the prescribed boundary's reaction.
    exact (Newmark beta = 1/4, gamma = 1/2, or generalized-alpha with spectral radius 1, the
    midpoint rule; linear elasticity): the total energy equals the external work at every step to
    1e-12 of the final work (their identities are exact for linear forces; measured 2e-15). dissipative (every other integrator): the total
    energy never exceeds the external work by more than 1e-12 of it (they dissipate; measured
    0), and the energy lost, W - E at the end, stays below 1e-2 of W (measured 3e-3 for
    generalized-alpha with spectral radius 0.8: damped high frequencies of the ramp's start).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from history_checks import Checks, read_history  # noqa: E402

directory = sys.argv[1]
E, d, area, height = map(float, sys.argv[2:6])
mode = sys.argv[6]
rows = read_history(directory)
checks = Checks()
exact_energy = E * d * d * area / (2.0 * height)
last = rows[-1]
work = last["external_work"]
checks.relative("final strain energy vs E d^2 A / (2 H)", last["strain_energy"], exact_energy, 1e-6)
checks.bound("final kinetic energy fraction", last["kinetic_energy"] / last["strain_energy"], 1e-6)
gain = max(row["total_energy"] - row["external_work"] for row in rows) / work
if mode == "exact":
    loss = max(abs(row["total_energy"] - row["external_work"]) for row in rows) / work
    checks.bound("max |E - W_ext| / W_ext (the energy identity)", loss, 1e-12)
else:
    checks.bound("max (E - W_ext) / W_ext (never a gain)", gain, 1e-12)
    checks.bound("final (W_ext - E) / W_ext (dissipated)", (work - last["total_energy"]) / work, 1e-2)
checks.finish()
