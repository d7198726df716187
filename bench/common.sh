# shellcheck shell=bash
# Sourced by every bench/*.sh script (after its own `set -euo pipefail`): the repository root as
# working directory, Open MPI allowed to run as root, a Release build of dyncontact (the only build
# to time), and the helpers below. Run one bench script at a time: each one rebuilds build/, and
# two at once would race on it or time a binary relinked under them.
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 --target dyncontact >/dev/null

# One two-sphere impact run of build/dyncontact on one rank into a fresh output directory (results
# of an earlier run there are removed first, so that a failed run leaves nothing to tabulate): the
# structured mesh family (PoleGrading 10) at the given refinement, the given material for both
# bodies, no VTU. prm/spheres_rho0.001.prm, whose default is the graded mesh, is put back on the
# paper's meshes/two_spheres.geo with node-to-node pairs and full Newton. Extra arguments go to
# dyncontact. The log goes to output.log; a failure is reported, with status 1.
run_sphere_impact() # output prm refinement material extra-arguments...
{
  local output=$1 prm=$2 refinement=$3 material=$4
  shift 4
  local structured=()
  if [ "$prm" = prm/spheres_rho0.001.prm ]; then
    structured=(--set "Mesh/file=../meshes/two_spheres.geo"
      --set "Contact/discretization=node-to-node" --set "Newton/method=full")
  fi
  rm -rf "$output" "$output.log"
  if ! build/dyncontact "$prm" --output "$output" "${structured[@]}" \
    --set "Mesh/geo parameters=Refinement: $refinement, PoleGrading: 10, CoreOffset: 0.3" \
    --set "Bodies/Body 1/material=$material" --set "Bodies/Body 2/material=$material" \
    --set "Output/vtu interval=0" "$@" >"$output.log" 2>&1; then
    echo "run failed, see $output.log" >&2
    return 1
  fi
}
export -f run_sphere_impact

# The large sphere impact of issue 27 on `ranks` MPI ranks (one: no mpirun; more than the cores:
# oversubscribed), under /usr/bin/time -v (output.time): the paper's rho = 0.001 spheres touching
# at t = 0 (CentreDistance 16) on the structured meshes/two_spheres.geo at the given Refinement
# (4: 1,092,996 DoFs; 3: 273,924), Divisions 7, linear elastic, node-to-node pairs, modified Newton,
# MUMPS (its symmetric LDL^T; SOLVER overrides), steps of dt = 0.0025 (every one a contact step)
# up to `end_time`, no VTU. The environment goes to every rank (mpirun passes it to local ranks).
# The log goes to output.log; a failure is reported, with status 3.
run_large_sphere() # output ranks refinement end-time
{
  local output=$1 ranks=$2 refinement=$3 end_time=$4 launcher=()
  [ "$ranks" -gt 1 ] && launcher=(mpirun --oversubscribe -np "$ranks")
  /usr/bin/time -v -o "$output.time" "${launcher[@]}" build/dyncontact \
    prm/spheres_rho0.001.prm --quiet --output "$output" \
    --set "Output/vtu interval=0" --set "Output/profile times=" \
    --set "Bodies/Body 1/material=linear elastic" --set "Bodies/Body 2/material=linear elastic" \
    --set "Newton/method=modified" --set "Newton/direct solver=${SOLVER:-mumps}" \
    --set "Mesh/file=../meshes/two_spheres.geo" \
    --set "Mesh/geo parameters=Refinement: $refinement, Divisions: 7, RadialDivisions: 6, PoleGrading: 10, CoreOffset: 0.3, CentreDistance: 16" \
    --set "Contact/discretization=node-to-node" --set "Time integration/end time=$end_time" \
    >"$output.log" 2>&1 || { echo "ranks $ranks failed, see $output.log" >&2; return 3; }
}

# Runs `function fields... extra-arguments...` for every line of standard input, two at a time;
# a line holds the fields separated by '|'. The function must be exported (export -f). Fails if
# any call failed, after all of them have run.
run_two_at_a_time() # function extra-arguments...
{
  local function=$1
  shift
  xargs -d '\n' -P 2 -I{} bash -c \
    'IFS="|" read -r -a fields <<<"$1"; shift; "$0" "${fields[@]}" "$@"' "$function" {} "$@"
}

# Seconds elapsed since START (a `date +%s.%N` reading), with awk, which every Debian has.
seconds_since() # start
{
  awk -v start="$1" -v now="$(date +%s.%N)" 'BEGIN { printf "%.3f\n", now - start }'
}

# Prints the CSV file as a table with aligned columns.
print_table() # file.csv
{
  /usr/bin/python3 -c '
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
widths = [max(len(row[i]) for row in rows if i < len(row)) for i in range(max(map(len, rows)))]
for row in rows:
    print("  ".join(cell.ljust(width) for cell, width in zip(row, widths)).rstrip())' "$1"
}
export -f seconds_since print_table
