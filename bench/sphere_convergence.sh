#!/usr/bin/env bash
# Convergence of the two-sphere impact (prm/spheres_rho0.001.prm) against Hertz: the three meshes
# of the family (Refinement 0, 1, 2 = coarse, medium, fine) x two time steps (0.0025, the paper's,
# and 0.00125) x two materials (neo-Hookean finite strain, small-strain linear elastic), two runs
# at a time on one rank each, from one Release build.
# Writes bench/results/sphere_convergence.csv (peak force, duration, impulse and ringing with their
# relative differences from Hertz, wall time) over every run in bench/results/sphere_convergence,
# and prints it.
# The fine-mesh runs dominate: about 15 minutes in all on a 2-core machine. Extra arguments go to
# every run; REFINEMENTS, TIME_STEPS and DENSITY choose other sets of runs. DENSITY (default 0.001)
# sets both spheres' density; Hertz's contact time scales as rho^0.4, and so do the default time
# steps and the end time (2.15 at rho = 0.001).
#   bench/sphere_convergence.sh
#   REFINEMENTS=3 TIME_STEPS=0.0025 bench/sphere_convergence.sh   # the extra-fine mesh, ~40 min
#   DENSITY=1e-2 REFINEMENTS=2 TIME_STEPS=0.00625 bench/sphere_convergence.sh   # the fine mesh at
#   DENSITY=1e-4 REFINEMENTS=2 TIME_STEPS=0.001 bench/sphere_convergence.sh     # other densities,
#   DENSITY=1e-5 REFINEMENTS=2 TIME_STEPS=0.0004 bench/sphere_convergence.sh    # ~35 min in all
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/sphere_convergence
mkdir -p "$results"
density=${DENSITY:-0.001}
contact_time_scale=$(/usr/bin/python3 -c "print(($density / 0.001) ** 0.4)")
scaled_time_step() { /usr/bin/python3 -c "print(f'{$1 * $contact_time_scale:.3g}')"; }
end_time=$(/usr/bin/python3 -c "print(f'{2 + 0.15 * $contact_time_scale:.4g}')")
time_steps=${TIME_STEPS:-default}
if [ "$time_steps" = default ]; then
  time_steps="$(scaled_time_step 0.0025) $(scaled_time_step 0.00125)"
fi
export density end_time results

run_case() # refinement time_step material extra-arguments...
{
  local refinement=$1 time_step=$2 material=$3
  shift 3
  local output="$results/rho${density}_r${refinement}_dt${time_step}_${material// /_}"
  local start
  start=$(date +%s.%N)
  run_sphere_impact "$output" prm/spheres_rho0.001.prm "$refinement" "$material" \
    --set "Time integration/time step=$time_step" --set "Time integration/end time=$end_time" \
    --set "Bodies/Body 1/density=$density" --set "Bodies/Body 2/density=$density" "$@" ||
    return 1
  seconds_since "$start" >"$output/wall_seconds"
}
export -f run_case

cases=()
for refinement in ${REFINEMENTS:-0 1 2}; do
  for time_step in $time_steps; do
    for material in neo-hookean "linear elastic"; do
      cases+=("$refinement|$time_step|$material")
    done
  done
done
# The longest runs (finest mesh, then smallest time step) first, so that the two slots stay busy
# to the end. A failed run is reported and left out of the table; the script then exits with 1.
all_succeeded=true
printf '%s\n' "${cases[@]}" | LC_ALL=C sort -t'|' -k1,1nr -k2,2g |
  run_two_at_a_time run_case "$@" || all_succeeded=false

table=bench/results/sphere_convergence.csv
/usr/bin/python3 - "$results" >"$table" <<'PY'
import csv, glob, os, sys
print("density,refinement,time_step,material,peak_force,peak_rel,duration,duration_rel,impulse,"
      "impulse_rel,ringing,wall_seconds")
for directory in sorted(glob.glob(sys.argv[1] + '/rho*_r*_dt*')):
    if not all(os.path.isfile(os.path.join(directory, name))
               for name in ('wall_seconds', 'impact_summary.csv')):
        continue  # a log file, or a failed or unfinished run
    density, refinement, time_step, material = os.path.basename(directory).split('_', 3)
    summary = {row['quantity']: row for row in csv.DictReader(open(directory + '/impact_summary.csv'))}
    values = []
    for quantity in ('peak_force', 'duration', 'impulse'):
        values += [float(summary[quantity]['computed']), float(summary[quantity]['relative_difference'])]
    seconds = float(open(directory + '/wall_seconds').read())
    print(f"{density[3:]},{refinement[1:]},{time_step[2:]},{material.replace('_', ' ')},"
          f"{values[0]:.4f},{values[1]:+.4%},{values[2]:.5f},{values[3]:+.4%},{values[4]:.5f},"
          f"{values[5]:+.4%},{float(summary['ringing']['computed']):.5f},{seconds:.0f}")
PY
print_table "$table"
$all_succeeded
