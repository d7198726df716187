#!/usr/bin/env bash
# The Hertz limit (issue 12, acceptance E): one sphere on the rigid plane z = 0
# (prm/sphere_on_rigid_plane.prm, the lower half of two identical spheres striking each other),
# R = 8, v = 1, E = 5e3, nu = 0.3, small strain (linear elastic), modified scheme, Lagrange
# multipliers, at the densities rho = 1e-2, 1e-3, 1e-5, 1e-6, 1e-7: as rho v^2 / E falls, the
# force must approach Hertz's, and at every density follow the finite-sphere law.
#
# Setup per density, from the identical-sphere Hertz values (R* = R/2, E* = E / (2 (1 - nu^2)),
# m* = m/2, m = rho 4/3 pi R^3, relative speed 2; delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5),
# contact radius a_max = sqrt(R* delta_max), duration t_c = 2.9432751843 delta_max / v): the mesh
# meshes/sphere_graded.geo with PoleSize = a_max / 8 (8 Q2 cells across the contact radius),
# ZoneRadius = 2 a_max, FarSize 0.8; dt = t_c / 33; the sphere's pole 3 dt below the plane
# (CentreZ = -(R + 3 dt v)), so it touches at t = 3 dt; end time 3 dt + 1.3 t_c (about 46 steps).
# Level 1 halves PoleSize and dt (same ZoneRadius): the resolution check.
#
# Metrics of each run, from history.csv (m = momentum_1 at t = 0 over v):
#   w(t)        the approach of the sphere's centre of mass toward the plane since first touch,
#               the trapezoid rule of v_cm = momentum_1 / m over the rows, minus the initial gap;
#               the two-sphere approach is delta = 2 w
#   F/F_Hertz   the mean over the samples with F > 0.2 F_max (the run's largest sample) of
#               F / F_Hertz(delta), F_Hertz = 4/3 E* sqrt(R*) delta^(3/2)
#   F/F_law     the same mean of F / F_law(w), the finite-sphere law inverted numerically:
#               w(F) = (F/K1)^(2/3) + C(a) F / (E R), K1 = 4/3 E1* sqrt(R), E1* = E / (1 - nu^2),
#               a = (3 F R / (4 E1*))^(1/3), C(a) = -0.49 + k ln(R/a), k = (1+nu)(1-2nu)^2/(2 pi)
#               (include/dyncontact/reference/finite_sphere_impact.h)
#   peak        the largest force refined by the parabola through the largest sample and its
#               neighbours; duration from F^(2/3) extrapolated linearly to zero through the first
#               (last) two positive samples, clamped to one step (as measure_impact() does);
#               both relative to Hertz and to the impact under the finite-sphere law (peak from
#               W(F_max) = m v^2 / 2, duration by quadrature of dt = dw / |w'|)
# Also the material shifts at rho = 1e-3, same mesh and dt: the peak force of neo-Hookean and of
# St. Venant-Kirchhoff relative to linear elastic.
#
# "steps" counts the rows after t = 0: a step the guards cut (the energy guard at the release)
# adds a row, and "cuts" counts those.
#
# Writes bench/results/hertz_limit.csv (the runs of this invocation only; the runs themselves in
# bench/results/hertz_limit/) and prints a markdown table; two runs at a time on one rank each,
# about 7 minutes on 2 cores (levels 0 and 1: 14 runs; a level-1 run takes 1-3 min). Extra
# arguments go to every run. DENSITIES, LEVELS and MATERIAL_LEVELS choose other sets of runs:
#   bench/hertz_limit.sh
#   LEVELS=0 MATERIAL_LEVELS=0 bench/hertz_limit.sh        # the base level only, ~3 min
#   DENSITIES=1e-3 LEVELS=2 MATERIAL_LEVELS=2 bench/hertz_limit.sh   # level 2 at rho = 1e-3:
#     6264 cells, 175 steps, 17-26 min per run, ~36 min for the three (measured: mean F/F_Hertz
#     1.04565, F/F_law 0.99965; peak shifts neo-Hookean -0.296 %, St. Venant-Kirchhoff -1.515 %)
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/hertz_limit
mkdir -p "$results"
export results

