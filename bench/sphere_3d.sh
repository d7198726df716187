#!/usr/bin/env bash
# The 3D sphere against the axisymmetric one (issue 28, B and F): prm/sphere_on_rigid_plane_3d.prm
# (the paper's sphere, neo-Hookean, rho = 0.001, speed 1, as a quarter on two symmetry planes,
# dropped on the rigid plane z = 0 from 0.005 above it) on its shipped mesh (N 8, NR 6,
# PoleGrading 10: 86,247 DoFs, pole edge 0.19), and with FINE=1 also on N 12, NR 8, PoleGrading 4
# (262,419 DoFs, about 40 minutes and 8.2 GB: the finer mesh of the README's figures, measured
# when the shipped mesh was graded by 4); beside prm/sphere_on_rigid_plane.prm, the axisymmetric case, moved to touch at the
# same t = 0.005 on the structured meshes Refinement 1 and 2 (pole edges 0.13 and 0.067). For each
# run, from its impact_summary.csv (the 3D one scaled to the whole sphere): the peak force,
# contact duration and impulse, their differences from the finite-sphere law, and the 3D runs'
# differences from the axisymmetric Refinement 2; wall time and peak memory from /usr/bin/time.
# Writes bench/results/sphere_3d.csv and prints it; about 7 minutes on 2 cores.
#   bench/sphere_3d.sh            FINE=1 bench/sphere_3d.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/sphere_3d
mkdir -p "$results"

run() # name prm arguments...
{
  local name=$1 prm=$2
  shift 2
  rm -rf "${results:?}/$name"
  /usr/bin/time -f "%e %M" -o "$results/$name.time" build/dyncontact "$prm" --quiet \
    --output "$results/$name" --set "Output/vtu interval=0" --set "Output/vtu times=" \
    --set "Output/profile times=" "$@" >"$results/$name.log" 2>&1 ||
    echo "$name failed, see $results/$name.log" >&2
}

for refinement in 1 2; do
  run "axisymmetric_r$refinement" prm/sphere_on_rigid_plane.prm \
    --set "Mesh/geo parameters=CentreZ: -8.005, Refinement: $refinement, PoleGrading: 10, CoreOffset: 0.3" \
    --set "Time integration/end time=0.095"
done
run quarter_n8 prm/sphere_on_rigid_plane_3d.prm
if [ "${FINE:-0}" = 1 ]; then
  run quarter_n12 prm/sphere_on_rigid_plane_3d.prm \
    --set "Mesh/geo parameters=R: 8, CentreZ: 8.005, N: 12, NR: 8, PoleGrading: 4"
fi

/usr/bin/python3 - "$results" <<'PY'
import csv, pathlib, re, sys
sys.path.insert(0, "bench")
from results_table import write_table
root = pathlib.Path(sys.argv[1])
def summary(name):
    path = root / name / "impact_summary.csv"
    if not path.exists():
        return None
    return {row["quantity"]: row for row in csv.DictReader(open(path))}
runs = ["axisymmetric_r1", "axisymmetric_r2", "quarter_n8", "quarter_n12"]
reference = summary("axisymmetric_r2")
rows = []
for name in runs:
    table = summary(name)
    if table is None:
        continue
    log = (root / f"{name}.log").read_text()
    dofs = re.search(r"(\d+) displacement DoFs", log).group(1)
    wall, memory = (root / f"{name}.time").read_text().split()
    row = {"run": name, "dofs": dofs, "wall_s": wall, "peak_memory_MiB": f"{int(memory) / 1024:.0f}"}
    for quantity in ("peak_force", "duration", "impulse"):
        computed = float(table[quantity]["computed"])
        row[quantity] = f"{computed:.6g}"
        row[f"{quantity}_vs_law"] = f"{float(table[quantity]['finite_sphere_difference']):+.3%}"
        if reference is not None:
            axisymmetric = float(reference[quantity]["computed"])
            row[f"{quantity}_vs_axisymmetric_r2"] = f"{computed / axisymmetric - 1:+.3%}"
    rows.append(row)
write_table(rows, root.parent / "sphere_3d.csv")
PY
