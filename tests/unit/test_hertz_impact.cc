#include <dyncontact/reference/hertz_impact.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <vector>

#include "runge_kutta.h"
#include "simpson.h"

using dyncontact::ElasticSphere;
using dyncontact::HertzImpact;

namespace
{
/// The paper's spheres of section 6.4 (R = 8, E = 5e3, nu = 0.3) with density rho.
ElasticSphere paper_sphere(const double rho)
{
  return {8.0, 5e3, 0.3, rho};
}

/// The impact of two paper_sphere(rho) at the relative speed 2, first touch at @p touch_time.
HertzImpact paper_impact(const double rho, const double touch_time)
{
  return HertzImpact::two_spheres(paper_sphere(rho), paper_sphere(rho), 2.0, touch_time);
}

/// The impact of two copies of @p sphere at the relative speed @p speed, first touch at t = 0.
HertzImpact identical_impact(const ElasticSphere& sphere, const double speed)
{
  return HertzImpact::two_spheres(sphere, sphere, speed, 0.0);
}

using dyncontact::testing::half_impulses;
using dyncontact::testing::OdeState;
using dyncontact::testing::simpson;

/**
 * An independent solution of m* d'' = -K max(d, 0)^{3/2}, d(0) = 0, d'(0) = v by the classical
 * fourth-order Runge-Kutta method with n_steps steps of size h: the states at t = 0, h, 2h, ...
 */
std::vector<OdeState>
runge_kutta_history(const HertzImpact& hertz, const double h, const unsigned int n_steps)
{
  const double k_over_m = hertz.contact_stiffness() / hertz.effective_mass();
  return dyncontact::testing::runge_kutta_history(
      [&](const double d) { return -k_over_m * std::pow(std::max(d, 0.0), 1.5); },
      hertz.relative_approach_speed(),
      h,
      n_steps);
}

/// The kinetic plus elastic energy m* d'^2 / 2 + 2 K d^{5/2} / 5 of the relative motion.
double relative_energy(const HertzImpact& hertz, const OdeState& s)
{
  return 0.5 * hertz.effective_mass() * s.rate * s.rate +
         0.4 * hertz.contact_stiffness() * std::pow(std::max(s.d, 0.0), 2.5);
}
} // namespace

// Checks the contact-duration coefficient 2 int_0^1 dx / sqrt(1 - x^{5/2}) (library: Gamma-function
// form) against (a) its 25-digit value from mpmath's Beta function, tolerance 4 ulps for the
// round-off of tgamma; (b) an independent composite Simpson quadrature after x = 1 - s^2, which
// removes the endpoint singularity (integrand 2 s / sqrt(1 - (1 - s^2)^{5/2}), smooth except for a
// (1 - s)^{5/2} term at s = 1, so 20000 intervals give an error far below the tolerance 1e-12).
// It also documents that doc/method.md's 2.9432 is the value truncated, not rounded, to 4 decimals.
TEST(HertzReference, ContactDurationCoefficient)
{
  const double coefficient = HertzImpact::contact_duration_coefficient();
  EXPECT_NEAR(coefficient, 2.943275184324704657381787, 4.0 * 4.4e-16);

  const double quadrature =
      simpson(1.0,
              20000,
              [](const double s)
              {
                if (s == 0.0)
                  return 2.0 / std::sqrt(2.5);
                return 2.0 * s / std::sqrt(-std::expm1(2.5 * std::log1p(-s * s)));
              });
  EXPECT_NEAR(coefficient, 2.0 * quadrature, 1e-12);

  EXPECT_NEAR(coefficient, 2.9433, 0.5e-4);
  EXPECT_GT(std::abs(coefficient - 2.9432), 0.5e-4);
}

