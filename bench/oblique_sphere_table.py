"""Table and plot of bench/oblique_sphere_on_plane.sh: the rebound of a sphere's oblique impact on
a rigid plane with friction, per incidence, against rigid-body impulse theory.

Usage: oblique_sphere_table.py RESULTS MU V R ANGLE...

From each run's history.csv (the half ball's columns): e = -v_z / V_n after the impact, the
tangential over the normal impulse, the centre's tangential velocity V_t' and spin omega = L_y / I
(I = 2/5 m R^2) after it, and the rebound angle atan(V_t' / v_z) from the normal. The rigid-body
references with the run's own e: gross slip (incidence above tan theta = mu (1 + e) 7/2),
V_t' = V_t - mu (1 + e) V_n, omega = mu (1 + e) V_n m R / I; below it a rigid ball ends rolling,
V_t' = omega R = 5/7 V_t. An elastic ball below the threshold (micro-slip, Maw, Barber & Fawcett
1976) lies between and about these; their published curve is not reproduced here.
Writes RESULTS.csv and RESULTS.png and prints the table.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

results, mu, speed, radius = sys.argv[1], *map(float, sys.argv[2:5])
angles = [float(a) for a in sys.argv[5:]]
table = []
for angle in angles:
    path = f"{results}/theta{angle:g}/history.csv"
    try:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(path))]
    except OSError:
        print(f"theta {angle:g}: no history ({path})")
        continue
    v_t, v_n = speed * math.sin(math.radians(angle)), speed * math.cos(math.radians(angle))
    first, last = rows[0], rows[-1]
    mass = -first["momentum_1_z"] / v_n
    inertia = 0.4 * mass * radius**2
    e = last["momentum_1_z"] / mass / v_n
    ratio = -(last["momentum_1_x"] - first["momentum_1_x"]) / (last["momentum_1_z"] - first["momentum_1_z"])
    tangential = last["momentum_1_x"] / mass
    spin = last["angular_momentum_y"] / inertia
    gross = math.tan(math.radians(angle)) > mu * (1 + e) * 3.5
    rigid_t = v_t - mu * (1 + e) * v_n if gross else 5 / 7 * v_t
    rigid_spin = mu * (1 + e) * v_n * mass * radius / inertia if gross else 5 / 7 * v_t / radius
    table.append({
        "theta": angle, "in_contact_at_end": int(last["active_constraints"] > 0), "e": e,
        "impulse_ratio": ratio, "tangential_velocity": tangential, "rigid_tangential_velocity": rigid_t,
        "spin": spin, "rigid_spin": rigid_spin,
        "rebound_angle": math.degrees(math.atan2(tangential, last["momentum_1_z"] / mass)),
        "branch": "gross slip" if gross else "stick/micro-slip",
        "max_linear_solves": max(r["newton_iterations"] for r in rows),
        "step_cuts": sum(r["step_cuts"] for r in rows)})
with open(f"{results}.csv", "w", newline="") as handle:
    writer = csv.DictWriter(handle, fieldnames=list(table[0]))
    writer.writeheader()
    writer.writerows(table)
print(f"{'theta':>5} {'e':>8} {'Jt/Jn':>10} {'Vt_after':>9} {'rigid':>9} {'omega':>9} {'rigid':>9} {'angle':>7} {'solves':>6} {'cuts':>4}  branch")
for r in table:
    print(f"{r['theta']:5g} {r['e']:8.5f} {r['impulse_ratio']:10.7f} {r['tangential_velocity']:9.5f} {r['rigid_tangential_velocity']:9.5f} "
          f"{r['spin']:9.5f} {r['rigid_spin']:9.5f} {r['rebound_angle']:7.3f} {r['max_linear_solves']:6g} {r['step_cuts']:4g}  {r['branch']}")

theta = [r["theta"] for r in table]
threshold = math.degrees(math.atan(mu * 2 * 3.5))
fine = [0.5 * k for k in range(1, 180)]


def rigid(angle):
    v_t, v_n = speed * math.sin(math.radians(angle)), speed * math.cos(math.radians(angle))
    if angle > threshold:
        return v_t - 2 * mu * v_n, 2 * mu * v_n * 2.5 / radius
    return 5 / 7 * v_t, 5 / 7 * v_t / radius


figure, axes = plt.subplots(1, 3, figsize=(15, 4.5))
for axis, key, label, index in ((axes[0], "tangential_velocity", "rebound tangential velocity V_t' [m/s]", 0),
                                (axes[1], "spin", "rebound spin omega [rad/ms]", 1)):
    axis.plot(fine, [rigid(a)[index] for a in fine], "k-", lw=1, label="rigid body, e = 1 (gross slip / rolling)")
    axis.plot(theta, [r[key] for r in table], "o", color="C0", label="dyncontact")
    axis.set_ylabel(label)
axes[2].plot(fine, [math.degrees(math.atan2(rigid(a)[0], speed * math.cos(math.radians(a)))) for a in fine], "k-", lw=1,
             label="rigid body, e = 1")
axes[2].plot(theta, [r["rebound_angle"] for r in table], "o", color="C0", label="dyncontact")
axes[2].set_ylabel("rebound angle from the normal [degrees]")
for axis in axes:
    axis.axvline(threshold, color="grey", ls=":", lw=1)
    axis.set_xlabel("incidence from the normal [degrees]")
    axis.legend(fontsize=8)
    axis.grid(alpha=0.3)
figure.suptitle(f"Al2O3 sphere on a rigid plane, V = {speed} m/s, mu = {mu} (Chung & Ooi 2011, Test 4); "
                f"dotted: the gross-slip threshold {threshold:.1f} degrees")
figure.tight_layout()
figure.savefig(f"{results}.png", dpi=110)
print(f"wrote {results}.csv and {results}.png")
