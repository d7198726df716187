#!/usr/bin/env bash
# Every contact-dynamics treatment (Contact/dynamics) on every benchmark problem with an exact or
# converged reference (issue 14), then the report: bench/results/schemes/report.md (tables of the
# metrics) and one PNG per problem (force, interface velocity and energy against the reference).
# Problems:
#   6.1 bar on a rigid wall, 6.2 identical bars, 6.3 dissimilar bars (the paper's prm files);
#   the stiff striker (6.2 with bar 1 at E = 1e4, trapezoidal rule) and its mirror, the soft
#   striker (bar 2 at E = 1e4); the Signorini bar (10 periods); the spheres (default prm, paper's
#   dt), the coarse spheres at dt = 0.02 and the dissimilar spheres.
# A run that fails is reported in its cells with its error line.
# Then the whole-kind sweep of issue 25, item 7 (bench/schemes_sweep.py: the stiff striker at
# impedance ratios 1e2 to 1e6 and dt 0.1 to 0.005, the coarse spheres at dt 0.03 to 0.0025, every
# shipped impact) for the schemes in SWEEP (default: the default, the previous one and mass
# redistribution on the trapezoidal rule; SWEEP= skips it): bench/results/schemes/sweep.md.
# Both parts: 17 minutes on 2 cores (2026-12-03).
#   bench/schemes.sh                       (every scheme)
#   SCHEMES="persistency none" RESULTS=/tmp/subset bench/schemes.sh   (a subset, elsewhere)
#   SCHEMES="taylor-papadopoulos@generalized-alpha:0.8" bench/schemes.sh   (on a dissipative
#     integrator: Time integration/integrator and spectral radius)
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=${RESULTS:-bench/results/schemes}
rm -rf "$results"
mkdir -p "$results"
read -r -a schemes <<<"${SCHEMES:-default none taylor-papadopoulos mass-redistribution contact-stabilized persistency velocity-update taylor-papadopoulos@generalized-alpha:0.8 mass-redistribution@generalized-alpha:0.8}"
trapezoidal=(--set "Time integration/beta=0.25")
coarse_spheres=(--set "Mesh/file=../meshes/two_spheres.geo"
  --set "Mesh/geo parameters=Refinement: 0, PoleGrading: 10, CoreOffset: 0.3"
  --set "Contact/discretization=node-to-node" --set "Newton/method=full")

run() # problem scheme prm arguments...
{
  local problem=$1 scheme=$2 prm=$3
  shift 3
  local output="$results/$problem/$scheme"
  # A scheme is a Contact/dynamics, optionally on a dissipative integrator: name@integrator:rho_inf.
  local integrator=() dynamics=(--set "Contact/dynamics=${scheme%%@*}")
  # default: what a file without these entries gets (the files name the paper's lines).
  if [[ $scheme == default ]]; then
    dynamics=(--set "Contact/dynamics=mass-redistribution" --set "Time integration/integrator=newmark"
      --set "Time integration/beta=" --set "Time integration/gamma=")
  fi
  if [[ $scheme == *@* ]]; then
    local member=${scheme#*@}
    integrator=(--set "Time integration/integrator=${member%%:*}"
      --set "Time integration/spectral radius=${member#*:}")
  fi
  mkdir -p "$output"
  /usr/bin/time -f "%e" -o "$output/wall_time" build/dyncontact "$prm" --quiet --output "$output" \
    --set "Output/vtu interval=0" "$@" "${dynamics[@]}" "${integrator[@]}" \
    >"$output/log" 2>&1 || echo "exit $?" >"$output/failed"
}

for scheme in "${schemes[@]}"; do
  run bar_rigid_wall "$scheme" prm/bar_rigid_wall.prm
  run bars_identical "$scheme" prm/bars_identical.prm
  run bars_dissimilar "$scheme" prm/bars_dissimilar.prm
  run stiff_striker "$scheme" prm/bars_identical.prm "${trapezoidal[@]}" \
    --set "Geometry/Bar 1/Young's modulus=1e4"
  run soft_striker "$scheme" prm/bars_identical.prm "${trapezoidal[@]}" \
    --set "Geometry/Bar 2/Young's modulus=1e4"
  run signorini_bar "$scheme" prm/signorini_bar.prm
  run spheres "$scheme" prm/spheres_rho0.001.prm --set "Time integration/end time=2.16"
  run spheres_dt0.02 "$scheme" prm/spheres_rho0.001.prm "${coarse_spheres[@]}" \
    --set "Time integration/time step=0.02" --set "Time integration/end time=2.16"
  run dissimilar_spheres "$scheme" prm/dissimilar_spheres.prm
done
/usr/bin/python3 bench/schemes_report.py "$results" "${schemes[@]}"
read -r -a sweep <<<"${SWEEP-default taylor-papadopoulos@generalized-alpha:0.8 mass-redistribution}"
if [ ${#sweep[@]} -gt 0 ]; then
  /usr/bin/python3 bench/schemes_sweep.py build/dyncontact "$results" "${sweep[@]}"
fi
