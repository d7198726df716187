#!/usr/bin/env python3
"""Tabulates bench/performance.sh: one row per case (markdown to stdout, CSV beside the results).

Usage: performance_table.py RESULTS_DIR CASE...
Per case: min and median wall time over its runs (of the whole process, /usr/bin/time), DoFs, steps, linear solves, factorizations, the
phases of the fastest run, peak RSS, and peak force / duration / impulse against Hertz, the
finite-sphere law and the finest run of the same material (the case with the most DoFs).
A CalculiX row is added for each bench/results/calculix/performance_*/summary.csv
(bench/calculix/run.sh, written by bench/performance.sh).
"""
import csv
import pathlib
import statistics
import sys

import run_log

root = pathlib.Path(sys.argv[1])
names = sys.argv[2:]


def parse_run(directory):
    run = run_log.parse_log((directory / "run.log").read_text(errors="replace"))
    if not run:
        return None
    process = run_log.parse_time_log((directory / "time.log").read_text())
    # The process's wall time (set-up and meshing included, as CalculiX's), not the done line's.
    run["wall"] = process["elapsed"] or run["wall"]
    run["rss_mb"] = process["rss_mb"] or 0
    run["summary"] = {}
    for row in csv.DictReader(open(directory / "impact_summary.csv")):
        run["summary"][row["quantity"]] = row
    return run


cases = {}
for name in names:
    runs = [r for r in (parse_run(d) for d in sorted((root / name).glob("run*"))) if r]
    if runs:
        cases[name] = runs

material = lambda name: "neo-hookean" if name.endswith("_neo") else "linear elastic"
finest = {}
for name, runs in cases.items():
    m = material(name)
    if m not in finest or runs[0]["dofs"] > cases[finest[m]][0]["dofs"]:
        finest[m] = name

rows = []
for name, runs in cases.items():
    fastest = min(runs, key=lambda r: r["wall"])
    summary = fastest["summary"]
    reference = cases[finest[material(name)]][0]["summary"]
    row = {"case": name, "material": material(name), "dofs": fastest["dofs"],
           "steps": fastest["steps"], "solves": fastest["solves"],
           "factorizations": fastest["factorizations"],
           "low_rank_updates": fastest["low_rank_updates"],
           "wall_min_s": fastest["wall"],
           "wall_median_s": statistics.median(r["wall"] for r in runs),
           "runs": len(runs), "rss_mb": round(max(r["rss_mb"] for r in runs))}
    for phase, seconds in fastest["phases"].items():
        row["phase_" + phase.replace(" ", "_").replace("-", "_") + "_s"] = seconds
    for quantity in ("peak_force", "duration", "impulse"):
        computed = float(summary[quantity]["computed"])
        row[quantity] = computed
        row[quantity + "_vs_hertz"] = float(summary[quantity]["relative_difference"])
        if summary[quantity].get("finite_sphere_difference"):
            row[quantity + "_vs_law"] = float(summary[quantity]["finite_sphere_difference"])
        row[quantity + "_vs_finest"] = computed / float(reference[quantity]["computed"]) - 1
    rows.append(row)

for summary_file in sorted((root.parent / "calculix").glob("performance_*/summary.csv")):
    for record in csv.DictReader(open(summary_file)):
        rows.append({"case": "calculix " + record["material"], "material": record["material"],
                     "dofs": record["equations"], "wall_min_s": float(record["wall_s"]),
                     "wall_median_s": float(record["wall_s"]), "runs": 1,
                     "peak_force": float(record["peak"]), "duration": float(record["duration"]),
                     "impulse": float(record["impulse"]), "rss_mb": record["peak_rss_mb"],
                     "peak_force_vs_hertz": float(record["peak_vs_hertz_pct"]) / 100,
                     "duration_vs_hertz": float(record["duration_vs_hertz_pct"]) / 100})

keys = []
for row in rows:
    keys += [k for k in row if k not in keys]
with open(root.parent / "performance.csv", "w", newline="") as handle:
    writer = csv.DictWriter(handle, fieldnames=keys)
    writer.writeheader()
    writer.writerows(rows)

pct = lambda row, key: f"{100 * row[key]:+.3f} %" if key in row else ""
print("| case | DoFs | wall min / median [s] | solves / factorizations / low-rank | assembly / "
      "factorization / low-rank / solve [s] | RSS [MB] | peak vs finest | duration vs finest | peak vs Hertz | peak vs law | "
      "duration vs law |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for row in rows:
    phases = " / ".join(f"{row.get('phase_' + p + '_s', 0):.2f}"
                        for p in ("assembly", "factorization", "low_rank_update", "linear_solve"))
    print(f"| {row['case']} | {row['dofs']} | {row['wall_min_s']:.2f} / {row['wall_median_s']:.2f} | "
          f"{row.get('solves', '')} / {row.get('factorizations', '')} / "
          f"{row.get('low_rank_updates', '')} | {phases} | {row['rss_mb']} | "
          f"{pct(row, 'peak_force_vs_finest')} | {pct(row, 'duration_vs_finest')} | "
          f"{pct(row, 'peak_force_vs_hertz')} | {pct(row, 'peak_force_vs_law')} | "
          f"{pct(row, 'duration_vs_law')} |")
