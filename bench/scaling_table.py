#!/usr/bin/env python3
"""Tables of bench/scaling.sh: wall time against steps and against DoFs with least-squares
exponents (log wall = a + p log x), peak memory per DoF, and 1 against 2 MPI ranks.

Usage: scaling_table.py RESULTS_DIR
"""
import math
import pathlib
import sys

import run_log

root = pathlib.Path(sys.argv[1])


def parse(name):
    run = run_log.parse_log((root / f"{name}.log").read_text())
    run["rss_mb"] = run_log.parse_time_log((root / f"{name}.time").read_text())["rss_mb"]
    return run


def exponent(xs, ys):
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


steps = [parse(f"steps_k{k}") for k in (1, 2, 4, 8)]
print("| steps | wall [s] | factorizations | wall per step [ms] |")
print("|---|---|---|---|")
for run in steps:
    print(f"| {run['steps']} | {run['wall']:.2f} | {run['factorizations']} | "
          f"{1e3 * run['wall'] / run['steps']:.1f} |")
print(f"\nfitted exponent in steps: {exponent([r['steps'] for r in steps], [r['wall'] for r in steps]):.3f}\n")

dofs = [parse(f"dofs_r{r}") for r in range(4)]
print("| DoFs | wall [s] | factorization [s] | assembly [s] | peak RSS [MB] | RSS per DoF [kB] |")
print("|---|---|---|---|---|---|")
for run in dofs:
    print(f"| {run['dofs']} | {run['wall']:.2f} | {run['phases'].get('factorization', 0):.2f} | "
          f"{run['phases'].get('assembly', 0):.2f} | {run['rss_mb']:.0f} | "
          f"{1024 * run['rss_mb'] / run['dofs']:.2f} |")
xs, ys = [r["dofs"] for r in dofs], [r["wall"] for r in dofs]
print(f"\nfitted exponent in DoFs: {exponent(xs, ys):.3f} (all four), "
      f"{exponent(xs[1:], ys[1:]):.3f} (the three largest)\n")

ranks = [parse(f"ranks_{n}") for n in (1, 2)]
print("| MPI ranks | wall [s] | factorization [s] | assembly [s] |")
print("|---|---|---|---|")
for n, run in zip((1, 2), ranks):
    print(f"| {n} | {run['wall']:.2f} | {run['phases'].get('factorization', 0):.2f} | "
          f"{run['phases'].get('assembly', 0):.2f} |")
