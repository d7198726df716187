#!/usr/bin/env bash
# Contact-force ringing of the two-sphere impact, classical vs modified Newmark (issue 4, A), on the
# cases of the README's "Known limitations" table: rho = 1 (dt = 0.05) on the coarse mesh with
# linear and neo-Hookean material and on the medium mesh with linear material, and rho = 0.001
# (dt = 0.0025) on the medium mesh with neo-Hookean material; plus the penalty formulation
# (classical only: it cannot be combined with the modified scheme) on the first case.
# Ringing is the RMS of the 4th difference / 16 over 5-sample windows inside the contact
# (measure_impact() in include/dyncontact/impact_measures.h):
#  - total: of the total contact force, relative to its peak (impact_summary.csv);
#  - multiplier, pressure: of every active pair's nodal force and recovered contact pressure
#    (contact_pressure_t*.csv, written at every step of the contact), over the windows in which
#    the pair is active throughout, relative to the largest nodal value.
# Writes bench/results/force_ringing.csv and prints it; about 4 minutes on a 2-core machine.
#   bench/force_ringing.sh
source "$(dirname "$0")/common.sh"
results=bench/results/force_ringing
mkdir -p "$results"

run_case() # name prm refinement material scheme formulation
{
  local name=$1 prm=$2 refinement=$3 material=$4 scheme=$5 formulation=$6
  local output="$results/$name"
  # Contact begins at t = 2 and ends within 40 steps in both densities (about 24 and 33).
  local time_step profile_times
  time_step=$(sed -n 's/^ *set time step *= *//p' "$prm")
  profile_times=$(/usr/bin/python3 -c \
    "print(', '.join(f'{2 + $time_step * i:.6g}' for i in range(1, 41)))")
  if ! build/dyncontact "$prm" --output "$output" \
    --set "Mesh/geo parameters=Refinement: $refinement, PoleGrading: 10, CoreOffset: 0.3" \
    --set "Time integration/scheme=$scheme" --set "Contact/formulation=$formulation" \
    --set "Bodies/Body 1/material=$material" --set "Bodies/Body 2/material=$material" \
    --set "Output/profile times=$profile_times" --set "Output/vtu interval=0" \
    >"$output.log" 2>&1; then
    echo "run failed, see $output.log" >&2
    return 1
  fi
}
export -f run_case
export results

cases=()
for scheme in classical modified; do
  cases+=("rho1_coarse_linear_$scheme|prm/spheres_rho1.prm|0|linear elastic|$scheme|lagrange multiplier"
    "rho1_coarse_neo_$scheme|prm/spheres_rho1.prm|0|neo-hookean|$scheme|lagrange multiplier"
    "rho1_medium_linear_$scheme|prm/spheres_rho1.prm|1|linear elastic|$scheme|lagrange multiplier"
    "rho0.001_medium_neo_$scheme|prm/spheres_rho0.001.prm|1|neo-hookean|$scheme|lagrange multiplier")
done
cases+=("rho1_coarse_linear_penalty_classical|prm/spheres_rho1.prm|0|linear elastic|classical|penalty")
all_succeeded=true
printf '%s\n' "${cases[@]}" |
  xargs -d '\n' -P 2 -I{} bash -c \
    'IFS="|" read -r n p r m s f <<<"$1"; run_case "$n" "$p" "$r" "$m" "$s" "$f"' _ {} ||
  all_succeeded=false

table=bench/results/force_ringing.csv
/usr/bin/python3 - "$results" >"$table" <<'PY'
import csv, glob, math, os, re, sys

def ringing(histories):
    """RMS of the 4th difference / 16 over the windows whose 5 samples are all positive."""
    squares = [((w[0] - 4 * w[1] + 6 * w[2] - 4 * w[3] + w[4]) / 16) ** 2
               for history in histories
               for w in (history[i - 2:i + 3] for i in range(2, len(history) - 2))
               if all(value > 0 for value in w)]
    largest = max(max(history) for history in histories)
    return math.sqrt(sum(squares) / len(squares)) / largest if squares else 0.0

print("case,total_ringing,multiplier_ringing,pressure_ringing")
for directory in sorted(glob.glob(sys.argv[1] + '/*')):
    if not os.path.exists(directory + '/impact_summary.csv'):
        continue  # a failed or unfinished run
    summary = {row['quantity']: row for row in csv.DictReader(open(directory + '/impact_summary.csv'))}
    profiles = sorted(glob.glob(directory + '/contact_pressure_t*.csv'),
                      key=lambda name: float(re.search(r'_t([0-9.]+)\.csv$', name).group(1)))
    rows = [list(csv.DictReader(open(name))) for name in profiles]
    pairs = range(len(rows[0]))
    columns = {column: [[float(step[k][column]) if step[k]['active'] == '1' else 0.0 for step in rows]
                        for k in pairs] for column in ('multiplier', 'pressure')}
    print(f"{os.path.basename(directory)},{float(summary['ringing']['computed']):.5f},"
          f"{ringing(columns['multiplier']):.5f},{ringing(columns['pressure']):.5f}")
PY
column -s, -t "$table"
$all_succeeded
