#!/usr/bin/python3
"""Contact pressures of a plane-strain line-contact run against Hertz's.

Reads a dyncontact output directory of a half model on the symmetry plane x = 0 (as
prm/cylinder_on_block_plane_strain.prm writes it): the last contact_pressure_t<T>.csv (the slave
surface's nodes: current x, y, gap, multiplier = nodal force, recovered pressure, active), and
takes the total contact force of the half model as the sum of the nodal forces. Hertz's line
contact of a cylinder of radius R on a flat body, per unit length, with the load P = 2 x that
force (the whole cylinder):

    1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,   a = sqrt(4 P R / (pi E*)),
    p0 = 2 P / (pi a),                         p(x) = p0 sqrt(1 - x^2/a^2) for |x| < a.

Prints P, a, the x of the outermost active node and of the next, inactive, one, the a and p0 of
Hertz's ellipse p^2 = p0^2 (1 - x^2/a^2) fitted to the active nodes' pressures, p0, the pressure
at x = 0, the largest |p(x) - p_Hertz(x)| / p0 over the active nodes with x < 0.8 a (the edge,
where Hertz's pressure falls with a square root, is left out), and a table of every slave node
with the ratio of its pressure to Hertz's. Nodes are labelled vertex or mid-side (of the Q2
cells) from cells.csv and the profile of the same time when the run wrote them, else by their
order along the surface.

E, nu and R are read from the run's record (parameters.prm: Bodies/Body 1 and 2, the geo
parameter R) where present; --E, --nu, --E2, --nu2 and --R override them (a rigid plane as the
master: --E2 1e300 --nu2 0). The half of the cylinder's weight, when its body force is a
constant, is printed beside the contact force.

Usage:
  /usr/bin/python3 scripts/hertz_line_contact.py [OUTPUT_DIR] [--E 1000] [--nu 0.3] [--R 10]
                                                  [--plot FILE.png | --no-plot]
OUTPUT_DIR defaults to output/cylinder_on_block_plane_strain. Exit 2 if the output is missing.
"""

import argparse
import glob
import math
import os
import re
import sys

import numpy as np

NAME = "hertz_line_contact"


def fail(message):
    print(f"{NAME}: {message}", file=sys.stderr)
    sys.exit(2)


def read_csv(path):
    """A CSV with a header line as a dict of float columns."""
    with open(path) as file:
        header = file.readline().strip().split(",")
        rows = [line.strip().split(",") for line in file if line.strip()]
    if not rows:
        return {name: np.array([]) for name in header}
    data = np.array(rows, dtype=float)
    return {name: data[:, k] for k, name in enumerate(header)}


def read_record(path):
    """deal.II parameter file -> {'Sub/section/entry': value}."""
    entries, sections = {}, []
    with open(path) as file:
        for raw in file:
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            words = line.split(None, 1)
            if words[0] == "subsection":
                sections.append(words[1].strip())
            elif words[0] == "end":
                sections.pop()
            elif words[0] == "set":
                name, _, value = words[1].partition("=")
                entries["/".join(sections + [name.strip()])] = value.strip()
    return entries


def record_number(record, key):
    try:
        return float(record[key])
    except (KeyError, ValueError):
        return None


def geo_parameter(record, name):
    text = record.get("Mesh/geo parameters", "")
    for pair in text.split(","):
        key, _, value = pair.partition(":")
        if key.strip() == name:
            try:
                return float(value)
            except ValueError:
                return None
    return None


def body_weight_per_volume(record, body):
    """-b_y of the body force of body `body` if it is a constant, else None."""
    expression = record.get(f"Bodies/Body {body}/Body force/Function expression", "")
    parts = expression.split(";")
    if len(parts) != 2:
        return None
    try:
        return -float(parts[1])
    except ValueError:
        return None


