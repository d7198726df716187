#!/usr/bin/env bash
# The refactoring check of issue 27 (moves 1-4 change no arithmetic): runs the paper's histories
# and the multi-body cases with a dyncontact binary into a directory, or compares two such
# directories file by file (history.csv, impact_summary.csv, exact_summary.csv: byte-identical).
#   bench/history_identity.sh run BINARY DIR     (about 4 minutes on 2 cores)
#   bench/history_identity.sh compare DIR1 DIR2  (exit 1 and the differing files if any differ)
# Typical use: copy build/dyncontact aside before a move, run both binaries, compare.
# Cases: 6.1-6.3 as shipped (the paper's modified Newmark, beta = 0.001) and in the classical
# scheme; the spheres (prm/spheres_rho0.001.prm: graded non-matching meshes, node-to-segment) in
# both schemes; the dissimilar spheres; the three spheres (two pairs, the default scheme); the
# striker and the coarse spheres on the default and on generalized-alpha (every integrator path).
set -euo pipefail
cd "$(dirname "$0")/.."

cases() # name prm arguments... (one per line, '|'-separated)
{
  cat <<'EOF'
bar_rigid_wall|prm/bar_rigid_wall.prm
bars_identical|prm/bars_identical.prm
bars_dissimilar|prm/bars_dissimilar.prm
bar_rigid_wall_classical|prm/bar_rigid_wall.prm|--set|Contact/dynamics=none|--set|Time integration/beta=0.25
bars_identical_classical|prm/bars_identical.prm|--set|Contact/dynamics=none|--set|Time integration/beta=0.25
spheres_modified|prm/spheres_rho0.001.prm
spheres_classical|prm/spheres_rho0.001.prm|--set|Contact/dynamics=none
dissimilar_spheres|prm/dissimilar_spheres.prm
three_spheres|prm/three_spheres.prm
striker_default|prm/bars_identical.prm|--set|Time integration/beta=|--set|Time integration/gamma=|--set|Contact/dynamics=mass-redistribution|--set|Geometry/Bar 1/Young's modulus=1e4
striker_generalized_alpha|prm/bars_identical.prm|--set|Time integration/beta=0.25|--set|Time integration/integrator=generalized-alpha|--set|Geometry/Bar 1/Young's modulus=1e4
coarse_spheres_default|prm/spheres_rho0.001.prm|--set|Mesh/file=../meshes/two_spheres.geo|--set|Mesh/geo parameters=Refinement: 0, PoleGrading: 10, CoreOffset: 0.3|--set|Contact/discretization=node-to-node|--set|Time integration/time step=0.02|--set|Time integration/end time=2.19|--set|Time integration/beta=|--set|Time integration/gamma=|--set|Contact/dynamics=mass-redistribution
coarse_spheres_hht|prm/spheres_rho0.001.prm|--set|Mesh/file=../meshes/two_spheres.geo|--set|Mesh/geo parameters=Refinement: 0, PoleGrading: 10, CoreOffset: 0.3|--set|Contact/discretization=node-to-node|--set|Time integration/time step=0.02|--set|Time integration/end time=2.19|--set|Time integration/integrator=hht
EOF
}

case ${1:-} in
  run)
    binary=$(realpath "$2") directory=$3
    mkdir -p "$directory"
    while IFS='|' read -r -a line; do
      name=${line[0]} arguments=("${line[@]:1}")
      "$binary" "${arguments[@]}" --quiet --output "$directory/$name" --set "Output/vtu interval=0" \
        >"$directory/$name.log" 2>&1 || echo "exit $?" >>"$directory/$name.log"
    done < <(cases)
    ;;
  compare)
    status=0
    while IFS='|' read -r -a line; do
      for file in history.csv impact_summary.csv exact_summary.csv; do
        a="$2/${line[0]}/$file" b="$3/${line[0]}/$file"
        if [ -e "$a" ] || [ -e "$b" ]; then
          if ! cmp -s "$a" "$b"; then
            echo "differs: ${line[0]}/$file"
            status=1
          fi
        fi
      done
    done < <(cases)
    [ $status = 0 ] && echo "all $(cases | wc -l) cases byte-identical"
    exit $status
    ;;
  *)
    echo "usage: $0 run BINARY DIR | compare DIR1 DIR2" >&2
    exit 2
    ;;
esac
