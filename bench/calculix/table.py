#!/usr/bin/python3
"""Markdown table of CalculiX runs: the summary.csv rows that run.sh appended to
bench/results/calculix.csv (or any such CSV given as argument, e.g. bench/results/calculix_3d.csv
of the 3D deck, whose columns compare with the finite-sphere law); the last row of each label
wins. Usage: table.py [CSV] [--labels A,B,...]"""
import argparse
import csv
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv", nargs="?",
                    default=os.path.join(HERE, "..", "results", "calculix.csv"))
    ap.add_argument("--labels", default=None, help="comma-separated labels, in this order")
    a = ap.parse_args()
    rows = {}
    with open(a.csv) as f:
        reader = csv.DictReader(f)
        three_d = "law_peak" in (reader.fieldnames or [])
        for r in reader:
            if r["label"] == "label":
                continue
            rows[r["label"]] = r
    labels = a.labels.split(",") if a.labels else list(rows)
    cols = [("run", "label"), ("rho", "rho"), ("material", "material"),
            ("pole edge", "pole_edge"), ("zone", "zone_radius"), ("cells", "elements"),
            ("equations", "equations"), ("t0", "start_time"),
            ("increments", "increments"), ("iterations", "iterations"), ("wall [s]", "wall_s"),
            ("RSS [MB]", "peak_rss_mb"), ("peak", "peak"), ("vs Hertz", "peak_vs_hertz_pct"),
            ("duration", "duration"), ("vs Hertz", "duration_vs_hertz_pct"),
            ("impulse", "impulse"), ("vs 2mv", "impulse_vs_2mv_pct")]
    if three_d:
        cols = [("run", "label"), ("element", "element"), ("contact", "contact"),
                ("slave", "slave"), ("N", "n"),
                ("NR", "nr"), ("PoleGrading", "pole_grading"), ("pole edge", "pole_edge"),
                ("penalty [E]", "penalty"), ("cells", "elements"), ("equations", "equations"),
                ("increments", "increments"), ("iterations", "iterations"),
                ("wall [s]", "wall_s"), ("RSS [MB]", "peak_rss_mb"), ("peak", "peak"),
                ("vs law", "peak_vs_law_pct"), ("duration", "duration"),
                ("vs law", "duration_vs_law_pct"), ("impulse", "impulse"),
                ("vs 2mv", "impulse_vs_2mv_pct")]
    print("| " + " | ".join(c[0] for c in cols) + " |")
    print("|" + "---|" * len(cols))
    for lab in labels:
        r = rows[lab]
        cells = []
        for _, k in cols:
            v = r.get(k, "")
            if k.endswith("_pct") and v not in ("", None):
                v = f"{float(v):+.3f} %"
            cells.append(str(v))
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
