#!/usr/bin/python3
"""CalculiX 2.20 deck of prm/sphere_on_rigid_plane_3d.prm (issue 28, F): a quarter sphere on a
rigid plane, the 3D peer of make_deck.py's axisymmetric deck (see README.md, "The 3D deck").

The elastic sphere R = 8, E = 5e3, nu = 0.3, rho = 0.001, centred at (0, 0, 8.005) (its pole
0.005 above the rigid plane z = 0), falls at speed 1 along -z and touches at t = 0.005; dt =
0.0025, end time 0.095, as dyncontact's case. One quarter, x >= 0, y >= 0, on the symmetry
planes x = 0 (u_x = 0) and y = 0 (u_y = 0), meshed by gmsh from meshes/quarter_sphere_3d.geo
(parameters N, NR, PoleGrading) as 20-node hexahedra (msh type 17), renumbered to ccx's C3D20
node order and checked (every element's Jacobian positive at its 27 Gauss points, each mid-edge
node next to its edge's midpoint, the volume against pi R^3 / 3). The rigid plane is one fixed
C3D8 brick under z = 0 whose top face is the master surface; the slave surface the sphere's faces
near the pole; penalty contact as make_deck.py. The reaction of the brick's supports is the
quarter's contact force: the whole sphere's is 4 times it (deck.json: wedge_factor 4).

Usage: make_deck_3d.py --out DIR [options] (or make_deck.py --geometry 3d --out DIR [options]);
writes DIR/sphere.inp, DIR/sphere.msh and DIR/deck.json. Stdlib only; needs gmsh.
"""
import argparse
import json
import math
import os
import sys

import ccx_deck
from ccx_deck import lines_of

HERE = os.path.dirname(os.path.abspath(__file__))
GEO = os.path.normpath(os.path.join(HERE, "..", "..", "meshes", "quarter_sphere_3d.geo"))

R, E, NU, V, RHO = 8.0, 5e3, 0.3, 1.0, 0.001
GAP = 0.005  # the pole's height above the plane at t = 0: it touches at t = 0.005

# The finite-sphere law for this impact (the whole sphere), as dyncontact computes it
# (include/dyncontact/reference/finite_sphere_impact.h; the `finite_sphere` column of
# impact_summary.csv of prm/sphere_on_rigid_plane_3d.prm): the accuracy reference.
LAW = {"peak": 98.9026882215, "duration": 0.0803498784918, "impulse": 4.2893211697}

# gmsh's 20-node hexahedron (msh type 17) -> ccx's C3D20: the corners agree; gmsh numbers the
# mid-edge nodes 8-19 on the edges 01 03 04 12 15 23 26 37 45 47 56 67, ccx on 01 12 23 30 45
# 56 67 74 04 15 26 37 (0-based corners). ccx node k is gmsh node GMSH_TO_CCX[k].
GMSH_TO_CCX = [0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15]
# ccx's C3D20 edges (the corners of mid-node 8 + i) and faces S1-S6 (corners, mid-nodes).
EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6),
         (3, 7)]
FACES = [((0, 1, 2, 3), (8, 9, 10, 11)), ((4, 7, 6, 5), (15, 14, 13, 12)),
         ((0, 4, 5, 1), (16, 12, 17, 8)), ((1, 5, 6, 2), (17, 13, 18, 9)),
         ((2, 6, 7, 3), (18, 14, 19, 10)), ((3, 7, 4, 0), (19, 15, 16, 11))]
CORNERS = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1),
           (1, 1, 1), (-1, 1, 1)]
NATURAL = CORNERS + [tuple(0.5 * (CORNERS[i][d] + CORNERS[j][d]) for d in range(3))
                     for i, j in EDGES]


def shape_gradients(p):
    """d N_k / d (xi, eta, zeta) of the 20-node serendipity hexahedron at p, ccx's order."""
    grads = []
    for q in NATURAL:
        s = [p[d] * q[d] for d in range(3)]
        if all(q[d] != 0 for d in range(3)):
            one = [(1 + s[d]) for d in range(3)]
            total = s[0] + s[1] + s[2]
            g = [q[d] / 8.0 * one[(d + 1) % 3] * one[(d + 2) % 3] * (total + s[d] - 1)
                 for d in range(3)]
        else:
            z = next(d for d in range(3) if q[d] == 0)
            o1, o2 = (z + 1) % 3, (z + 2) % 3
            g = [0.0] * 3
            g[z] = -2 * p[z] * (1 + s[o1]) * (1 + s[o2]) / 4.0
            g[o1] = q[o1] * (1 - p[z] ** 2) * (1 + s[o2]) / 4.0
            g[o2] = q[o2] * (1 - p[z] ** 2) * (1 + s[o1]) / 4.0
        grads.append(g)
    return grads


