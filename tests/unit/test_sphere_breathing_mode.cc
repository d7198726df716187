#include <dyncontact/reference/sphere_breathing_mode.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <vector>

#include "simpson.h"

using dyncontact::breathing_mode_frequency_function;
using dyncontact::breathing_mode_roots;
using dyncontact::ElasticSphere;
using dyncontact::SphereBreathingModes;

namespace
{
constexpr double pi      = 3.14159265358979323846;
constexpr double epsilon = std::numeric_limits<double>::epsilon();

/// The paper's sphere of section 6.4 (R = 8, E = 5e3, nu = 0.3) with density rho.
ElasticSphere paper_sphere(const double rho)
{
  return {8.0, 5e3, 0.3, rho};
}

/**
 * The frequency equation in the sine/cosine form a xi^2 sin(xi) - 4 (sin(xi) - xi cos(xi)) = 0
 * (xi^3 times the library's f), coded here independently of the library.
 */
double frequency_equation_without_bessel_functions(const double xi, const double nu)
{
  const double a = 2.0 * (1.0 - nu) / (1.0 - 2.0 * nu);
  return a * xi * xi * std::sin(xi) - 4.0 * (std::sin(xi) - xi * std::cos(xi));
}

using dyncontact::testing::simpson;
} // namespace

// Checks that every computed root is a root of the frequency equation to full double precision:
// the independently coded sine/cosine form of the equation changes sign between the doubles 4
// units in the last place below and above the root, for Poisson's ratios across the whole range
// and the first 20 roots (nu >= -0.5 keeps xi_1 >= 1.26, where this form does not cancel). Four
// ulps (not one) leave room for the round-off of evaluating the equation itself, which is a few
// ulps of its largest term.
TEST(SphereBreathingMode, RootsAreBracketedBySignChangeWithinFourUlps)
{
  for (const double nu : {-0.5, 0.0, 0.25, 0.3, 0.45, 0.499})
  {
    const std::vector<double> roots = breathing_mode_roots(nu, 20);
    ASSERT_EQ(roots.size(), 20u);
    for (unsigned int m = 0; m < roots.size(); ++m)
    {
      const double xi    = roots[m];
      const double below = xi - 4.0 * epsilon * xi;
      const double above = xi + 4.0 * epsilon * xi;
      EXPECT_LE(frequency_equation_without_bessel_functions(below, nu) *
                    frequency_equation_without_bessel_functions(above, nu),
                0.0)
          << "nu = " << nu << ", root " << m + 1 << " = " << xi;
      EXPECT_GT(xi, m * pi) << "nu = " << nu << ", root " << m + 1;
      EXPECT_LT(xi, (m + 1) * pi) << "nu = " << nu << ", root " << m + 1;
    }
  }
}

// Checks the residual at the roots of the library's own (Bessel-function) form f of the equation
// and of the cotangent form h(xi) = xi cot(xi) - 1 + a xi^2 / 4 (Lamb 1882, n = 0). A root rounded
// to double leaves a residual up to the change of the function over one ulp of xi, plus the
// round-off of evaluating its terms; the bound is that change (over two ulps, for margin) plus 8
// epsilon times the sum of the magnitudes of the terms.
TEST(SphereBreathingMode, FrequencyEquationResidualIsRoundOff)
{
  const double infinity = std::numeric_limits<double>::infinity();
  for (const double nu : {-0.5, 0.0, 0.25, 0.3, 0.45})
  {
    const double a         = 2.0 * (1.0 - nu) / (1.0 - 2.0 * nu);
    const auto bessel_form = [&](const double xi)
    { return breathing_mode_frequency_function(xi, nu); };
    const auto cotangent_form = [&](const double xi)
    { return xi / std::tan(xi) - 1.0 + a * xi * xi / 4.0; };
    for (const double xi : breathing_mode_roots(nu, 10))
    {
      const double below = std::nextafter(xi, -infinity);
      const double above = std::nextafter(xi, infinity);

      const double bessel_terms = std::abs(a * std::sin(xi) / xi) +
                                  std::abs(4.0 * (std::sin(xi) / xi - std::cos(xi)) / (xi * xi));
      EXPECT_LE(std::abs(bessel_form(xi)),
                std::abs(bessel_form(above) - bessel_form(below)) + 8.0 * epsilon * bessel_terms)
          << "nu = " << nu << ", xi = " << xi;

      const double cotangent_terms = std::abs(xi / std::tan(xi)) + 1.0 + a * xi * xi / 4.0;
      EXPECT_LE(std::abs(cotangent_form(xi)),
                std::abs(cotangent_form(above) - cotangent_form(below)) +
                    8.0 * epsilon * cotangent_terms)
          << "nu = " << nu << ", xi = " << xi;
    }
  }
}

