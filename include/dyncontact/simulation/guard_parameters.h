#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/parameter_handler.h>

namespace dyncontact
{
/**
 * The physical checks of every step (StepGuards): each on by default, with a tolerance relative to
 * the run's own scale. Subsection `Guards`.
 */
struct GuardParameters
{
  bool energy;
  double energy_tolerance;
  double plain_energy_tolerance;
  bool tensile_force;
  double tensile_force_tolerance;
  bool momentum;
  double momentum_tolerance;
  /// massless contact nodes: the largest contact event work of a step per unit of energy (0..1)
  double contact_event_tolerance;

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm);
};
} // namespace dyncontact
