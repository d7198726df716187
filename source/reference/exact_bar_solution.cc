#include <dyncontact/reference/exact_bar_solution.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <string>

namespace dyncontact
{
namespace internal
{
StepFunction::StepFunction(const double value_before_breakpoints)
    : initial_value(value_before_breakpoints)
{
}

double StepFunction::value(const double t, const double tolerance) const
{
  const auto first_after = std::upper_bound(times.begin(), times.end(), t + tolerance);
  return first_after == times.begin() ? initial_value : values[first_after - times.begin() - 1];
}

bool StepFunction::update(const double t, const double new_value, const double threshold)
{
  const double current_value = values.empty() ? initial_value : values.back();
  if (std::abs(new_value - current_value) <= threshold)
    return false;
  running_integral.push_back(
      times.empty() ? 0. : running_integral.back() + (t - times.back()) * values.back());
  times.push_back(t);
  values.push_back(new_value);
  return true;
}

double StepFunction::antiderivative(const double t) const
{
  if (times.empty() || t < times.front())
    return (t - (times.empty() ? 0. : times.front())) * initial_value;
  const std::size_t k = std::upper_bound(times.begin(), times.end(), t) - times.begin() - 1;
  return running_integral[k] + (t - times[k]) * values[k];
}

double StepFunction::integral(const double lower, const double upper) const
{
  return antiderivative(upper) - antiderivative(lower);
}
} // namespace internal

namespace
{
/**
 * The integral over [lower, upper] of a function @p f that is constant between consecutive
 * @p breakpoints (which may lie outside the interval and be unsorted). Each piece is evaluated at
 * its midpoint, away from the jumps, so the result is exact up to round-off.
 */
template <typename Function>
double integrate_piecewise_constant(const double lower,
                                    const double upper,
                                    std::vector<double> breakpoints,
                                    const Function& f)
{
  breakpoints.push_back(lower);
  breakpoints.push_back(upper);
  std::sort(breakpoints.begin(), breakpoints.end());
  double integral = 0.0;
  for (unsigned int k = 0; k + 1 < breakpoints.size(); ++k)
  {
    const double piece_begin = std::max(lower, breakpoints[k]);
    const double piece_end   = std::min(upper, breakpoints[k + 1]);
    if (piece_end > piece_begin)
      integral += (piece_end - piece_begin) * f(0.5 * (piece_begin + piece_end));
  }
  return integral;
}

/// The breakpoints of @p f in [@p earliest, @p latest].
std::vector<double>
breakpoints_between(const internal::StepFunction& f, const double earliest, const double latest)
{
  const std::vector<double>& times = f.breakpoints();
  return {std::lower_bound(times.begin(), times.end(), earliest),
          std::upper_bound(times.begin(), times.end(), latest)};
}

/// Throw std::invalid_argument with @p message unless @p value is positive (and not NaN).
void require_positive(const double value, const std::string& message)
{
  if (!(value > 0.0))
    throw std::invalid_argument("ExactBarSolution: " + message + " must be positive");
}
} // namespace

ExactBarSolution::ExactBarSolution(const std::vector<ExactBar>& input_bars,
                                   const std::optional<double> wall_position,
                                   const double end_time_to_track,
                                   const bool clamped_left_end)
    : end_time(end_time_to_track)
{
  if (input_bars.empty())
    throw std::invalid_argument("ExactBarSolution: no bars given");
  // A run that fails its first step writes the reference of t = 0 alone.
  if (!(end_time >= 0.0))
    throw std::invalid_argument("ExactBarSolution: end_time must not be negative");
  double length_scale   = wall_position ? std::abs(*wall_position) : 0.0;
  double velocity_scale = 0.0;
  shortest_travel_time  = std::numeric_limits<double>::infinity();
  for (unsigned int i = 0; i < input_bars.size(); ++i)
  {
    const ExactBar& bar    = input_bars[i];
    const std::string name = "bar " + std::to_string(i) + ": ";
    require_positive(bar.length, name + "length");
    require_positive(bar.youngs_modulus, name + "Young's modulus");
    require_positive(bar.density, name + "density");
    require_positive(bar.area, name + "area");
    if (!std::isfinite(bar.left_end) || !std::isfinite(bar.initial_velocity))
      throw std::invalid_argument("ExactBarSolution: " + name +
                                  "left end and initial velocity must be finite");
    const double wave_speed = std::sqrt(bar.youngs_modulus / bar.density);
    bars.push_back({bar,
                    wave_speed,
                    bar.density * wave_speed * bar.area,
                    bar.length / wave_speed,
                    internal::StepFunction(bar.initial_velocity),
                    internal::StepFunction(bar.initial_velocity)});
    length_scale         = std::max(length_scale, std::abs(bar.left_end) + bar.length);
    velocity_scale       = std::max(velocity_scale, std::abs(bar.initial_velocity));
    shortest_travel_time = std::min(shortest_travel_time, bars.back().travel_time);
  }
  length_tolerance = 1e-12 * length_scale;
  signal_tolerance = 1e-14 * velocity_scale;

  std::vector<unsigned int> x_order(bars.size());
  std::iota(x_order.begin(), x_order.end(), 0u);
  std::stable_sort(x_order.begin(),
                   x_order.end(),
                   [&](const unsigned int a, const unsigned int b)
                   { return input_bars[a].left_end < input_bars[b].left_end; });

  std::vector<double> gaps;
  const auto add_interface = [&](const unsigned int left, const int right, const double gap)
  {
    if (gap < -length_tolerance)
      throw std::invalid_argument(
          "ExactBarSolution: bar " + std::to_string(left) +
          (right >= 0 ? " overlaps bar " + std::to_string(right)
                      : " reaches beyond the wall (its right end is right of wall_position)"));
    interfaces.push_back(
        {static_cast<int>(left), right, internal::StepFunction(0.0), internal::StepFunction(0.0)});
    gaps.push_back(gap <= length_tolerance ? 0.0 : gap);
  };
  const auto right_end = [&](const unsigned int bar)
  { return input_bars[bar].left_end + input_bars[bar].length; };
  for (unsigned int k = 0; k + 1 < x_order.size(); ++k)
    add_interface(x_order[k],
                  static_cast<int>(x_order[k + 1]),
                  input_bars[x_order[k + 1]].left_end - right_end(x_order[k]));
  if (wall_position)
    add_interface(x_order.back(), -1, *wall_position - right_end(x_order.back()));

  track_events(x_order.front(), x_order.back(), wall_position.has_value(), clamped_left_end, gaps);
}

void ExactBarSolution::track_events(const unsigned int leftmost_bar,
                                    const unsigned int rightmost_bar,
                                    const bool has_wall,
                                    const bool clamped_left_end,
                                    std::vector<double> gaps)
{
  ArrivalQueue arrivals;
  std::vector<double> closing_speeds(interfaces.size(), 0.0);

  const auto emit = [&](internal::StepFunction& wave, const Bar& bar, double t, double value)
  {
    if (wave.update(t, value, signal_tolerance) &&
        t + bar.travel_time <= end_time + time_tolerance(end_time))
      arrivals.push(t + bar.travel_time);
  };
  const auto incoming_at_left_end = [&](const Bar& bar, const double t)
  { return bar.left_going.value(t - bar.travel_time, time_tolerance(t)); };
  const auto incoming_at_right_end = [&](const Bar& bar, const double t)
  { return bar.right_going.value(t - bar.travel_time, time_tolerance(t)); };

  for (double t = 0.0;;)
  {
    // End conditions at t. Incoming waves left their origin at least one travel time ago, so they
    // are known; each outgoing wave is set exactly once.
    // A free end reflects the incoming L as R = L (N = 0), a clamped one as R = -L (v = 0).
    Bar& leftmost = bars[leftmost_bar];
    emit(leftmost.right_going,
         leftmost,
         t,
         (clamped_left_end ? -1.0 : 1.0) * incoming_at_left_end(leftmost, t));
    if (!has_wall)
    {
      Bar& rightmost = bars[rightmost_bar];
      emit(rightmost.left_going, rightmost, t, incoming_at_right_end(rightmost, t));
    }
    for (unsigned int i = 0; i < interfaces.size(); ++i)
    {
      Interface& interface = interfaces[i];
      Bar& left            = bars[interface.left_bar];
      Bar* right           = interface.right_bar >= 0 ? &bars[interface.right_bar] : nullptr;
      // The wall is a bar of infinite impedance at rest.
      const double incoming_R       = incoming_at_right_end(left, t);
      const double incoming_L       = right ? incoming_at_left_end(*right, t) : 0.0;
      const double right_compliance = right ? 1.0 / right->impedance : 0.0;
      const double force = (incoming_L - incoming_R) / (1.0 / left.impedance + right_compliance);
      const bool contact = gaps[i] <= 0.0 && force <= 0.0;

      emit(left.left_going,
           left,
           t,
           contact ? incoming_R + 2.0 * force / left.impedance : incoming_R);
      if (right)
        emit(right->right_going,
             *right,
             t,
             contact ? incoming_L - 2.0 * force * right_compliance : incoming_L);
      interface.contact.update(t, contact ? 1.0 : 0.0, 0.0);
      interface.force.update(t, contact ? -force : 0.0, 0.0);
      // Free ends move with their incoming invariant (R on the left, L on the right).
      closing_speeds[i] = contact ? 0.0 : incoming_R - incoming_L;
      if (contact)
        gaps[i] = 0.0;
    }

    const double next_time = advance_to_next_event(t, arrivals, gaps, closing_speeds);
    if (next_time > end_time + time_tolerance(end_time))
      break;
    t = next_time;
  }
}

double ExactBarSolution::advance_to_next_event(const double t,
                                               ArrivalQueue& arrivals,
                                               std::vector<double>& gaps,
                                               const std::vector<double>& closing_speeds) const
{
  double next_time = arrivals.empty() ? std::numeric_limits<double>::infinity() : arrivals.top();
  for (unsigned int i = 0; i < gaps.size(); ++i)
    if (closing_speeds[i] > 0.0)
      next_time = std::min(next_time, t + gaps[i] / closing_speeds[i]);
  if (next_time > end_time + time_tolerance(end_time))
    return next_time;

  // Events closer than half the lookup tolerance are processed together, so that the lookups at
  // the group's first instant safely see all jumps arriving within the group.
  const double group_tolerance = 0.5 * time_tolerance(next_time);
  while (!arrivals.empty() && arrivals.top() <= next_time + group_tolerance)
    arrivals.pop();
  for (unsigned int i = 0; i < gaps.size(); ++i)
  {
    const bool closes =
        closing_speeds[i] > 0.0 && t + gaps[i] / closing_speeds[i] <= next_time + group_tolerance;
    gaps[i] = closes ? 0.0 : gaps[i] - closing_speeds[i] * (next_time - t);
  }
  return next_time;
}

unsigned int ExactBarSolution::n_bars() const
{
  return bars.size();
}

unsigned int ExactBarSolution::n_interfaces() const
{
  return interfaces.size();
}

int ExactBarSolution::left_bar(const unsigned int interface) const
{
  return checked_interface(interface).left_bar;
}

int ExactBarSolution::right_bar(const unsigned int interface) const
{
  return checked_interface(interface).right_bar;
}

const ExactBarSolution::Bar& ExactBarSolution::checked_bar(const unsigned int bar,
                                                           const double t) const
{
  if (bar >= bars.size())
    throw std::out_of_range("ExactBarSolution: there is no bar " + std::to_string(bar));
  if (!(t >= 0.0 && t <= end_time + time_tolerance(end_time)))
    throw std::out_of_range("ExactBarSolution: time " + std::to_string(t) +
                            " is outside [0, end_time]");
  return bars[bar];
}

const ExactBarSolution::Bar&
ExactBarSolution::checked_point(const unsigned int bar, const double X, const double t) const
{
  const Bar& checked = checked_bar(bar, t);
  if (!(X >= checked.data.left_end - length_tolerance &&
        X <= checked.data.left_end + checked.data.length + length_tolerance))
    throw std::out_of_range("ExactBarSolution: X = " + std::to_string(X) + " is not on bar " +
                            std::to_string(bar));
  return checked;
}

const ExactBarSolution::Interface&
ExactBarSolution::checked_interface(const unsigned int interface) const
{
  if (interface >= interfaces.size())
    throw std::out_of_range("ExactBarSolution: there is no interface " + std::to_string(interface));
  return interfaces[interface];
}

std::pair<double, double> ExactBarSolution::invariants(const Bar& bar,
                                                       const double X,
                                                       const double t,
                                                       const double tolerance) const
{
  const double distance_to_left  = X - bar.data.left_end;
  const double distance_to_right = bar.data.left_end + bar.data.length - X;
  return {bar.right_going.value(t - distance_to_left / bar.wave_speed, tolerance),
          bar.left_going.value(t - distance_to_right / bar.wave_speed, tolerance)};
}

double ExactBarSolution::displacement(const unsigned int bar, const double X, const double t) const
{
  const Bar& b = checked_point(bar, X, t);
  // u = integral over [0, t] of v = (R + L)/2, the invariants arriving from the ends with their
  // travel delays.
  const double delay_from_left  = (X - b.data.left_end) / b.wave_speed;
  const double delay_from_right = (b.data.left_end + b.data.length - X) / b.wave_speed;
  return 0.5 * (b.right_going.integral(-delay_from_left, t - delay_from_left) +
                b.left_going.integral(-delay_from_right, t - delay_from_right));
}

double ExactBarSolution::velocity(const unsigned int bar, const double X, const double t) const
{
  const auto [R, L] = invariants(checked_point(bar, X, t), X, t, time_tolerance(t));
  return 0.5 * (R + L);
}

double ExactBarSolution::axial_force(const unsigned int bar, const double X, const double t) const
{
  const Bar& b      = checked_point(bar, X, t);
  const auto [R, L] = invariants(b, X, t, time_tolerance(t));
  return 0.5 * b.impedance * (L - R);
}

double ExactBarSolution::contact_force(const unsigned int interface, const double t) const
{
  return checked_interface(interface).force.value(t, time_tolerance(t));
}

double ExactBarSolution::contact_impulse(const unsigned int interface, const double t) const
{
  return checked_interface(interface).force.integral(0.0, t);
}

bool ExactBarSolution::in_contact(const unsigned int interface, const double t) const
{
  return checked_interface(interface).contact.value(t, time_tolerance(t)) > 0.5;
}

std::vector<std::pair<double, double>>
ExactBarSolution::contact_intervals(const unsigned int interface) const
{
  // The contact state alternates between 1 (contact) and 0 (apart), starting apart before t = 0.
  const internal::StepFunction& contact = checked_interface(interface).contact;
  std::vector<std::pair<double, double>> intervals;
  for (unsigned int k = 0; k < contact.breakpoints().size(); ++k)
    if (contact.values_from_breakpoints()[k] > 0.5)
      intervals.emplace_back(contact.breakpoints()[k], end_time);
    else
      intervals.back().second = contact.breakpoints()[k];
  return intervals;
}

double ExactBarSolution::integrate_over_bar(
    const Bar& bar, const double t, const std::function<double(double, double)>& integrand) const
{
  // A jump emitted at time s is at distance c (t - s) from its end, so on the bar if s is within
  // one travel time before t.
  std::vector<double> front_positions;
  for (const double emission : breakpoints_between(bar.right_going, t - bar.travel_time, t))
    front_positions.push_back(bar.data.left_end + bar.wave_speed * (t - emission));
  for (const double emission : breakpoints_between(bar.left_going, t - bar.travel_time, t))
    front_positions.push_back(bar.data.left_end + bar.data.length -
                              bar.wave_speed * (t - emission));
  return integrate_piecewise_constant(bar.data.left_end,
                                      bar.data.left_end + bar.data.length,
                                      front_positions,
                                      [&](const double X)
                                      {
                                        const auto [R, L] = invariants(bar, X, t, 0.0);
                                        return integrand(0.5 * (R + L),
                                                         0.5 * bar.impedance * (L - R));
                                      });
}

double ExactBarSolution::momentum(const unsigned int bar, const double t) const
{
  const Bar& b = checked_bar(bar, t);
  return integrate_over_bar(
      b, t, [&](const double v, double) { return b.data.density * b.data.area * v; });
}

double ExactBarSolution::kinetic_energy(const unsigned int bar, const double t) const
{
  const Bar& b = checked_bar(bar, t);
  return integrate_over_bar(
      b, t, [&](const double v, double) { return 0.5 * b.data.density * b.data.area * v * v; });
}

double ExactBarSolution::strain_energy(const unsigned int bar, const double t) const
{
  const Bar& b = checked_bar(bar, t);
  return integrate_over_bar(b,
                            t,
                            [&](double, const double N)
                            { return N * N / (2.0 * b.data.youngs_modulus * b.data.area); });
}
} // namespace dyncontact
