#!/usr/bin/env bash
# The oblique impact of a sphere on a rigid plane with Coulomb friction over the incidences 5 to
# 85 degrees (issue 29, C): prm/oblique_sphere_on_plane_3d.prm (Chung & Ooi 2011, Test 4: Al2O3,
# R = 2.5 mm, V = 3.9 m/s, mu = 0.092) at each angle, to 1.15 times the Hertz contact duration at
# its normal speed after the first touch. oblique_sphere_table.py writes
# bench/results/oblique_sphere_on_plane.csv (per angle: e, the impulse ratio, the rebound
# tangential velocity, spin and angle against the rigid-body gross-slip line) and
# oblique_sphere_on_plane.png. About 3 minutes on 2 cores (the prm's coarse half ball).
#   bench/oblique_sphere_on_plane.sh        ANGLES="30 35" bench/oblique_sphere_on_plane.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/oblique_sphere_on_plane
mkdir -p "$results"
angles=${ANGLES:-"5 10 15 20 25 30 35 40 45 50 55 60 65 70 75 80 85"}
for angle in $angles; do
  # Free flight over the gap 0.0011, then 1.15 Hertz durations (7.8e-3 at 45 degrees, as v_n^-1/5).
  end=$(/usr/bin/python3 -c "import math; c = math.cos(math.radians($angle)); print(0.0011 / (3.9 * c) + 1.15 * 7.8e-3 * (math.cos(math.pi / 4) / c) ** 0.2)")
  rm -rf "${results:?}/theta$angle"
  build/dyncontact prm/oblique_sphere_on_plane_3d.prm --quiet --output "$results/theta$angle" \
    --set "Bodies/Body 1/Initial velocity/Function constants=V=3.9, theta=$angle" \
    --set "Time integration/end time=$end" --set "Output/vtu times=" \
    >"$results/theta$angle.log" 2>&1 || echo "theta $angle failed, see $results/theta$angle.log" >&2
done
/usr/bin/python3 bench/oblique_sphere_table.py "$results" 0.092 3.9 2.5 $angles