// Checks the closed forms for doc/method.md's case 6.4 (E = 5e3, nu = 0.3, R = 8, v = 2, rho = 1
// and 0.001): against 20-digit values computed independently with mpmath (tolerance 1e-14
// relative, a few ulps of the pow() chain) and against doc/method.md's rounded numbers (to half a
// unit of their last digit). Prints the values with 15 digits.
TEST(HertzReference, ClosedFormsReproduceMethodNumbers)
{
  struct Case
  {
    double rho, d_max, duration, peak_force, impulse;
    double rounded_d_max, d_max_unit, rounded_duration, duration_unit, rounded_force, force_unit;
  };
  const std::vector<Case> cases = {{1.0,
                                    0.88261741466142793642,
                                    1.2988929669129042962,
                                    6074.7175084725810705,
                                    4289.3211697012643682,
                                    0.883,
                                    1e-3,
                                    1.30,
                                    1e-2,
                                    6.07e3,
                                    10.0},
                                   {0.001,
                                    0.055689394014674815436,
                                    0.081954605716736560853,
                                    96.277784253025302193,
                                    4.2893211697012643682,
                                    0.0557,
                                    1e-4,
                                    0.082,
                                    1e-3,
                                    96.3,
                                    0.1}};
  for (const Case& c : cases)
  {
    const HertzImpact hertz = paper_impact(c.rho, 0.0);
    EXPECT_NEAR(hertz.maximum_approach(), c.d_max, 1e-14 * c.d_max);
    EXPECT_NEAR(hertz.contact_duration(), c.duration, 1e-14 * c.duration);
    EXPECT_NEAR(hertz.maximum_force(), c.peak_force, 1e-14 * c.peak_force);
    EXPECT_NEAR(hertz.impulse(), c.impulse, 1e-14 * c.impulse);

    EXPECT_NEAR(hertz.maximum_approach(), c.rounded_d_max, 0.5 * c.d_max_unit);
    EXPECT_NEAR(hertz.contact_duration(), c.rounded_duration, 0.5 * c.duration_unit);
    EXPECT_NEAR(hertz.maximum_force(), c.rounded_force, 0.5 * c.force_unit);

    std::cout << std::setprecision(15) << "[ info     ] Hertz, rho = " << c.rho
              << ": d_max = " << hertz.maximum_approach() << ", t_c = " << hertz.contact_duration()
              << ", F_max = " << hertz.maximum_force() << ", impulse = " << hertz.impulse()
              << std::endl;
  }
}

// Checks the library's history (obtained by inverting t(d), no time stepping) against an
// independent classical Runge-Kutta integration of the ODE with 2^17 steps over the contact. The
// Runge-Kutta error is estimated by comparing with 2^16 steps (fourth order: the error of the
// finer run is about 1/15 of the difference), and must be below 1e-12 relative; the library's
// approach, rate and force must then agree to 1e-10 relative to d_max, v and F_max, the accuracy
// asked of the reference.
TEST(HertzReference, HistoryAgreesWithIndependentRungeKutta)
{
  for (const double rho : {1.0, 0.001})
  {
    const HertzImpact hertz            = paper_impact(rho, 0.0);
    const unsigned int n_fine          = 1u << 17;
    const double h                     = hertz.contact_duration() / n_fine;
    const std::vector<OdeState> fine   = runge_kutta_history(hertz, h, n_fine);
    const std::vector<OdeState> coarse = runge_kutta_history(hertz, 2.0 * h, n_fine / 2);

    for (unsigned int i = 0; i <= n_fine; i += 256)
    {
      const double t    = i * h;
      const OdeState& s = fine[i];
      EXPECT_LE(std::abs(s.d - coarse[i / 2].d) / 15.0, 1e-12 * hertz.maximum_approach());

      EXPECT_NEAR(hertz.approach(t), s.d, 1e-10 * hertz.maximum_approach()) << "t = " << t;
      EXPECT_NEAR(hertz.approach_rate(t), s.rate, 1e-10 * hertz.relative_approach_speed())
          << "t = " << t;
      EXPECT_NEAR(hertz.contact_force(t),
                  hertz.contact_stiffness() * std::pow(std::max(s.d, 0.0), 1.5),
                  1e-10 * hertz.maximum_force())
          << "t = " << t;
    }
  }
}

