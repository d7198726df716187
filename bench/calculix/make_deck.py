#!/usr/bin/python3
"""CalculiX 2.20 deck for the sphere impact of issue 13, seen from its symmetry plane.

Two identical elastic spheres (R = 8, E = 5e3, nu = 0.3, speeds 1 toward each other, poles 4
apart) are, by symmetry, one sphere striking a rigid plane: a sphere of radius R centred on the
axis at z = -(R + 2) (contact pole at z = -2), initial velocity +v along z, rigid plane z = 0.
It touches at t = 2.

ccx's axisymmetric convention: x = r >= 0, y = the axis (so the model's z is ccx's y). CAX8
elements are expanded internally into a 2-degree wedge of C3D20 elements (rotation about the y
axis, +-1 degree); the rigid plane is one fixed C3D8 brick above the sphere whose face y = 0
covers that wedge (see README.md for why not a CAX8 plate). Its reaction force is the force on
the 2-degree wedge: the full ring is 180 times it.

Usage: make_deck.py [--geometry 3d] --out DIR [options]; writes DIR/sphere.inp (the deck), DIR/sphere.msh (the
gmsh mesh) and DIR/deck.json (the parameters and the derived figures the runner needs).
With --geometry 3d the deck is make_deck_3d.py's quarter sphere (its options follow).
Stdlib only; needs the gmsh binary (Debian package gmsh).
"""
import argparse
import json
import math
import os
import sys

import ccx_deck
from ccx_deck import lines_of

HERE = os.path.dirname(os.path.abspath(__file__))
GEO = os.path.normpath(os.path.join(HERE, "..", "..", "meshes", "sphere_graded.geo"))

R, E, NU, V = 8.0, 5e3, 0.3, 1.0


def hertz(rho):
    """Hertz's sphere on a rigid plane: E* = E/(1-nu^2), R* = R, m* = m, speed V."""
    return ccx_deck.hertz(R, E, NU, V, rho)


def run_gmsh(msh, centre_z, pole_size, far_size, zone_radius):
    ccx_deck.run_gmsh(GEO, msh, 2, {"R": R, "CentreZ": centre_z, "PoleSide": 1,
                                    "PoleSize": pole_size, "FarSize": far_size,
                                    "ZoneRadius": zone_radius})


def read_msh2(path):
    """Nodes {id: (x, y)} and the 8-node quadrilaterals [[8 node ids]] of an ASCII msh 2.2 file
    (element type 16)."""
    nodes, elements = ccx_deck.read_msh2(path, [16], dim=2)
    return nodes, [q for _, q in elements[16]]


def orient(nodes, q):
    """CAX8 wants the corners counter-clockwise in the (r, z) plane."""
    area2 = 0.0
    for k in range(4):
        x0, y0 = nodes[q[k]]
        x1, y1 = nodes[q[(k + 1) % 4]]
        area2 += x0 * y1 - x1 * y0
    if area2 > 0:
        return q
    return [q[0], q[3], q[2], q[1], q[7], q[6], q[5], q[4]]


