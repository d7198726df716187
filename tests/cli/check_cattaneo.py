"""Writes DIRECTORY/cattaneo.csv and cattaneo.png, the run of prm/cattaneo_cylinders.prm or
prm/cattaneo_sphere_3d.prm beside Hertz and Cattaneo-Mindlin, and checks it (issue 29, B).

Usage: check_cattaneo.py DIRECTORY MU E NU R H [--sphere]

--sphere: an elastic sphere of radius R on a rigid plane, a half model on y = 0, pushed along x
(P and Q are twice the half model's sums; Hertz a^3 = 3 P R / (4 E*), E* = E / (1 - NU^2),
p0 = 3 P / (2 pi a^2); Cattaneo-Mindlin c = a (1 - Q / (MU P))^(1/3); distances are radial in the
plane, from (x0, 0)). The checks below are those of the cylinders, with the sphere's formulas; H is then the cell
edge at the pole (the run's "shortest edge").

The cylinder of radius R and the block, both of Young's modulus E and Poisson's ratio NU (plane
strain, per unit length), pressed by the normal load P and pushed by a tangential load Q, friction
coefficient MU; H is the cell edge at the contact (the mesh's ContactSize). From each
contact_pressure_t<T>.csv of the run's tangential phase:
  P, Q: the sums of the active pairs' normal and tangential nodal forces (the cylinder's side;
  the tangential ones signed by their x-direction);
  Hertz: a = sqrt(4 P R / (pi E*)), E* = E / (2 (1 - NU^2)), p0 = 2 P / (pi a), about the
  contact's centre x0 (the centroid of the normal nodal forces);
  Cattaneo-Mindlin (the same material on both sides, Dundurs' beta = 0): c = a sqrt(1 - Q / (MU P)),
  shear traction MU p in the slip zone c < |x - x0| < a;
  measured: a and c, the largest |x - x0| of an active and of a stuck slave node.
Checks, at the times whose Q / (MU P) is nearest 0.3, 0.6 and 0.9 (each within 0.05 of it):
  - a and c within one cell edge H of Hertz and Cattaneo (the contact's edge and the stick-slip
    boundary fall between two nodes, H / 2 apart on the Q2 faces; measured within 0.21 H for a
    and 0.21 H for c on the cylinders at H = a / 9, 0.27 H and 0.13 H on the sphere at H = a / 4,
    0.03 H and 0.29 H at H = a / 3; at that coarse a mesh only the 0.9 point tells Cattaneo's c
    from no slip zone at all);
  - Coulomb's law at the nodes: a sliding node's tangential force is MU times its normal one to
    1e-5 of MU P / (number of active nodes), a stuck node's at most that (the slip rows converge
    to Newton's tolerance: measured 7e-15 on the cylinders, where a 2D slip row is linear once
    its direction is known, and 8e-7 on the sphere, whose 3D slip direction is iterated);
  - cylinders only: the shear traction (the run's shear column: on mortar pairs the dual
    multiplier's nodal value) of the sliding nodes in the slip zone within 3 % of MU p0 of
    MU p0 sqrt(1 - (x - x0)^2 / a^2), the issue's figure, at every node farther than H from
    Hertz's edge (measured 0.75 % at 39 nodes with mortar at H = a / 9; node-to-segment contact
    fails it, its pressure departing from Hertz's node by node, 14 % of p0 at H = a / 10 and 34 %
    at a / 20 without friction too: the patch test); within H of the edge, where the edge falls
    inside the last cell and Hertz's pressure drops as a square root no Q2 field follows, within
    10 % (measured 5.1 %, the frictionless pressure's own error there); and at least 10 nodes so
    checked over the three times (the sliding nodes carry MU times their normal force, so this
    checks the pressure under them). The sphere's (on a rigid plane) are printed: 0.2 MU p0.
Checked over the whole tangential phase: P constant to 0.5 % (measured 0.05 %); gross slip reached,
where Q = MU P then follows from the nodal law (a consistency check of the sums, to 1e-5;
measured 2e-16 and 1e-7); the kinetic energy at most 1e-3 of the strain energy (quasi-static:
it is that of the imposed motion, the body carried at the holder's speed; measured 6e-5 on the
cylinders, 1.4e-4 on the sphere).
"""
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from history_checks import Checks, read_history  # noqa: E402

directory = sys.argv[1]
mu, E, nu, R, h = map(float, sys.argv[2:7])
sphere = "--sphere" in sys.argv[7:]
# A cylinder on a block of the same material (two elastic bodies) or a sphere on a rigid plane.
e_star = E / (1.0 - nu * nu) if sphere else E / (2.0 * (1.0 - nu * nu))
symmetry = 2.0 if sphere else 1.0  # the half model's forces are half the whole body's
checks = Checks()
edge_band = 1.0  # cell edges H from the contact's edge: the slip zone's band held to 10 %


def tangential(row):
    """The magnitude of a pair's tangential force."""
    return math.sqrt(sum(row[k] ** 2 for k in row if k.startswith("tangential_force_")))