// Checks the roots against values computed independently with 40-digit arithmetic (mpmath,
// bisection on the sine/cosine form), and the classical nu = 1/4 fundamental xi_1 = 0.8160 pi
// (to the 4 digits in which it is usually quoted). The tolerance, 8 ulps relative, allows for the
// conditioning of the root in nu (the decimal nu is itself rounded to double).
TEST(SphereBreathingMode, RootsMatchHighPrecisionValues)
{
  struct Case
  {
    double nu;
    std::vector<double> roots;
  };
  const std::vector<Case> cases = {
      {0.25, {2.5634341631055000401, 6.0586700836699872981, 9.279861114446727043}},
      {0.3, {2.6702147332370524052, 6.0919890671742853378, 9.3008945060747833971}},
      {0.0, {2.0815759778181006105, 5.9403699905727124972, 9.2058401429366649154}},
      {-0.5, {1.2605588254848631738, 5.8218094538697816705, 9.1317926146569149928}}};
  for (const Case& c : cases)
  {
    const std::vector<double> roots = breathing_mode_roots(c.nu, c.roots.size());
    for (unsigned int m = 0; m < roots.size(); ++m)
      EXPECT_NEAR(roots[m], c.roots[m], 8.0 * epsilon * c.roots[m]) << "nu = " << c.nu;
  }
  EXPECT_NEAR(breathing_mode_roots(0.25, 1)[0] / pi, 0.8160, 0.5e-4);
  // The value 2.5704 sometimes quoted for nu = 1/4 is not a root.
  EXPECT_GT(std::abs(breathing_mode_roots(0.25, 1)[0] - 2.5704), 5e-3);
}

// Checks the two limits of Poisson's ratio. Incompressible, nu -> 0.5: a = 2 (1 - nu) / (1 - 2 nu)
// -> infinity and the equation becomes sin(xi) = 0; expanding xi cot(xi) = 1 - a xi^2 / 4 at
// xi = m pi - delta gives delta = 4 / (a m pi) + O(1 / a^2), checked to 20 / a^2. Vanishing bulk
// modulus, nu -> -1: a -> 4/3 and f(xi) = (a - 4/3) - (a/6 - 2/15) xi^2 + O(xi^4), so the
// fundamental tends to 0 as xi_1 = sqrt(45 (a - 4/3) / 4) (1 + O(xi_1^2)), checked to a relative
// 10 xi_1^2; this also exercises the small-argument series of j1.
TEST(SphereBreathingMode, IncompressibleAndZeroBulkModulusLimits)
{
  const double nu_incompressible = 0.5 - 1e-4;
  const double a_incompressible = 2.0 * (1.0 - nu_incompressible) / (1.0 - 2.0 * nu_incompressible);
  const std::vector<double> roots = breathing_mode_roots(nu_incompressible, 5);
  for (unsigned int m = 1; m <= roots.size(); ++m)
    EXPECT_NEAR(roots[m - 1],
                m * pi - 4.0 / (a_incompressible * m * pi),
                20.0 / (a_incompressible * a_incompressible))
        << "root " << m;

  const double nu_no_bulk = -1.0 + 1e-6;
  const double a_no_bulk  = 2.0 * (1.0 - nu_no_bulk) / (1.0 - 2.0 * nu_no_bulk);
  const double xi_1       = breathing_mode_roots(nu_no_bulk, 1)[0];
  const double asymptotic = std::sqrt(45.0 * (a_no_bulk - 4.0 / 3.0) / 4.0);
  EXPECT_NEAR(xi_1, asymptotic, 10.0 * asymptotic * asymptotic * asymptotic);
}

