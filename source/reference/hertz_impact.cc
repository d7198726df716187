#include <dyncontact/reference/hertz_impact.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dyncontact
{
namespace
{
constexpr double pi = 3.14159265358979323846;

/// The split point z_s of z = x^{5/2} = 1 - u^2 between the two parametrizations of the history.
constexpr double split_z = 0.35;

/// Number of Gauss-Legendre points of the quadratures in the history.
constexpr unsigned int n_gauss_points = 32;

/// Gauss-Legendre nodes and weights on [-1, 1].
struct GaussLegendreRule
{
  std::array<double, n_gauss_points> nodes;
  std::array<double, n_gauss_points> weights;
};

/**
 * The n_gauss_points-point Gauss-Legendre rule, computed once: each node by Newton's method on the
 * Legendre polynomial P_n from the classical starting value cos(pi (i + 3/4) / (n + 1/2)), until
 * the Newton step no longer exceeds round-off.
 */
const GaussLegendreRule& gauss_legendre_rule()
{
  static const GaussLegendreRule rule = []()
  {
    GaussLegendreRule result{};
    const unsigned int n = n_gauss_points;
    for (unsigned int i = 0; i < n; ++i)
    {
      double x          = std::cos(pi * (i + 0.75) / (n + 0.5));
      double derivative = 1.0;
      for (unsigned int iteration = 0; iteration < 100; ++iteration)
      {
        // P_n(x) and P_n'(x) by the three-term recurrence.
        double p_previous = 1.0;
        double p          = x;
        for (unsigned int k = 2; k <= n; ++k)
        {
          const double p_next = ((2.0 * k - 1.0) * x * p - (k - 1.0) * p_previous) / k;
          p_previous          = p;
          p                   = p_next;
        }
        derivative        = n * (x * p - p_previous) / (x * x - 1.0);
        const double step = p / derivative;
        x -= step;
        if (std::abs(step) <= 1e-16)
          break;
      }
      result.nodes[i]   = x;
      result.weights[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
    return result;
  }();
  return rule;
}

/// The Gauss-Legendre approximation of the integral of @p f over [0, @p upper].
template <typename Function>
double integrate_from_zero(const double upper, const Function& f)
{
  const GaussLegendreRule& rule = gauss_legendre_rule();
  double sum                    = 0.0;
  for (unsigned int i = 0; i < n_gauss_points; ++i)
    sum += rule.weights[i] * f(0.5 * upper * (1.0 + rule.nodes[i]));
  return 0.5 * upper * sum;
}

/**
 * tau(x) = integral_0^x dy / sqrt(1 - y^{5/2}), the scaled time to reach the scaled approach x in
 * [0, x_s], as integral_0^{sqrt x} 2 w / sqrt(1 - w^5) dw (y = w^2), whose integrand is analytic.
 */
double scaled_time_from_touch(const double x)
{
  return integrate_from_zero(
      std::sqrt(x), [](const double w) { return 2.0 * w / std::sqrt(1.0 - std::pow(w, 5)); });
}

/**
 * The scaled time from the state with scaled rate u in [0, u_s] to the peak: substituting u =
 * sqrt(1 - y^{5/2}) in integral_x^1 dy / sqrt(1 - y^{5/2}) gives (4/5) integral_0^u (1 -
 * s^2)^{-3/5} ds, again with an analytic integrand.
 */
double scaled_time_to_peak(const double u)
{
  return 0.8 * integrate_from_zero(u, [](const double s) { return std::pow(1.0 - s * s, -0.6); });
}

/**
 * The root of the convex, increasing function @p g (with derivative @p g_derivative) below
 * @p start, where g(start) >= 0: Newton's method then decreases monotonically to the root, so it
 * stops when a step no longer decreases the iterate (round-off) or after a generous number of
 * (quadratically converging) steps.
 */
template <typename Function, typename Derivative>
double decreasing_newton_root(double start, const Function& g, const Derivative& g_derivative)
{
  double x = start;
  for (unsigned int iteration = 0; iteration < 100; ++iteration)
  {
    const double next = x - g(x) / g_derivative(x);
    if (!(next < x))
      break;
    x = std::max(next, 0.0);
  }
  return x;
}

/**
 * Throw std::invalid_argument with @p message unless @p value is positive (and not NaN) and, if
 * not @p infinity_allowed, finite.
 */
void require_positive(const double value,
                      const std::string& message,
                      const bool infinity_allowed = false)
{
  if (!(value > 0.0) || (!infinity_allowed && std::isinf(value)))
    throw std::invalid_argument("HertzImpact: " + message + " must be positive" +
                                (infinity_allowed ? "" : " and finite"));
}

/// Throw std::invalid_argument unless @p nu lies in (-1, 0.5].
void require_poissons_ratio(const double nu)
{
  if (!(nu > -1.0 && nu <= 0.5))
    throw std::invalid_argument("HertzImpact: Poisson's ratio must lie in (-1, 0.5], not " +
                                std::to_string(nu));
}

/// a b / (a + b), or the finite one of @p a and @p b if the other is infinite.
double series_combination(const double a, const double b)
{
  if (std::isinf(b))
    return a;
  if (std::isinf(a))
    return b;
  return a * b / (a + b);
}

/// Check the data of @p sphere that Hertz's theory needs.
void require_valid_sphere(const ElasticSphere& sphere)
{
  require_positive(sphere.radius, "the radius");
  require_positive(sphere.youngs_modulus, "Young's modulus");
  require_positive(sphere.density, "the density");
  require_poissons_ratio(sphere.poissons_ratio);
}
} // namespace

double sphere_mass(const ElasticSphere& sphere)
{
  return sphere.density * 4.0 / 3.0 * pi * std::pow(sphere.radius, 3);
}

double effective_radius(const double r1, const double r2)
{
  return series_combination(r1, r2);
}

double effective_modulus(const double e1, const double nu1, const double e2, const double nu2)
{
  return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

double effective_mass(const double m1, const double m2)
{
  return series_combination(m1, m2);
}

HertzImpact::HertzImpact(const double effective_radius,
                         const double effective_modulus,
                         const double effective_mass,
                         const double relative_approach_speed,
                         const double first_touch_time)
    : effective_radius_value(effective_radius), effective_modulus_value(effective_modulus),
      effective_mass_value(effective_mass), speed(relative_approach_speed),
      touch_time(first_touch_time)
{
  require_positive(effective_radius, "the effective radius");
  require_positive(effective_modulus, "the effective modulus");
  require_positive(effective_mass, "the effective mass");
  require_positive(relative_approach_speed, "the relative approach speed");

  stiffness         = 4.0 / 3.0 * effective_modulus_value * std::sqrt(effective_radius_value);
  max_approach      = std::pow(15.0 * effective_mass_value * speed * speed /
                              (16.0 * effective_modulus_value * std::sqrt(effective_radius_value)),
                          0.4);
  duration          = contact_duration_coefficient() * max_approach / speed;
  split_scaled_time = scaled_time_from_touch(std::pow(split_z, 0.4));
}

HertzImpact HertzImpact::two_spheres(const ElasticSphere& first,
                                     const ElasticSphere& second,
                                     const double relative_approach_speed,
                                     const double first_touch_time)
{
  require_valid_sphere(first);
  require_valid_sphere(second);
  return HertzImpact(
      dyncontact::effective_radius(first.radius, second.radius),
      dyncontact::effective_modulus(
          first.youngs_modulus, first.poissons_ratio, second.youngs_modulus, second.poissons_ratio),
      dyncontact::effective_mass(sphere_mass(first), sphere_mass(second)),
      relative_approach_speed,
      first_touch_time);
}

HertzImpact HertzImpact::sphere_on_flat(const ElasticSphere& sphere,
                                        const ElasticFlatBody& flat,
                                        const double relative_approach_speed,
                                        const double first_touch_time)
{
  require_valid_sphere(sphere);
  require_positive(flat.youngs_modulus, "the flat body's Young's modulus", true);
  require_poissons_ratio(flat.poissons_ratio);
  require_positive(flat.mass, "the flat body's mass", true);
  return HertzImpact(
      sphere.radius,
      dyncontact::effective_modulus(
          sphere.youngs_modulus, sphere.poissons_ratio, flat.youngs_modulus, flat.poissons_ratio),
      dyncontact::effective_mass(sphere_mass(sphere), flat.mass),
      relative_approach_speed,
      first_touch_time);
}

double HertzImpact::contact_duration_coefficient()
{
  return 2.0 * 0.4 * std::tgamma(0.4) * std::sqrt(pi) / std::tgamma(0.9);
}

double HertzImpact::effective_radius() const
{
  return effective_radius_value;
}

double HertzImpact::effective_modulus() const
{
  return effective_modulus_value;
}

double HertzImpact::effective_mass() const
{
  return effective_mass_value;
}

double HertzImpact::contact_stiffness() const
{
  return stiffness;
}

double HertzImpact::relative_approach_speed() const
{
  return speed;
}

double HertzImpact::first_touch_time() const
{
  return touch_time;
}

double HertzImpact::maximum_approach() const
{
  return max_approach;
}

double HertzImpact::maximum_force() const
{
  return stiffness * std::pow(max_approach, 1.5);
}

double HertzImpact::contact_duration() const
{
  return duration;
}

double HertzImpact::impulse() const
{
  return 2.0 * effective_mass_value * speed;
}

double HertzImpact::approach(const double t) const
{
  const double time_since_touch = t - touch_time;
  if (time_since_touch < 0.0)
    return speed * time_since_touch;
  if (time_since_touch > duration)
    return -speed * (time_since_touch - duration);
  return max_approach * state_in_contact(time_since_touch).x;
}

double HertzImpact::approach_rate(const double t) const
{
  const double time_since_touch = t - touch_time;
  if (time_since_touch < 0.0)
    return speed;
  if (time_since_touch > duration)
    return -speed;
  const double rate = speed * state_in_contact(time_since_touch).u;
  return time_since_touch <= 0.5 * duration ? rate : -rate;
}

double HertzImpact::approach_under_force(const double force) const
{
  return std::pow(force / stiffness, 2.0 / 3.0);
}

double HertzImpact::contact_force(const double t) const
{
  const double time_since_touch = t - touch_time;
  if (time_since_touch < 0.0 || time_since_touch > duration)
    return 0.0;
  return maximum_force() * std::pow(state_in_contact(time_since_touch).x, 1.5);
}

std::vector<double> HertzImpact::contact_force_history(const std::vector<double>& times) const
{
  std::vector<double> forces;
  forces.reserve(times.size());
  for (const double t : times)
    forces.push_back(contact_force(t));
  return forces;
}

HertzImpact::ScaledState HertzImpact::state_in_contact(const double time_since_touch) const
{
  // The motion is symmetric about the peak at t_c / 2: measure the scaled time from the nearer end
  // of the contact and, separately (to avoid cancellation), to the peak.
  const double time_scale = max_approach / speed;
  const double scaled_time_from_end =
      std::min(time_since_touch, duration - time_since_touch) / time_scale;
  const double scaled_time_from_peak = std::abs(time_since_touch - 0.5 * duration) / time_scale;

  if (scaled_time_from_end <= split_scaled_time)
  {
    // Solve tau(x) = scaled_time_from_end; tau(x) >= x, so x = tau (at most x_s, which lies above
    // the root) is above the root.
    const double x = decreasing_newton_root(
        std::min(scaled_time_from_end, std::pow(split_z, 0.4)),
        [&](const double y) { return scaled_time_from_touch(y) - scaled_time_from_end; },
        [](const double y) { return 1.0 / std::sqrt(1.0 - std::pow(y, 2.5)); });
    return {x, std::sqrt(1.0 - std::pow(x, 2.5))};
  }
  // Solve (4/5) integral_0^u (1 - s^2)^{-3/5} ds = scaled_time_from_peak; the integral is at least
  // 4 u / 5, so u = 5/4 times the time (at most u_s, which lies above the root) is above the root.
  const double u = decreasing_newton_root(
      std::min(1.25 * scaled_time_from_peak, std::sqrt(1.0 - split_z)),
      [&](const double s) { return scaled_time_to_peak(s) - scaled_time_from_peak; },
      [](const double s) { return 0.8 * std::pow(1.0 - s * s, -0.6); });
  return {std::pow(1.0 - u * u, 0.4), u};
}
} // namespace dyncontact
