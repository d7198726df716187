#!/usr/bin/env python3
"""The report of bench/schemes.sh: every contact-dynamics treatment on every problem.

Reads RESULTS/<problem>/<scheme>/ (history.csv, exact.csv or impact_summary.csv and the reference
force curve, log, wall_time, failed) and writes RESULTS/report.md (one table per problem, a cell per
metric and scheme; a run that failed says why in its cells) and RESULTS/<problem>.png (force,
interface velocity and energy against the reference, zoomed on the contact).

    bench/schemes_report.py RESULTS SCHEME...
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PROBLEMS = [
    ("bar_rigid_wall", "6.1 bar on a rigid wall (the paper's prm: Newmark, beta = 0.001, Courant 1)"),
    ("bars_identical", "6.2 identical bars (the paper's prm: Newmark, beta = 0.001, Courant 1)"),
    ("bars_dissimilar", "6.3 dissimilar bars (the paper's prm: Newmark, beta = 0.001, Courant 1)"),
    ("stiff_striker", "stiff striker: bar 1 E = 1e4 on bar 2 (dt = 0.1, Courant 100 / 1; Newmark: beta = 1/4)"),
    ("soft_striker", "soft striker: bar 1 on bar 2 E = 1e4 (dt = 0.1, Courant 1 / 100; Newmark: beta = 1/4)"),
    ("signorini_bar", "Signorini bar, 10 periods (Courant 1; Newmark: beta = 1/4)"),
    ("spheres", "spheres, default mesh, the paper's dt = 0.0025"),
    ("spheres_dt0.02", "spheres, coarse mesh, dt = 0.02 (4 steps in contact)"),
    ("dissimilar_spheres", "dissimilar spheres, non-matching meshes"),
]


def read_csv(path):
    """Rows of a CSV file as dicts of floats (lines starting with # are skipped)."""
    with open(path) as handle:
        lines = [line for line in handle if not line.startswith("#")]
    return [{key: float(value) for key, value in row.items()} for row in csv.DictReader(lines)]


def column(rows, name):
    return [row[name] for row in rows]


def episodes(active):
    """Contact episodes: rows with contact after a row without, and a contact at the first row."""
    return int(active[0] > 0) + sum(1 for i in range(1, len(active)) if active[i] > 0 and active[i - 1] == 0)


def failure(run):
    """The error line of a failed run, or None."""
    if not os.path.exists(os.path.join(run, "failed")):
        return None
    with open(os.path.join(run, "log")) as handle:
        errors = [line.strip() for line in handle if "error" in line or "failed" in line]
    # The reason, without the program name and the note on where the results are.
    reason = errors[-1] if errors else "failed"
    reason = reason.replace("dyncontact: ", "", 1).split(" Results up to")[0]
    return reason.replace("|", "/")


def bar_metrics(run, history):
    exact = read_csv(os.path.join(run, "exact.csv"))
    exact_at = {round(row["time"], 9): row for row in exact}
    in_contact = [
        (row, exact_at[round(row["time"], 9)])
        for row in history
        if round(row["time"], 9) in exact_at and exact_at[round(row["time"], 9)]["contact_force"] > 0
    ]
    force_rms = math.sqrt(
        sum((row["contact_force"] - ref["contact_force"]) ** 2 for row, ref in in_contact)
        / max(len(in_contact), 1)
    )
    bodies = [name[len("momentum_"):] for name in history[0] if name.startswith("momentum_")]
    scale = sum(abs(history[0]["momentum_" + b]) for b in bodies)
    momentum_error = max(
        abs(history[-1]["momentum_" + b] - exact[-1]["momentum_" + b]) for b in bodies
    ) / scale
    # Window means over 1 time unit (issue 14, C): a chattering force can average right.
    contact_end = max(row["time"] for row in exact if row["contact_force"] > 0)
    window_errors = []
    for start in range(int(math.ceil(contact_end))):
        computed = [r["contact_force"] for r in history if start < r["time"] <= start + 1]
        reference = [r["contact_force"] for r in exact if start < r["time"] <= start + 1]
        if computed and reference:
            window_errors.append(abs(sum(computed) / len(computed) - sum(reference) / len(reference)))
    return {
        "force error (RMS in exact contact)": "%.3g" % force_rms,
        "force error (largest mean over a 1-unit window)": "%.3g" % max(window_errors or [0.0]),
        "contact episodes (exact)": "%d (%d)"
        % (episodes(column(history, "active_constraints")), episodes(column(exact, "active_constraints"))),
        "final momentum error (of the initial total)": "%.2g" % momentum_error,
    }


def sphere_metrics(run, history):
    summary = {row["quantity"]: row for row in csv.DictReader(open(os.path.join(run, "impact_summary.csv")))}
    bodies = [name for name in history[0] if name.startswith("momentum_")]
    total = [sum(row[b] for b in bodies) for row in history]
    return {
        "peak force vs finite-sphere law": "%+.2f %%" % (100 * float(summary["peak_force"]["finite_sphere_difference"])),
        "duration vs finite-sphere law": "%+.2f %%" % (100 * float(summary["duration"]["finite_sphere_difference"])),
        "contact episodes (exact)": "%d (1)" % episodes(column(history, "active_constraints")),
        "momentum drift (of body 1 initial)": "%.2g" % (abs(total[-1] - total[0]) / abs(history[0][bodies[0]])),
    }


def common_metrics(run, history):
    energy = column(history, "total_energy")
    in_contact = [row for row in history if row["active_constraints"] > 0]
    steps = len(history) - 1
    with open(os.path.join(run, "wall_time")) as handle:
        wall = handle.read().strip().splitlines()[-1]
    # The energy changes of the steps that close and that open contact, summed over the episodes.
    active = column(history, "active_constraints")
    closing = sum(energy[i] - energy[i - 1] for i in range(1, len(active)) if active[i] > 0 and active[i - 1] == 0)
    opening = sum(energy[i] - energy[i - 1] for i in range(1, len(active)) if active[i] == 0 and active[i - 1] > 0)
    return {
        "largest energy gain / E0": "%.2g" % max(0.0, max(e / energy[0] - 1 for e in energy)),
        "energy change at impacts / E0 (steps closing contact)": "%+.2g" % (closing / energy[0]),
        "energy change at releases / E0 (steps opening contact)": "%+.2g" % (opening / energy[0]),
        "final energy change / E0": "%+.2g" % (energy[-1] / energy[0] - 1),
        "max velocity jump in contact": "%.2g" % max([r["velocity_jump"] for r in in_contact] or [0]),
        "max acceleration jump in contact": "%.2g" % max([r["acceleration_jump"] for r in in_contact] or [0]),
        "max penetration": "%.2g" % max(column(history, "max_penetration")),
        "step cuts (all steps)": "%d" % sum(column(history, "step_cuts")),
        "linear solves per step": "%.2f" % (sum(column(history, "newton_iterations")) / max(steps, 1)),
        "wall time [s]": wall,
    }


def metrics(run, problem):
    reason = failure(run)
    if reason is not None:
        return None, reason
    history = read_csv(os.path.join(run, "history.csv"))
    specific = sphere_metrics(run, history) if "spheres" in problem else bar_metrics(run, history)
    return {**specific, **common_metrics(run, history)}, None


def reference_force(run, problem):
    """(times, forces) of the reference: the exact solution (bars) or the finite-sphere law."""
    name = "finite_sphere.csv" if "spheres" in problem else "exact.csv"
    path = os.path.join(run, name)
    if not os.path.exists(path):
        return None
    rows = read_csv(path)
    return column(rows, "time"), column(rows, "contact_force")


def plot(results, problem, title, schemes):
    figure, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    window = None
    for scheme in schemes:
        run = os.path.join(results, problem, scheme)
        if failure(run) is not None or not os.path.exists(os.path.join(run, "history.csv")):
            continue
        history = read_csv(os.path.join(run, "history.csv"))
        times = column(history, "time")
        contact_times = [r["time"] for r in history if r["active_constraints"] > 0]
        if contact_times and window is None:
            span = contact_times[-1] - contact_times[0]
            window = (contact_times[0] - 0.2 * span, contact_times[-1] + 0.3 * span)
        color = "C%d" % schemes.index(scheme)  # the same colour for a scheme in every figure
        axes[0].plot(times, column(history, "contact_force"), color=color, label=scheme, lw=1)
        axes[1].plot(times, column(history, "v_tip_1"), color=color, label=scheme, lw=1)
        energy = column(history, "total_energy")
        axes[2].plot(times, [e / energy[0] for e in energy], color=color, label=scheme, lw=1)
    for scheme in schemes:  # the reference, from the first run that completed
        if failure(os.path.join(results, problem, scheme)) is not None:
            continue
        reference = reference_force(os.path.join(results, problem, scheme), problem)
        if reference:
            axes[0].plot(*reference, "k--", lw=1.2, label="exact" if "spheres" not in problem else "finite-sphere law")
            # Zoom on the reference's range: a chattering scheme's peaks (up to 10x) are clipped.
            axes[0].set_ylim(-0.1 * max(reference[1]), 3 * max(reference[1]))
            exact_path = os.path.join(results, problem, scheme, "exact.csv")
            if os.path.exists(exact_path):
                exact = read_csv(exact_path)
                axes[1].plot(column(exact, "time"), column(exact, "v_tip_1"), "k--", lw=1.2, label="exact")
            break
    axes[0].set_ylabel("contact force")
    axes[1].set_ylabel("tip velocity, body 1")
    axes[2].set_ylabel("total energy / E0")
    axes[2].set_xlabel("time")
    if window and "signorini" not in problem:
        axes[2].set_xlim(*window)
    for ax in axes:
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:  # not when every run failed
            ax.legend(fontsize=7)
    figure.suptitle(title, fontsize=10)
    figure.tight_layout()
    figure.savefig(os.path.join(results, problem + ".png"), dpi=110)
    plt.close(figure)


def main():
    results, schemes = sys.argv[1], sys.argv[2:]
    lines = ["# Contact-dynamics treatments on problems with exact answers", "",
             "Generated by `bench/schemes.sh`; one table per problem, one column per "
             "`Contact/dynamics`. A run that failed says why in its cells.", ""]
    for problem, title in PROBLEMS:
        table = {}
        for scheme in schemes:
            table[scheme] = metrics(os.path.join(results, problem, scheme), problem)
        names = []
        for values, _ in table.values():
            for name in values or {}:
                if name not in names:
                    names.append(name)
        lines += ["## " + title, "", "![%s](%s.png)" % (problem, problem), "",
                  "| metric | " + " | ".join(schemes) + " |",
                  "|---|" + "---|" * len(schemes)]
        # A failed run: its reason once, in the first row, and "(failed)" below it.
        for row, name in enumerate(names):
            cells = [
                values.get(name, "n/a") if values else ("**failed:** " + reason if row == 0 else "(failed)")
                for values, reason in (table[s] for s in schemes)
            ]
            lines.append("| " + name + " | " + " | ".join(cells) + " |")
        if not names:
            lines.append("| every run | " + " | ".join("**failed:** " + table[s][1] for s in schemes) + " |")
        lines.append("")
        plot(results, problem, title, schemes)
    with open(os.path.join(results, "report.md"), "w") as handle:
        handle.write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
