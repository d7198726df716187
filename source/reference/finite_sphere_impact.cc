#include <dyncontact/reference/finite_sphere_impact.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dyncontact
{
namespace
{
constexpr double pi = 3.14159265358979323846;

/// The step and the half-width of the tanh-sinh rule in its variable tau.
constexpr double tanh_sinh_step          = 1.0 / 32.0;
constexpr unsigned int n_tanh_sinh_steps = 112; // |tau| <= 3.5

/// The split y = F / F_max = 1/2 between the two sides, as p = y^{2/3} and q = sqrt(1 - y).
const double split_p = std::pow(0.5, 2.0 / 3.0);
const double split_q = std::sqrt(0.5);

/**
 * The tanh-sinh approximation of the integral of @p f over [0, @p upper]: with z = upper / (1 +
 * exp(-pi sinh tau)), the sum over tau = j h, |j| <= n_tanh_sinh_steps, of h dz/dtau f(z). The
 * nodes never reach the ends (the outermost are 3e-23 upper from them), so f may be singular
 * there; the weights decay double exponentially, so the truncation is below round-off for an f
 * that is integrable like a power of z at the ends.
 */
template <typename Function>
double tanh_sinh_integral(const double upper, const Function& f)
{
  double sum = 0.0;
  for (int j = -static_cast<int>(n_tanh_sinh_steps); j <= static_cast<int>(n_tanh_sinh_steps); ++j)
  {
    const double tau    = j * tanh_sinh_step;
    const double s      = 0.5 * pi * std::sinh(tau);
    const double z      = upper / (1.0 + std::exp(-2.0 * s));
    const double weight = 0.5 * upper * 0.5 * pi * std::cosh(tau) / std::pow(std::cosh(s), 2);
    sum += weight * f(z);
  }
  return tanh_sinh_step * sum;
}

/**
 * The root in [@p lower, @p upper] of g(z) = @p target, g increasing with the positive derivative
 * @p g_derivative and g(lower) <= target <= g(upper): Newton's method, replaced by bisection when
 * it would leave the current bracket, until the step or the bracket is at round-off.
 */
template <typename Function, typename Derivative>
double increasing_root(double lower,
                       double upper,
                       const double target,
                       const Function& g,
                       const Derivative& g_derivative)
{
  constexpr double tolerance = 4.0 * std::numeric_limits<double>::epsilon();
  double z                   = 0.5 * (lower + upper);
  for (unsigned int iteration = 0; iteration < 200; ++iteration)
  {
    const double residual = g(z) - target;
    if (residual == 0.0)
      return z;
    (residual < 0.0 ? lower : upper) = z;
    double next                      = z - residual / g_derivative(z);
    if (!(next > lower && next < upper))
      next = 0.5 * (lower + upper);
    if (std::abs(next - z) <= tolerance * std::abs(z) || upper - lower <= tolerance * upper)
      return next;
    z = next;
  }
  return z;
}
} // namespace

FiniteSphereImpact::FiniteSphereImpact(const ElasticSphere& first,
                                       const ElasticSphere& second,
                                       const double relative_approach_speed,
                                       const double first_touch_time,
                                       const std::optional<double> first_c0,
                                       const std::optional<double> second_c0)
    : FiniteSphereImpact(
          HertzImpact::two_spheres(first, second, relative_approach_speed, first_touch_time),
          {{&first, &second}},
          {{first_c0, second_c0}})
{
}

FiniteSphereImpact FiniteSphereImpact::sphere_on_flat(const ElasticSphere& sphere,
                                                      const ElasticFlatBody& flat,
                                                      const double relative_approach_speed,
                                                      const double first_touch_time,
                                                      const std::optional<double> c0)
{
  return FiniteSphereImpact(
      HertzImpact::sphere_on_flat(sphere, flat, relative_approach_speed, first_touch_time),
      {{&sphere, nullptr}},
      {{c0, std::nullopt}});
}

FiniteSphereImpact::FiniteSphereImpact(const HertzImpact& hertz,
                                       const std::array<const ElasticSphere*, 2>& spheres,
                                       const std::array<std::optional<double>, 2>& c0_given)
    : hertz_impact(hertz), corrections{{0.0, 0.0}, {0.0, 0.0}}, log_slope(0.0)
{
  for (unsigned int i = 0; i < 2; ++i)
  {
    if (!spheres[i]) // a flat body: a half-space, no finite-size term
      continue;
    const ElasticSphere& sphere = *spheres[i];
    const double nu             = sphere.poissons_ratio;
    if (!c0_given[i] && nu != 0.3)
      throw std::invalid_argument("FiniteSphereImpact: C0 is known for nu = 0.3 only; give it "
                                  "for sphere " +
                                  std::to_string(i + 1) + " with nu = " + std::to_string(nu));
    const double c0 = c0_given[i].value_or(c0_for_nu_0_3);
    if (!std::isfinite(c0))
      throw std::invalid_argument("FiniteSphereImpact: C0 must be finite");
    const double er = sphere.youngs_modulus * sphere.radius;
    const double k  = log_coefficient(nu);
    corrections[i]  = {(c0 + k * std::log(sphere.radius)) / er, k / er};
    log_slope += k / (3.0 * er);
  }

  // W(F) increases while delta'(F) > 0, and delta' decreases: double the bracket from Hertz's peak
  // force while W is short of the energy, as long as the law is still increasing.
  const double energy =
      0.5 * hertz_impact.effective_mass() * std::pow(hertz_impact.relative_approach_speed(), 2);
  double upper = hertz_impact.maximum_force();
  for (unsigned int doubling = 0; elastic_energy(upper) < energy; ++doubling)
  {
    if (!(compliance(upper) > 0.0) || doubling == 100)
      throw std::domain_error("FiniteSphereImpact: the finite-sphere law delta(F) stops increasing "
                              "before it stores the impact energy (outside its range)");
    upper *= 2.0;
  }
  max_force = increasing_root(
      0.0,
      upper,
      energy,
      [&](const double f) { return elastic_energy(f); },
      [&](const double f) { return f * compliance(f); });
  if (!(compliance(max_force) > 0.0))
    throw std::domain_error("FiniteSphereImpact: the finite-sphere law delta(F) is not increasing "
                            "up to the peak force " +
                            std::to_string(max_force) + " (outside its range)");

  split_time_from_touch   = time_from_touch(split_p);
  duration                = 2.0 * (split_time_from_touch + time_to_peak(split_q));
  const double touch_side = tanh_sinh_integral(
      split_p,
      [&](const double p) { return max_force * std::pow(p, 1.5) * touch_side_integrand(p); });
  const double peak_side = tanh_sinh_integral(
      split_q, [&](const double q) { return max_force * (1.0 - q * q) * peak_side_integrand(q); });
  impulse_value = 2.0 * (touch_side + peak_side);
}

double FiniteSphereImpact::log_coefficient(const double poissons_ratio)
{
  return (1.0 + poissons_ratio) * std::pow(1.0 - 2.0 * poissons_ratio, 2) / (2.0 * pi);
}

const HertzImpact& FiniteSphereImpact::hertz() const
{
  return hertz_impact;
}

double FiniteSphereImpact::contact_radius(const double force) const
{
  return std::cbrt(3.0 * force * hertz_impact.effective_radius() /
                   (4.0 * hertz_impact.effective_modulus()));
}

double FiniteSphereImpact::approach_under_force(const double force) const
{
  if (force == 0.0)
    return 0.0;
  return hertz_impact.approach_under_force(force) + force * correction_coefficient(force);
}

double FiniteSphereImpact::elastic_energy(const double force) const
{
  if (force == 0.0)
    return 0.0;
  return 0.4 * force * hertz_impact.approach_under_force(force) +
         0.5 * force * force * (correction_coefficient(force) - 0.5 * log_slope);
}

double FiniteSphereImpact::maximum_force() const
{
  return max_force;
}

double FiniteSphereImpact::maximum_approach() const
{
  return approach_under_force(max_force);
}

double FiniteSphereImpact::contact_duration() const
{
  return duration;
}

double FiniteSphereImpact::impulse() const
{
  return impulse_value;
}

double FiniteSphereImpact::approach(const double t) const
{
  const double time_since_touch = t - hertz_impact.first_touch_time();
  const double speed            = hertz_impact.relative_approach_speed();
  if (time_since_touch < 0.0)
    return speed * time_since_touch;
  if (time_since_touch > duration)
    return -speed * (time_since_touch - duration);
  return approach_under_force(max_force * state_in_contact(time_since_touch).y);
}

double FiniteSphereImpact::approach_rate(const double t) const
{
  const double time_since_touch = t - hertz_impact.first_touch_time();
  const double speed            = hertz_impact.relative_approach_speed();
  if (time_since_touch < 0.0)
    return speed;
  if (time_since_touch > duration)
    return -speed;
  const double rate = state_in_contact(time_since_touch).rate;
  return time_since_touch <= 0.5 * duration ? rate : -rate;
}

double FiniteSphereImpact::contact_force(const double t) const
{
  const double time_since_touch = t - hertz_impact.first_touch_time();
  if (time_since_touch < 0.0 || time_since_touch > duration)
    return 0.0;
  return max_force * state_in_contact(time_since_touch).y;
}

std::vector<double>
FiniteSphereImpact::contact_force_history(const std::vector<double>& times) const
{
  std::vector<double> forces;
  forces.reserve(times.size());
  for (const double t : times)
    forces.push_back(contact_force(t));
  return forces;
}

double FiniteSphereImpact::correction_coefficient(const double force) const
{
  const double log_a = std::log(contact_radius(force));
  double sum         = 0.0;
  for (const Correction& c : corrections)
    sum += c.constant_over_er - c.log_coefficient_over_er * log_a;
  return sum;
}

double FiniteSphereImpact::compliance(const double force) const
{
  return 2.0 / 3.0 * hertz_impact.approach_under_force(force) / force +
         correction_coefficient(force) - log_slope;
}

double FiniteSphereImpact::rate_at(const double x) const
{
  if (x >= 1.0)
    return hertz_impact.relative_approach_speed();
  // W(F_max) - W(F_max y), y = 1 - x: the Hertz part (2/5) F_max delta_H(F_max) (1 - y^{5/3}) and
  // the correction F_max^2 / 2 ((c(F_max) - b / 2) (1 - y^2) + b y^2 ln y).
  const double y     = 1.0 - x;
  const double log_y = std::log1p(-x);
  const double hertz = 0.4 * max_force * hertz_impact.approach_under_force(max_force) *
                       -std::expm1(5.0 / 3.0 * log_y);
  const double excess = 0.5 * max_force * max_force *
                        ((correction_coefficient(max_force) - 0.5 * log_slope) * x * (2.0 - x) +
                         log_slope * y * y * log_y);
  return std::sqrt(2.0 * (hertz + excess) / hertz_impact.effective_mass());
}

double FiniteSphereImpact::touch_side_integrand(const double p) const
{
  // dt = delta'(F) dF / rate with F = F_max p^{3/2}: the Hertz part of delta'(F) dF / dp is
  // delta_H(F_max), the rest 3/2 F_max sqrt(p) (c(F) - b).
  const double y = std::pow(p, 1.5);
  const double f = max_force * y;
  return (hertz_impact.approach_under_force(max_force) +
          1.5 * max_force * std::sqrt(p) * (correction_coefficient(f) - log_slope)) /
         rate_at(1.0 - y);
}

double FiniteSphereImpact::peak_side_integrand(const double q) const
{
  // dt = delta'(F) dF / rate with F = F_max (1 - q^2); the rate is about proportional to q.
  return 2.0 * q * max_force * compliance(max_force * (1.0 - q * q)) / rate_at(q * q);
}

double FiniteSphereImpact::time_from_touch(const double p) const
{
  return tanh_sinh_integral(p, [&](const double s) { return touch_side_integrand(s); });
}

double FiniteSphereImpact::time_to_peak(const double q) const
{
  return tanh_sinh_integral(q, [&](const double s) { return peak_side_integrand(s); });
}

FiniteSphereImpact::State FiniteSphereImpact::state_in_contact(const double time_since_touch) const
{
  // As in HertzImpact: the time from the nearer end of the contact and, separately, to the peak.
  const double time_from_end  = std::min(time_since_touch, duration - time_since_touch);
  const double time_from_peak = std::abs(time_since_touch - 0.5 * duration);
  if (time_from_end <= split_time_from_touch)
  {
    const double p = time_from_end == 0.0
                         ? 0.0
                         : increasing_root(
                               0.0,
                               split_p,
                               time_from_end,
                               [&](const double s) { return time_from_touch(s); },
                               [&](const double s) { return touch_side_integrand(s); });
    const double y = std::pow(p, 1.5);
    return {y, rate_at(1.0 - y)};
  }
  const double q = time_from_peak == 0.0
                       ? 0.0
                       : increasing_root(
                             0.0,
                             split_q,
                             time_from_peak,
                             [&](const double s) { return time_to_peak(s); },
                             [&](const double s) { return peak_side_integrand(s); });
  return {1.0 - q * q, rate_at(q * q)};
}
} // namespace dyncontact
