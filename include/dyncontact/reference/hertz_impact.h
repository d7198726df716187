#pragma once

#include <dyncontact/reference/sphere_breathing_mode.h>

#include <vector>

namespace dyncontact
{
/**
 * A flat elastic body hit by a sphere (HertzImpact::sphere_on_flat()): in Hertz's theory its
 * surface is a half-space (radius of curvature infinite). Plain data, checked by the user.
 */
struct ElasticFlatBody
{
  /// Young's modulus E (> 0; std::numeric_limits<double>::infinity() for a rigid body).
  double youngs_modulus;
  /// Poisson's ratio nu (-1 < nu <= 0.5).
  double poissons_ratio;
  /// Mass m (> 0; std::numeric_limits<double>::infinity() for a fixed, immovable body).
  double mass;
};

/// The mass rho 4/3 pi R^3 of @p sphere.
double sphere_mass(const ElasticSphere& sphere);

/**
 * The effective radius R* = R1 R2 / (R1 + R2) of two convex bodies with radii of curvature
 * @p r1, @p r2 at the contact point (R* = R1 if R2 is infinite: a flat body). Unchecked.
 */
double effective_radius(double r1, double r2);

/**
 * The effective modulus E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2) of two elastic bodies.
 * Unchecked.
 */
double effective_modulus(double e1, double nu1, double e2, double nu2);

/**
 * The effective (reduced) mass m* = m1 m2 / (m1 + m2) of two bodies (m* = m1 if m2 is infinite:
 * an immovable body). Unchecked.
 */
double effective_mass(double m1, double m2);

/**
 * Hertz's quasi-static theory of the frictionless, head-on impact of two elastic bodies with
 * smooth convex surfaces (doc/method.md section 5): closed forms for the maximum approach, peak
 * force, contact duration and impulse, and the time histories of the approach and of the contact
 * force. Named constructors give two spheres (two_spheres()) and a sphere on a flat elastic body
 * (sphere_on_flat()); the general constructor takes the effective quantities.
 *
 * Model. With the effective radius R* = R1 R2 / (R1 + R2), modulus E* = 1 / ((1 - nu1^2) / E1 +
 * (1 - nu2^2) / E2), mass m* = m1 m2 / (m1 + m2) and stiffness K = 4/3 E* sqrt(R*), the approach d
 * of the two centres of mass (the overlap of the undeformed bodies) obeys
 *
 *   m* d'' = -K d^{3/2},   d(0) = 0,   d'(0) = v,
 *
 * with t measured from first touch and v the relative approach speed (2 for two spheres moving at
 * speed 1 toward each other). Two identical spheres have R* = R / 2, E* = E / (2 (1 - nu^2)) and
 * m* = m / 2; a sphere on a flat body R* = R, and on an immovable one m* = m. The contact force is
 * F = K d^{3/2}. Energy conservation, m* d'^2 / 2 + 2 K d^{5/2} / 5 = m* v^2 / 2, gives
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
 * relative velocity reverses, and the impulse of the contact force is 2 m* v (= m v for identical
 * spheres: each sphere's momentum changes by m v / 2 twice over).
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
 * Outside contact the bodies move as rigid bodies: before first touch (t < t0) the approach is
 * v (t - t0) (negative: a gap) and after separation (t > t0 + t_c) it is -v (t - t0 - t_c), the
 * approach rate is v and -v, and the force is zero.
 *
 * This is what it is NOT: not dynamic elasticity (no waves inside the bodies: Hertz assumes the
 * contact duration is long compared with the bodies' own vibration periods, which the finite-
 * element solution need not satisfy, see SphereBreathingModes), not valid beyond small approach
 * d << R* (each body is a half-space: the finite-size correction is FiniteSphereImpact), not for
 * a flat body of finite thickness (its bending is ignored), frictionless and central only, and
 * not coupled to the finite-element code, for which it is an independent reference only.
 */
class HertzImpact
{
public:
  /**
   * The impact with effective radius @p effective_radius, modulus @p effective_modulus and mass
   * @p effective_mass (see the class documentation), relative approach speed
   * @p relative_approach_speed and first touch at time @p first_touch_time. Throws
   * std::invalid_argument unless the radius, modulus, mass and speed are positive and finite.
   */
  HertzImpact(double effective_radius,
              double effective_modulus,
              double effective_mass,
              double relative_approach_speed,
              double first_touch_time);

  /**
   * The impact of the spheres @p first and @p second (any radii, constants and densities) that
   * approach each other at the relative speed @p relative_approach_speed and first touch at time
   * @p first_touch_time. Throws std::invalid_argument for a non-positive or infinite radius,
   * Young's modulus or density, for nu outside (-1, 0.5] and for a non-positive speed.
   */
  static HertzImpact two_spheres(const ElasticSphere& first,
                                 const ElasticSphere& second,
                                 double relative_approach_speed,
                                 double first_touch_time);

  /**
   * The impact of @p sphere on the flat body @p flat (R2 infinite; mass infinite for an immovable
   * body, then m* = m of the sphere), with the same conventions and checks as two_spheres(); the
   * flat body's mass must be positive (infinity allowed).
   */
  static HertzImpact sphere_on_flat(const ElasticSphere& sphere,
                                    const ElasticFlatBody& flat,
                                    double relative_approach_speed,
                                    double first_touch_time);

  /**
   * The coefficient 2 tau(1) = 2 integral_0^1 dx / sqrt(1 - x^{5/2}) = 2.9432751843247047 of the
   * contact duration t_c = coefficient d_max / v, from the Gamma-function form of the integral.
   */
  static double contact_duration_coefficient();

  /// The effective radius R*.
  double effective_radius() const;

  /// The effective modulus E*.
  double effective_modulus() const;

  /// The effective mass m*.
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

  /// The approach (F / K)^{2/3} under the static contact force @p force >= 0 (the Hertz law).
  double approach_under_force(double force) const;

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
