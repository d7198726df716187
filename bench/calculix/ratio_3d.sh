#!/usr/bin/env bash
# Issue 28, acceptance F: dyncontact against its CalculiX 3D peer at equal accuracy, in one run.
# Runs, one after the other, each under /usr/bin/time -f "%e %M" (wall seconds, peak RSS kB):
#   1. build/dyncontact prm/sphere_on_rigid_plane_3d.prm (the shipped quarter sphere, N 8, NR 6,
#      PoleGrading 10), no VTU;
#   2. ccx 2.20 on the equal-accuracy deck of make_deck_3d.py (bench/calculix/README.md, "The 3D
#      deck"), OMP_NUM_THREADS = CCX_NPROC_EQUATION_SOLVER = THREADS;
# then prints both wall times, peak memories, the accuracy figures (whole sphere: peak, duration,
# impulse against the finite-sphere law) and the ratio ccx wall / dyncontact wall (goal >= 20).
# It builds nothing: build/dyncontact must exist (a Release build). Run nothing else meanwhile.
#
# Usage: bench/calculix/ratio_3d.sh
# Environment (for tests on tiny meshes; the defaults are the measurement):
#   CCX_ARGS       make_deck_3d.py options of the ccx deck (default "--n 5 --nr 4
#                  --pole-grading 10": the equal-accuracy mesh, C3D20R, node-to-surface, 200 E)
#   DYNCONTACT_SET one extra --set for dyncontact, e.g. "Mesh/geo parameters=R: 8, CentreZ:
#                  8.005, N: 2, NR: 2, PoleGrading: 4" (default: none)
#   THREADS        ccx's threads (2)
#   OUT            output directory (bench/results/ratio_3d)
# Writes OUT/dyncontact/ (dyncontact's output), OUT/dyncontact.time, OUT/ccx/ (deck, ccx output,
# history.csv, summary.csv), OUT/ccx.time and OUT/ratio.txt (what it prints).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
cd "$root"
out=${OUT:-$root/bench/results/ratio_3d}
threads=${THREADS:-2}
ccx_args=${CCX_ARGS:---n 5 --nr 4 --pole-grading 10}
python=/usr/bin/python3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

[[ -x build/dyncontact ]] || { echo "ratio_3d.sh: no build/dyncontact (build it first)" >&2; exit 1; }
command -v ccx >/dev/null || { echo "ratio_3d.sh: no ccx (apt-get install calculix-ccx)" >&2; exit 1; }
command -v gmsh >/dev/null || { echo "ratio_3d.sh: no gmsh (apt-get install gmsh)" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"

# 1. dyncontact
extra=()
[[ -n ${DYNCONTACT_SET:-} ]] && extra=(--set "$DYNCONTACT_SET")
/usr/bin/time -f "%e %M" -o "$out/dyncontact.time" build/dyncontact \
  prm/sphere_on_rigid_plane_3d.prm --quiet --output "$out/dyncontact" \
  --set "Output/vtu interval=0" --set "Output/vtu times=" "${extra[@]}" \
  >"$out/dyncontact.log" 2>&1 || { echo "ratio_3d.sh: dyncontact failed, see $out/dyncontact.log" >&2; exit 1; }

# 2. ccx (the deck is made before the clock starts; gmsh is not timed)
mkdir -p "$out/ccx"
# shellcheck disable=SC2086
if ! $python "$here/make_deck_3d.py" --out "$out/ccx" $ccx_args >"$out/ccx/make_deck.log" 2>&1; then
  cat "$out/ccx/make_deck.log" >&2
  exit 1
fi
(
  cd "$out/ccx"
  export OMP_NUM_THREADS=$threads CCX_NPROC_EQUATION_SOLVER=$threads
  /usr/bin/time -f "%e %M" -o ../ccx.time ccx sphere >ccx.log 2>&1
) || { echo "ratio_3d.sh: ccx failed, see $out/ccx/ccx.log" >&2; exit 1; }
if grep -q '\*ERROR' "$out/ccx/ccx.log"; then
  echo "ratio_3d.sh: ccx reported an error, see $out/ccx/ccx.log" >&2
  exit 1
fi
cp "$out/ccx.time" "$out/ccx/time.log"
$python "$here/analyze.py" "$out/ccx" --label ratio_3d >/dev/null

# 3. the figures
$python - "$out" "$ccx_args" "$threads" <<'PY' | tee "$out/ratio.txt"
import csv, json, pathlib, re, sys
out, ccx_args, threads = pathlib.Path(sys.argv[1]), sys.argv[2], sys.argv[3]
def timing(path):
    wall, kb = path.read_text().split()[-2:]
    return float(wall), int(kb) / 1024.0
dc_wall, dc_mem = timing(out / "dyncontact.time")
cx_wall, cx_mem = timing(out / "ccx.time")
summary = {r["quantity"]: r for r in csv.DictReader(open(out / "dyncontact" / "impact_summary.csv"))}
m = re.search(r"(\d+) displacement DoFs", (out / "dyncontact.log").read_text())
dc_dofs = m.group(1) if m else "?"
law = {q: float(summary[q]["finite_sphere"]) for q in ("peak_force", "duration", "impulse")}
dc = {q: float(summary[q]["computed"]) for q in ("peak_force", "duration", "impulse")}
cx_row = next(csv.DictReader(open(out / "ccx" / "summary.csv")))
cx = {"peak_force": float(cx_row["peak"]), "duration": float(cx_row["duration"]),
      "impulse": float(cx_row["impulse"])}
deck = json.load(open(out / "ccx" / "deck.json"))
for q, v in deck["law"].items():  # the deck's law constants against dyncontact's own law
    key = {"peak": "peak_force"}.get(q, q)
    if abs(v / law[key] - 1) > 1e-6:
        print(f"WARNING: make_deck_3d.py's law {q} {v:.9g} differs from dyncontact's {law[key]:.9g}")
print("sphere on a rigid plane, 3D quarter (issue 28, F); whole-sphere figures vs the "
      "finite-sphere law")
print(f"law: peak {law['peak_force']:.6g}, duration {law['duration']:.6g}, impulse "
      f"{law['impulse']:.6g}")
print("DoFs: dyncontact's displacement DoFs; ccx's number of equations (free DoFs)")
print(f"{'run':<12} {'DoFs':>8} {'wall [s]':>10} {'peak RSS [MiB]':>15} {'peak':>9} {'vs law':>8} "
      f"{'duration':>10} {'vs law':>8} {'impulse':>9} {'vs law':>8}")
def line(name, dofs, wall, mem, r):
    cells = []
    for q in ("peak_force", "duration", "impulse"):
        cells += [f"{r[q]:.6g}", f"{100 * (r[q] / law[q] - 1):+.3f}%"]
    print(f"{name:<12} {dofs:>8} {wall:>10.1f} {mem:>15.0f} {cells[0]:>9} {cells[1]:>8} "
          f"{cells[2]:>10} {cells[3]:>8} {cells[4]:>9} {cells[5]:>8}")
line("dyncontact", dc_dofs, dc_wall, dc_mem, dc)
line("ccx", cx_row["equations"], cx_wall, cx_mem, cx)
print(f"ccx deck: make_deck_3d.py {ccx_args}; {deck['element']}, {deck['nodes']} nodes, "
      f"{cx_row['increments']} increments, {cx_row['iterations']} iterations, {threads} threads")
print(f"ratio ccx / dyncontact wall time: {cx_wall / dc_wall:.2f} (goal >= 20)")
PY
