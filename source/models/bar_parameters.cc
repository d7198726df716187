#include <dyncontact/base/parameter_entries.h>
#include <dyncontact/models/bar_parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace dyncontact
{
namespace
{
/**
 * How close the ends of bars `a` and `b` (or of a bar and the wall at `wall`) count as touching:
 * 1e-9 of the shorter element, and at least the round-off of the positions (8 units in the last
 * place of the largest |x| involved), which matters far from the origin.
 */
double touching_tolerance(const BarParameters& a, const BarParameters& b, const double wall = 0.)
{
  const double largest_position = std::max({std::abs(a.left_end),
                                            std::abs(a.right_end()),
                                            std::abs(b.left_end),
                                            std::abs(b.right_end()),
                                            std::abs(wall)});
  return std::max(1e-9 * std::min(a.element_length(), b.element_length()),
                  8. * std::numeric_limits<double>::epsilon() * largest_position);
}
} // namespace

double BarParameters::wave_speed() const
{
  return std::sqrt(youngs_modulus / density);
}

void BarParameters::declare_parameters(ParameterHandler& prm)
{
  // Every entry of a bar must be given: a bar the user forgot must not appear with defaults.
  prm.declare_entry(
      "left end", "0", Patterns::Double(), "x of the bar's left end at t = 0 [length].", true);
  prm.declare_entry("length", "10", Patterns::Double(), "Bar length L [length], > 0.", true);
  prm.declare_entry("number of elements",
                    "100",
                    Patterns::Integer(1, 10000000),
                    "Number of equal 2-node linear elements along the bar [-], >= 1.",
                    true);
  prm.declare_entry("Young's modulus", "1", Patterns::Double(), "E [force/length^2], > 0.", true);
  prm.declare_entry("density", "1", Patterns::Double(), "rho [mass/length^3], > 0.", true);
  prm.declare_entry("cross-section area", "1", Patterns::Double(), "A [length^2], > 0.", true);
  prm.declare_entry("initial velocity",
                    "0",
                    Patterns::Double(),
                    "Uniform velocity along +x at t = 0 [length/time]; the bar starts "
                    "stress-free.",
                    true);
}

void BarParameters::parse_parameters(ParameterHandler& prm, const std::string& section)
{
  left_end         = prm.get_double("left end");
  length           = get_positive(prm, "length", section);
  n_elements       = prm.get_integer("number of elements");
  youngs_modulus   = get_positive(prm, "Young's modulus", section);
  density          = get_positive(prm, "density", section);
  area             = get_positive(prm, "cross-section area", section);
  initial_velocity = prm.get_double("initial velocity");
}

void GeometryParameters::declare_parameters(ParameterHandler& prm, const unsigned int n_bars)
{
  prm.enter_subsection("Geometry");
  prm.declare_entry("number of bars",
                    "1",
                    Patterns::Integer(1, 100),
                    "Number of bars [-], 1..100; bar b is described in subsection 'Bar b' and is "
                    "body b of the outputs. Contact is checked between facing ends of bars "
                    "that are neighbours along x, and between the rightmost bar and the wall.");
  for_each_numbered_subsection(prm,
                               "Bar",
                               n_bars,
                               [&prm](unsigned int, const std::string&)
                               { BarParameters::declare_parameters(prm); });
  prm.declare_entry("clamped left end",
                    "false",
                    Patterns::Bool(),
                    "Whether the left end of the leftmost bar is clamped (u = 0 there, a fixed "
                    "support). With a rigid wall and one bar: the Signorini bar, a bar clamped at "
                    "one end bouncing on an obstacle.");
  prm.enter_subsection("Rigid wall");
  prm.declare_entry("enabled", "false", Patterns::Bool(), "Whether a fixed rigid wall exists.");
  prm.declare_entry("position",
                    "0",
                    Patterns::Double(),
                    "x of the wall [length]. The wall faces -x: every bar must lie to its left "
                    "(touching is allowed).");
  prm.leave_subsection();
  prm.leave_subsection();
}

void GeometryParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Geometry");
  const unsigned int n_bars = prm.get_integer("number of bars");
  bars.resize(n_bars);
  for_each_numbered_subsection(prm,
                               "Bar",
                               n_bars,
                               [&](const unsigned int bar, const std::string& name)
                               { bars[bar].parse_parameters(prm, "Geometry/" + name); });
  clamped_left_end = prm.get_bool("clamped left end");
  prm.enter_subsection("Rigid wall");
  wall_enabled  = prm.get_bool("enabled");
  wall_position = prm.get_double("position");
  prm.leave_subsection();
  prm.leave_subsection();

  // Positions are compared with a tolerance: a left end typed as 0.3 and a right end computed as
  // 0.1 + 0.2 = 0.30000000000000004 touch. Within it, bodies touch and are snapped together, so
  // that the reference gap is exactly zero and contact starts closed; beyond it they overlap.
  for (unsigned int a = 0; a < n_bars; ++a)
    for (unsigned int b = a + 1; b < n_bars; ++b)
    {
      const double tolerance = touching_tolerance(bars[a], bars[b]);
      const double overlap   = std::min(bars[a].right_end(), bars[b].right_end()) -
                             std::max(bars[a].left_end, bars[b].left_end);
      if (overlap > tolerance)
        throw InputError(
            "Geometry: Bar " + std::to_string(a + 1) + " [" + format_exact(bars[a].left_end) +
            ", " + format_exact(bars[a].right_end()) + "] and Bar " + std::to_string(b + 1) + " [" +
            format_exact(bars[b].left_end) + ", " + format_exact(bars[b].right_end()) +
            "] overlap at t = 0 by " + format_number(overlap) + "; bars may touch (to " +
            format_number(tolerance) + ", 1e-9 of the shorter element) but not overlap.");
    }
  std::vector<unsigned int> x_order(n_bars);
  std::iota(x_order.begin(), x_order.end(), 0u);
  std::sort(x_order.begin(),
            x_order.end(),
            [this](const unsigned int a, const unsigned int b)
            { return bars[a].left_end < bars[b].left_end; });
  for (unsigned int i = 0; i + 1 < n_bars; ++i)
  {
    const BarParameters& left = bars[x_order[i]];
    BarParameters& right      = bars[x_order[i + 1]];
    if (right.left_end - left.right_end() <= touching_tolerance(left, right))
      right.left_end = left.right_end();
  }

  if (!wall_enabled)
    return;
  const BarParameters& rightmost = bars[x_order.back()];
  const double tolerance         = touching_tolerance(rightmost, rightmost, wall_position);
  // Every bar lies left of the rightmost one's right end: the bars do not overlap.
  if (rightmost.right_end() - wall_position > tolerance)
    throw InputError("Geometry/Rigid wall/position = " + format_exact(wall_position) +
                     " is left of the right end " + format_exact(rightmost.right_end()) +
                     " of Bar " + std::to_string(x_order.back() + 1) + " [" +
                     format_exact(rightmost.left_end) + ", " + format_exact(rightmost.right_end()) +
                     "], which reaches " + format_number(rightmost.right_end() - wall_position) +
                     " past it; the wall faces -x, so every bar must lie at x <= position "
                     "(touching, to " +
                     format_number(tolerance) + " = 1e-9 of an element, is allowed).");
  if (wall_position - rightmost.right_end() <= tolerance)
    wall_position = rightmost.right_end();
}
} // namespace dyncontact
