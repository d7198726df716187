// Unit tests of FiniteSphereImpact: the finite-sphere law against its formula and its Hertz limit,
// the paper's sphere case against the deviations from Hertz quoted in issue 12, the impulse, and
// the history against an independent Runge-Kutta solution of the impact ODE.
#include <dyncontact/reference/finite_sphere_impact.h>
#include <dyncontact/simulation/parameter_reader.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "case_run.h"
#include "runge_kutta.h"
#include "simpson.h"

namespace dyncontact::testing
{
namespace
{
constexpr double pi = 3.14159265358979323846;

/**
 * The per-sphere law of issue 12 as stated there, typed out independently of the library: the
 * approach w of the centre of a sphere (R, E, nu = 0.3) pressed by F on a rigid plane.
 */
double issue_law(const double radius, const double modulus, const double force)
{
  const double nu     = 0.3;
  const double e1     = modulus / (1.0 - nu * nu);
  const double k1     = 4.0 / 3.0 * e1 * std::sqrt(radius);
  const double a      = std::cbrt(3.0 * force * radius / (4.0 * e1));
  const double k      = (1.0 + nu) * std::pow(1.0 - 2.0 * nu, 2) / (2.0 * pi);
  const double c_of_a = -0.49 + k * std::log(radius / a);
  return std::pow(force / k1, 2.0 / 3.0) + c_of_a * force / (modulus * radius);
}

/**
 * An independent solution of m* d'' = -F(d), d(0) = 0, d'(0) = v by the classical Runge-Kutta
 * method with @p n_steps steps of size @p h, F(d) being the inverse of the library's static law
 * approach_under_force() by bisection to adjacent doubles (F = 0 for d <= 0).
 */
std::vector<OdeState>
finite_sphere_history(const FiniteSphereImpact& impact, const double h, const unsigned int n_steps)
{
  const double mass       = impact.hertz().effective_mass();
  const double upper      = 2.0 * impact.maximum_force();
  const auto acceleration = [&](const double d)
  {
    if (d <= 0.0)
      return 0.0;
    double lower = 0.0, higher = upper;
    for (double middle = 0.5 * upper; middle > lower && middle < higher;
         middle        = 0.5 * (lower + higher))
      (impact.approach_under_force(middle) < d ? lower : higher) = middle;
    return -0.5 * (lower + higher) / mass;
  };
  return runge_kutta_history(acceleration, impact.hertz().relative_approach_speed(), h, n_steps);
}

/// Two dissimilar spheres (R1 = 8, R2 = 4, E, nu, rho all different; C0 of sphere 2 given).
FiniteSphereImpact dissimilar_impact()
{
  return FiniteSphereImpact(
      {8.0, 5e3, 0.3, 1e-3}, {4.0, 2e4, 0.25, 3e-3}, 2.0, 0.0, std::nullopt, -0.45);
}
} // namespace

// Checks the law: for two identical spheres the approach of the centres is 2 w(F) with w the
// issue's per-sphere formula typed out in the test (1e-14 relative: round-off of the differently
// ordered operations); and as R grows at fixed load F the relative deviation from Hertz,
// delta / delta_H - 1, shrinks exactly like the correction term, C(a) F / (E R) over (F /
// K1)^{2/3}, which is C(a) times a constant times R^{-2/3}: their ratio is the same for R = 8 ...
// 8e6 (1e-9 relative: the deviation is a difference of nearly equal numbers, cancellation loses up
// to 1e-16 / 1e-5 of it), and the deviation itself falls below 1e-5.
TEST(FiniteSphereImpact, LawIsTwiceTheIssueFormulaAndTendsToHertz)
{
  const double force = 100.0;
  double ratio_at_8  = 0.0;
  for (const double radius : {8.0, 80.0, 800.0, 8e3, 8e4, 8e5, 8e6})
  {
    const ElasticSphere sphere{radius, 5e3, 0.3, 1e-3};
    const FiniteSphereImpact impact(sphere, sphere, 2.0, 0.0);
    const double law = impact.approach_under_force(force);
    EXPECT_NEAR(law, 2.0 * issue_law(radius, 5e3, force), 1e-14 * law);

    const double hertz     = impact.hertz().approach_under_force(force);
    const double deviation = law / hertz - 1.0;
    const double a         = impact.contact_radius(force);
    const double c_of_a = -0.49 + FiniteSphereImpact::log_coefficient(0.3) * std::log(radius / a);
    const double ratio  = deviation / (c_of_a * std::pow(radius, -2.0 / 3.0));
    if (radius == 8.0)
      ratio_at_8 = ratio;
    EXPECT_NEAR(ratio, ratio_at_8, 1e-9 * std::abs(ratio_at_8)) << "R = " << radius;
    if (radius == 8e6)
    {
      EXPECT_LT(std::abs(deviation), 1e-5);
    }
  }
}

// The key check (issue 12): the paper's sphere case at rho = 0.001, small strain, parameters read
// from prm/spheres_rho0.001.prm (E, nu, rho of both bodies; v = the difference of the initial
// velocities at the centres; R = 8, the default of meshes/sphere.geo, which the prm does not
// override). The issue quotes peak force +2.70 % and contact duration -1.91 % relative to Hertz,
// to be met within 0.15 percentage points (the precision of C0, about 2 digits). Prints both.
TEST(FiniteSphereImpact, PaperSphereCaseDeviatesFromHertzAsQuoted)
{
  const RunParameters parameters =
      ParameterReader(source_path("prm/spheres_rho0.001.prm"), {}).parameters();
  const BodyParameters& lower = parameters.bodies.bodies.at(0);
  const BodyParameters& upper = parameters.bodies.bodies.at(1);
  const double radius         = 8.0;
  const double speed          = lower.initial_velocity.create<2>(2)->value(Point<2>(0., -10.), 1) -
                       upper.initial_velocity.create<2>(2)->value(Point<2>(0., 10.), 1);
  ASSERT_EQ(speed, 2.0);
  const FiniteSphereImpact impact(
      {radius, lower.youngs_modulus, lower.poissons_ratio, lower.density},
      {radius, upper.youngs_modulus, upper.poissons_ratio, upper.density},
      speed,
      2.0);
  const double peak = 100.0 * (impact.maximum_force() / impact.hertz().maximum_force() - 1.0);
  const double duration =
      100.0 * (impact.contact_duration() / impact.hertz().contact_duration() - 1.0);
  std::cout << std::setprecision(6) << "[ info     ] finite sphere, rho = 0.001: peak force "
            << impact.maximum_force() << " (" << peak << " % vs Hertz), duration "
            << impact.contact_duration() << " (" << duration << " %), max approach "
            << impact.maximum_approach() << std::endl;
  EXPECT_NEAR(peak, 2.70, 0.15);
  EXPECT_NEAR(duration, -1.91, 0.15);
}

// Checks that the finite-sphere integrator, given the Hertz law (nu = 0.5 makes k = 0, and C0 = 0:
// no correction at all), reproduces Hertz's closed forms and exact history: peak force, maximum
// approach and duration to 1e-13 relative, the history to 1e-12 of the peak values (a few hundred
// ulps: the inverted time integral near the ends carries the round-off of t0 + t_c - t).
TEST(FiniteSphereImpact, WithoutCorrectionItIsHertz)
{
  const ElasticSphere sphere{8.0, 5e3, 0.5, 1e-3};
  const FiniteSphereImpact impact(sphere, sphere, 2.0, 2.0, 0.0, 0.0);
  const HertzImpact& hertz = impact.hertz();
  EXPECT_NEAR(impact.maximum_force(), hertz.maximum_force(), 1e-13 * hertz.maximum_force());
  EXPECT_NEAR(
      impact.maximum_approach(), hertz.maximum_approach(), 1e-13 * hertz.maximum_approach());
  EXPECT_NEAR(
      impact.contact_duration(), hertz.contact_duration(), 1e-13 * hertz.contact_duration());
  for (unsigned int i = 0; i <= 100; ++i)
  {
    const double t = 1.99 + i * (hertz.contact_duration() + 0.02) / 100.0;
    EXPECT_NEAR(impact.contact_force(t), hertz.contact_force(t), 1e-12 * hertz.maximum_force());
    EXPECT_NEAR(impact.approach(t), hertz.approach(t), 1e-12 * hertz.maximum_approach());
    EXPECT_NEAR(impact.approach_rate(t), hertz.approach_rate(t), 1e-12 * 2.0);
  }
}

// Checks the impulse: impulse() (a quadrature of F dt over the contact) equals 2 m* v to round-off
// (1e-14 relative: the sum of 450 terms), and so does an independent integration of
// contact_force(t) (composite Simpson after t = t0 + (t_c / 2) sigma^2 from each end, which makes
// the integrand smooth to O(sigma^4 ln sigma) at the ends; 1000 intervals: error below 1e-9).
TEST(FiniteSphereImpact, ImpulseIsTwiceReducedMassTimesSpeed)
{
  const ElasticSphere paper{8.0, 5e3, 0.3, 1e-3};
  for (const FiniteSphereImpact& impact :
       {FiniteSphereImpact(paper, paper, 2.0, 2.0), dissimilar_impact()})
  {
    const HertzImpact& hertz = impact.hertz();
    const double expected    = 2.0 * hertz.effective_mass() * hertz.relative_approach_speed();
    EXPECT_NEAR(impact.impulse(), expected, 1e-14 * expected);

    const double t0  = hertz.first_touch_time();
    const double t_c = impact.contact_duration();
    const auto halves =
        half_impulses([&](const double t) { return impact.contact_force(t); }, t0, t_c, 1000);
    const double integral = halves.first + halves.second;
    EXPECT_NEAR(integral, expected, 1e-9 * expected);
  }
}

// Checks the history (the library inverts its time integral, no time stepping) against an
// independent classical Runge-Kutta solution of m* d'' = -F(d) with 2^15 steps over 1.02 t_c, for
// the paper's spheres and for dissimilar spheres. The Runge-Kutta error, estimated from the run
// with 2^14 steps (fourth order: 1/15 of the difference), must be below 1e-11 relative; the
// library's approach, rate and force must then agree to 1e-9 of d_max, v and F_max, and the
// Runge-Kutta contact duration (zero of d, linear interpolation: O(h^2.5) error, ~1e-12) to 1e-9.
TEST(FiniteSphereImpact, HistoryAgreesWithIndependentRungeKutta)
{
  const ElasticSphere paper{8.0, 5e3, 0.3, 1e-3};
  for (const FiniteSphereImpact& impact :
       {FiniteSphereImpact(paper, paper, 2.0, 0.0), dissimilar_impact()})
  {
    const unsigned int n_fine          = 1u << 15;
    const double h                     = 1.02 * impact.contact_duration() / n_fine;
    const std::vector<OdeState> fine   = finite_sphere_history(impact, h, n_fine);
    const std::vector<OdeState> coarse = finite_sphere_history(impact, 2.0 * h, n_fine / 2);
    const double d_max                 = impact.maximum_approach();
    const double v                     = impact.hertz().relative_approach_speed();
    for (unsigned int i = 0; i <= n_fine; i += 128)
    {
      const double t    = i * h;
      const OdeState& s = fine[i];
      EXPECT_LE(std::abs(s.d - coarse[i / 2].d) / 15.0, 1e-11 * d_max);
      EXPECT_NEAR(impact.approach(t), s.d, 1e-9 * d_max) << "t = " << t;
      EXPECT_NEAR(impact.approach_rate(t), s.rate, 1e-9 * v) << "t = " << t;
      if (s.d > 0.0)
      {
        EXPECT_NEAR(impact.approach_under_force(impact.contact_force(t)), s.d, 1e-9 * d_max)
            << "t = " << t;
      }
    }
    unsigned int last = n_fine / 2;
    while (fine[last + 1].d > 0.0)
      ++last;
    const double duration = (last + fine[last].d / (fine[last].d - fine[last + 1].d)) * h;
    EXPECT_NEAR(duration, impact.contact_duration(), 1e-9 * impact.contact_duration());
  }
}

// Checks the input checks (no tolerance involved): C0 omitted for nu != 0.3 is rejected with a
// message naming nu, a non-finite C0 too; a law that turns over before the impact energy is
// stored (rho v^2 / E so large that the approach would reach a sizeable part of R) is a
// std::domain_error; bad sphere data is rejected as by HertzImpact.
TEST(FiniteSphereImpact, RejectsInvalidInput)
{
  const ElasticSphere paper{8.0, 5e3, 0.3, 1e-3};
  const ElasticSphere other_nu{8.0, 5e3, 0.25, 1e-3};
  try
  {
    FiniteSphereImpact(paper, other_nu, 2.0, 0.0);
    ADD_FAILURE() << "no exception for nu = 0.25 without C0";
  }
  catch (const std::invalid_argument& error)
  {
    EXPECT_NE(std::string(error.what()).find("nu = 0.25"), std::string::npos) << error.what();
  }
  EXPECT_NO_THROW(FiniteSphereImpact(paper, other_nu, 2.0, 0.0, std::nullopt, -0.45));
  EXPECT_THROW(FiniteSphereImpact(paper, paper, 2.0, 0.0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(FiniteSphereImpact({8.0, 5e3, 0.3, 1.0}, {8.0, 5e3, 0.3, 1.0}, 200.0, 0.0),
               std::domain_error);
  EXPECT_THROW(FiniteSphereImpact({-8.0, 5e3, 0.3, 1e-3}, paper, 2.0, 0.0), std::invalid_argument);
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
// A sphere on a flat body: Hertz's sphere on a half-space plus the sphere's own finite-size term.
//  - On the rigid fixed plane it is one sphere of the identical pair pressed on their symmetry
//    plane: the same force history as the pair at twice the speed (1e-12 of the peak: the same
//    law through differently ordered effective quantities), half its approach.
//  - On an elastic flat its approach is Hertz's sphere-on-flat term plus the sphere's correction
//    C(a) F / (E R) at the common contact radius, typed out in the test (1e-13 of the approach),
//    and its history agrees with the independent Runge-Kutta solution (1e-9 as above).
TEST(FiniteSphereImpact, SphereOnFlatAddsOnlyTheSpheresFiniteSizeTerm)
{
  const ElasticSphere paper{8.0, 5e3, 0.3, 1e-3};
  constexpr double infinity = std::numeric_limits<double>::infinity();
  const FiniteSphereImpact on_plane =
      FiniteSphereImpact::sphere_on_flat(paper, {infinity, 0.0, infinity}, 1.0, 0.0);
  const FiniteSphereImpact pair(paper, paper, 2.0, 0.0);
  const double peak = pair.maximum_force();
  EXPECT_NEAR(on_plane.maximum_force(), peak, 1e-12 * peak);
  EXPECT_NEAR(
      on_plane.contact_duration(), pair.contact_duration(), 1e-12 * pair.contact_duration());
  for (const double t : {0.01, 0.03, 0.04, 0.07})
  {
    EXPECT_NEAR(on_plane.contact_force(t), pair.contact_force(t), 1e-12 * peak) << "t = " << t;
    EXPECT_NEAR(on_plane.approach(t), 0.5 * pair.approach(t), 1e-12 * pair.maximum_approach());
  }

  const double block_mass           = 1e-3 * pi * 40.0 * 40.0 * 40.0;
  const ElasticFlatBody block       = {5e3, 0.3, block_mass};
  const FiniteSphereImpact on_block = FiniteSphereImpact::sphere_on_flat(paper, block, 1.0, 0.0);
  const HertzImpact hertz           = HertzImpact::sphere_on_flat(paper, block, 1.0, 0.0);
  const double e_star               = hertz.effective_modulus();
  const double k                    = 1.3 * 0.4 * 0.4 / (2.0 * pi);
  for (const double force : {1.0, 30.0, on_block.maximum_force()})
  {
    // Hertz's approach of the pair plus the sphere's term C(a) F / (E R), a the pair's contact
    // radius (the class's model: each body's term at the common contact radius).
    const double a        = std::cbrt(3.0 * force * 8.0 / (4.0 * e_star));
    const double expected = std::pow(force / (4.0 / 3.0 * e_star * std::sqrt(8.0)), 2.0 / 3.0) +
                            (-0.49 + k * std::log(8.0 / a)) * force / (5e3 * 8.0);
    EXPECT_NEAR(on_block.approach_under_force(force), expected, 1e-13 * expected)
        << "F = " << force;
  }
  std::cout << "  sphere on block: law peak " << on_block.maximum_force() << " vs Hertz "
            << hertz.maximum_force() << ", duration " << on_block.contact_duration() << " vs "
            << hertz.contact_duration() << std::endl;
  // The finite sphere is stiffer: about half the pair's excess over Hertz (only one body has the
  // finite-size term; the pair's law is +2.7 %).
  EXPECT_GT(on_block.maximum_force(), 1.01 * hertz.maximum_force());
  EXPECT_LT(on_block.maximum_force(), 1.02 * hertz.maximum_force());

  const unsigned int n_steps      = 1u << 14;
  const double h                  = 1.02 * on_block.contact_duration() / n_steps;
  const std::vector<OdeState> ode = finite_sphere_history(on_block, h, n_steps);
  for (unsigned int i = 0; i <= n_steps; i += 128)
    EXPECT_NEAR(on_block.approach(i * h), ode[i].d, 1e-9 * on_block.maximum_approach())
        << "t = " << i * h;
}
} // namespace dyncontact::testing
