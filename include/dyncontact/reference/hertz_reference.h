#pragma once

#include <dyncontact/reference/sphere_breathing_mode.h>

#include <vector>

namespace dyncontact
{
/**
 * Hertz's quasi-static theory of the frictionless, head-on impact of two identical elastic spheres
 * (doc/method.md section 5): closed forms for the maximum approach, peak force, contact duration
 * and impulse, and the time histories of the approach and of the contact force.
 *
 * Model. With the effective radius R* = R / 2, modulus E* = E / (2 (1 - nu^2)), mass m* = m / 2
 * (m = rho 4/3 pi R^3) and stiffness K = 4/3 E* sqrt(R*), the approach d of the two centres (the
 * overlap of the undeformed spheres) obeys
 *
 *   m* d'' = -K d^{3/2},   d(0) = 0,   d'(0) = v,
 *
 * with t measured from first touch and v the relative approach speed (2 for two spheres moving at
 * speed 1 toward each other). The contact force is F = K d^{3/2}. Energy conservation,
 * m* d'^2 / 2 + 2 K d^{5/2} / 5 = m* v^2 / 2, gives
 *
 *   d_max = (5 m* v^2 / (4 K))^{2/5} = (15 m* v^2 / (16 E* sqrt(R*)))^{2/5},  F_max = K
 * d_max^{3/2},
 *
 * and, with x = d / d_max (so that 4 K d_max^{5/2} / (5 m*) = v^2), the time to reach x:
 *
 *   t(x) = (d_max / v) tau(x),   tau(x) = integral_0^x dy / sqrt(1 - y^{5/2}).
 *
 * The motion is symmetric about the peak; the contact lasts t_c = 2 (d_max / v) tau(1) with
 * (substituting z = y^{5/2}) tau(1) = (2/5) B(2/5, 1/2) = (2/5) Gamma(2/5) Gamma(1/2) / Gamma(9/10)
 * = 1.4716375921623523, so t_c = 2.9432751843247047 d_max / v. The rebound is elastic, the
 * relative velocity reverses, and the impulse of the contact force is 2 m* v (= m v: each sphere's
 * momentum changes by m v / 2 twice over).
 *
 * History. d(t) is obtained by inverting tau, without time stepping: with the split point z_s =
 * 0.35 of z = x^{5/2}, in the first part (tau below tau(x_s)) tau(x) = integral_0^{sqrt x} 2 w /
 * sqrt(1 - w^5) dw is solved for x; in the part around the peak the rate u = d' / v = sqrt(1 -
 * x^{5/2}) is the unknown and the time to the peak is (4/5) integral_0^u (1 - s^2)^{-3/5} ds, then
 * x = (1 - u^2)^{2/5}. Both integrands are analytic on their intervals (their nearest singularity
 * lies at 1, beyond 0.81), so 32-point Gauss-Legendre quadrature is exact to round-off (the error
 * bound, of order 2.5^{-64}, is far below 1e-16); both functions are convex and increasing, so
 * Newton's method started above the root decreases monotonically to it. The result is accurate to
 * round-off: it agrees with an independent classical Runge-Kutta solution of the ODE to about
 * 5e-14 relative (the Runge-Kutta solution's own round-off, reached with 2^16 or more steps), far
 * inside 1e-10; the unit tests check that and the closed forms. Each sample costs a few
 * microseconds.
 *
 * Outside contact the spheres move as rigid bodies: before first touch (t < t0) the approach is
 * v (t - t0) (negative: a gap) and after separation (t > t0 + t_c) it is -v (t - t0 - t_c), the
 * approach rate is v and -v, and the force is zero.
 *
 * This is what it is NOT: not dynamic elasticity (no waves inside the spheres: Hertz assumes the
 * contact duration is long compared with the spheres' own vibration periods, which the finite-
 * element solution need not satisfy, see SphereBreathingModes), not valid beyond small approach
 * d << R, frictionless and central only, and not coupled to the finite-element code, for which it
 * is an independent reference only.
 */
class HertzImpactOfIdenticalSpheres
{
public:
  /**
   * The impact of two copies of @p sphere that approach each other at the relative speed
   * @p relative_approach_speed and first touch at time @p first_touch_time. Throws
   * std::invalid_argument for a non-positive radius, Young's modulus, density or speed and for
   * nu outside (-1, 0.5].
   */
  HertzImpactOfIdenticalSpheres(const ElasticSphere& sphere,
                                double relative_approach_speed,
                                double first_touch_time);

  /**
   * The coefficient 2 tau(1) = 2 integral_0^1 dx / sqrt(1 - x^{5/2}) = 2.9432751843247047 of the
   * contact duration t_c = coefficient d_max / v, from the Gamma-function form of the integral.
   */
  static double contact_duration_coefficient();

  /// The effective radius R* = R / 2.
  double effective_radius() const;

  /// The effective modulus E* = E / (2 (1 - nu^2)).
  double effective_modulus() const;

  /// The effective mass m* = m / 2 = rho 2/3 pi R^3.
  double effective_mass() const;

  /// The Hertz stiffness K = 4/3 E* sqrt(R*) in F = K d^{3/2}.
  double contact_stiffness() const;

  /// The relative approach speed v at first touch.
  double relative_approach_speed() const;

  /// The time t0 of first touch.
  double first_touch_time() const;

  /// The maximum approach d_max = (15 m* v^2 / (16 E* sqrt(R*)))^{2/5}.
  double maximum_approach() const;

  /// The peak contact force K d_max^{3/2}, reached at t0 + t_c / 2.
  double maximum_force() const;

  /// The contact duration t_c = contact_duration_coefficient() d_max / v.
  double contact_duration() const;

  /// The impulse of the contact force over the whole contact, 2 m* v.
  double impulse() const;

  /// The approach d at time @p t (negative before first touch and after separation).
  double approach(double t) const;

  /// The approach rate d' at time @p t (v before and at first touch, -v after separation).
  double approach_rate(double t) const;

  /// The contact force K d^{3/2} at time @p t; zero before first touch and after separation.
  double contact_force(double t) const;

  /// contact_force() at each of @p times, in the same order.
  std::vector<double> contact_force_history(const std::vector<double>& times) const;

private:
  /// The state in contact, in units of d_max and v: x = d / d_max and u = |d'| / v.
  struct ScaledState
  {
    double x;
    double u;
  };

  /// The scaled state at time t0 + @p time_since_touch, 0 <= time_since_touch <= t_c.
  ScaledState state_in_contact(double time_since_touch) const;

  double effective_radius_value;
  double effective_modulus_value;
  double effective_mass_value;
  double stiffness;
  double speed;
  double touch_time;
  double max_approach;
  double duration;
  /// tau at the split point between the two parametrizations of the history.
  double split_scaled_time;
};
} // namespace dyncontact