// Checks that the Runge-Kutta solution of the ODE (independent of the library's history) reproduces
// the closed forms to 1e-8 relative: the peak force (from the step where d' changes sign, with the
// parabola d_peak = d + d'^2 / (2 |d''|)), the contact duration (the zero of d after the peak, by
// linear interpolation in a step where d is linear to O(h^3.5)), the impulse m* (v - d'(end)), and
// conservation of m* d'^2 / 2 + 2 K d^{5/2} / 5 (fourth-order drift, below 1e-10 relative). The
// step, t_c / 2^16, makes all these errors far smaller than the tolerances.
TEST(HertzReference, OdeReproducesClosedFormsAndConservesEnergy)
{
  for (const double rho : {1.0, 0.001})
  {
    const HertzImpact hertz    = paper_impact(rho, 0.0);
    const unsigned int n_steps = 1u << 16;
    const double h             = hertz.contact_duration() / n_steps;
    const double k_over_m      = hertz.contact_stiffness() / hertz.effective_mass();
    // A few steps beyond the closed-form duration, to see d turn negative.
    const std::vector<OdeState> states = runge_kutta_history(hertz, h, n_steps + 8);

    const double initial_energy = relative_energy(hertz, states.front());
    for (const OdeState& s : states)
      EXPECT_NEAR(relative_energy(hertz, s), initial_energy, 1e-10 * initial_energy);

    unsigned int peak = 0;
    while (states[peak + 1].rate > 0.0)
      ++peak;
    const OdeState& s   = states[peak];
    const double d_peak = s.d + s.rate * s.rate / (2.0 * k_over_m * std::pow(s.d, 1.5));
    EXPECT_NEAR(hertz.contact_stiffness() * std::pow(d_peak, 1.5),
                hertz.maximum_force(),
                1e-8 * hertz.maximum_force());

    unsigned int last_in_contact = peak;
    while (states[last_in_contact + 1].d > 0.0)
      ++last_in_contact;
    const OdeState& before = states[last_in_contact];
    const OdeState& after  = states[last_in_contact + 1];
    const double duration  = (last_in_contact + before.d / (before.d - after.d)) * h;
    EXPECT_NEAR(duration, hertz.contact_duration(), 1e-8 * hertz.contact_duration());

    const double impulse = hertz.effective_mass() * (hertz.relative_approach_speed() - after.rate);
    EXPECT_NEAR(impulse, hertz.impulse(), 1e-8 * hertz.impulse());
  }
}

// Checks the library's history against the closed forms without any ODE solver: the force
// integrated over the contact (composite Simpson in sigma with t = t0 + (t_c / 2) sigma^2 from each
// end, which makes the integrand analytic, 4000 intervals: error far below 1e-10) equals the
// impulse 2 m* v, the momentum balance m* (d'(t2) - d'(t1)) = -int_t1^t2 F dt holds on a part of
// the contact, the peak F_max is reached at the middle of the contact, the rate matches central
// differences of the approach (step 1e-6 t_c: truncation ~1e-12, round-off ~1e-10 relative, so
// 1e-8) and the energy is conserved to round-off (1e-13: both parametrizations of the history
// keep x^{5/2} + u^2 = 1 exactly up to pow() round-off). The first touch is at t0 = 2 (the paper's
// spheres start 4 apart at speed 2), to check the offset as well.
TEST(HertzReference, HistoryReproducesPeakImpulseAndEnergy)
{
  const HertzImpact hertz = paper_impact(1.0, 2.0);
  const double t0         = hertz.first_touch_time();
  const double t_c        = hertz.contact_duration();

  const auto [first_half, second_half] =
      half_impulses([&](const double t) { return hertz.contact_force(t); }, t0, t_c, 4000);
  EXPECT_NEAR(first_half + second_half, hertz.impulse(), 1e-10 * hertz.impulse());
  EXPECT_NEAR(first_half, second_half, 1e-10 * hertz.impulse());

  const double t1 = t0 + 0.1 * t_c;
  const double t2 = t0 + 0.7 * t_c;
  const double part =
      simpson(t2 - t1, 4000, [&](const double t) { return hertz.contact_force(t1 + t); });
  const double rate_change = hertz.approach_rate(t2) - hertz.approach_rate(t1);
  EXPECT_NEAR(hertz.effective_mass() * rate_change, -part, 1e-10 * hertz.impulse());

  EXPECT_NEAR(
      hertz.contact_force(t0 + 0.5 * t_c), hertz.maximum_force(), 1e-14 * hertz.maximum_force());
  EXPECT_NEAR(
      hertz.approach(t0 + 0.5 * t_c), hertz.maximum_approach(), 1e-14 * hertz.maximum_approach());
  EXPECT_LT(hertz.contact_force(t0 + 0.499 * t_c), hertz.maximum_force());
  EXPECT_LT(hertz.contact_force(t0 + 0.501 * t_c), hertz.maximum_force());

  const double energy = 0.5 * hertz.effective_mass() * std::pow(hertz.relative_approach_speed(), 2);
  const double step   = 1e-6 * t_c;
  for (unsigned int i = 1; i < 200; ++i)
  {
    const double t   = t0 + i * t_c / 200.0;
    const OdeState s = {hertz.approach(t), hertz.approach_rate(t)};
    EXPECT_NEAR(relative_energy(hertz, s), energy, 1e-13 * energy) << "t = " << t;
    const double difference = (hertz.approach(t + step) - hertz.approach(t - step)) / (2.0 * step);
    EXPECT_NEAR(s.rate, difference, 1e-8 * hertz.relative_approach_speed()) << "t = " << t;
  }
}