// Checks frequencies and shapes together, independently of the frequency equation: for an exact
// mode of the free sphere, integration by parts with the traction-free surface makes the Rayleigh
// quotient exactly omega^2,
//   omega^2 int rho u^2 r^2 dr = int [lambda (r u' + 2 u)^2 + 2 mu (r^2 u'^2 + 2 u^2)] dr,
// and modes of different frequencies are orthogonal in int rho u_m u_n r^2 dr. A wrong equation,
// root or shape breaks both. Composite Simpson with 20000 intervals has a relative error of order
// (xi / 20000)^4 < 1e-13 for these smooth integrands, hence the tolerance 1e-11.
TEST(SphereBreathingMode, RayleighQuotientAndOrthogonalityOfModeShapes)
{
  const ElasticSphere sphere = paper_sphere(1.0);
  const SphereBreathingModes modes(sphere, 4);
  const double E       = sphere.youngs_modulus;
  const double nu      = sphere.poissons_ratio;
  const double lambda  = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double mu      = E / (2.0 * (1.0 + nu));
  const double R       = sphere.radius;
  const unsigned int n = 20000;

  for (unsigned int m = 0; m < modes.n_modes(); ++m)
  {
    const double mass = simpson(
        R,
        n,
        [&](const double r) { return sphere.density * std::pow(modes.mode_shape(m, r) * r, 2); });
    const double stiffness = simpson(R,
                                     n,
                                     [&](const double r)
                                     {
                                       const double u  = modes.mode_shape(m, r);
                                       const double du = modes.mode_shape_derivative(m, r);
                                       return lambda * std::pow(r * du + 2.0 * u, 2) +
                                              2.0 * mu * (r * r * du * du + 2.0 * u * u);
                                     });
    const double omega     = modes.angular_frequency(m);
    EXPECT_NEAR(stiffness / mass, omega * omega, 1e-11 * omega * omega) << "mode " << m;

    for (unsigned int other = 0; other < m; ++other)
    {
      const double overlap =
          simpson(R,
                  n,
                  [&](const double r)
                  { return modes.mode_shape(m, r) * modes.mode_shape(other, r) * r * r; });
      const double norm_m =
          simpson(R, n, [&](const double r) { return std::pow(modes.mode_shape(m, r) * r, 2); });
      const double norm_other = simpson(
          R, n, [&](const double r) { return std::pow(modes.mode_shape(other, r) * r, 2); });
      EXPECT_NEAR(overlap / std::sqrt(norm_m * norm_other), 0.0, 1e-11)
          << "modes " << m << " and " << other;
    }
  }
}

// Checks the mode shape itself: value 1 at the surface and 0 at the centre, a traction-free
// surface (lambda + 2 mu) u'(R) + 2 lambda u(R) / R = 0 to round-off of its terms (1e-13
// relative), the derivative against central differences (step 1e-5 R: truncation ~1e-10, round-off
// ~1e-11 relative, so 1e-8), and the linear behaviour j1(x) ~ x / 3 near the centre (relative
// correction x^2 / 10 < 1e-16 at r = 1e-9 R, so round-off, 1e-14).
TEST(SphereBreathingMode, ModeShapeNormalizationTractionAndDerivative)
{
  const ElasticSphere sphere = paper_sphere(1.0);
  const SphereBreathingModes modes(sphere, 3);
  const double E      = sphere.youngs_modulus;
  const double nu     = sphere.poissons_ratio;
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double mu     = E / (2.0 * (1.0 + nu));
  const double R      = sphere.radius;

  for (unsigned int m = 0; m < modes.n_modes(); ++m)
  {
    EXPECT_NEAR(modes.mode_shape(m, R), 1.0, 2.0 * epsilon);
    EXPECT_EQ(modes.mode_shape(m, 0.0), 0.0);

    const double surface_slope = (lambda + 2.0 * mu) * modes.mode_shape_derivative(m, R);
    EXPECT_NEAR(surface_slope + 2.0 * lambda / R, 0.0, 1e-13 * std::abs(surface_slope));

    const double h = 1e-5 * R;
    for (const double r : {0.1 * R, 0.37 * R, 0.5 * R, 0.81 * R, R - h})
    {
      const double difference = (modes.mode_shape(m, r + h) - modes.mode_shape(m, r - h)) / (2 * h);
      EXPECT_NEAR(modes.mode_shape_derivative(m, r), difference, 1e-8 * std::abs(surface_slope))
          << "mode " << m << ", r = " << r;
    }

    const double xi       = modes.dimensionless_wavenumber(m);
    const double j1_of_xi = std::sin(xi) / (xi * xi) - std::cos(xi) / xi;
    const double r_small  = 1e-9 * R;
    const double linear   = xi * r_small / R / 3.0 / j1_of_xi;
    EXPECT_NEAR(modes.mode_shape(m, r_small), linear, 1e-14 * std::abs(linear));
    EXPECT_NEAR(modes.mode_shape_derivative(m, 0.0), xi / R / 3.0 / j1_of_xi, 1e-14 * xi / R);
  }
}

