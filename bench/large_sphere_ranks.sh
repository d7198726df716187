#!/usr/bin/env bash
# Memory per rank and time per contact step of the largest 2D sphere impact of issue 27 (D, E):
# the paper's rho = 0.001 spheres touching at t = 0 (CentreDistance 16) on the structured mesh
# meshes/two_spheres.geo at Refinement 4, Divisions 7 (1,092,996 displacement DoFs, 136,192 Q2
# cells), linear elastic, node-to-node pairs, modified Newton, MUMPS (its symmetric LDL^T), 4
# steps of dt = 0.0025 (every step a contact step), on each rank count given (default 1 2 4; more
# ranks than the machine's cores are oversubscribed: right for memory, not for time).
# Writes bench/results/large_sphere_ranks/ranks_N.{log,time} and prints a markdown table, from
# dyncontact's last lines: wall per contact step, its factorization share, MUMPS's flops and the
# busiest rank's share of them, the peak resident memory of the largest rank (VmHWM) and its
# ratio to one rank. About 6 minutes for
# 1 2 4 on 2 cores; set-up (meshing, caches, the solver's symbolic analysis: METIS's order and
# MUMPS's analysis, given in its own column) is 30 to 40 s of each run and is not in the per-step
# figure.
#   bench/large_sphere_ranks.sh [RANKS...]
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/large_sphere_ranks
mkdir -p "$results"
ranks_list=("$@")
[ ${#ranks_list[@]} -gt 0 ] || ranks_list=(1 2 4)
for ranks in "${ranks_list[@]}"; do
  run_large_sphere "$results/ranks_$ranks" "$ranks" 4 0.01
done
/usr/bin/python3 - "$results" "${ranks_list[@]}" <<'EOF'
import re, sys
results, ranks_list = sys.argv[1], sys.argv[2:]
print("| ranks | DoFs | wall per contact step | factorization | MUMPS's flops, busiest rank's share | symbolic analysis (set-up) | peak memory, largest rank | vs 1 rank | smallest rank |")
print("|---|---|---|---|---|---|---|---|---|")
one = None
for ranks in ranks_list:
    log = open(f"{results}/ranks_{ranks}.log").read()
    dofs = re.search(r"(\d+) displacement DoFs", log).group(1)
    step = float(re.search(r"([\d.e+]+) ms with active pairs \((\d+) steps\)", log).group(1)) / 1e3
    n_steps = int(re.search(r"ms with active pairs \((\d+) steps\)", log).group(1))
    factorization = float(re.search(r"factorization ([\d.e+]+) s", log).group(1))
    analysis = float(re.search(r"symbolic analysis of the fixed pattern ([\d.e+]+) s", log).group(1))
    largest, smallest = map(float, re.search(
        r"peak memory per rank ([\d.]+) MiB \(largest.*?([\d.]+) MiB \(smallest", log).groups())
    flops = re.search(r"([\d.e+]+) flops, ([\d.]+) % of them on the busiest", log)
    flops = f"{flops.group(1)}, {flops.group(2)} %" if flops else "(not MUMPS)"
    one = one or largest
    print(f"| {ranks} | {dofs} | {step:.1f} s | {factorization / n_steps / step * 100:.0f} % | {flops} | {analysis:.1f} s | "
          f"{largest:.0f} MiB | {largest / one:.2f} | {smallest:.0f} MiB |")
EOF
