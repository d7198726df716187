#!/usr/bin/env bash
# Cost of one time step of the two-sphere impact against one factorization + solve of its system
# (issue 13 B). The default case (prm/spheres_rho0.001.prm: free flight for t < 2, contact for
# 2 < t < 2.0825) runs to the end of the contact, REPEAT times (default 3; the fastest run counts).
# dyncontact's last line gives the mean wall time of a step without active pairs (here the 800
# free-flight steps) and with them (the 33 contact steps); one factorization + solve is the run's
# factorization phase over its factorizations plus its linear solve phase over its solves.
# Extra arguments are passed to dyncontact (e.g. --set "Newton/direct solver=mumps").
#   bench/step_cost.sh [--set "..."]...
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/step_cost
mkdir -p "$results"
repeat=${REPEAT:-3}
for run in $(seq 1 "$repeat"); do
  build/dyncontact prm/spheres_rho0.001.prm --quiet --output "$results/run" \
    --set "Output/vtu interval=0" --set "Time integration/end time=2.0825" "$@" \
    >"$results/run$run.log" 2>&1 || { cat "$results/run$run.log"; exit 3; }
done
/usr/bin/python3 - "$results" "$repeat" <<'PYTHON'
import re, sys, pathlib
root, repeat = pathlib.Path(sys.argv[1]), int(sys.argv[2])
runs = []
for run in range(1, repeat + 1):
    log = (root / f"run{run}.log").read_text()
    done = re.search(r"done, (\d+) steps .*?, (\d+) linear solves \((\d+) factorizations, "
                     r"(\d+) low-rank updates\), wall time ([0-9.e+-]+) s \((.*?)\)\. Results", log)
    per_step = re.search(r"cost per step ([0-9.e+-]+) ms without active pairs \((\d+) steps\), "
                         r"([0-9.e+-]+) ms with active pairs \((\d+) steps\)", log)
    phases = dict((n.strip(), float(v)) for n, v in
                  re.findall(r"([a-z -]+) ([0-9.e+-]+) s", done.group(6)))
    runs.append({"wall": float(done.group(5)), "solves": int(done.group(2)),
                 "factorizations": int(done.group(3)), "low_rank": int(done.group(4)),
                 "phases": phases, "free": float(per_step.group(1)) / 1e3,
                 "contact": float(per_step.group(3)) / 1e3, "n_contact": int(per_step.group(4))})
best = min(runs, key=lambda r: r["wall"])
p = best["phases"]
factorization = p.get("factorization", 0) / max(best["factorizations"], 1)
solve = p.get("linear solve", 0) / max(best["solves"], 1)
unit = factorization + solve
print(f"fastest of {repeat} runs, wall {best['wall']:.2f} s: {best['factorizations']} factorizations, "
      f"{best['low_rank']} low-rank updates, {best['solves']} solves, {best['n_contact']} steps in contact")
print(f"one factorization {1e3*factorization:.1f} ms + one solve {1e3*solve:.2f} ms = {1e3*unit:.1f} ms")
print(f"free-flight step {1e3*best['free']:.2f} ms = {best['free']/unit:.3f} x")
print(f"contact step {1e3*best['contact']:.1f} ms = {best['contact']/unit:.2f} x")
PYTHON
