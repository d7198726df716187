#include <dyncontact/reference/impact_measures.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace dyncontact
{
namespace
{
/// Two steps of a ringing window are equal when they differ by at most this fraction of a step.
constexpr double relative_step_tolerance = 1e-9;

[[noreturn]] void fail(const std::string& message)
{
  throw std::invalid_argument("measure_impact: " + message);
}

/** Checks the history as documented for measure_impact(). */
void check_history(const std::vector<double>& times, const std::vector<double>& force)
{
  if (times.size() != force.size())
    fail("the times and forces differ in number (" + std::to_string(times.size()) + " and " +
         std::to_string(force.size()) + ")");
  if (times.size() < 3)
    fail("at least 3 samples are needed, got " + std::to_string(times.size()));
  for (std::size_t n = 0; n < times.size(); ++n)
  {
    if (!std::isfinite(times[n]))
      fail("time " + std::to_string(n) + " is not finite");
    if (!std::isfinite(force[n]))
      fail("force " + std::to_string(n) + " is not finite");
  }
  for (std::size_t n = 0; n + 1 < times.size(); ++n)
    if (!(times[n + 1] > times[n]))
      fail("the times must increase strictly, but time " + std::to_string(n + 1) +
           " does not exceed time " + std::to_string(n));
}

/**
 * Whether the four steps of the window of samples n - 2 .. n + 2 are equal: to 1e-9 of a step
 * plus the round-off of the stored times (a difference of two times carries up to about two ulps
 * of the larger one).
 */
bool uniform_window(const std::vector<double>& times, const std::size_t n)
{
  const double step = times[n - 1] - times[n - 2];
  const double tolerance =
      relative_step_tolerance * step + 4.0 * std::numeric_limits<double>::epsilon() *
                                           std::max(std::abs(times[n - 2]), std::abs(times[n + 2]));
  for (std::size_t k = n - 1; k < n + 2; ++k)
    if (std::abs(times[k + 1] - times[k] - step) > tolerance)
      return false;
  return true;
}

/**
 * The zero of the straight line through (@p t_outer, @p g_outer) and (@p t_inner, @p g_inner),
 * where g = F^{2/3} and the outer sample is the one nearer the end of the contact, clamped to the
 * interval between @p t_outer and @p t_boundary (the sample just outside the contact). If g does
 * not increase into the contact (g_inner <= g_outer), the line gives no zero on that side and
 * @p t_boundary is returned.
 */
double extrapolated_contact_limit(const double t_boundary,
                                  const double t_outer,
                                  const double g_outer,
                                  const double t_inner,
                                  const double g_inner)
{
  if (!(g_inner > g_outer))
    return t_boundary;
  const double zero = t_outer - g_outer * (t_inner - t_outer) / (g_inner - g_outer);
  return t_boundary < t_outer ? std::max(zero, t_boundary) : std::min(zero, t_boundary);
}
/**
 * The peak of a force history as (force, time): the vertex of the parabola through the largest
 * sample and its neighbours, if it is concave: F0 + b s + c s^2 in s = t - t0, from the divided
 * differences of the two steps h1 = t0 - t_before and h2 = t_after - t0 (for h1 = h2 = dt:
 * b = (F+ - F-) / (2 dt), c = (F+ - 2 F0 + F-) / (2 dt^2)); else the largest sample.
 */
std::pair<double, double> interpolated_peak(const std::vector<double>& times,
                                            const std::vector<double>& force)
{
  const std::size_t largest =
      static_cast<std::size_t>(std::max_element(force.begin(), force.end()) - force.begin());
  if (largest > 0 && largest + 1 < force.size())
  {
    const double h1          = times[largest] - times[largest - 1];
    const double h2          = times[largest + 1] - times[largest];
    const double slope_left  = (force[largest] - force[largest - 1]) / h1;
    const double slope_right = (force[largest + 1] - force[largest]) / h2;
    const double b           = (slope_left * h2 + slope_right * h1) / (h1 + h2);
    const double c           = (slope_right - slope_left) / (h1 + h2);
    if (c < 0.0)
      return {force[largest] - b * b / (4.0 * c), times[largest] - b / (2.0 * c)};
  }
  return {force[largest], times[largest]};
}

} // namespace

ImpactMeasures measure_impact(const std::vector<double>& times, const std::vector<double>& force)
{
  check_history(times, force);
  const std::size_t n_samples = times.size();

  std::vector<std::size_t> positive_samples;
  for (std::size_t n = 0; n < n_samples; ++n)
    if (force[n] > 0.0)
      positive_samples.push_back(n);
  if (positive_samples.empty())
    return {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0};

  ImpactMeasures measures{};
  measures.contact_samples = static_cast<unsigned int>(positive_samples.size());
  const std::size_t first  = positive_samples.front();
  const std::size_t last   = positive_samples.back();

  // Contact start and end from F^{2/3}, linear in t near both ends.
  const auto g = [&](const std::size_t n) { return std::cbrt(force[n] * force[n]); };
  if (first == 0)
    measures.contact_start = times.front();
  else if (positive_samples.size() < 2)
    measures.contact_start = times[first - 1];
  else
  {
    const std::size_t second = positive_samples[1];
    measures.contact_start   = extrapolated_contact_limit(
        times[first - 1], times[first], g(first), times[second], g(second));
  }
  if (last == n_samples - 1)
    measures.contact_end = times.back();
  else if (positive_samples.size() < 2)
    measures.contact_end = times[last + 1];
  else
  {
    const std::size_t second_last = positive_samples[positive_samples.size() - 2];
    measures.contact_end          = extrapolated_contact_limit(
        times[last + 1], times[last], g(last), times[second_last], g(second_last));
  }
  measures.duration = measures.contact_end - measures.contact_start;

  std::tie(measures.peak_force, measures.peak_time) = interpolated_peak(times, force);

  // Impulse: trapezoidal rule over all samples, each step with its own size.
  for (std::size_t n = 0; n + 1 < n_samples; ++n)
    measures.impulse += 0.5 * (times[n + 1] - times[n]) * (force[n] + force[n + 1]);

  // Ringing: RMS of the period-2 component (4th difference / 16) over the uniform windows in
  // contact.
  double sum_of_squares = 0.0;
  std::size_t n_windows = 0;
  for (std::size_t n = first + 2; n + 2 <= last; ++n)
  {
    if (!uniform_window(times, n))
      continue;
    const double period_2_component =
        (force[n - 2] - 4.0 * force[n - 1] + 6.0 * force[n] - 4.0 * force[n + 1] + force[n + 2]) /
        16.0;
    sum_of_squares += period_2_component * period_2_component;
    ++n_windows;
  }
  if (n_windows > 0)
    measures.ringing =
        std::sqrt(sum_of_squares / static_cast<double>(n_windows)) / measures.peak_force;
  return measures;
}
} // namespace dyncontact
