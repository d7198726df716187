#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace dyncontact
{
/** One straight linear elastic bar on the x axis. Subsection `Geometry/Bar <b>`. */
struct BarParameters
{
  double left_end;
  double length;
  unsigned int n_elements;
  double youngs_modulus;
  double density;
  double area;
  double initial_velocity;

  double right_end() const { return left_end + length; }
  double wave_speed() const;
  double element_length() const { return length / n_elements; }

  static void declare_parameters(ParameterHandler& prm);
  /// `section` is the subsection path used in error messages, e.g. "Geometry/Bar 2".
  void parse_parameters(ParameterHandler& prm, const std::string& section);
};

/**
 * The bodies of a bar problem: bars in prm order (body b = bar b) and an optional rigid wall at
 * x = wall position that faces -x (all bars lie to its left). Subsection `Geometry`.
 */
struct GeometryParameters
{
  std::vector<BarParameters> bars;
  bool wall_enabled;
  double wall_position;
  /// the left end of the leftmost bar is clamped (u = 0 there)
  bool clamped_left_end;

  static void declare_parameters(ParameterHandler& prm, unsigned int n_bars);
  void parse_parameters(ParameterHandler& prm);
};
} // namespace dyncontact