// Checks the behaviour outside contact and the sampling interface (exact statements, no
// tolerance beyond round-off): zero force before first touch and after separation, rigid-body
// approach v (t - t0) before and -v (t - t0 - t_c) after, a history with t0 = 2 that is the one
// with t0 = 0 shifted (to round-off of the shifted time, 1e-12 relative), and
// contact_force_history() equal to pointwise contact_force().
TEST(HertzReference, OutsideContactTimeOffsetAndSampling)
{
  const HertzImpact shifted   = paper_impact(1.0, 2.0);
  const HertzImpact unshifted = paper_impact(1.0, 0.0);
  const double t_c            = shifted.contact_duration();
  const double v              = shifted.relative_approach_speed();

  EXPECT_EQ(shifted.contact_force(1.999), 0.0);
  EXPECT_EQ(shifted.contact_force(2.0 + t_c * (1.0 + 1e-12)), 0.0);
  EXPECT_EQ(shifted.contact_force(10.0), 0.0);
  EXPECT_GT(shifted.contact_force(2.0 + 1e-9), 0.0);
  EXPECT_GT(shifted.contact_force(2.0 + t_c * (1.0 - 1e-9)), 0.0);
  EXPECT_DOUBLE_EQ(shifted.approach(1.5), -0.5 * v);
  EXPECT_DOUBLE_EQ(shifted.approach(3.0 + t_c), -v);
  EXPECT_EQ(shifted.approach_rate(0.0), v);
  EXPECT_EQ(shifted.approach_rate(10.0), -v);

  std::vector<double> times;
  for (unsigned int i = 0; i <= 100; ++i)
    times.push_back(1.9 + i * (t_c + 0.2) / 100.0);
  const std::vector<double> forces = shifted.contact_force_history(times);
  ASSERT_EQ(forces.size(), times.size());
  for (unsigned int i = 0; i < times.size(); ++i)
  {
    EXPECT_EQ(forces[i], shifted.contact_force(times[i]));
    EXPECT_NEAR(
        forces[i], unshifted.contact_force(times[i] - 2.0), 1e-12 * shifted.maximum_force());
  }
}

// Checks that bad input is rejected with std::invalid_argument (no tolerance involved), and that
// the incompressible limit nu = 0.5 is accepted (E* = 2 E / 3).
TEST(HertzReference, RejectsInvalidInput)
{
  EXPECT_THROW(identical_impact({0.0, 5e3, 0.3, 1.0}, 2.0), std::invalid_argument);
  EXPECT_THROW(identical_impact({8.0, 0.0, 0.3, 1.0}, 2.0), std::invalid_argument);
  EXPECT_THROW(identical_impact({8.0, 5e3, 0.3, -1.0}, 2.0), std::invalid_argument);
  EXPECT_THROW(identical_impact({8.0, 5e3, 0.6, 1.0}, 2.0), std::invalid_argument);
  EXPECT_THROW(identical_impact({8.0, 5e3, -1.0, 1.0}, 2.0), std::invalid_argument);
  EXPECT_THROW(identical_impact(paper_sphere(1.0), 0.0), std::invalid_argument);
  const HertzImpact incompressible = identical_impact({8.0, 5e3, 0.5, 1.0}, 2.0);
  EXPECT_DOUBLE_EQ(incompressible.effective_modulus(), 2.0 * 5e3 / 3.0);
}