def gauss27():
    x, w = [-math.sqrt(0.6), 0.0, math.sqrt(0.6)], [5 / 9, 8 / 9, 5 / 9]
    return [((x[i], x[j], x[k]), w[i] * w[j] * w[k])
            for i in range(3) for j in range(3) for k in range(3)]


GAUSS = [(p, wt, shape_gradients(p)) for p, wt in gauss27()]


def element_check(nodes, hexes):
    """(volume, smallest detJ, largest |mid-node - edge midpoint| / edge length)."""
    volume, min_det, worst_mid = 0.0, float("inf"), 0.0
    for h in hexes:
        x = [nodes[n] for n in h]
        for p, wt, grads in GAUSS:
            jac = [[sum(grads[k][c] * x[k][r] for k in range(20)) for c in range(3)]
                   for r in range(3)]
            det = (jac[0][0] * (jac[1][1] * jac[2][2] - jac[1][2] * jac[2][1])
                   - jac[0][1] * (jac[1][0] * jac[2][2] - jac[1][2] * jac[2][0])
                   + jac[0][2] * (jac[1][0] * jac[2][1] - jac[1][1] * jac[2][0]))
            min_det = min(min_det, det)
            volume += wt * det
        for m, (i, j) in enumerate(EDGES):
            mid = [0.5 * (x[i][d] + x[j][d]) for d in range(3)]
            worst_mid = max(worst_mid, math.dist(mid, x[8 + m]) / math.dist(x[i], x[j]))
    return volume, min_det, worst_mid


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--out", required=True, help="output directory")
    # The defaults are the equal-accuracy mesh of README.md ("The 3D peer"); dyncontact's
    # shipped mesh is N 8, NR 6, PoleGrading 10.
    ap.add_argument("--n", type=int, default=5, help="N of quarter_sphere_3d.geo (cells along "
                    "each cube edge and each eighth of a great circle)")
    ap.add_argument("--nr", type=int, default=4, help="NR of quarter_sphere_3d.geo (cells "
                    "radially across the shell)")
    ap.add_argument("--pole-grading", type=float, default=10.0,
                    help="PoleGrading of quarter_sphere_3d.geo (1-10)")
    ap.add_argument("--element", choices=["C3D20", "C3D20R"], default="C3D20R",
                    help="ccx element type for the sphere")
    ap.add_argument("--dt", type=float, default=0.0025, help="time step")
    ap.add_argument("--end-time", type=float, default=0.095, help="end time")
    ap.add_argument("--start-time", type=float, default=0.0,
                    help="start at this time of the problem (the sphere placed where its free "
                    "flight has brought it); at most 0.005 - dt")
    ccx_deck.add_penalty_dynamics_options(
        ap, penalty=200.0, launch="initial-velocity",
        launch_help="ccx 2.20 honours the latter on C3D20/C3D20R nodes (README.md)")
    ap.add_argument("--slave-depth", type=float, default=None,
                    help="slave faces: the sphere faces with a corner within this height of the "
                    "pole (default (4 a + 0.5)^2 / (2 R), a the Hertz contact radius, "
                    "as make_deck.py)")
    ap.add_argument("--slave", choices=["sphere", "plate"], default="sphere",
                    help="the slave surface of the contact pair: the sphere's faces near the pole "
                    "(master: the plane brick's face), or the plane meshed finely by C3D8 "
                    "bricks (master: the sphere's faces near the pole)")
    ap.add_argument("--plate-size", type=float, default=0.05,
                    help="with --slave plate: the edge of its square C3D8 cells (slave nodes)")
    ap.add_argument("--plate-extent", type=float, default=1.0,
                    help="with --slave plate: it covers 0 <= x, y <= this (about 2 Hertz "
                    "contact radii at the peak)")
    ap.add_argument("--controls", default="",
                    help="data line of *CONTROLS, PARAMETERS=TIME INCREMENTATION (ccx's I0, IR, "
                    "IP, IC, IL, IG, IS, IA; default none: ccx's 4,8,9,16,10,4,0,5)")
    a = ap.parse_args(argv)

    a.rho = RHO
    h = ccx_deck.hertz(R, E, NU, V, RHO)
    slope = ccx_deck.complete_options(a, h, R, E)
    nsteps = int(round((a.end_time - a.start_time) / a.dt))
    # The gravity launch leaves u(t) = v (t - dt/2) (README.md): start dt/2 closer to touch at
    # t = 0.005 all the same.
    launch_shift = 0.5 * V * a.dt if a.launch == "gravity" else 0.0
    gap = GAP - V * a.start_time - launch_shift
    if a.start_time < 0 or GAP - V * a.start_time < a.dt - 1e-12:
        sys.exit(f"make_deck_3d.py: --start-time {a.start_time:g} must lie in [0, "
                 f"{GAP:g} - dt]")
    centre_z = R + gap

    os.makedirs(a.out, exist_ok=True)
    msh = os.path.join(a.out, "sphere.msh")
    ccx_deck.run_gmsh(GEO, msh, 3, {"R": R, "CentreZ": centre_z, "N": a.n, "NR": a.nr,
                                    "PoleGrading": a.pole_grading}, tool="make_deck_3d.py")
    nodes, elements = ccx_deck.read_msh2(msh, [17], dim=3)
    hexes = [[g[k] for k in GMSH_TO_CCX] for _, g in elements[17]]
    if not hexes:
        sys.exit("make_deck_3d.py: gmsh wrote no 20-node hexahedra")
    volume, min_det, worst_mid = element_check(nodes, hexes)
    exact = math.pi * R**3 / 3.0
    if min_det <= 0 or worst_mid > 0.1 or abs(volume / exact - 1) > 1e-3:
        sys.exit(f"make_deck_3d.py: bad elements: smallest detJ {min_det:g}, mid-node offset "
                 f"{worst_mid:g} of the edge, volume {volume:.8g} vs pi R^3/3 = {exact:.8g}")
    used = sorted({n for hx in hexes for n in hx})

    tol = 1e-6 * R
    centre = (0.0, 0.0, centre_z)
    on_sphere = {n for n in used if abs(math.dist(nodes[n], centre) - R) < tol}
    x0 = [n for n in used if abs(nodes[n][0]) < tol]
    y0 = [n for n in used if abs(nodes[n][1]) < tol]
    pole_z = centre_z - R
    pole = min(used, key=lambda n: math.dist(nodes[n], (0.0, 0.0, pole_z)))
    far = min(used, key=lambda n: math.dist(nodes[n], (0.0, 0.0, centre_z + R)))
    slave = []  # (element, face): the sphere's contact faces (slave or master)
    for e, hx in enumerate(hexes, start=1):
        for f, (corners, mids) in enumerate(FACES, start=1):
            ids = [hx[k] for k in corners + mids]
            if all(n in on_sphere for n in ids) and \
               min(nodes[hx[k]][2] for k in corners) < pole_z + a.slave_depth:
                slave.append((e, f))
    slave_nodes = {hexes[e - 1][k] for e, f in slave for k in sum(FACES[f - 1], ())}
    pole_edge = min(math.dist(nodes[p], nodes[o]) for hx in hexes if pole in hx[:8]
                    for i, j in EDGES for p, o in ((hx[i], hx[j]), (hx[j], hx[i]))
                    if p == pole and o in on_sphere)

    # The rigid plane, all nodes fixed, under z = 0: one C3D8 brick -1 <= z <= 0 whose top face
    # (S2, nodes 5-8, normal +z toward the sphere) is the master surface; or (--slave plate)
    # a layer of m x m C3D8 cells -h <= z <= 0 over 0 <= x, y <= plate_extent whose top faces
    # are the slave surface. Bottom face 1-2-3-4 counter-clockwise seen from +z, so that the top
    # lies at +z (a positive Jacobian).
    p0 = (max(used) // 1000 + 1) * 1000 + 1
    ne = len(hexes)
    plate_nodes, plate_els = {}, []
    if a.slave == "sphere":
        lo, hi = -1.0, 0.5 * R
        ticks, depth = [lo, hi], 1.0
    else:
        m = max(1, int(math.ceil(a.plate_extent / a.plate_size - 1e-9)))
        ticks, depth = [a.plate_extent * i / m for i in range(m + 1)], a.plate_extent / m
    k = len(ticks)

    def pid(i, j, top):
        return p0 + (k * k if top else 0) + j * k + i

    for top in (0, 1):
        for j, y in enumerate(ticks):
            for i, x in enumerate(ticks):
                plate_nodes[pid(i, j, top)] = (x, y, 0.0 if top else -depth)
    for j in range(k - 1):
        for i in range(k - 1):
            quad = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            plate_els.append([pid(ii, jj, 0) for ii, jj in quad] +
                             [pid(ii, jj, 1) for ii, jj in quad])
    plate_el0 = ne + 1

    inp = []
    w = inp.append
    w("*HEADING")
    w(f"Quarter sphere R={R:g} E={E:g} nu={NU:g} rho={RHO:g} v={V:g} on a rigid plane "
      f"(dyncontact issue 28 CalculiX 3D peer); N {a.n} NR {a.nr} PoleGrading {a.pole_grading:g}"
      f" {a.element}")
    w("*NODE, NSET=NSPHERE")
    for n in used:
        w(f"{n}, " + ", ".join(f"{c:.15g}" for c in nodes[n]))
    w("*NODE, NSET=NPLATE")
    for n, xyz in sorted(plate_nodes.items()):
        w(f"{n}, " + ", ".join(f"{c:.15g}" for c in xyz))
    w(f"*ELEMENT, TYPE={a.element}, ELSET=ESPHERE")
    for e, hx in enumerate(hexes, start=1):  # 16 per line at most: continue after the 15th
        w(f"{e}, " + ", ".join(str(n) for n in hx[:15]) + ",")
        w(", ".join(str(n) for n in hx[15:]))
    w("*ELEMENT, TYPE=C3D8, ELSET=EPLATE")
    for e, br in enumerate(plate_els, start=plate_el0):
        w(f"{e}, " + ", ".join(str(n) for n in br))
    w("*NSET, NSET=X0")
    w(lines_of(x0))
    w("*NSET, NSET=Y0")
    w(lines_of(y0))
    w("*NSET, NSET=POLE")
    w(f"{pole},")
    w("*NSET, NSET=FARPOLE")
    w(f"{far},")
    w("*SURFACE, NAME=SSPHERE")
    for e, f in slave:
        w(f"{e}, S{f}")
    w("*SURFACE, NAME=SPLANE")
    for e in range(plate_el0, plate_el0 + len(plate_els)):
        w(f"{e}, S2")
    ccx_deck.write_sphere_and_plate(w, E, NU, RHO)
    w("*BOUNDARY")
    w("X0, 1, 1")
    w("Y0, 2, 2")
    w("NPLATE, 1, 3")
    pair = ("SSPHERE", "SPLANE") if a.slave == "sphere" else ("SPLANE", "SSPHERE")
    ccx_deck.write_contact(w, slope, a.sigma_inf, a.c0, a.contact, a.small_sliding, *pair)
    if a.launch == "initial-velocity":
        w("*INITIAL CONDITIONS, TYPE=VELOCITY")
        w(f"NSPHERE, 3, {-V:.15g}")

    ccx_deck.write_steps(w, a, nsteps, (V / a.dt, 0, 0, -1),
                         lambda: ccx_deck.write_outputs(w, a.print_every))

    with open(os.path.join(a.out, "sphere.inp"), "w") as f:
        f.write("\n".join(inp) + "\n")
    info = dict(vars(a))
    info.update({"geometry": "3d", "geo": GEO, "R": R, "E": E, "nu": NU, "v": V,
                 "centre_z": centre_z, "gap": gap, "launch_shift": launch_shift,
                 "penalty_slope": slope, "increments": nsteps, "nodes": len(used),
                 "elements": ne, "pole_node": pole, "slave_faces": len(slave),
                 "slave_nodes": len(slave_nodes), "plate_cells": len(plate_els),
                 "pole_edge": pole_edge,
                 "volume": volume, "volume_vs_exact": volume / exact - 1,
                 "min_detJ": min_det, "wedge_factor": 4.0, "force_component": 2,
                 "force_sign": 1.0, "contact_time": GAP, "hertz": h, "law": LAW})
    with open(os.path.join(a.out, "deck.json"), "w") as f:
        json.dump(info, f, indent=1)
    print(f"{a.out}/sphere.inp: {len(used)} nodes, {ne} {a.element}, {len(slave)} sphere contact "
          f"faces ({len(slave_nodes)} nodes), slave {a.slave}, {len(plate_els)} plane cells, pole edge {pole_edge:.4g}, volume {volume:.8g} "
          f"({100 * (volume / exact - 1):+.4f} % vs pi R^3/3), dt {a.dt:g}, end {a.end_time:g}")


if __name__ == "__main__":
    main()
