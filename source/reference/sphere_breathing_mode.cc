#include <dyncontact/reference/sphere_breathing_mode.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dyncontact
{
namespace
{
constexpr double pi = 3.14159265358979323846;

/// The spherical Bessel function j0(x) = sin(x) / x, with j0(0) = 1.
double spherical_bessel_j0(const double x)
{
  return x == 0.0 ? 1.0 : std::sin(x) / x;
}

/**
 * j1(x) / x for x >= 0, with j1 the spherical Bessel function of the first kind of order 1. Below
 * x = 1 the closed form (sin(x) / x - cos(x)) / x^2 cancels, so there the power series
 * sum_k (-1)^k x^(2k) / (2^k k! (2k + 3)!!) = 1/3 - x^2/30 + ... is summed until its terms no
 * longer change the sum (each term is at most 1/10 of the previous one).
 */
double spherical_bessel_j1_over_x(const double x)
{
  if (x >= 1.0)
    return (std::sin(x) / x - std::cos(x)) / (x * x);
  double term = 1.0 / 3.0;
  double sum  = term;
  for (unsigned int k = 0; std::abs(term) > std::numeric_limits<double>::epsilon() * sum; ++k)
  {
    term *= -x * x / (2.0 * (k + 1) * (2.0 * k + 5.0));
    sum += term;
  }
  return sum;
}

/// The ratio a = (lambda + 2 mu) / mu = 2 (1 - nu) / (1 - 2 nu) for Poisson's ratio @p nu.
double dilatational_to_shear_modulus_ratio(const double nu)
{
  return 2.0 * (1.0 - nu) / (1.0 - 2.0 * nu);
}

/// Throw std::invalid_argument unless -1 < @p nu < 0.5 (and not NaN).
void require_breathing_mode_poissons_ratio(const double nu)
{
  if (!(nu > -1.0 && nu < 0.5))
    throw std::invalid_argument("SphereBreathingModes: Poisson's ratio must lie in (-1, 0.5)");
}

/// Throw std::invalid_argument with @p message unless @p value is positive (and not NaN).
void require_positive(const double value, const std::string& message)
{
  if (!(value > 0.0))
    throw std::invalid_argument("SphereBreathingModes: " + message + " must be positive");
}
} // namespace

double breathing_mode_frequency_function(const double xi, const double poissons_ratio)
{
  return dilatational_to_shear_modulus_ratio(poissons_ratio) * spherical_bessel_j0(xi) -
         4.0 * spherical_bessel_j1_over_x(xi);
}

std::vector<double> breathing_mode_roots(const double poissons_ratio, const unsigned int n_roots)
{
  require_breathing_mode_poissons_ratio(poissons_ratio);
  if (n_roots == 0)
    throw std::invalid_argument("breathing_mode_roots: at least one root must be asked for");
  std::vector<double> roots;
  for (unsigned int m = 1; m <= n_roots; ++m)
  {
    // (-1)^(m-1) f is positive left of the only root in ((m-1) pi, m pi) and negative right of it.
    const double sign_left_of_root = (m % 2 == 1) ? 1.0 : -1.0;
    double left                    = (m - 1) * pi;
    double right                   = m * pi;
    while (true)
    {
      const double middle = 0.5 * (left + right);
      if (middle <= left || middle >= right)
        break;
      if (sign_left_of_root * breathing_mode_frequency_function(middle, poissons_ratio) > 0.0)
        left = middle;
      else
        right = middle;
    }
    const double left_residual = std::abs(breathing_mode_frequency_function(left, poissons_ratio));
    const double right_residual =
        std::abs(breathing_mode_frequency_function(right, poissons_ratio));
    roots.push_back(left_residual <= right_residual ? left : right);
  }
  return roots;
}

SphereBreathingModes::SphereBreathingModes(const ElasticSphere& sphere, const unsigned int n_modes)
    : radius(sphere.radius)
{
  require_positive(sphere.radius, "the radius");
  require_positive(sphere.youngs_modulus, "Young's modulus");
  require_positive(sphere.density, "the density");
  require_breathing_mode_poissons_ratio(sphere.poissons_ratio);
  if (n_modes == 0)
    throw std::invalid_argument("SphereBreathingModes: at least one mode must be asked for");

  const double nu = sphere.poissons_ratio;
  const double p_wave_modulus =
      sphere.youngs_modulus * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  wave_speed = std::sqrt(p_wave_modulus / sphere.density);
  roots      = breathing_mode_roots(nu, n_modes);
}

unsigned int SphereBreathingModes::n_modes() const
{
  return static_cast<unsigned int>(roots.size());
}

double SphereBreathingModes::dilatational_wave_speed() const
{
  return wave_speed;
}

double SphereBreathingModes::dimensionless_wavenumber(const unsigned int mode) const
{
  return checked_root(mode, radius);
}

double SphereBreathingModes::angular_frequency(const unsigned int mode) const
{
  return dimensionless_wavenumber(mode) * wave_speed / radius;
}

double SphereBreathingModes::period(const unsigned int mode) const
{
  return 2.0 * pi / angular_frequency(mode);
}

double SphereBreathingModes::mode_shape(const unsigned int mode, const double r) const
{
  const double xi = checked_root(mode, r);
  const double x  = xi * r / radius;
  return x * spherical_bessel_j1_over_x(x) / (xi * spherical_bessel_j1_over_x(xi));
}

double SphereBreathingModes::mode_shape_derivative(const unsigned int mode, const double r) const
{
  // d/dr j1(k r) = k j1'(k r) with j1'(x) = j0(x) - 2 j1(x) / x.
  const double xi = checked_root(mode, r);
  const double x  = xi * r / radius;
  const double k  = xi / radius;
  return k * (spherical_bessel_j0(x) - 2.0 * spherical_bessel_j1_over_x(x)) /
         (xi * spherical_bessel_j1_over_x(xi));
}

double SphereBreathingModes::checked_root(const unsigned int mode, const double r) const
{
  if (mode >= roots.size())
    throw std::out_of_range("SphereBreathingModes: mode " + std::to_string(mode) +
                            " was not computed");
  if (!(r >= 0.0 && r <= radius * (1.0 + 4.0 * std::numeric_limits<double>::epsilon())))
    throw std::out_of_range("SphereBreathingModes: radius outside the sphere");
  return roots[mode];
}
} // namespace dyncontact