// Checks the two-body effective quantities and closed forms for dissimilar spheres (R1 = 8, R2 =
// 4, E1 = 5e3, E2 = 2e4, nu1 = 0.3, nu2 = 0.25, rho1 = 1e-3, rho2 = 3e-3, v = 2) against values
// computed by hand from R* = R1 R2 / (R1 + R2), E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2),
// m* = m1 m2 / (m1 + m2) and the closed forms, with 40-digit decimal arithmetic (Python's
// decimal); tolerance 1e-14 relative, a few ulps of the pow() chain as in the identical case.
// Swapping the spheres must give bit-identical results (the formulas are symmetric, and + and *
// commute exactly in floating point).
TEST(HertzImpact, DissimilarSpheresMatchHandComputedClosedFormsAndAreSymmetric)
{
  const ElasticSphere first{8.0, 5e3, 0.3, 1e-3};
  const ElasticSphere second{4.0, 2e4, 0.25, 3e-3};
  const HertzImpact hertz   = HertzImpact::two_spheres(first, second, 2.0, 0.0);
  const HertzImpact swapped = HertzImpact::two_spheres(second, first, 2.0, 0.0);

  const auto expect_relative = [](const double computed, const double expected)
  { EXPECT_NEAR(computed, expected, 1e-14 * expected); };
  expect_relative(hertz.effective_radius(), 2.666666666666666666667);
  expect_relative(hertz.effective_modulus(), 4369.197160021845985800);
  expect_relative(hertz.effective_mass(), 0.5849074322319905956701);
  expect_relative(hertz.contact_stiffness(), 9513.158780151914453828);
  expect_relative(hertz.maximum_approach(), 0.03936343227442083009807);
  expect_relative(hertz.maximum_force(), 74.29578652521054483546);
  expect_relative(hertz.contact_duration(), 0.05792870669157449849518);
  expect_relative(hertz.impulse(), 2.339629728927962382681);

  EXPECT_EQ(swapped.effective_radius(), hertz.effective_radius());
  EXPECT_EQ(swapped.effective_modulus(), hertz.effective_modulus());
  EXPECT_EQ(swapped.effective_mass(), hertz.effective_mass());
  EXPECT_EQ(swapped.maximum_force(), hertz.maximum_force());
  EXPECT_EQ(swapped.contact_duration(), hertz.contact_duration());
  for (unsigned int i = 0; i <= 20; ++i)
  {
    const double t = i * hertz.contact_duration() / 20.0;
    EXPECT_EQ(swapped.contact_force(t), hertz.contact_force(t));
  }
}

// Checks that two identical spheres give the identical-sphere effective quantities R / 2,
// E / (2 (1 - nu^2)) and rho 2/3 pi R^3 of the former identical-sphere class to round-off (4 ulps,
// EXPECT_DOUBLE_EQ: the two-body forms round differently), and Hertz's law F = K d^{3/2} through
// approach_under_force() (a few ulps of pow(), 1e-15 relative).
TEST(HertzImpact, IdenticalSpheresGiveIdenticalSphereQuantities)
{
  for (const double rho : {1.0, 0.001})
  {
    const HertzImpact hertz = paper_impact(rho, 0.0);
    EXPECT_DOUBLE_EQ(hertz.effective_radius(), 4.0);
    EXPECT_DOUBLE_EQ(hertz.effective_modulus(), 5e3 / (2.0 * (1.0 - 0.3 * 0.3)));
    EXPECT_DOUBLE_EQ(hertz.effective_mass(), rho * 2.0 / 3.0 * 3.14159265358979323846 * 512.0);
    const double d = hertz.approach_under_force(hertz.maximum_force());
    EXPECT_NEAR(d, hertz.maximum_approach(), 1e-15 * hertz.maximum_approach());
  }
}

