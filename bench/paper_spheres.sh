#!/usr/bin/env bash
# Wall time of the paper's two sphere runs (prm/spheres_rho1.prm, prm/spheres_rho0.001.prm, their
# default mesh) on 1 and 2 MPI ranks, with the DoF count and Newton linear solves per step, from
# one Release build. Extra arguments go to every run (e.g. --set "Mesh/geo parameters=...").
# Writes bench/results/paper_spheres.csv and prints it. Run on an otherwise idle machine.
#   bench/paper_spheres.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
mkdir -p bench/results
table=bench/results/paper_spheres.csv
echo "case,ranks,wall_seconds,dofs,steps,linear_solves,steps_in_contact,solves_per_contact_step" >"$table"
for case in spheres_rho1 spheres_rho0.001; do
  for ranks in 1 2; do
    output=bench/results/$case-np$ranks
    start=$(date +%s.%N)
    mpirun -np "$ranks" build/dyncontact "prm/$case.prm" --output "$output" \
      --set "Output/vtu interval=0" "$@" >"$output.log"
    seconds=$(seconds_since "$start")
    /usr/bin/python3 - "$case" "$ranks" "$seconds" "$output" >>"$table" <<'PY'
import csv, re, sys
case, ranks, seconds, output = sys.argv[1:]
rows = list(csv.DictReader(open(output + '/history.csv')))[1:]
solves = [float(r['newton_iterations']) for r in rows]
contact = [float(r['newton_iterations']) for r in rows if float(r['active_constraints']) > 0]
dofs = re.search(r'(\d+) displacement DoFs', open(output + '.log').read()).group(1)
print(f"{case},{ranks},{float(seconds):.1f},{dofs},{len(rows)},{sum(solves):.0f},{len(contact)},"
      f"{sum(contact) / max(1, len(contact)):.2f}")
PY
  done
done
print_table "$table"
