#!/usr/bin/env bash
# The CalculiX peer of issue 13: one run of CalculiX 2.20 on the sphere impact (bench/calculix/
# README.md). Makes the deck (make_deck.py: gmsh mesh of meshes/sphere_graded.geo, CAX8, rigid
# plate, node-to-surface penalty 50 E, *DYNAMIC DIRECT), runs ccx on 2 threads under
# /usr/bin/time -v (bash's time if that is missing), and analyses the contact force history
# (analyze.py). Needs ccx and gmsh: installs calculix-ccx and gmsh with apt-get when missing
# (as root), and is skipped with a note (status 0) when it cannot.
#
# Usage: bench/calculix/run.sh [--label NAME] [make_deck.py options]
#   bench/calculix/run.sh                                   # rho 0.001, linear, pole size 0.05
#   bench/calculix/run.sh --label p0.1 --pole-size 0.1      # a coarser mesh
#   bench/calculix/run.sh --nlgeom                          # finite strain (St Venant-Kirchhoff)
#   bench/calculix/run.sh --rho 1                           # dt 0.05, end time 4
#   bench/calculix/run.sh --start-time 1.95 ...             # skip most of the free flight
#   bench/calculix/run.sh --geometry 3d --label quarter_n8  # the 3D quarter sphere (make_deck_3d.py)
# Writes bench/results/calculix/LABEL/ (deck, mesh, ccx output, history.csv, history.png,
# summary.csv) and appends the summary row to bench/results/calculix.csv; prints it as one line.
# With --geometry 3d: bench/results/calculix_3d/LABEL/ and bench/results/calculix_3d.csv.
# Environment: CCX_THREADS (2), RESULTS (bench/results/calculix or bench/results/calculix_3d).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
threads=${CCX_THREADS:-2}
python=/usr/bin/python3

label=""
geometry=axisymmetric
args=()
while (($#)); do
  case $1 in
    --label) label=$2; shift 2 ;;
    --geometry) geometry=$2; args+=("$1" "$2"); shift 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
set -- "${args[@]}"
if [[ -z $label ]]; then
  label=$(printf '%s' "${*:-default}" | tr -s ' =' '__' | tr -cd 'A-Za-z0-9._-' | sed 's/^-*//')
  label=${label:-default}
fi
if [[ $geometry == 3d ]]; then
  results=${RESULTS:-$root/bench/results/calculix_3d}
  summary=$results/../calculix_3d.csv
else
  results=${RESULTS:-$root/bench/results/calculix}
  summary=$results/../calculix.csv
fi

skip() {
  echo "calculix: SKIPPED: $*" >&2
  echo "calculix,skipped,\"$*\""
  exit 0
}

# Installs a Debian package when its command is missing; false when that is not possible.
ensure() # command package
{
  command -v "$1" >/dev/null 2>&1 && return 0
  [[ $(id -u) == 0 ]] && command -v apt-get >/dev/null 2>&1 || return 1
  echo "calculix: installing $2" >&2
  if ! DEBIAN_FRONTEND=noninteractive apt-get install -y "$2" >/dev/null 2>&1; then
    apt-get update >/dev/null 2>&1 || true
    DEBIAN_FRONTEND=noninteractive apt-get install -y "$2" >/dev/null 2>&1 || return 1
  fi
  command -v "$1" >/dev/null 2>&1
}

[[ -x $python ]] || skip "no $python"
ensure ccx calculix-ccx || skip "no ccx and calculix-ccx cannot be installed"
ensure gmsh gmsh || skip "no gmsh and it cannot be installed"

dir=$results/$label
rm -rf "$dir"
mkdir -p "$dir"
$python "$here/make_deck.py" --out "$dir" "$@" >"$dir/make_deck.log"

cd "$dir"
export OMP_NUM_THREADS=$threads CCX_NPROC_EQUATION_SOLVER=$threads
status=0
if [[ -x /usr/bin/time ]]; then
  /usr/bin/time -v -o time.log ccx sphere >ccx.log 2>&1 || status=$?
else
  { time -p ccx sphere >ccx.log 2>&1; } 2>time.log || status=$?
fi
if ((status != 0)) || grep -q '\*ERROR' ccx.log; then
  echo "calculix: ccx failed (status $status), see $dir/ccx.log" >&2
  grep -m3 -A2 '\*ERROR' ccx.log >&2 || true
  exit 1
fi

line=$($python "$here/analyze.py" "$dir" --label "$label")
if [[ ! -s $summary ]]; then
  head -1 "$dir/summary.csv" >"$summary"
fi
tail -1 "$dir/summary.csv" >>"$summary"
echo "$line"
