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
/usr/bin/python3 bench/step_cost_table.py "$results" "$repeat"
