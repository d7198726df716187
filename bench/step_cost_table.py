#!/usr/bin/env python3
"""Table of bench/step_cost.sh: of its runs (run1.log ... runN.log) the fastest counts; the mean
wall time of a free-flight step and of a contact step against one factorization + solve (the
factorization phase per factorization plus the linear solve phase per solve).

Usage: step_cost_table.py RESULTS_DIR N
"""
import pathlib
import sys

import run_log

root, repeat = pathlib.Path(sys.argv[1]), int(sys.argv[2])
runs = [run_log.parse_log((root / f"run{run}.log").read_text()) for run in range(1, repeat + 1)]
best = min(runs, key=lambda run: run["wall"])
phases = best["phases"]
factorization = phases.get("factorization", 0) / max(best["factorizations"], 1)
solve = phases.get("linear solve", 0) / max(best["solves"], 1)
unit = factorization + solve
print(f"fastest of {repeat} runs, wall {best['wall']:.2f} s: {best['factorizations']} factorizations, "
      f"{best['low_rank_updates']} low-rank updates, {best['solves']} solves, "
      f"{best['contact_steps']} steps in contact")
print(f"one factorization {1e3 * factorization:.1f} ms + one solve {1e3 * solve:.2f} ms = "
      f"{1e3 * unit:.1f} ms")
print(f"free-flight step {1e3 * best['free_step']:.2f} ms = {best['free_step'] / unit:.3f} x")
print(f"contact step {1e3 * best['contact_step']:.1f} ms = {best['contact_step'] / unit:.2f} x")
