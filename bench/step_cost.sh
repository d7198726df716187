#!/usr/bin/env bash
# Cost of one time step of the two-sphere impact against one factorization + solve of its system
# (issue 13 B). The default case (prm/spheres_rho0.001.prm: free flight t < 2, contact
# 2 < t < 2.0825) runs to three end times, REPEAT times each (default 3, the fastest counts):
#   free-flight step = (T(2.0) - T(0.0025)) / 799,   contact step = (T(2.0825) - T(2.0)) / 33,
# and one factorization + solve = the run's factorization phase / factorizations + its linear
# solve phase / linear solves (the TimerOutput phases of the longest run).
# Extra arguments are passed to dyncontact (e.g. --set "Newton/method=modified").
#   bench/step_cost.sh [--set "..."]...
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/step_cost
mkdir -p "$results"
repeat=${REPEAT:-3}
for end in 0.0025 2.0 2.0825; do
  for run in $(seq 1 "$repeat"); do
    build/dyncontact prm/spheres_rho0.001.prm --quiet --output "$results/run" \
      --set "Output/vtu interval=0" --set "Time integration/end time=$end" "$@" \
      >"$results/t${end}_run$run.log" 2>&1 || { cat "$results/t${end}_run$run.log"; exit 3; }
  done
done
/usr/bin/python3 - "$results" "$repeat" <<'PYTHON'
import re, sys, pathlib
root, repeat = pathlib.Path(sys.argv[1]), int(sys.argv[2])
def parse(end):
    best = None
    for run in range(1, repeat + 1):
        log = (root / f"t{end}_run{run}.log").read_text()
        done = re.search(r"done, (\d+) steps .*?, (\d+) linear solves \((\d+) factorizations, "
                         r"(\d+) low-rank updates\), wall time ([0-9.e+-]+) s \((.*?)\)\. Results", log)
        wall = float(done.group(5))
        phases = dict((n.strip(), float(v)) for n, v in re.findall(r"([a-z -]+) ([0-9.e+-]+) s", done.group(6)))
        record = {"wall": wall, "solves": int(done.group(2)), "factorizations": int(done.group(3)),
                  "low_rank": int(done.group(4)), "phases": phases}
        if best is None or wall < best["wall"]:
            best = record
    return best
start, flight, contact = parse("0.0025"), parse("2.0"), parse("2.0825")
free_step = (flight["wall"] - start["wall"]) / 799
contact_step = (contact["wall"] - flight["wall"]) / 33
p = contact["phases"]
factorization = p.get("factorization", 0) / max(contact["factorizations"], 1)
solve = p.get("linear solve", 0) / max(contact["solves"], 1)
unit = factorization + solve
print(f"one factorization {1e3*factorization:.1f} ms + one solve {1e3*solve:.2f} ms = {1e3*unit:.1f} ms")
print(f"free-flight step {1e3*free_step:.2f} ms = {free_step/unit:.3f} x")
print(f"contact step {1e3*contact_step:.1f} ms = {contact_step/unit:.2f} x "
      f"({(contact['factorizations']-flight['factorizations'])/33:.2f} factorizations, "
      f"{(contact['low_rank']-flight['low_rank'])/33:.2f} low-rank updates, "
      f"{(contact['solves']-flight['solves'])/33:.2f} solves per step)")
PYTHON
