#!/usr/bin/env bash
# Performance of the two-sphere impact (issue 13): wall time against accuracy on a family of meshes,
# and CalculiX on the same problem in the same run.
#
# Every case runs REPEAT times (default 3) one after the other, alone on the machine (no other
# bench case runs meanwhile), with --quiet and no VTU; reported per case: the min and median wall
# time, displacement DoFs, steps, linear solves, factorizations, the time of each phase (the
# TimerOutput summary of the fastest run), the peak resident memory (/usr/bin/time), and the
# accuracy: peak force, contact duration and impulse against Hertz and the finite-sphere law
# (impact_summary.csv) and against the finest mesh of the same family and material.
# Cases (rho = 0.001, t = 0 -> 2.15, dt = 0.0025, the paper's run):
#   graded_P  meshes/two_spheres_graded.geo with PoleSize P (node-to-segment), linear elastic;
#   graded_P_neo  the same mesh, neo-Hookean;
#   structured_rN  meshes/two_spheres.geo Refinement N (node-to-node, the meshes before issue 13).
# All with modified Newton (the prm's) and SOLVER (klu, the default, or mumps) as direct solver.
# CASES (space-separated names) runs a subset; CALCULIX=1 (default) adds bench/calculix/run.sh
# (the same impact as one sphere on the rigid symmetry plane, CAX8, penalty 50 E). Writes bench/results/performance.csv and
# prints the markdown table.
#   bench/performance.sh
#   REPEAT=1 CASES="graded_0.1 graded_0.05" CALCULIX=0 bench/performance.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/performance
mkdir -p "$results"
repeat=${REPEAT:-3}
all_cases="graded_0.2 graded_0.14 graded_0.1 graded_0.07 graded_0.05 graded_0.035 \
graded_0.1_neo graded_0.05_neo structured_r0 structured_r1 structured_r2"
cases=${CASES:-$all_cases}

case_arguments() # name -> the dyncontact arguments of the case, one per line
{
  local name=$1 material="linear elastic"
  case $name in *_neo) material=neo-hookean ;; esac
  printf '%s\n' --set "Bodies/Body 1/material=$material" --set "Bodies/Body 2/material=$material" \
    --set "Newton/direct solver=${SOLVER:-klu}"
  case $name in
    graded_*)
      local pole=${name#graded_}
      pole=${pole%_neo}
      printf '%s\n' --set "Mesh/file=../meshes/two_spheres_graded.geo" \
        --set "Mesh/geo parameters=PoleSize: $pole" \
        --set "Contact/discretization=node-to-segment" ;;
    structured_r*)
      printf '%s\n' --set "Mesh/file=../meshes/two_spheres.geo" \
        --set "Mesh/geo parameters=Refinement: ${name#structured_r}, PoleGrading: 10, CoreOffset: 0.3" \
        --set "Contact/discretization=node-to-node" ;;
  esac
}

for name in $cases; do
  mapfile -t arguments < <(case_arguments "$name")
  for run in $(seq 1 "$repeat"); do
    output="$results/$name/run$run"
    rm -rf "$output"
    mkdir -p "$output"
    if ! /usr/bin/time -v -o "$output/time.log" build/dyncontact prm/spheres_rho0.001.prm \
      --quiet --output "$output" --set "Output/vtu interval=0" "${arguments[@]}" \
      >"$output/run.log" 2>&1; then
      echo "$name run $run failed, see $output/run.log" >&2
    fi
  done
done

# CalculiX at its converged mesh (bench/calculix/README.md), linear and NLGEOM, once each (8 and
# 18 minutes on this machine): its run-to-run spread is far below the ratios of interest.
if [ "${CALCULIX:-1}" = 1 ]; then
  bench/calculix/run.sh --label performance_linear || echo "CalculiX linear run failed" >&2
  bench/calculix/run.sh --label performance_nlgeom --nlgeom || echo "CalculiX NLGEOM run failed" >&2
fi

/usr/bin/python3 bench/performance_table.py "$results" $cases
