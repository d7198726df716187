"""Checks a run of prm/oblique_sphere_on_plane_3d.prm (issue 29, C) in the gross-slip branch
against rigid-body impulse theory.

Usage: check_oblique_impact.py DIRECTORY MU V THETA R

Writes DIRECTORY/oblique_impact.csv beside the run: quantity, computed, reference (rigid-body
gross slip with the run's e), difference, relative_difference.

The half ball (its history's momenta and angular momenta are the half's, mass m) meets the plane
at the speed V, THETA degrees from the normal: V_t = V sin THETA along x, V_n = V cos THETA along -z.
Above the threshold tan THETA = MU (1 + e) (1 + m R^2 / I) it slides throughout, so
  - the tangential impulse over the normal one (the momentum changes along x and z) is MU: every
    active pair is on the slip branch with its force MU lambda_n along -x, so the ratio holds to
    the Newton tolerance (bound 1e-6, the issue's; measured 1e-14);
  - the centre's tangential velocity after the impact is V_t - MU (1 + e) V_n, e = -v_z / V_n the
    run's own normal rebound (bound 1 %, the issue's; it follows from the impulses);
  - the spin L_y / I, I = 2/5 m R^2 of the rigid ball, is MU (1 + e) V_n m R / I (bound 1 %, the
    issue's): L_y also holds the elastic vibration's angular momentum after the impact, and the
    contact force acts a little less than R below the centre (measured 0.55 % on the shipped coarse
    mesh).
Also: frictional_dissipation never decreases; while the ball is in contact E + D stays at its
value at the first contact step to 1e-8 of E_0 (the friction's work is what D counts; the closing
and the release have the frictionless event work of massless contact nodes, -1.9e-5 and +4.4e-5
of E_0 with and without friction, which the energy guard holds to 1e-4); at most 15 linear solves in any step (the semismooth Newton, issue 29 F).
"""
import math
import sys

from history_checks import Checks, read_history

directory = sys.argv[1]
mu, speed, theta, radius = map(float, sys.argv[2:6])
rows = read_history(directory)
checks = Checks()
check = checks.relative


v_t, v_n = speed * math.sin(math.radians(theta)), speed * math.cos(math.radians(theta))
first, last = rows[0], rows[-1]
mass = -first["momentum_1_z"] / v_n
if last["active_constraints"] != 0:
    checks.failures.append("the ball is still in contact at the end")
restitution = last["momentum_1_z"] / mass / v_n
inertia = 0.4 * mass * radius**2
print(f"half ball: m = {mass:.6g}, e = {restitution:.6g}, threshold {math.degrees(math.atan(mu * (1 + restitution) * 3.5)):.3f} degrees")
impulse_t = last["momentum_1_x"] - first["momentum_1_x"]
impulse_n = last["momentum_1_z"] - first["momentum_1_z"]
comparisons = [
    ("tangential / normal impulse", -impulse_t / impulse_n, mu, 1e-6),
    ("tangential velocity after", last["momentum_1_x"] / mass, v_t - mu * (1 + restitution) * v_n, 1e-2),
    ("spin after", last["angular_momentum_y"] / inertia,
     mu * (1 + restitution) * v_n * mass * radius / inertia, 1e-2),
]
with open(f"{directory}/oblique_impact.csv", "w") as table:
    table.write("quantity,computed,reference,difference,relative_difference\n")
    table.write(f"restitution e (normal rebound),{restitution:.15g},,,\n")
    for name, computed, reference, _ in comparisons:
        table.write(f"{name},{computed:.15g},{reference:.15g},{computed - reference:.6g},"
                    f"{(computed - reference) / reference:.6g}\n")
for name, computed, reference, tolerance in comparisons:
    check(name, computed, reference, tolerance)
drops = [a["frictional_dissipation"] - b["frictional_dissipation"] for a, b in zip(rows, rows[1:])]
check("largest decrease of frictional_dissipation / E_0", max(0.0, max(drops)) / first["total_energy"], 0.0, 1e-14, False)
balance = [r["algorithmic_energy"] + r["frictional_dissipation"] for r in rows if r["active_constraints"] > 0]
check("E + D in contact against its first contact step / E_0", max(abs(b - balance[0]) for b in balance) / first["total_energy"], 0.0, 1e-8, False)
check("largest linear solves in a step", max(r["newton_iterations"] for r in rows), 0.0, 15, False)
checks.finish()
