"""Checks the ParaView output of a 2D (axisymmetric) contact run in DIRECTORY (issue 15, A), on
any number of MPI ranks (each frame's pieces, one per rank, read as one):

 - solution.pvd and contact_surface.pvd list, with its history time, a frame for every row of
   history.csv with active pairs (frame files are numbered by history row);
 - every cell is a VTK Lagrange cell (70, quadrilateral; 68, the surface curves), so a Q2 cell is
   one curved 9-node cell, not four linear quads;
 - the fields are there: displacement, velocity, acceleration, contact traction, Cauchy stress,
   Green-Lagrange strain, von Mises stress and body; on the surfaces contact pressure, gap, active;
 - in every contact frame the surface's pressure at the axis is history.csv's centre_pressure (to
   float32 round-off), and the normal Cauchy stress there balances it: -sigma_zz = p within
   STRESS_TOLERANCE times the peak centre pressure (the element stress at the surface is not the
   consistent pressure, so this is the discretization's traction jump, bounded in the calling
   test).

 - at the peak centre pressure p0, with the run's own contact radius a, the stresses along the axis
   of body 1 down to a depth of 2 a are Hertz's subsurface field (Johnson, Contact Mechanics,
   eq. 3.45, Poisson's ratio NU): sigma_zz = -p0 / (1 + z^2/a^2), sigma_rr = sigma_thetatheta =
   -p0 [(1 + nu)(1 - (z/a) atan(a/z)) - 1 / (2 (1 + z^2/a^2))], and von Mises |sigma_zz -
   sigma_rr|, within HERTZ_TOLERANCE times p0 (the largest von Mises stress, 0.62 p0 at 0.48 a for
   nu = 0.3, is the point of this check).

Usage: check_vtu.py DIRECTORY STRESS_TOLERANCE NU HERTZ_TOLERANCE. Exit 1 with the first failure,
0 otherwise."""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu  # noqa: E402

SOLUTION_FIELDS = ["displacement", "velocity", "acceleration", "contact_traction", "body",
                   "von_mises_stress"] + [
    f"{q}_{c}" for q in ("cauchy_stress", "green_lagrange_strain")
    for c in ("rr", "zz", "thetatheta", "rz")]
SURFACE_FIELDS = ["displacement", "contact_pressure", "gap", "active"]


def fail(message):
    print("check_vtu: " + message)
    sys.exit(1)


def hertz_axis_stresses(depth, a, p0, nu):
    """(sigma_zz, sigma_rr) on the axis at `depth` below the centre of a Hertz contact."""
    ratio = depth / a
    sigma_zz = -p0 / (1. + ratio * ratio)
    arctangent = math.pi / 2. if depth == 0. else math.atan(1. / ratio)
    sigma_rr = -p0 * ((1. + nu) * (1. - ratio * arctangent) - 0.5 / (1. + ratio * ratio))
    return sigma_zz, sigma_rr


def check_hertz(rows, pieces, contact_rows, nu, tolerance):
    """Largest deviation / p0 of the axis stresses of body 1 from Hertz's, at the peak frame."""
    peak = max(contact_rows, key=lambda r: float(rows[r]["centre_pressure"]))
    p0 = float(rows[peak]["centre_pressure"])
    a = float(rows[peak]["contact_radius"])
    solution = pieces["solution", peak]
    fields = solution["fields"]
    axis = [i for i, p in enumerate(solution["points"]) if p[0] == 0. and fields["body"][i] == 1]
    top = max(solution["points"][i][1] for i in axis)
    worst = {"cauchy_stress_zz": 0., "cauchy_stress_rr": 0., "von_mises_stress": 0.}
    n_points = 0
    for i in axis:
        depth = top - solution["points"][i][1]
        if depth > 2. * a:
            continue
        n_points += 1
        sigma_zz, sigma_rr = hertz_axis_stresses(depth, a, p0, nu)
        for name, exact in (("cauchy_stress_zz", sigma_zz), ("cauchy_stress_rr", sigma_rr),
                            ("von_mises_stress", abs(sigma_zz - sigma_rr))):
            worst[name] = max(worst[name], abs(fields[name][i] - exact) / p0)
    print(f"check_vtu: Hertz's axis stresses at the peak (row {peak}, p0 = {p0:.4g}, "
          f"a = {a:.4g}, {n_points} nodes to depth 2a): largest deviation / p0 " +
          ", ".join(f"{name} {value:.3g}" for name, value in worst.items()))
    if n_points < 5:
        fail(f"only {n_points} axis nodes of body 1 lie within 2a of the surface")
    if max(worst.values()) > tolerance:
        fail(f"the axis stresses miss Hertz's by {max(worst.values()):.3g} p0 (bound {tolerance})")


def main(directory, stress_tolerance, nu, hertz_tolerance):
    with open(os.path.join(directory, "history.csv")) as file:
        rows = list(csv.DictReader(file))
    contact_rows = [r for r, row in enumerate(rows) if float(row["active_constraints"]) > 0]
    if not contact_rows:
        fail("the run has no step with active pairs")
    pieces = {}
    for record, cell_type, fields in (("solution", 70, SOLUTION_FIELDS),
                                      ("contact_surface", 68, SURFACE_FIELDS)):
        frames = {int(name.split("_")[-1].split(".")[0]): (time, name)
                  for time, name in vtu.pvd_frames(os.path.join(directory, record + ".pvd"))}
        missing = [r for r in contact_rows if r not in frames]
        if missing:
            fail(f"{record}.pvd has no frame for the contact rows {missing[:5]}")
        for row in contact_rows:
            time, name = frames[row]
            if abs(time - float(rows[row]["time"])) > 1e-12 * max(1., time):
                fail(f"{name}: time {time} in the PVD, {rows[row]['time']} in history.csv")
            piece = vtu.read_record(os.path.join(directory, name))
            if set(piece["types"]) != {cell_type}:
                fail(f"{name}: cell types {set(piece['types'])}, expected {cell_type}")
            absent = [f for f in fields if f not in piece["fields"]]
            if absent:
                fail(f"{name}: no field {absent}")
            pieces[record, row] = piece

    worst_jump = 0.
    peak = max(float(rows[r]["centre_pressure"]) for r in contact_rows)
    for row in contact_rows:
        surface, solution = pieces["contact_surface", row], pieces["solution", row]
        # The slave node on the axis: the surface point of smallest r.
        axis = min(range(len(surface["points"])), key=lambda i: surface["points"][i][0])
        pressure = surface["fields"]["contact_pressure"][axis]
        centre = float(rows[row]["centre_pressure"])
        if abs(pressure - centre) > 1e-6 * abs(centre):
            fail(f"row {row}: axis pressure {pressure} in the VTU, {centre} in history.csv")
        point = surface["points"][axis]
        match = [i for i, p in enumerate(solution["points"])
                 if abs(p[0] - point[0]) + abs(p[1] - point[1]) < 1e-6]
        if not match:
            fail(f"row {row}: no solution point at the surface's axis node {point}")
        if centre > 0:
            sigma = solution["fields"]["cauchy_stress_zz"][match[0]]
            worst_jump = max(worst_jump, abs(-sigma - centre) / peak)
    print(f"check_vtu: {len(contact_rows)} contact rows, each with a frame; largest "
          f"|sigma_zz + p| at the axis / peak p = {worst_jump:.3g}")
    if worst_jump > stress_tolerance:
        fail(f"the normal stress at the axis misses the pressure by {worst_jump:.3g} of it "
             f"(bound {stress_tolerance})")
    check_hertz(rows, pieces, contact_rows, nu, hertz_tolerance)


if __name__ == "__main__":
    main(sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]))
