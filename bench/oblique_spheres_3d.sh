#!/usr/bin/env bash
# The oblique impact of two spheres in 3D (issue 28, C and D): prm/oblique_spheres_3d.prm (ball 2
# at speed 1 along -z onto ball 1 at rest, the line of centres 30 degrees from z; half balls on
# y = 0, non-matching meshes N 6 and 5, PoleGrading 10: 111,360 DoFs) beside the central impact on
# the same meshes (Angle 0) at the oblique one's normal approach speed cos 30. For each run, from
# its history.csv (the halves' columns; twice the force is the whole balls'): the largest rise
# and the final change of the algorithmic energy, the largest change of the momentum's x and z
# components (of m v / 2) and of the angular momentum about y (relative), the largest velocity
# and acceleration jumps, each ball's velocity change across the line of centres, and the peak
# force and contact duration (F^(2/3) extrapolated to zero at both ends, a parabola through the
# largest sample, as impact_summary.csv) against Hertz's two equal spheres at speed cos 30; wall
# time and peak memory from /usr/bin/time. Writes bench/results/oblique_spheres_3d.csv and prints
# it; about 15 minutes on 2 cores. COARSE=1: the ctest's coarse meshes (N 3/2, 12,756 DoFs).
# STEP=dt: both runs at the time step dt instead of the prm's 0.0025, into
# bench/results/oblique_spheres_3d_step<dt>(.csv) (STEP=0.00125: about 45 minutes).
#   bench/oblique_spheres_3d.sh     COARSE=1 bench/oblique_spheres_3d.sh     STEP=0.00125 bench/...
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/oblique_spheres_3d${STEP:+_step$STEP}
mkdir -p "$results"
step=()
[ -n "${STEP:-}" ] && step=(--set "Time integration/time step=$STEP")

meshes="N1: 6, NR1: 4, N2: 5, NR2: 4, PoleGrading: 10"
if [ "${COARSE:-0}" = 1 ]; then
  meshes="N1: 3, NR1: 2, N2: 2, NR2: 2, PoleGrading: 2"
fi

run() # name arguments...
{
  local name=$1
  shift
  rm -rf "${results:?}/$name"
  /usr/bin/time -f "%e %M" -o "$results/$name.time" build/dyncontact prm/oblique_spheres_3d.prm \
    --quiet --output "$results/$name" --set "Output/vtu interval=0" --set "Output/vtu times=" \
    "${step[@]}" "$@" >"$results/$name.log" 2>&1 || echo "$name failed, see $results/$name.log" >&2
}

run oblique --set "Mesh/geo parameters=Angle: 30, Gap: 0.01, $meshes"
run central --set "Mesh/geo parameters=Angle: 0, Gap: 0.01, $meshes" \
  --set "Bodies/Body 2/Initial velocity/Function expression=0; 0; -0.8660254037844387"

/usr/bin/python3 - "$results" <<'PY'
import csv, math, pathlib, re, sys
sys.path.insert(0, "bench")
from results_table import write_table
root = pathlib.Path(sys.argv[1])
# The prm's balls: R = 8, E = 5e3, nu = 0.3, rho = 0.001; Hertz for two equal spheres at the
# normal approach speed cos 30: E* = E / (2 (1 - nu^2)), R* = R / 2, m* = m / 2.
R, E, nu, rho = 8., 5e3, 0.3, 1e-3
m = rho * 4. / 3. * math.pi * R**3
speed = math.cos(math.radians(30.))
E_star, R_star, m_star = E / (2. * (1. - nu**2)), R / 2., m / 2.
approach = (15. * m_star * speed**2 / (16. * E_star * math.sqrt(R_star)))**0.4
hertz_peak = 4. / 3. * E_star * math.sqrt(R_star) * approach**1.5
hertz_duration = 2.9432 * approach / speed

def impact(times, force):
    inside = [k for k, f in enumerate(force) if f > 0.]
    a, b = inside[0], inside[-1]
    g = lambda k: force[k]**(2. / 3.)
    start = times[a] - g(a) * (times[a + 1] - times[a]) / (g(a + 1) - g(a))
    end = times[b] + g(b) * (times[b] - times[b - 1]) / (g(b - 1) - g(b))
    i = max(range(len(force)), key=lambda k: force[k])
    f0, f1, f2 = force[i - 1], force[i], force[i + 1]
    curvature = f0 - 2. * f1 + f2
    shift = 0.5 * (f0 - f2) / curvature if curvature != 0. else 0.
    return f1 - 0.25 * (f0 - f2) * shift, end - start

rows = []
for name, angle in (("oblique", 30.), ("central", 0.)):
    path = root / name / "history.csv"
    if not path.exists():
        continue
    history = list(csv.DictReader(open(path)))
    column = lambda key: [float(row[key]) for row in history]
    across = (math.cos(math.radians(angle)), 0., -math.sin(math.radians(angle)))
    energy = column("algorithmic_energy")
    scale = abs(column("momentum_z")[0])
    change = lambda key: max(abs(v - column(key)[0]) for v in column(key))
    log = (root / f"{name}.log").read_text()
    wall, memory = (root / f"{name}.time").read_text().split()
    peak, duration = impact(column("time"), [2. * f for f in column("contact_force")])
    row = {"run": name, "dofs": re.search(r"(\d+) displacement DoFs", log).group(1),
           "wall_s": wall, "peak_memory_MiB": f"{int(memory) / 1024:.0f}",
           "energy_largest_rise": f"{max(e / energy[0] - 1. for e in energy):.2e}",
           "energy_change_at_end": f"{energy[-1] / energy[0] - 1.:.2e}",
           "momentum_x_change": f"{change('momentum_x') / scale:.1e}",
           "momentum_z_change": f"{change('momentum_z') / scale:.1e}",
           "angular_momentum_y_change": f"{change('angular_momentum_y') / abs(column('angular_momentum_y')[0]):.1e}",
           "velocity_jump": f"{max(column('velocity_jump')):.1e}",
           "acceleration_jump": f"{max(column('acceleration_jump')):.1e}"}
    for ball in (1, 2):
        first, last = history[0], history[-1]
        velocity = lambda row: sum(float(row[f"momentum_{ball}_{c}"]) * t
                                   for c, t in zip("xyz", across)) / (m / 2.)
        row[f"ball_{ball}_across_change"] = f"{velocity(last) - velocity(first):+.2e}"
    row["peak_force_vs_hertz"] = f"{peak / hertz_peak - 1.:+.2%}"
    row["duration_vs_hertz"] = f"{duration / hertz_duration - 1.:+.2%}"
    rows.append(row)
write_table(rows, root.parent / f"{root.name}.csv")
PY