def last_pressure_file(directory):
    files = glob.glob(os.path.join(directory, "contact_pressure_t*.csv"))
    timed = []
    for path in files:
        match = re.fullmatch(r"contact_pressure_t(.+)\.csv", os.path.basename(path))
        try:
            timed.append((float(match.group(1)), path))
        except (AttributeError, ValueError):
            pass
    if not timed:
        return None, None
    return max(timed)


def vertex_flags(directory, time_text, x, y):
    """True for the samples at Q2 cell vertices, False at mid-side nodes; None if unknown."""
    cells_path = os.path.join(directory, "cells.csv")
    profile_path = os.path.join(directory, f"profile_t{time_text}.csv")
    if not (os.path.exists(cells_path) and os.path.exists(profile_path)):
        return None
    cells = read_csv(cells_path)
    profile = read_csv(profile_path)
    # cells.csv: each cell's 8 boundary nodes counter-clockwise from a corner (rows of the
    # profile): node_0, 2, 4, 6 are vertices, node_1, 3, 5, 7 mid-side nodes.
    vertices = set()
    for k in range(0, 8, 2):
        vertices.update(cells[f"node_{k}"].astype(int).tolist())
    current = np.column_stack([profile["x"] + profile["u_x"], profile["y"] + profile["u_y"]])
    # The slave surface's body: the one that has a node at every sample (the two bodies' nodes at
    # the contact point may coincide).
    for body in np.unique(profile["body"]):
        flags = []
        for xs, ys in zip(x, y):
            distance = np.hypot(current[:, 0] - xs, current[:, 1] - ys)
            distance[profile["body"] != body] = np.inf
            row = int(np.argmin(distance))
            if distance[row] > 1e-9 * (1.0 + abs(xs) + abs(ys)):
                break
            flags.append(row in vertices)
        else:
            return flags
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory", nargs="?", default="output/cylinder_on_block_plane_strain")
    parser.add_argument("--E", type=float, help="Young's modulus of body 1 (the cylinder)")
    parser.add_argument("--nu", type=float, help="Poisson's ratio of body 1")
    parser.add_argument("--E2", type=float, help="Young's modulus of body 2 (default: --E)")
    parser.add_argument("--nu2", type=float, help="Poisson's ratio of body 2 (default: --nu)")
    parser.add_argument("--R", type=float, help="cylinder radius")
    parser.add_argument("--plot", help="PNG file (default: DIRECTORY/hertz_line_contact.png)")
    parser.add_argument("--no-plot", action="store_true", help="write no PNG")
    args = parser.parse_args()

    directory = args.directory
    if not os.path.isdir(directory):
        fail(f"no output directory '{directory}': run dyncontact first "
             "(e.g. prm/cylinder_on_block_plane_strain.prm)")
    time, path = last_pressure_file(directory)
    if path is None:
        fail(f"no contact_pressure_t*.csv in '{directory}': the run wrote no pressure profile "
             "(set Output/profile times to the end time)")
    time_text = os.path.basename(path)[len("contact_pressure_t"):-len(".csv")]
    samples = read_csv(path)
    needed = {"x", "y", "multiplier", "pressure", "active"}
    if not needed <= samples.keys() or len(samples["x"]) == 0:
        fail(f"'{path}' is empty or lacks columns {sorted(needed - samples.keys())}")

    record_path = os.path.join(directory, "parameters.prm")
    record = read_record(record_path) if os.path.exists(record_path) else {}
    E1 = args.E or record_number(record, "Bodies/Body 1/Young's modulus") or 1000.0
    nu1 = args.nu if args.nu is not None else record_number(record, "Bodies/Body 1/Poisson's ratio")
    nu1 = 0.3 if nu1 is None else nu1
    E2 = args.E2 or args.E or record_number(record, "Bodies/Body 2/Young's modulus") or E1
    nu2 = args.nu2 if args.nu2 is not None else (
        args.nu if args.nu is not None else record_number(record, "Bodies/Body 2/Poisson's ratio"))
    nu2 = nu1 if nu2 is None else nu2
    R = args.R or geo_parameter(record, "R") or 10.0
    E_star = 1.0 / ((1.0 - nu1 ** 2) / E1 + (1.0 - nu2 ** 2) / E2)

    # The last step of the run, for comparison with the profile's time.
    history_path = os.path.join(directory, "history.csv")
    history = read_csv(history_path) if os.path.exists(history_path) else None

    order = np.argsort(samples["x"])
    x = samples["x"][order]
    y = samples["y"][order]
    force = samples["multiplier"][order]
    p = samples["pressure"][order]
    active = samples["active"][order] > 0.5
    if not active.any():
        fail(f"'{path}': no active contact node at t = {time_text}")

    flags = vertex_flags(directory, time_text, x, y)
    kind_source = "cells.csv"
    if flags is None:  # along the surface: vertex, mid-side, vertex, ... from the symmetry plane
        flags = [k % 2 == 0 for k in range(len(x))]
        kind_source = "order along the surface"

    half_force = float(force[active].sum())
    P = 2.0 * half_force
    a = math.sqrt(4.0 * P * R / (math.pi * E_star))
    p0 = 2.0 * P / (math.pi * a)
    p_hertz = p0 * np.sqrt(np.clip(1.0 - (x / a) ** 2, 0.0, None))

    outermost = int(np.flatnonzero(active)[-1])
    beyond = [k for k in range(outermost + 1, len(x)) if not active[k]]
    centre = int(np.argmin(np.abs(x)))
    inner = active & (x < 0.8 * a)
    deviation = np.abs(p - p_hertz) / p0
    worst = int(np.flatnonzero(inner)[np.argmax(deviation[inner])]) if inner.any() else None

    print(f"{NAME}: {path}")
    if history is not None and len(history.get("time", [])):
        last_time = history["time"][-1]
        note = "" if abs(last_time - time) <= 1e-9 * max(1.0, abs(time)) else \
            "  (NOT the last step: the profile is at an earlier time)"
        print(f"  profile time {time:g}, last step of the run t = {last_time:g}{note}")
        if "contact_force" in history and "kinetic_energy" in history:
            print(f"  history at the last step: contact_force {history['contact_force'][-1]:.6g}, "
                  f"kinetic_energy {history['kinetic_energy'][-1]:.3g}")
    print(f"  E1 = {E1:g}, nu1 = {nu1:g}, E2 = {E2:g}, nu2 = {nu2:g}, R = {R:g}, "
          f"E* = {E_star:.6g}")
    print(f"  slave nodes: {len(x)}, active: {int(active.sum())}; node kinds from {kind_source}")
    print(f"  {'half-model force (sum of nodal forces)':44s}{half_force:.6g}")
    weight = body_weight_per_volume(record, 1)
    density = record_number(record, "Bodies/Body 1/density")
    if weight is not None and R:
        expected = weight * math.pi * R ** 2 / 2.0
        print(f"  half the cylinder's weight (body force {weight:g} x pi R^2 / 2) {expected:.6g}: "
              f"force {100.0 * (half_force / expected - 1.0):+.3f} %")
    elif density is not None:
        print("  (the body force is not a constant: no weight to compare with)")
    print(f"  {'P = 2 x half-model force':44s}{P:.6g}")
    print(f"  {'a_Hertz = sqrt(4 P R / (pi E*))':44s}{a:.6g}")
    print(f"  {'outermost active node x':44s}{x[outermost]:.6g}  "
          f"({100.0 * (x[outermost] / a - 1.0):+.2f} % of a)")
    if beyond:
        k = beyond[0]
        print(f"  {'next (inactive) node x':44s}{x[k]:.6g}  "
              f"({100.0 * (x[k] / a - 1.0):+.2f} % of a)")
    else:
        print(f"  {'next (inactive) node x':44s}none: the whole slave surface is active")
    # Hertz's ellipse p^2 = p0^2 (1 - x^2 / a^2) fitted to the active nodes (least squares in p^2).
    slope, intercept = np.polyfit(x[active] ** 2, p[active] ** 2, 1)
    if slope < 0.0 < intercept:
        a_fit, p0_fit = math.sqrt(-intercept / slope), math.sqrt(intercept)
        print(f"  {'Hertz ellipse fitted to the active nodes':44s}a {a_fit:.6g} "
              f"({100.0 * (a_fit / a - 1.0):+.2f} %), p0 {p0_fit:.6g} "
              f"({100.0 * (p0_fit / p0 - 1.0):+.2f} %)")
    print(f"  {'p0_Hertz = 2 P / (pi a)':44s}{p0:.6g}")
    print(f"  {'pressure at x = %.3g' % x[centre]:44s}{p[centre]:.6g}  "
          f"({100.0 * (p[centre] / p0 - 1.0):+.2f} % of p0)")
    if worst is not None:
        print(f"  {'max |p - p_Hertz| / p0, active, x < 0.8 a':44s}{deviation[worst]:.4f}  "
              f"(at x = {x[worst]:.4g}, {'vertex' if flags[worst] else 'mid-side'} node)")
        for label, wanted in (("vertex", True), ("mid-side", False)):
            chosen = inner & (np.array(flags) == wanted)
            if chosen.any():
                signed = (p[chosen] - p_hertz[chosen]) / p0
                print(f"    {label:8s} nodes: {int(chosen.sum()):3d}, (p - p_Hertz) / p0 mean "
                      f"{signed.mean():+.4f}, min {signed.min():+.4f}, max {signed.max():+.4f}")
    print()
    print(f"  {'x':>9s} {'x/a':>7s} {'node':>8s} {'active':>6s} {'nodal force':>12s} "
          f"{'p':>10s} {'p_Hertz':>10s} {'p/p_Hertz':>9s} {'(p-pH)/p0':>9s}")
    last_row = beyond[0] if beyond else len(x) - 1
    for k in range(0, last_row + 1):
        ratio = f"{p[k] / p_hertz[k]:9.4f}" if p_hertz[k] > 0 else f"{'-':>9s}"
        print(f"  {x[k]:9.5f} {x[k] / a:7.4f} {'vertex' if flags[k] else 'mid-side':>8s} "
              f"{int(active[k]):6d} {force[k]:12.6g} {p[k]:10.5g} {p_hertz[k]:10.5g} {ratio} "
              f"{(p[k] - p_hertz[k]) / p0:+9.4f}")
    if last_row + 1 < len(x):
        print(f"  ... {len(x) - last_row - 1} more slave nodes up to x = {x[-1]:.4g}, "
              f"{int(active[last_row + 1:].sum())} of them active")

    if args.no_plot:
        return
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print(f"{NAME}: matplotlib not available, no plot")
        return
    plot_path = args.plot or os.path.join(directory, "hertz_line_contact.png")
    figure, axes = plt.subplots(figsize=(7, 4.5))
    xs = np.linspace(0.0, a, 400)
    axes.plot(xs, p0 * np.sqrt(1.0 - (xs / a) ** 2), "k-", label=f"Hertz, a = {a:.4g}, "
              f"p0 = {p0:.4g}")
    shown = x <= 1.5 * a
    vertex = np.array(flags) & shown
    midside = ~np.array(flags) & shown
    axes.plot(x[vertex], p[vertex], "o", color="tab:blue", label="FE, vertex nodes")
    axes.plot(x[midside], p[midside], "s", color="tab:red", mfc="none",
              label="FE, mid-side nodes")
    axes.axvline(a, color="grey", lw=0.8, ls=":")
    axes.set_xlabel("x (distance from the symmetry plane)")
    axes.set_ylabel("contact pressure")
    axes.set_title(f"Line contact, t = {time:g}: P = {P:.4g} (2 x half model)")
    axes.set_xlim(0.0, 1.5 * a)
    axes.set_ylim(bottom=min(0.0, float(p[shown].min()) * 1.1))
    axes.grid(alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(plot_path, dpi=120)
    print(f"{NAME}: wrote {plot_path}")


if __name__ == "__main__":
    main()
