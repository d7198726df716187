#pragma once

#include <dyncontact/reference/hertz_impact.h>
#include <dyncontact/reference/sphere_breathing_mode.h>

#include <array>
#include <optional>
#include <vector>

namespace dyncontact
{
/**
 * The quasi-static, frictionless, head-on impact of two elastic spheres with the finite-sphere
 * contact law, a sharper reference than Hertz (HertzImpact) for spheres whose contact radius is
 * not negligible against their radius (doc/method.md section 5, "Two bodies and the finite-sphere
 * law").
 *
 * Law of one sphere. A sphere of radius R, Young's modulus E and Poisson's ratio nu pressed by
 * the force F on a rigid frictionless plane (the symmetry plane of two identical spheres) has the
 * approach of its centre
 *
 *   w(F) = (F / K1)^{2/3} + C(a) F / (E R),   K1 = 4/3 E1* sqrt(R),   E1* = E / (1 - nu^2),
 *   a = (3 F R / (4 E1*))^{1/3},   C(a) = C0 + k ln(R / a),   k = (1 + nu) (1 - 2 nu)^2 / (2 pi).
 *
 * The first term is Hertz's half-space; the second is the first-order finite-size correction: a
 * sphere is stiffer than a half-space at the same approach of its centre of mass. The ln term
 * with the coefficient k comes from the curved traction-free surface (a Boussinesq reciprocity
 * argument); C0 = -0.49 for nu = 0.3 is from an independent axisymmetric finite-element study,
 * quoted in the project's issue 12 ("C0 ≈ -0.49 (nu = 0.3)"). It is known for nu = 0.3 only:
 * for any other nu (exactly: any double other than 0.3) C0 must be given.
 *
 * Two bodies (this split is our derivation, not from the source). The approach of the two
 * centres is
 *
 *   delta(F) = (F / K)^{2/3} + F sum_i C_i(a) / (E_i R_i),   K = 4/3 E* sqrt(R*),
 *   a = (3 F R* / (4 E*))^{1/3},   C_i(a) = C0_i + k_i ln(R_i / a),
 *
 * with R*, E* of HertzImpact::two_spheres(): the Hertz part of the pair is exact for two
 * half-spaces, and each body adds its own finite-size correction, taken at the common contact
 * radius a with its own E_i, R_i, nu_i (and C0_i). For two identical spheres this is exactly
 * delta = 2 w(F) (R* = R / 2, E* = E1* / 2 give the same a and (F / K)^{2/3} = 2 (F / K1)^{2/3}).
 * Writing c(F) = sum_i C_i(a) / (E_i R_i) = c1 - b ln F with b = sum_i k_i / (3 E_i R_i),
 *
 *   delta'(F) = (2/3) (F / K)^{2/3} / F + c(F) - b,
 *   W(F) = integral_0^F f delta'(f) df = (2/5) F (F / K)^{2/3} + F^2 / 2 (c(F) - b / 2),
 *
 * W being the work of the contact force (the elastic energy stored). delta'' < 0 (b >= 0), so
 * delta is increasing up to the peak force if delta'(F_max) > 0, which the constructor checks.
 *
 * Impact. m* delta'' = -F(delta), delta(0) = 0, delta'(0) = v (m* = m1 m2 / (m1 + m2), t from
 * first touch). Energy conservation m* delta'^2 / 2 + W = m* v^2 / 2 gives the peak force from
 * W(F_max) = m* v^2 / 2 (safeguarded Newton, to round-off) and the time as a function of the
 * force: with y = F / F_max,
 *
 *   t(y) = integral_0^y F_max delta'(F_max s) / r(s) ds,
 *   r(y) = sqrt(2 (W(F_max) - W(F_max y)) / m*),
 *
 * r being the approach rate |delta'|. The endpoint singularities are removed by y = p^{3/2} on the
 * touch side (0 <= y <= 1/2) and y = 1 - q^2 on the peak side (1/2 <= y <= 1; q is about the rate
 * over v, and W(F_max) - W(F_max y) is evaluated from q^2 with expm1 and log1p, without
 * cancellation). What is left, terms like sqrt(p) ln p, is integrated by tanh-sinh quadrature
 * (step 1/32, |tau| <= 3.5: 225 nodes), which converges exponentially for such endpoint
 * behaviour. The motion is symmetric about the peak. History: t(y) is inverted by safeguarded
 * Newton in p or in q (from the nearer end of the contact, or from the peak, as in HertzImpact);
 * the histories agree with an independent Runge-Kutta solution of the ODE to 1e-9
 * (unit tests). A sample costs a few hundred microseconds.
 *
 * Outside contact the spheres move as rigid bodies, as in HertzImpact.
 *
 * This is what it is NOT: small strain only (linear elasticity: at finite strain the material law
 * shifts the result, doc/method.md), quasi-static (no waves, as Hertz), a first-order correction in
 * a / R (not for a approaching R), only as good as C0 (an FE fit, about 2 digits), only spheres
 * and a sphere on a flat body (sphere_on_flat(): the flat body is a half-space, which has no
 * finite-size term; a finite block's own compliance is not in it), and an independent reference,
 * not coupled to the finite-element code. Only rho v^2 / E matters for the relative deviation from
 * Hertz: it vanishes as rho v^2 / E goes to zero.
 */
class FiniteSphereImpact
{
public:
  /// C0 for nu = 0.3, from the independent axisymmetric FE study of issue 12.
  static constexpr double c0_for_nu_0_3 = -0.49;

