#!/usr/bin/env bash
# Dissimilar spheres (issue 10, acceptance B): the rho = 0.001 impact of prm/spheres_rho0.001.prm
# with body 1 stiffer by E1/E2 = 1 (identical, the reference bands), 2, 10 and 100, on the coarse
# (Refinement 0) and medium (Refinement 1) meshes, neo-Hookean, modified scheme, paper's dt.
# For each run: completed or not, step cuts, the largest sampled force (no parabola), the contact
# window (from the last sample before the contact to the first after it: an upper bound of the
# duration, within two steps) and the trapezoidal impulse, against Hertz with
# E* = 1 / ((1 - nu^2)/E1 + (1 - nu^2)/E2) (the identical-sphere reference with the same E*); the
# largest energy gain over E_0, and the largest |momentum change - impulse| over the momentum.
# The precise measures (measure_impact) of the coarse runs with E1/E2 = 2, 10 and 100 are ctests.
# Writes bench/results/dissimilar_spheres.csv and prints it; about 2 minutes on 2 cores.
#   bench/dissimilar_spheres.sh
set -euo pipefail
source "$(dirname "$0")/common.sh"
results=bench/results/dissimilar_spheres
mkdir -p "$results"
export results

run_case() # refinement ratio
{
  local refinement=$1 ratio=$2
  run_sphere_impact "$results/r${refinement}_E${ratio}" prm/spheres_rho0.001.prm "$refinement" \
    neo-hookean --set "Bodies/Body 1/Young's modulus=$(/usr/bin/python3 -c "print(5e3 * $ratio)")" ||
    true # a failed run is reported in the table
}
export -f run_case

printf '%s\n' "1|100" "1|10" "1|2" "1|1" "0|100" "0|10" "0|2" "0|1" | run_two_at_a_time run_case

/usr/bin/python3 - "$results" <<'PY'
import csv, math, pathlib, re, sys
root = pathlib.Path(sys.argv[1])
sys.path.insert(0, "scripts")
rows = []
for refinement in (0, 1):
    for ratio in (1, 2, 10, 100):
        directory = root / f"r{refinement}_E{ratio}"
        log = (root / f"r{refinement}_E{ratio}.log").read_text() if (root / f"r{refinement}_E{ratio}.log").exists() else ""
        history = list(csv.DictReader(open(directory / "history.csv"))) if (directory / "history.csv").exists() else []
        completed = "done," in log
        nu, e2, rho, radius, speed = 0.3, 5e3, 0.001, 8.0, 2.0
        e1 = ratio * e2
        e_star = 1 / ((1 - nu**2) / e1 + (1 - nu**2) / e2)
        r_star, m_star = radius / 2, 0.5 * rho * 4 / 3 * math.pi * radius**3
        # Hertz: F_max = (4/3) E* sqrt(R*) d_max^{3/2}, d_max = (15 m* v^2 / (16 E* sqrt(R*)))^{2/5},
        # duration 2.9432751843 d_max / v.
        d_max = (15 * m_star * speed**2 / (16 * e_star * math.sqrt(r_star))) ** 0.4
        f_max = 4 / 3 * e_star * math.sqrt(r_star) * d_max**1.5
        duration = 2.9432751843247047 * d_max / speed
        t = [float(r["time"]) for r in history]
        f = [float(r["contact_force"]) for r in history]
        positive = [i for i, x in enumerate(f) if x > 0]
        peak = max(f) if f else float("nan")
        contact = (t[positive[-1] + 1] - t[positive[0] - 1]) if positive and positive[-1] + 1 < len(t) else float("nan")
        impulse = sum(0.5 * (t[i + 1] - t[i]) * (f[i] + f[i + 1]) for i in range(len(t) - 1))
        energy = [float(r["algorithmic_energy"]) for r in history]
        gain = (max(energy) - energy[0]) / energy[0] if energy else float("nan")
        mismatch = float("nan")
        if history:
            scale = sum(abs(float(history[0][f"momentum_{b}"])) for b in (1, 2))
            mismatch = max(abs(float(r[f"momentum_{b}"]) - float(history[0][f"momentum_{b}"]) - float(r[f"impulse_{b}"])) / scale
                           for r in history for b in (1, 2))
        cuts = sum(float(r["step_cuts"]) for r in history)
        rows.append([refinement, ratio, completed, int(cuts), f"{peak:.4g}", f"{f_max:.4g}", f"{peak / f_max - 1:+.4f}",
                     f"{contact:.5g}", f"{duration:.5g}", f"{impulse:.5g}", f"{gain:.2e}", f"{mismatch:.2e}"])
header = ["refinement", "E1/E2", "completed", "cuts", "peak", "hertz_peak", "peak_error", "contact_window",
          "hertz_duration", "impulse", "energy_gain", "momentum_mismatch"]
with open(root.parent / "dissimilar_spheres.csv", "w", newline="") as out:
    writer = csv.writer(out)
    writer.writerow(header)
    writer.writerows(rows)
print(" | ".join(header))
for row in rows:
    print(" | ".join(str(x) for x in row))
PY
