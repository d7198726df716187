#!/usr/bin/env bash
# Issue 27, acceptance C: the same history.csv on any number of MPI ranks. Runs each case on
# 1, 2, 3, 4 and 8 ranks (more than the machine's cores is oversubscribed: for correctness, not
# speed) and compares every history with the 1-rank one: byte-identical, or the largest relative
# column difference (tests/cli/compare_histories.py: max |a - b| over the column's max |a|).
#   bench/rank_consistency.sh BINARY DIR [RANKS...]   (default ranks: 1 2 3 4 8)
# Cases: the default (prm/spheres_rho0.001.prm), the dissimilar spheres, the three spheres.
set -euo pipefail
cd "$(dirname "$0")/.."
binary=$(realpath "$1") directory=$2
shift 2
ranks=("$@")
[ ${#ranks[@]} -gt 0 ] || ranks=(1 2 3 4 8)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$directory"
for prm in prm/spheres_rho0.001.prm prm/dissimilar_spheres.prm prm/three_spheres.prm; do
  name=$(basename "$prm" .prm)
  for n in "${ranks[@]}"; do
    output="$directory/$name.np$n"
    start=$(date +%s.%N)
    mpirun --oversubscribe -np "$n" "$binary" "$prm" --quiet --output "$output" \
      --set "Output/vtu interval=0" --set "Output/profile times=" >"$output.log" 2>&1
    end=$(date +%s.%N)
    reference="$directory/$name.np${ranks[0]}/history.csv"
    if cmp -s "$reference" "$output/history.csv"; then
      verdict="byte-identical"
    else
      verdict=$(/usr/bin/python3 tests/cli/compare_histories.py "$reference" "$output/history.csv" 1 |
        sed 's/ (tolerance 1)//')
    fi
    printf '%-18s %2s ranks %7.1f s  %s\n' "$name" "$n" "$(echo "$end - $start" | bc)" "$verdict"
  done
done