  /**
   * The impact of the spheres @p first and @p second that approach each other at the relative
   * speed @p relative_approach_speed and first touch at time @p first_touch_time, with the
   * constants C0 of the law @p first_c0 and @p second_c0; either may be omitted for nu = 0.3
   * (then c0_for_nu_0_3). Throws std::invalid_argument for the bad input HertzImpact::two_spheres()
   * rejects, for an omitted C0 with nu != 0.3 (the message names nu) and for a non-finite C0;
   * throws std::domain_error if the law delta(F) is not increasing up to the peak force (the
   * correction overwhelms Hertz: far outside the law's range).
   */
  FiniteSphereImpact(const ElasticSphere& first,
                     const ElasticSphere& second,
                     double relative_approach_speed,
                     double first_touch_time,
                     std::optional<double> first_c0  = std::nullopt,
                     std::optional<double> second_c0 = std::nullopt);

  /**
   * A sphere striking a flat body (HertzImpact::sphere_on_flat(), whose checks and throws apply):
   * Hertz's sphere on a half-space plus the sphere's own finite-size term C(a) F / (E R), the
   * half-space having none. With C0 @p c0 (omitted: c0_for_nu_0_3, nu = 0.3 only). A rigid fixed
   * flat gives the sphere pressed on the symmetry plane, i.e. the law of one of two identical
   * spheres.
   */
  static FiniteSphereImpact sphere_on_flat(const ElasticSphere& sphere,
                                           const ElasticFlatBody& flat,
                                           double relative_approach_speed,
                                           double first_touch_time,
                                           std::optional<double> c0 = std::nullopt);

  /// The coefficient k = (1 + nu) (1 - 2 nu)^2 / (2 pi) of ln(R / a) in C(a).
  static double log_coefficient(double poissons_ratio);

  /// Hertz's impact with the same effective quantities, speed and first touch.
  const HertzImpact& hertz() const;

  /// The contact radius a = (3 F R* / (4 E*))^{1/3} under the force @p force >= 0.
  double contact_radius(double force) const;

  /// The approach delta(F) of the centres under the static contact force @p force >= 0.
  double approach_under_force(double force) const;

  /// The work W(F) of the contact force up to the force @p force >= 0 (the elastic energy).
  double elastic_energy(double force) const;

  /// The peak contact force F_max, from W(F_max) = m* v^2 / 2, reached at t0 + t_c / 2.
  double maximum_force() const;

  /// The maximum approach delta(F_max).
  double maximum_approach() const;

  /// The contact duration t_c.
  double contact_duration() const;

  /// The impulse of the contact force over the contact, by quadrature (= 2 m* v to round-off).
  double impulse() const;

  /// The approach delta at time @p t (rigid-body motion before first touch, after separation).
  double approach(double t) const;

  /// The approach rate delta' at time @p t (v before and at first touch, -v after separation).
  double approach_rate(double t) const;

  /// The contact force at time @p t; zero before first touch and after separation.
  double contact_force(double t) const;

  /// contact_force() at each of @p times, in the same order.
  std::vector<double> contact_force_history(const std::vector<double>& times) const;

private:
  /**
   * The law on top of the Hertz impact @p hertz of the same bodies: the finite-size terms of the
   * spheres @p spheres (nullptr: a flat body, no term) with their C0 @p c0_given (see the public
   * constructor for the checks).
   */
  FiniteSphereImpact(const HertzImpact& hertz,
                     const std::array<const ElasticSphere*, 2>& spheres,
                     const std::array<std::optional<double>, 2>& c0_given);

  /// One sphere's part of c(F): C0 + k ln R and k, over E R.
  struct Correction
  {
    double constant_over_er;
    double log_coefficient_over_er;
  };

  /// The state in contact: y = F / F_max and the rate |delta'|.
  struct State
  {
    double y;
    double rate;
  };

  /// c(F) = sum_i (C0_i + k_i ln(R_i / a)) / (E_i R_i).
  double correction_coefficient(double force) const;

  /// delta'(F), positive for 0 < F <= F_max.
  double compliance(double force) const;

  /// The rate |delta'| at the force F_max (1 - @p x), from the energy, without cancellation.
  double rate_at(double x) const;

  /// dt / dp on the touch side, y = p^{3/2}.
  double touch_side_integrand(double p) const;

  /// dt / dq on the peak side, y = 1 - q^2.
  double peak_side_integrand(double q) const;

  /// The time from first touch to the force F_max @p p^{3/2}, p <= 2^{-2/3}.
  double time_from_touch(double p) const;

  /// The time from the force F_max (1 - @p q^2) to the peak, q <= 2^{-1/2}.
  double time_to_peak(double q) const;

  /// The state at time t0 + @p time_since_touch, 0 <= time_since_touch <= t_c.
  State state_in_contact(double time_since_touch) const;

  HertzImpact hertz_impact;
  Correction corrections[2];
  double log_slope; ///< b = sum_i k_i / (3 E_i R_i)
  double max_force;
  double duration;
  double impulse_value;
  double split_time_from_touch; ///< the time from touch to y = 1/2
};
} // namespace dyncontact