def time_of(name):
    return float(os.path.basename(name)[len("contact_pressure_t"):-len(".csv")])


def plot(chosen):
    """DIRECTORY/cattaneo.png: the pressure and the shear traction of the active nodes at the
    chosen times against Hertz's and Cattaneo-Mindlin's, over the contact (x / a or r / a)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, len(chosen), figsize=(5 * len(chosen), 4.2), sharey=True)
    grid = [-1.0 + 0.002 * i for i in range(1001)]
    for axis, s in zip(axes, chosen):
        a, c = s["a_hertz"], s["c_cattaneo"]
        hertz = [math.sqrt(max(0.0, 1.0 - x * x)) for x in grid]
        stick = [math.sqrt(max(0.0, 1.0 - x * x)) - (c / a) * math.sqrt(max(0.0, 1.0 - (x * a / c) ** 2))
                 for x in grid]
        axis.plot(grid, hertz, "k-", lw=1, label="Hertz p / p0 (slip zone: q / (mu p0))")
        axis.plot(grid, stick, "C1-", lw=1, label="Cattaneo-Mindlin q / (mu p0)")
        points = nodes[s["time"]]
        xs = [x / a for x, *_ in points]
        axis.plot(xs, [p for _, p, _, _ in points], "k.", ms=4, label="run: pressure")
        for flag, colour, text in ((1, "C3", "run: shear, sliding"), (0, "C0", "run: shear, stuck")):
            axis.plot([x / a for x, _, _, f in points if f == flag],
                      [q for _, _, q, f in points if f == flag], "o", color=colour, ms=3.5,
                      mfc="none", label=text)
        axis.axvspan(-c / a, c / a, color="C0", alpha=0.07)
        axis.set_xlim(-1.15 if not sphere else 0.0, 1.15)
        axis.set_xlabel("r / a" if sphere else "(x - x0) / a")
        axis.set_title(f"Q / (mu P) = {s['Q_over_muP']:.2f}, t = {s['time']:g}: c = {s['c_measured']:.3f}"
                       f" (Cattaneo {c:.3f})", fontsize=9)
        axis.grid(alpha=0.3)
    axes[0].set_ylabel("traction / p0, shear / (mu p0)")
    # Below the panels: inside, it hid the stick zone's shear.
    handles, labels = axes[0].get_legend_handles_labels()
    figure.legend(handles, labels, fontsize=8, loc="lower center", ncol=len(labels))
    figure.tight_layout(rect=(0, 0.07, 1, 1))
    figure.savefig(f"{directory}/cattaneo.png", dpi=110)
    plt.close(figure)


history = read_history(directory)
kinetic_fraction = {row["time"]: row["kinetic_energy"] / row["strain_energy"]
                    for row in history if row["strain_energy"] > 0}
samples = []
nodes = {}  # per time: (x - x0 or r, p / p0, q / (MU p0), sliding) of the active nodes
for name in sorted(glob.glob(f"{directory}/contact_pressure_t*.csv"), key=time_of):
    with open(name, newline="") as handle:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(handle)]
    active = [r for r in rows if r["active"] == 1]
    if not active:
        continue
    P = symmetry * sum(r["multiplier"] for r in active)
    # The tangential forces along the surface, signed by their x-direction: on the indented
    # surface the tangents tilt by up to about a / R, which the small-slope theory neglects.
    Q_signed = symmetry * sum(math.copysign(tangential(r), r["tangential_force_x"]) for r in active)
    Q, sign = abs(Q_signed), (1.0 if Q_signed >= 0 else -1.0)
    x0 = symmetry * sum(r["x"] * r["multiplier"] for r in active) / P
    if sphere:
        a = (3.0 * P * R / (4.0 * e_star)) ** (1.0 / 3.0)
        p0 = 3.0 * P / (2.0 * math.pi * a * a)
    else:
        a = math.sqrt(4.0 * P * R / (math.pi * e_star))
        p0 = 2.0 * P / (math.pi * a)
    ratio = Q / (mu * P)
    c = a * max(0.0, 1.0 - ratio) ** (1.0 / 3.0 if sphere else 0.5)

    def distance(r):
        return math.hypot(r["x"] - x0, r["y"]) if sphere else abs(r["x"] - x0)

    stuck = [r for r in active if r["sliding"] == 0]
    sliding = [r for r in active if r["sliding"] == 1]
    a_measured = max(distance(r) for r in active)
    c_measured = max((distance(r) for r in stuck), default=0.0)
    in_slip_zone = [r for r in sliding if c < distance(r) < a]

    def shear_error(zone):
        return max((abs(sign * r["shear_x"] - mu * p0 * math.sqrt(1.0 - (distance(r) / a) ** 2))
                    / (mu * p0) for r in zone), default=0.0)

    inside = [r for r in in_slip_zone if distance(r) <= a - edge_band * h]
    edge = [r for r in in_slip_zone if distance(r) > a - edge_band * h]
    pressure_error = max(abs(r["pressure"] - p0 * math.sqrt(max(0.0, 1.0 - (distance(r) / a) ** 2)))
                         / p0 for r in active)
    force_scale = mu * P / len(active)
    law_sliding = max((abs(tangential(r) - mu * r["multiplier"]) / force_scale for r in sliding),
                      default=0.0)
    law_stuck = max((tangential(r) - mu * r["multiplier"] for r in stuck), default=0.0) / force_scale
    t = time_of(name)
    nodes[t] = [(distance(r) if sphere else r["x"] - x0, r["pressure"] / p0,
                 sign * math.copysign(math.hypot(r["shear_x"], r["shear_y"]), r["shear_x"]) / (mu * p0),
                 r["sliding"]) for r in active]
    samples.append(dict(time=t, P=P, Q=Q, Q_over_muP=ratio, a_hertz=a, a_measured=a_measured,
                        c_cattaneo=c, c_measured=c_measured, cell_edge=h, active_nodes=len(active),
                        sliding_nodes=len(sliding), slip_zone_nodes_inside=len(inside),
                        slip_zone_nodes_edge=len(edge),
                        shear_error_slip_zone=shear_error(inside),
                        shear_error_edge_band=shear_error(edge),
                        pressure_error=pressure_error, coulomb_law_sliding=law_sliding,
                        coulomb_law_stuck=law_stuck,
                        kinetic_energy_fraction=kinetic_fraction.get(t, float("nan"))))

with open(f"{directory}/cattaneo.csv", "w", newline="") as handle:
    writer = csv.DictWriter(handle, fieldnames=list(samples[0].keys()))
    writer.writeheader()
    for sample in samples:
        writer.writerow({k: f"{v:.10g}" for k, v in sample.items()})
print(f"wrote {directory}/cattaneo.csv ({len(samples)} times) and, below, cattaneo.png")

loaded = [s for s in samples if s["Q_over_muP"] > 0.01]
chosen = []
for target in (0.3, 0.6, 0.9):
    s = min(loaded, key=lambda s: abs(s["Q_over_muP"] - target))
    chosen.append(s)
    label = f"Q/(mu P) = {s['Q_over_muP']:.3f} (t = {s['time']:g})"
    checks.bound(f"{label}: |Q/(mu P) - {target}|", abs(s["Q_over_muP"] - target), 0.05)
    checks.bound(f"{label}: |a - a_Hertz| / H ({s['a_measured']:.4f} vs {s['a_hertz']:.4f})",
                 abs(s["a_measured"] - s["a_hertz"]) / h, 1.0)
    checks.bound(f"{label}: |c - c_Cattaneo| / H ({s['c_measured']:.4f} vs {s['c_cattaneo']:.4f})",
                 abs(s["c_measured"] - s["c_cattaneo"]) / h, 1.0)
    shear = (f"{label}: slip zone beyond {edge_band:g} H of the edge ({s['slip_zone_nodes_inside']:g}"
             f" nodes): |shear - mu p_Hertz| / (mu p0)")
    edge_shear = f"{label}: slip zone's edge band: |shear - mu p_Hertz| / (mu p0)"
    if sphere:
        print(f"  (not checked: {shear} {s['shear_error_slip_zone']:.3f}, "
              f"{edge_shear} {s['shear_error_edge_band']:.3f})")
    else:
        checks.bound(shear, s["shear_error_slip_zone"], 0.03)
        checks.bound(edge_shear, s["shear_error_edge_band"], 0.10)
        checks.bound(f"{label}: sliding nodes in the edge band", s["slip_zone_nodes_edge"], 1,
                     above=True)
        if target > 0.5:  # near 0.3 the slip zone is about one cell wide
            checks.bound(f"{label}: sliding nodes beyond the edge band", s["slip_zone_nodes_inside"],
                         1, above=True)
    print(f"  (not checked: the pressure vs Hertz, of p0: {s['pressure_error']:.3f}; "
          f"kinetic / strain energy {s['kinetic_energy_fraction']:.2g})")
    checks.bound(f"{label}: sliding nodes |lambda_t| - mu lambda_n", s["coulomb_law_sliding"], 1e-5)
    checks.bound(f"{label}: stuck nodes |lambda_t| - mu lambda_n", s["coulomb_law_stuck"], 1e-5)
plot(chosen)
loads = [s["P"] for s in samples]
checks.bound("P's change over the tangential phase, relative", (max(loads) - min(loads)) / max(loads),
             5e-3)
gross = [s for s in samples if s["sliding_nodes"] == s["active_nodes"]]
checks.bound("gross slip reached (times)", len(gross), 1, above=True)
if gross:
    # Once every node slides, Q = mu P follows from the nodal law: a consistency check of the sums.
    checks.bound("gross slip, every node sliding: |Q / (mu P) - 1|",
                 max(abs(s["Q_over_muP"] - 1.0) for s in gross), 1e-5)
if not sphere:
    checks.bound("slip zone nodes beyond the edge band at the three times",
                 sum(s["slip_zone_nodes_inside"] for s in chosen), 10, above=True)
checks.bound("kinetic / strain energy in the tangential phase",
             max(f for t, f in kinetic_fraction.items() if t >= samples[0]["time"]), 1e-3)
checks.finish()