# One line per run: label|density|material|level|pole size|zone radius|dt|centre z|end time.
# The longest runs (finest level, lowest density: the most cells and steps) first.
plan=$(/usr/bin/python3 - "${DENSITIES:-1e-2 1e-3 1e-5 1e-6 1e-7}" "${LEVELS:-0 1}" \
  "${MATERIAL_LEVELS:-0 1}" <<'PY'
import math, sys
E, NU, R, V = 5e3, 0.3, 8.0, 1.0
densities = [f"{float(rho):g}" for rho in sys.argv[1].split()]
levels = [int(level) for level in sys.argv[2].split()]
material_levels = [int(level) for level in sys.argv[3].split()]
cases = [(rho, "linear elastic", level) for rho in densities for level in levels]
cases += [("0.001", material, level) for material in ("neo-hookean", "st venant-kirchhoff")
          for level in material_levels]
if material_levels:  # the linear reference of the material shifts
    cases += [("0.001", "linear elastic", level) for level in material_levels
              if ("0.001", "linear elastic", level) not in cases]
lines = []
for rho, material, level in cases:
    mass = float(rho) * 4 / 3 * math.pi * R**3
    m_star, e_star, r_star, v_rel = mass / 2, E / (2 * (1 - NU**2)), R / 2, 2 * V
    d_max = (15 * m_star * v_rel**2 / (16 * e_star * math.sqrt(r_star))) ** 0.4
    a_max = math.sqrt(r_star * d_max)
    duration = 2.9432751843247047 * d_max / v_rel
    pole_size = a_max / 8 / 2**level
    zone_radius = 2 * a_max
    dt = duration / 33 / 2**level
    centre_z = -(R + 3 * dt * V)
    end_time = 3 * dt + 1.3 * duration
    label = f"rho{rho}_L{level}_{material.replace(' ', '_')}"
    lines.append((-level, float(rho), label, f"{label}|{rho}|{material}|{level}|{pole_size:.6g}|"
                  f"{zone_radius:.6g}|{dt!r}|{centre_z!r}|{end_time!r}"))
for *_, line in sorted(lines):
    print(line)
PY
)
n_runs=$(wc -l <<<"$plan")
labels=$(cut -d'|' -f1 <<<"$plan")
for label in $labels; do rm -rf "${results:?}/$label" "$results/$label.log"; done
export n_runs labels

run_case() # label density material level pole_size zone_radius dt centre_z end_time extra...
{
  local label=$1 density=$2 material=$3 level=$4 pole_size=$5 zone_radius=$6 dt=$7
  local centre_z=$8 end_time=$9
  shift 9
  local output="$results/$label" start seconds
  local mesh="CentreZ: $centre_z, PoleSize: $pole_size, ZoneRadius: $zone_radius, FarSize: 0.8"
  rm -rf "$output" "$output.log"
  echo "[hertz_limit] start  $label: PoleSize $pole_size, ZoneRadius $zone_radius, dt $dt"
  start=$(date +%s.%N)
  if ! build/dyncontact prm/sphere_on_rigid_plane.prm --output "$output" \
    --set "Bodies/Body 1/density=$density" --set "Bodies/Body 1/material=$material" \
    --set "Mesh/file=../meshes/sphere_graded.geo" \
    --set "Mesh/geo parameters=$mesh" \
    --set "Time integration/time step=$dt" --set "Time integration/end time=$end_time" \
    --set "Output/vtu interval=0" --set "Output/profile times=" "$@" >"$output.log" 2>&1; then
    echo "[hertz_limit] FAILED $label, see $output.log" >&2
    return 1
  fi
  seconds=$(seconds_since "$start")
  printf '%s|%s|%s|%s|%s|%s|%s|%s|%s\n' "$label" "$density" "$material" "$level" "$pole_size" \
    "$zone_radius" "$dt" "$centre_z" "$seconds" >"$output/case"
  printf '[hertz_limit] done   %s in %.1f s (%d of %d runs finished)\n' "$label" "$seconds" \
    "$(for l in $labels; do [ -f "$results/$l/case" ] && echo; done | wc -l)" "$n_runs"
}
export -f run_case

start_all=$(date +%s)
all_succeeded=true
run_two_at_a_time run_case "$@" <<<"$plan" || all_succeeded=false
echo "[hertz_limit] $n_runs runs in $(($(date +%s) - start_all)) s"

table=bench/results/hertz_limit.csv
/usr/bin/python3 - "$results" "$table" "$labels" <<'PY'
import csv, math, os, re, sys
sys.path.insert(0, "bench")
import impact_measures

