#!/usr/bin/env bash
# Scaling of the two-sphere impact (issue 13 C): wall time against the number of steps on a fixed
# mesh and against the DoFs at a fixed number of steps, with fitted exponents; peak memory per DoF;
# one MPI rank against two. Every run is the paper's rho = 0.001 spheres touching at t = 0
# (CentreDistance 16), linear elastic, modified Newton, direct solver SOLVER (default mumps; klu
# factorizes the 224k-DoF mesh 10x slower, its ordering is not made for 2D meshes), so that every
# step is a contact step:
#   steps: the graded default mesh (13092 DoFs), t = 0 -> 0.08 (the contact) at dt = 0.0025 / k,
#          k = 1, 2, 4, 8 (32 to 256 steps);
#   DoFs:  the paper's structured meshes/two_spheres.geo, Refinement 0 to 3 (3.6k to 224k DoFs),
#          node-to-node, 16 steps of dt = 0.0025;
#   ranks: the graded default mesh, 32 steps, on 1 and on 2 ranks.
# Writes bench/results/scaling/*.log and prints the markdown tables. About 10 minutes.
#   bench/scaling.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/scaling
rm -rf "$results"
mkdir -p "$results"
common=(--quiet --set "Output/vtu interval=0" --set "Bodies/Body 1/material=linear elastic"
  --set "Bodies/Body 2/material=linear elastic" --set "Newton/method=modified"
  --set "Newton/direct solver=${SOLVER:-mumps}")

run() # name launcher-words... -- dyncontact-arguments...
{
  local name=$1
  shift
  local launcher=()
  while [ "$1" != -- ]; do launcher+=("$1"); shift; done
  shift
  /usr/bin/time -v -o "$results/$name.time" "${launcher[@]}" build/dyncontact \
    prm/spheres_rho0.001.prm --output "$results/$name" "${common[@]}" "$@" \
    >"$results/$name.log" 2>&1 || { echo "$name failed, see $results/$name.log" >&2; exit 3; }
}

for k in 1 2 4 8; do
  dt=$(/usr/bin/python3 -c "print(0.0025 / $k)")
  run "steps_k$k" -- --set "Mesh/geo parameters=PoleSize: 0.1, CentreDistance: 16" \
    --set "Time integration/time step=$dt" --set "Time integration/end time=0.08"
done
for refinement in 0 1 2 3; do
  run "dofs_r$refinement" -- --set "Mesh/file=../meshes/two_spheres.geo" \
    --set "Mesh/geo parameters=Refinement: $refinement, PoleGrading: 10, CoreOffset: 0.3, CentreDistance: 16" \
    --set "Contact/discretization=node-to-node" --set "Time integration/end time=0.04"
done
for ranks in 1 2; do
  run "ranks_$ranks" mpirun -np "$ranks" -- --set "Mesh/geo parameters=PoleSize: 0.1, CentreDistance: 16" \
    --set "Time integration/end time=0.08"
done
/usr/bin/python3 bench/scaling_table.py "$results"
