#!/usr/bin/env bash
# Contact-force ringing of the two-sphere impact, classical vs modified Newmark (issue 4, A), on the
# cases of the "Known limitations" table in doc/validation.md: rho = 1 (dt = 0.05) on the coarse
# mesh with linear and neo-Hookean material and on the medium mesh with linear material, and
# rho = 0.001 (dt = 0.0025) on the medium mesh with neo-Hookean material; plus the penalty
# formulation (classical only: it cannot be combined with the modified scheme) on the first case.
# Ringing is the RMS of the 4th difference / 16 over 5-sample windows inside the contact
# (measure_impact() in include/dyncontact/reference/impact_measures.h):
#  - total: of the total contact force, relative to its peak (impact_summary.csv);
#  - nodal force, nodal pressure: of every pair's multiplier and recovered contact pressure
#    (contact_pressure_t*.csv, written at every step of the contact), over the windows in which
#    the pair is active at all five steps, relative to the largest value of any pair.
# Writes bench/results/force_ringing.csv and prints it; about 2 minutes on a 2-core machine.
#   bench/force_ringing.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/force_ringing
mkdir -p "$results"
export results

# The Contact/dynamics of the paper's scheme names: classical -> none, modified -> taylor-papadopoulos.
contact_dynamics() { if [ "$1" = classical ]; then echo none; else echo taylor-papadopoulos; fi; }
export -f contact_dynamics

run_case() # name prm refinement material scheme formulation
{
  local name=$1 prm=$2 refinement=$3 material=$4 scheme=$5 formulation=$6
  # Contact begins at t = 2 and ends within 40 steps in both densities (about 24 and 33).
  local time_step profile_times
  time_step=$(sed -n 's/^ *set time step *= *//p' "$prm")
  profile_times=$(/usr/bin/python3 -c \
    "print(', '.join(f'{2 + $time_step * i:.6g}' for i in range(1, 41)))")
  run_sphere_impact "$results/$name" "$prm" "$refinement" "$material" \
    --set "Contact/dynamics=$(contact_dynamics "$scheme")" --set "Contact/formulation=$formulation" \
    --set "Output/profile times=$profile_times"
}
export -f run_case

# The longest runs (rho = 0.001: 860 steps, medium mesh) first.
cases=()
for scheme in classical modified; do
  cases+=("rho0.001_medium_neo_$scheme|prm/spheres_rho0.001.prm|1|neo-hookean|$scheme|lagrange multiplier")
done
for scheme in classical modified; do
  cases+=("rho1_coarse_linear_$scheme|prm/spheres_rho1.prm|0|linear elastic|$scheme|lagrange multiplier"
    "rho1_coarse_neo_$scheme|prm/spheres_rho1.prm|0|neo-hookean|$scheme|lagrange multiplier"
    "rho1_medium_linear_$scheme|prm/spheres_rho1.prm|1|linear elastic|$scheme|lagrange multiplier")
done
cases+=("rho1_coarse_linear_penalty_classical|prm/spheres_rho1.prm|0|linear elastic|classical|penalty")
all_succeeded=true
printf '%s\n' "${cases[@]}" | run_two_at_a_time run_case || all_succeeded=false

table=bench/results/force_ringing.csv
/usr/bin/python3 - "$results" >"$table" <<'PY'
import csv, glob, math, os, re, sys

def ringing(histories):
    """RMS of the 4th difference / 16 over the windows of 5 active samples (None: inactive),
    relative to the largest value in all histories."""
    squares = [((w[0] - 4 * w[1] + 6 * w[2] - 4 * w[3] + w[4]) / 16) ** 2
               for history in histories
               for w in (history[i - 2:i + 3] for i in range(2, len(history) - 2))
               if None not in w]
    largest = max(value for history in histories for value in history if value is not None)
    return math.sqrt(sum(squares) / len(squares)) / largest if squares else 0.0

print("case,total_ringing,nodal_force_ringing,nodal_pressure_ringing")
for directory in sorted(glob.glob(sys.argv[1] + '/*')):
    if not os.path.isfile(directory + '/impact_summary.csv'):
        continue  # a log file, or a failed or unfinished run
    summary = {row['quantity']: row for row in csv.DictReader(open(directory + '/impact_summary.csv'))}
    profiles = sorted(glob.glob(directory + '/contact_pressure_t*.csv'),
                      key=lambda name: float(re.search(r'_t([0-9.]+)\.csv$', name).group(1)))
    steps = [list(csv.DictReader(open(name))) for name in profiles]
    if not steps:
        continue  # no contact
    pair_indices = range(len(steps[0]))
    histories = {column: [[float(step[k][column]) if step[k]['active'] == '1' else None
                           for step in steps] for k in pair_indices]
                 for column in ('multiplier', 'pressure')}
    print(f"{os.path.basename(directory)},{float(summary['ringing']['computed']):.5f},"
          f"{ringing(histories['multiplier']):.5f},{ringing(histories['pressure']):.5f}")
PY
print_table "$table"
$all_succeeded