// Checks and prints the fundamental breathing period of the paper's sphere (R = 8, E = 5e3,
// nu = 0.3) for rho = 1 and rho = 0.001 against 20-digit values computed with mpmath (tolerance
// 1e-14 relative: a few ulps of the root and of c_p), and that the periods scale with sqrt(rho).
TEST(SphereBreathingMode, PaperSphereFundamentalPeriod)
{
  const SphereBreathingModes heavy(paper_sphere(1.0), 3);
  const SphereBreathingModes light(paper_sphere(0.001), 3);
  EXPECT_NEAR(heavy.dilatational_wave_speed(), 82.041265414236699042, 1e-14 * 82.04);
  EXPECT_NEAR(heavy.period(0), 0.22945171977475066684, 1e-14 * 0.2295);
  EXPECT_NEAR(light.period(0), 0.0072559004753090919311, 1e-14 * 0.007256);
  for (unsigned int m = 0; m < 3; ++m)
    EXPECT_NEAR(light.period(m) / heavy.period(m), std::sqrt(0.001), 1e-14);

  std::cout << std::setprecision(15) << "[ info     ] breathing modes of R = 8, E = 5e3, nu = 0.3:"
            << " xi = " << heavy.dimensionless_wavenumber(0) << ", "
            << heavy.dimensionless_wavenumber(1) << ", " << heavy.dimensionless_wavenumber(2)
            << "\n[ info     ] rho = 1:     c_p = " << heavy.dilatational_wave_speed()
            << ", periods " << heavy.period(0) << ", " << heavy.period(1) << ", " << heavy.period(2)
            << "\n[ info     ] rho = 0.001: c_p = " << light.dilatational_wave_speed()
            << ", periods " << light.period(0) << ", " << light.period(1) << ", " << light.period(2)
            << std::endl;
}

// Checks that bad input is rejected with the documented exceptions (no tolerance involved).
TEST(SphereBreathingMode, RejectsInvalidInput)
{
  EXPECT_THROW(SphereBreathingModes({0.0, 5e3, 0.3, 1.0}, 1), std::invalid_argument);
  EXPECT_THROW(SphereBreathingModes({8.0, -1.0, 0.3, 1.0}, 1), std::invalid_argument);
  EXPECT_THROW(SphereBreathingModes({8.0, 5e3, 0.3, 0.0}, 1), std::invalid_argument);
  EXPECT_THROW(SphereBreathingModes({8.0, 5e3, 0.5, 1.0}, 1), std::invalid_argument);
  EXPECT_THROW(SphereBreathingModes({8.0, 5e3, -1.0, 1.0}, 1), std::invalid_argument);
  EXPECT_THROW(SphereBreathingModes(paper_sphere(1.0), 0), std::invalid_argument);
  EXPECT_THROW(breathing_mode_roots(0.5, 1), std::invalid_argument);

  const SphereBreathingModes modes(paper_sphere(1.0), 2);
  EXPECT_THROW(modes.period(2), std::out_of_range);
  EXPECT_THROW(modes.mode_shape(0, 8.1), std::out_of_range);
  EXPECT_THROW(modes.mode_shape(0, -0.1), std::out_of_range);
}