E, NU, R, V = 5e3, 0.3, 8.0, 1.0
E1 = E / (1 - NU**2)                 # E1* of one sphere on the rigid plane
K1 = 4 / 3 * E1 * math.sqrt(R)       # = 4/3 E* sqrt(R*) 2^(3/2): F_Hertz(2 w) = K1 w^(3/2)
C0, K_LOG = -0.49, (1 + NU) * (1 - 2 * NU) ** 2 / (2 * math.pi)


def law_approach(force):
    """w(F) of the finite-sphere law."""
    if force <= 0:
        return 0.0
    a = (3 * force * R / (4 * E1)) ** (1 / 3)
    return (force / K1) ** (2 / 3) + (C0 + K_LOG * math.log(R / a)) * force / (E * R)


def law_force(approach):
    """F_law(w): w(F) inverted by bisection (w is increasing over the range used)."""
    if approach <= 0:
        return 0.0
    low, high = 0.0, K1 * approach**1.5
    while law_approach(high) < approach:
        high *= 2
    for _ in range(200):
        middle = 0.5 * (low + high)
        low, high = (middle, high) if law_approach(middle) < approach else (low, middle)
    return 0.5 * (low + high)


def law_work(force):
    """W(F) = integral of f w'(f) df, closed form (finite_sphere_impact.h, one sphere)."""
    if force <= 0:
        return 0.0
    a = (3 * force * R / (4 * E1)) ** (1 / 3)
    c, b = (C0 + K_LOG * math.log(R / a)) / (E * R), K_LOG / (3 * E * R)
    return 0.4 * force * (force / K1) ** (2 / 3) + force**2 / 2 * (c - b / 2)


def law_compliance(force):
    """w'(F)."""
    a = (3 * force * R / (4 * E1)) ** (1 / 3)
    c, b = (C0 + K_LOG * math.log(R / a)) / (E * R), K_LOG / (3 * E * R)
    return (2 / 3) * (force / K1) ** (2 / 3) / force + c - b


def law_impact(mass):
    """Peak force and duration of the impact of the sphere (mass m, speed V) under the law."""
    energy = mass * V**2 / 2
    low, high = 0.0, 1.0
    while law_work(high) < energy:
        high *= 2
    for _ in range(200):
        middle = 0.5 * (low + high)
        low, high = (middle, high) if law_work(middle) < energy else (low, middle)
    f_max = 0.5 * (low + high)
    rate = lambda force: math.sqrt(max(2 * (energy - law_work(force)) / mass, 0.0))
    # t = integral dF w'(F) / |w'|, on [0, F_max / 2] with F = F_max p^(3/2) and on
    # [F_max / 2, F_max] with F = F_max (1 - q^2): both integrands stay bounded; midpoint rule.
    n, half_time = 4000, 0.0
    p_end, q_end = 0.5 ** (2 / 3), 0.5**0.5
    for i in range(n):
        p = (i + 0.5) * p_end / n
        force = f_max * p**1.5
        half_time += law_compliance(force) * f_max * 1.5 * p**0.5 / rate(force) * p_end / n
        q = (i + 0.5) * q_end / n
        force = f_max * (1 - q * q)
        half_time += law_compliance(force) * f_max * 2 * q / rate(force) * q_end / n
    return f_max, 2 * half_time


def measures(times, forces):
    """Peak (parabola) and duration (F^(2/3) extrapolation), as measure_impact() does."""
    peak, _, start, stop = impact_measures.measures(times, forces)
    return peak, stop - start