// Checks the sphere on a flat body: R* = R, E* from both bodies, m* = m for an immovable flat body
// and m1 m2 / (m1 + m2) for a finite one (exact formulas, 1e-15 relative for the division
// round-off); and that it is the limit of two spheres as the second sphere's radius R2 grows with
// its mass kept (its density scaled by (R / R2)^3): R* = R / (1 + R / R2), so the relative
// deviation of F_max (proportional to R*^{1/5}) and t_c (to R*^{-1/5}) is about (R / R2) / 5, below
// the tolerance 2 R / R2 for R2 = 1e3 R and 1e6 R.
TEST(HertzImpact, SphereOnFlatBodyIsTheLargeRadiusLimit)
{
  const ElasticSphere sphere{8.0, 5e3, 0.3, 1e-3};
  const double infinity         = std::numeric_limits<double>::infinity();
  const HertzImpact on_rigid    = HertzImpact::sphere_on_flat(sphere, {2e4, 0.25, infinity}, 2, 0);
  const double sphere_mass_hand = 1e-3 * 4.0 / 3.0 * 3.14159265358979323846 * 512.0;
  const double modulus_hand     = 1.0 / ((1.0 - 0.09) / 5e3 + (1.0 - 0.0625) / 2e4);
  EXPECT_EQ(on_rigid.effective_radius(), 8.0);
  EXPECT_NEAR(on_rigid.effective_modulus(), modulus_hand, 1e-15 * modulus_hand);
  EXPECT_NEAR(on_rigid.effective_mass(), sphere_mass_hand, 1e-15 * sphere_mass_hand);

  const HertzImpact on_finite = HertzImpact::sphere_on_flat(sphere, {2e4, 0.25, 3.0}, 2, 0);
  const double reduced_mass   = sphere_mass_hand * 3.0 / (sphere_mass_hand + 3.0);
  EXPECT_NEAR(on_finite.effective_mass(), reduced_mass, 1e-15 * reduced_mass);

  for (const double ratio : {1e3, 1e6})
  {
    const double r2 = 8.0 * ratio;
    const ElasticSphere big{
        r2, 2e4, 0.25, 3.0 / (4.0 / 3.0 * 3.14159265358979323846 * r2 * r2 * r2)};
    const HertzImpact two = HertzImpact::two_spheres(sphere, big, 2.0, 0.0);
    EXPECT_NEAR(two.maximum_force(), on_finite.maximum_force(), 2.0 / ratio * two.maximum_force());
    EXPECT_NEAR(
        two.contact_duration(), on_finite.contact_duration(), 2.0 / ratio * two.contact_duration());
    EXPECT_NEAR(two.impulse(), on_finite.impulse(), 1e-14 * two.impulse());
  }
}

// Checks the two-body input checks (no tolerance involved): an infinite sphere radius or
// effective mass, a flat body with non-positive mass or bad Poisson's ratio are rejected.
TEST(HertzImpact, RejectsInvalidTwoBodyInput)
{
  const ElasticSphere sphere{8.0, 5e3, 0.3, 1e-3};
  const double infinity = std::numeric_limits<double>::infinity();
  EXPECT_THROW(HertzImpact::two_spheres(sphere, {infinity, 5e3, 0.3, 1e-3}, 2.0, 0.0),
               std::invalid_argument);
  EXPECT_THROW(HertzImpact::sphere_on_flat(sphere, {5e3, 0.3, 0.0}, 2.0, 0.0),
               std::invalid_argument);
  EXPECT_THROW(HertzImpact::sphere_on_flat(sphere, {5e3, 0.7, infinity}, 2.0, 0.0),
               std::invalid_argument);
  EXPECT_THROW(HertzImpact(4.0, 2e3, infinity, 2.0, 0.0), std::invalid_argument);
  EXPECT_THROW(HertzImpact(4.0, -2e3, 1.0, 2.0, 0.0), std::invalid_argument);
}
