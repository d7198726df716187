#!/usr/bin/python3
"""Compares two history.csv files column by column.

Usage: compare_histories.py A.csv B.csv TOLERANCE
Passes (exit 0) when both have the same columns and rows and, for every column except
newton_iterations, max |a - b| <= TOLERANCE * max |a| over that column; prints the worst column.
Columns that are round-off or tolerance-level by nature are scaled by the quantity they measure
(SCALE_COLUMN), or by themselves where they are larger: the force imbalance by the contact force,
the penetration by the displacement of the contact pole, the normal velocity and acceleration
jumps by the pole's velocity and acceleration (a jump the contact-dynamics treatment leaves, as
mass redistribution does at the three spheres' two contacts, can exceed them), the strain energy
by the total energy, as the energy guard weighs it: W(F) sums first-order terms that cancel, so
its round-off is 1e-16 over the strain, 1e-11 where the bodies strain by 1e-5 (the oblique
spheres on 2 ranks: 4.9e-11 to 7.2e-11 of its own maximum against one rank, 1.9e-11 to 2.7e-11
of the total energy, varying from run to run: runs on several ranks are not repeatable bit for
bit, their contact forces differing by 2e-14 between two runs). A body's momentum
and impulse are scaled by the largest momentum or impulse of any body (MOMENTUM_COLUMNS): a body
at rest by symmetry (the middle of three spheres) has a momentum of round-off size, which is no
scale for its own differences. The angular momentum components are scaled by the largest of
them (ANGULAR_MOMENTUM_COLUMNS): a component that vanishes by symmetry (L_x and L_z of the oblique
spheres, whose motion lies in their symmetry plane y = 0) is round-off, no scale either.
"""
import csv
import sys

SCALE_COLUMN = {
    "force_imbalance": "contact_force",
    "max_penetration": "u_tip_1",
    "velocity_jump": "v_tip_1",
    "acceleration_jump": "a_tip_1",
    "strain_energy": "total_energy",
}

MOMENTUM_COLUMNS = ("momentum_", "impulse_")
ANGULAR_MOMENTUM_COLUMNS = ("angular_momentum_",)


def read(path):
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))
    return rows[0], [[float(value) for value in row] for row in rows[1:]]


def main():
    names_a, rows_a = read(sys.argv[1])
    names_b, rows_b = read(sys.argv[2])
    tolerance = float(sys.argv[3])
    if names_a != names_b or len(rows_a) != len(rows_b):
        print(f"different shapes: {len(names_a)}x{len(rows_a)} vs {len(names_b)}x{len(rows_b)}")
        return 1
    worst_name, worst = "", 0.0
    for column, name in enumerate(names_a):
        if name == "newton_iterations":
            continue
        group = next((prefixes for prefixes in (MOMENTUM_COLUMNS, ANGULAR_MOMENTUM_COLUMNS)
                      if name.startswith(prefixes)), None)
        if group:
            scale_columns = [j for j, other in enumerate(names_a) if other.startswith(group)]
        else:
            scale_columns = sorted({column, names_a.index(SCALE_COLUMN.get(name, name))})
        scale = max(abs(row[j]) for row in rows_a for j in scale_columns)
        difference = max(abs(a[column] - b[column]) for a, b in zip(rows_a, rows_b))
        relative = difference / scale if scale > 0 else difference
        if relative > worst:
            worst_name, worst = name, relative
    print(f"{len(rows_a)} rows; largest relative difference {worst:.3e} in column '{worst_name}'"
          f" (tolerance {tolerance:g})")
    return 0 if worst <= tolerance else 1


if __name__ == "__main__":
    sys.exit(main())