rows = []
for directory in sys.argv[3].split():
    path = os.path.join(sys.argv[1], directory)
    if not os.path.isfile(os.path.join(path, "case")):
        continue  # a log file, or a failed or unfinished run
    label, rho, material, level, pole_size, zone_radius, dt, centre_z, seconds = \
        open(os.path.join(path, "case")).read().strip().split("|")
    rho, dt, centre_z = float(rho), float(dt), float(centre_z)
    log = open(path + ".log").read()
    cells = int(re.search(r"(\d+) cells", log).group(1))
    cuts = int(re.search(r"(\d+) step cuts", log).group(1))
    history = list(csv.DictReader(open(os.path.join(path, "history.csv"))))
    t = [float(r["time"]) for r in history]
    force = [float(r["contact_force"]) for r in history]
    momentum = [float(r["momentum_1"]) for r in history]
    mass = momentum[0] / V
    gap = -(centre_z + R)
    w, travel = [], 0.0
    for i in range(len(t)):
        if i:
            travel += 0.5 * (t[i] - t[i - 1]) * (momentum[i] + momentum[i - 1]) / mass
        w.append(travel - gap)
    f_max_sample = max(force)
    to_hertz, to_law = [], []
    for f, approach in zip(force, w):
        if f > 0.2 * f_max_sample:
            to_hertz.append(f / (K1 * approach**1.5))
            to_law.append(f / law_force(approach))
    # Hertz of the mirrored pair = the sphere on the rigid plane (R* = R, E* = E1*, m* = m),
    # with m = rho 4/3 pi R^3.
    m_star, e_star, r_star, v_rel = rho * 4 / 3 * math.pi * R**3 / 2, E / (2 * (1 - NU**2)), \
        R / 2, 2 * V
    d_max = (15 * m_star * v_rel**2 / (16 * e_star * math.sqrt(r_star))) ** 0.4
    hertz_peak = 4 / 3 * e_star * math.sqrt(r_star) * d_max**1.5
    hertz_duration = 2.9432751843247047 * d_max / v_rel
    law_peak, law_duration = law_impact(2 * m_star)
    peak, duration = measures(t, force)
    rows.append(dict(
        density=f"{rho:g}", material=material, level=int(level), pole_size=float(pole_size),
        zone_radius=float(zone_radius), cells=cells, time_step=f"{dt:.6g}", steps=len(t) - 1,
        step_cuts=cuts,
        a_max=f"{math.sqrt(r_star * d_max):.5g}",
        peak_force=f"{peak:.6g}", peak_hertz=f"{hertz_peak:.6g}",
        peak_vs_hertz=f"{peak / hertz_peak - 1:+.4%}", peak_vs_law=f"{peak / law_peak - 1:+.4%}",
        duration=f"{duration:.6g}", duration_hertz=f"{hertz_duration:.6g}",
        duration_vs_hertz=f"{duration / hertz_duration - 1:+.4%}",
        duration_vs_law=f"{duration / law_duration - 1:+.4%}",
        mean_F_over_F_hertz=f"{sum(to_hertz) / len(to_hertz):.5f}",
        mean_F_over_F_law=f"{sum(to_law) / len(to_law):.5f}", samples=len(to_hertz),
        wall_seconds=f"{float(seconds):.1f}"))
order = {"linear elastic": 0, "neo-hookean": 1, "st venant-kirchhoff": 2}
rows.sort(key=lambda r: (order[r["material"]], -float(r["density"]), r["level"]))

with open(sys.argv[2], "w", newline="") as table:
    writer = csv.DictWriter(table, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)

columns = [("density", "rho"), ("material", "material"), ("level", "level"),
           ("pole_size", "PoleSize"), ("zone_radius", "ZoneRadius"), ("cells", "cells"),
           ("time_step", "dt"), ("steps", "steps"), ("step_cuts", "cuts"),
           ("mean_F_over_F_hertz", "mean F/F_Hertz"),
           ("mean_F_over_F_law", "mean F/F_law"), ("samples", "samples"),
           ("peak_force", "peak"), ("peak_vs_hertz", "peak vs Hertz"),
           ("peak_vs_law", "peak vs law"), ("duration_vs_hertz", "duration vs Hertz"),
           ("duration_vs_law", "duration vs law"), ("wall_seconds", "wall [s]")]
print("| " + " | ".join(title for _, title in columns) + " |")
print("|" + "---|" * len(columns))
for row in rows:
    print("| " + " | ".join(f"{row[key]:.4g}" if isinstance(row[key], float) else str(row[key])
                            for key, _ in columns) + " |")
print()
for row in rows:
    if row["material"] != "linear elastic":
        linear = [r for r in rows if r["material"] == "linear elastic" and
                  r["density"] == row["density"] and r["level"] == row["level"]]
        if linear:
            shift = float(row["peak_force"]) / float(linear[0]["peak_force"]) - 1
            print(f"peak force, {row['material']} vs linear elastic, rho = {row['density']}, "
                  f"level {row['level']}: {shift:+.3%}")
PY
$all_succeeded
