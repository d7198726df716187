#!/usr/bin/env bash
# Non-matching meshes against Hertz (issue 12, acceptances C and D), small strain (linear elastic),
# the paper's modified Newmark, node-to-segment contact (the sphere on a block: mortar, its prm's):
#  C  identical spheres (prm/spheres_rho0.001.prm, R = 8, rho = 0.001): meshes/two_spheres.geo
#     (matching, node-to-node) against meshes/two_spheres_nonmatching.geo (body 2 with 4 more
#     divisions, node-to-segment), Refinement 0 and 1, dt = 0.0025;
#  D  dissimilar spheres (prm/dissimilar_spheres.prm, R1 = 8 and R2 = 4, different E and rho,
#     meshes/dissimilar_spheres.geo) on Refinement 0, 1 and 2, and the sphere on a thick block
#     (prm/sphere_on_block.prm) on Refinement 0 and 1, each at dt = 0.0025 and 0.00125.
# Each run's impact_summary.csv (measure_impact against the run's own Hertz reference, and the
# finite-sphere law where the run writes it) is collected into bench/results/non_matching_hertz.csv
# and printed as a markdown table. About 30 minutes on 2 cores (the Refinement 2 runs 15).
#   bench/non_matching_hertz.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/non_matching_hertz
mkdir -p "$results"
export results

run_case() # name prm refinement time-step extra-arguments...
{
  local name=$1 prm=$2 refinement=$3 dt=$4
  shift 4
  run_sphere_impact "$results/$name" "$prm" "$refinement" "linear elastic" \
    --set "Time integration/time step=$dt" "$@" || true # a failed run is reported in the table
}
export -f run_case

nonmatching="--set|Mesh/file=../meshes/two_spheres_nonmatching.geo|--set|Contact/discretization=node-to-segment"
printf '%s\n' \
  "D_dissimilar_r2_dt0.00125|prm/dissimilar_spheres.prm|2|0.00125" \
  "D_dissimilar_r2_dt0.0025|prm/dissimilar_spheres.prm|2|0.0025" \
  "C_matching_r1|prm/spheres_rho0.001.prm|1|0.0025" \
  "C_nonmatching_r1|prm/spheres_rho0.001.prm|1|0.0025|${nonmatching}" \
  "D_dissimilar_r1_dt0.00125|prm/dissimilar_spheres.prm|1|0.00125" \
  "D_dissimilar_r1_dt0.0025|prm/dissimilar_spheres.prm|1|0.0025" \
  "D_dissimilar_r0_dt0.00125|prm/dissimilar_spheres.prm|0|0.00125" \
  "D_dissimilar_r0_dt0.0025|prm/dissimilar_spheres.prm|0|0.0025" \
  "D_block_r1_dt0.00125|prm/sphere_on_block.prm|1|0.00125|--set|Mesh/geo parameters=Gap: 2, Refinement: 1, PoleGrading: 10, CoreOffset: 0.3" \
  "D_block_r1_dt0.0025|prm/sphere_on_block.prm|1|0.0025|--set|Mesh/geo parameters=Gap: 2, Refinement: 1, PoleGrading: 10, CoreOffset: 0.3" \
  "D_block_r0_dt0.00125|prm/sphere_on_block.prm|0|0.00125|--set|Mesh/geo parameters=Gap: 2, Refinement: 0, PoleGrading: 10, CoreOffset: 0.3" \
  "D_block_r0_dt0.0025|prm/sphere_on_block.prm|0|0.0025|--set|Mesh/geo parameters=Gap: 2, Refinement: 0, PoleGrading: 10, CoreOffset: 0.3" \
  "C_matching_r0|prm/spheres_rho0.001.prm|0|0.0025" \
  "C_nonmatching_r0|prm/spheres_rho0.001.prm|0|0.0025|${nonmatching}" |
  run_two_at_a_time run_case

/usr/bin/python3 - "$results" <<'PY'
import csv, pathlib, re, sys
root = pathlib.Path(sys.argv[1])
names = ["C_matching_r0", "C_nonmatching_r0", "C_matching_r1", "C_nonmatching_r1",
         "D_dissimilar_r0_dt0.0025", "D_dissimilar_r0_dt0.00125",
         "D_dissimilar_r1_dt0.0025", "D_dissimilar_r1_dt0.00125",
         "D_dissimilar_r2_dt0.0025", "D_dissimilar_r2_dt0.00125",
         "D_block_r0_dt0.0025", "D_block_r0_dt0.00125", "D_block_r1_dt0.0025", "D_block_r1_dt0.00125"]
quantities = ["peak_force", "duration", "impulse"]
table, out = [], []
for name in names:
    summary = root / name / "impact_summary.csv"
    log = root / f"{name}.log"
    text = log.read_text() if log.exists() else ""
    wall = re.search(r"wall time ([0-9.e+-]+) s", text)
    cuts = re.search(r"\((\d+) taken, (\d+) step cuts", text)
    row = {"case": name, "completed": "done," in text,
           "wall_s": wall.group(1) if wall else "", "cuts": cuts.group(2) if cuts else ""}
    if summary.exists():
        for r in csv.DictReader(open(summary)):
            if r["quantity"] in quantities:
                row[r["quantity"]] = float(r["computed"])
                row[r["quantity"] + "_vs_hertz"] = float(r["relative_difference"])
                if r.get("finite_sphere"):
                    row[r["quantity"] + "_vs_finite_sphere"] = float(r["finite_sphere_difference"])
    table.append(row)
keys = sorted({k for row in table for k in row}, key=lambda k: (k != "case", k))
with open(root.parent / "non_matching_hertz.csv", "w", newline="") as handle:
    writer = csv.DictWriter(handle, fieldnames=keys)
    writer.writeheader()
    writer.writerows(table)
print("| case | peak | vs Hertz | vs law | duration | vs Hertz | vs law | impulse | vs Hertz | cuts | wall [s] |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for row in table:
    cells = [row["case"]]
    for q in quantities:
        cells += [f"{row[q]:.5g}" if q in row else "failed", f"{100 * row[q + '_vs_hertz']:+.2f} %" if q in row else ""]
        if q != "impulse":
            law = row.get(q + "_vs_finite_sphere")
            cells.append(f"{100 * law:+.2f} %" if law is not None else "")
    cells += [row["cuts"], row["wall_s"]]
    print("| " + " | ".join(cells) + " |")
for r in ("r0", "r1"):
    a, b = (next((x for x in table if x["case"] == f"C_{kind}_{r}"), {}) for kind in ("matching", "nonmatching"))
    if all(q in a and q in b for q in quantities):
        print(f"C {r}: non-matching vs matching: " + ", ".join(
            f"{q} {100 * (b[q] - a[q]) / a[q]:+.3f} %" for q in quantities))
PY