def main():
    # --geometry 3d: the quarter sphere of prm/sphere_on_rigid_plane_3d.prm (make_deck_3d.py).
    pre = argparse.ArgumentParser(add_help=False)
    pre.add_argument("--geometry", choices=["axisymmetric", "3d"], default="axisymmetric")
    known, rest = pre.parse_known_args()
    if known.geometry == "3d":
        import make_deck_3d
        make_deck_3d.main(rest)
        return
    sys.argv[1:] = rest
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--out", required=True, help="output directory")
    ap.add_argument("--pole-size", type=float, default=0.0,
                    help="PoleSize of sphere_graded.geo (0: 0.05 (rho/0.001)^0.2, i.e. the Hertz "
                    "contact radius / 9.4: the converged mesh of README.md at rho 0.001)")
    ap.add_argument("--far-size", type=float, default=0.8, help="FarSize of sphere_graded.geo")
    ap.add_argument("--zone-radius", type=float, default=0.0,
                    help="ZoneRadius of sphere_graded.geo (0: 0.5 (rho/0.001)^0.2, i.e. 1.06 x the "
                    "Hertz contact radius: the geo's default at rho 0.001)")
    ap.add_argument("--rho", type=float, default=0.001, help="density")
    ap.add_argument("--dt", type=float, default=None, help="time step (default 0.0025 at rho "
                    "0.001, 0.05 at rho 1, else 0.0025 (rho/0.001)^0.4)")
    ap.add_argument("--end-time", type=float, default=None,
                    help="end time (default 2.2 at rho 0.001, 4 at rho 1, else 2 + 2.4 t_Hertz)")
    ap.add_argument("--start-time", type=float, default=0.0,
                    help="start the run at this time of the problem (the sphere placed where its "
                    "free flight has brought it; the free flight is a rigid translation that "
                    "Newmark integrates exactly): for cheap mesh studies. The runner adds it to "
                    "ccx's times")
    ccx_deck.add_penalty_dynamics_options(
        ap, penalty=50.0, launch="gravity",
        launch_help="ccx 2.20 ignores the latter on CAX8 nodes (kept to show that; README.md)")
    ap.add_argument("--slave-depth", type=float, default=None,
                    help="slave faces: the surface within this axial distance of the pole "
                    "(default min(R, 4 x Hertz contact radius + 0.5))")
    a = ap.parse_args()

    h = hertz(a.rho)
    scale = (a.rho / 0.001) ** 0.4
    if a.dt is None:
        a.dt = 0.05 if a.rho == 1.0 else 0.0025 * scale
    if a.end_time is None:
        a.end_time = 4.0 if a.rho == 1.0 else (2.2 if a.rho == 0.001 else 2.0 + 2.4 * h["duration"])
    if a.pole_size <= 0:
        a.pole_size = 0.05 * (a.rho / 0.001) ** 0.2
    if a.zone_radius <= 0:
        a.zone_radius = 0.5 * (a.rho / 0.001) ** 0.2
    slope = ccx_deck.complete_options(a, h, R, E)
    nsteps = int(round((a.end_time - a.start_time) / a.dt))

    # The launch: the first step is one increment dt long with a uniform body force g = v / dt
    # on the sphere, full strength from the start of the step (a rigid uniform acceleration: no
    # strain). Measured in ccx 2.20 (README.md): after it, the sphere moves at v with u(dt) =
    # v dt / 2, i.e. u(t) = v (t - dt/2) from then on. So the sphere starts v dt/2 closer to the
    # plane (pole gap 2 - v dt/2) and touches at t = 2 exactly, as a sphere launched at t = 0.
    launch_shift = 0.5 * V * a.dt if a.launch == "gravity" else 0.0
    gap = 2.0 - V * a.start_time - launch_shift
    centre_z = -(R + gap)
    if 2.0 - a.start_time < a.dt - 1e-12 or a.start_time < 0:
        sys.exit(f"make_deck.py: --start-time {a.start_time:g} must lie in [0, 2 - dt]: the "
                 "launch increment must end before the contact")

    os.makedirs(a.out, exist_ok=True)
    msh = os.path.join(a.out, "sphere.msh")
    run_gmsh(msh, centre_z, a.pole_size, a.far_size, a.zone_radius)
    nodes, quads = read_msh2(msh)
    quads = [orient(nodes, q) for q in quads]
    used = sorted({n for q in quads for n in q})

    tol = 1e-7 * R
    on_sphere = {n for n in used
                 if abs(math.hypot(nodes[n][0], nodes[n][1] - centre_z) - R) < tol}
    axis = [n for n in used if abs(nodes[n][0]) < tol]
    pole_y = centre_z + R
    pole = min(used, key=lambda n: math.hypot(nodes[n][0], nodes[n][1] - pole_y))
    far = min(used, key=lambda n: math.hypot(nodes[n][0], nodes[n][1] - (centre_z - R)))
    slave = []  # (element, face)
    for e, q in enumerate(quads, start=1):
        for k in range(4):
            c0, c1, mid = q[k], q[(k + 1) % 4], q[4 + k]
            if c0 in on_sphere and c1 in on_sphere and mid in on_sphere and \
               min(nodes[c0][1], nodes[c1][1]) > pole_y - a.slave_depth:
                slave.append((e, k + 1))
    pole_edge = min(math.dist(nodes[pole], nodes[q[(q.index(pole) + s) % 4]])
                    for q in quads if pole in q[:4] for s in (1, 3)
                    if q[(q.index(pole) + s) % 4] in on_sphere)

    # The rigid plate: one C3D8 brick above the sphere, 0 <= y <= 1, all nodes fixed; its face
    # y = 0 is the master surface. It spans the wedge (|z| <= r sin 1 deg) and reaches past the
    # axis so that no master face is collapsed.
    nmax = max(used)
    p0 = (nmax // 1000 + 1) * 1000 + 1
    x0, x1, yt, zw = -1.0, 1.25 * R, 1.0, 0.25 * R
    # Face 1 (nodes 1-2-3-4) at y = 0, counter-clockwise seen from +y (z x x = +y) so that
    # nodes 5-8 lie above it at y = yt (a positive Jacobian).
    corners = [(x0, -zw), (x0, zw), (x1, zw), (x1, -zw)]
    plate_nodes = {}
    for i, (x, z) in enumerate(corners):
        plate_nodes[p0 + i] = (x, 0.0, z)
        plate_nodes[p0 + 4 + i] = (x, yt, z)
    ne = len(quads)
    plate_el = ne + 1

    inp = []
    w = inp.append
    w("*HEADING")
    w(f"Sphere R={R:g} E={E:g} nu={NU:g} rho={a.rho:g} v={V:g} on a rigid plate (dyncontact "
      f"issue 13 CalculiX peer); pole size {a.pole_size:g}")
    w("*NODE, NSET=NSPHERE")
    for n in used:
        w(f"{n}, {nodes[n][0]:.15g}, {nodes[n][1]:.15g}, 0")
    w("*NODE, NSET=NPLATE")
    for n, (x, y, z) in sorted(plate_nodes.items()):
        w(f"{n}, {x:.15g}, {y:.15g}, {z:.15g}")
    w("*ELEMENT, TYPE=CAX8, ELSET=ESPHERE")
    for e, q in enumerate(quads, start=1):
        w(f"{e}, " + ", ".join(str(n) for n in q))
    w("*ELEMENT, TYPE=C3D8, ELSET=EPLATE")
    w(f"{plate_el}, " + ", ".join(str(n) for n in sorted(plate_nodes)))
    w("*NSET, NSET=AXIS")
    w(lines_of(axis))
    w("*NSET, NSET=POLE")
    w(f"{pole},")
    w("*NSET, NSET=FARPOLE")
    w(f"{far},")
    w("*SURFACE, NAME=SSLAVE")
    for e, f in slave:
        w(f"{e}, S{f}")
    w("*SURFACE, NAME=SMASTER")
    w(f"{plate_el}, S1")
    ccx_deck.write_sphere_and_plate(w, E, NU, a.rho)
    w("*BOUNDARY")
    w("AXIS, 1, 1")
    w("NPLATE, 1, 3")
    ccx_deck.write_contact(w, slope, a.sigma_inf, a.c0, a.contact, a.small_sliding)
    if a.launch == "initial-velocity":
        w("*INITIAL CONDITIONS, TYPE=VELOCITY")
        w(f"NSPHERE, 2, {V:.15g}")

    ccx_deck.write_steps(w, a, nsteps, (V / a.dt, 0, 1, 0),
                         lambda: ccx_deck.write_outputs(w, a.print_every))

    with open(os.path.join(a.out, "sphere.inp"), "w") as f:
        f.write("\n".join(inp) + "\n")
    info = dict(vars(a))
    info.update({"geo": GEO, "R": R, "E": E, "nu": NU, "v": V, "centre_z": centre_z, "gap": gap,
                 "launch_shift": launch_shift, "penalty_slope": slope, "increments": nsteps,
                 "nodes": len(used), "elements": ne, "pole_node": pole, "axis_nodes": len(axis),
                 "slave_faces": len(slave), "pole_edge": pole_edge, "wedge_factor": 180.0,
                 "hertz": h})
    with open(os.path.join(a.out, "deck.json"), "w") as f:
        json.dump(info, f, indent=1)
    print(f"{a.out}/sphere.inp: {len(used)} nodes, {ne} CAX8, {len(slave)} slave faces, "
          f"pole edge {pole_edge:.4g}, dt {a.dt:g}, end {a.end_time:g}")


if __name__ == "__main__":
    main()
