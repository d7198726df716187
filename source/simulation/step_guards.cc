#include <dyncontact/simulation/step_guards.h>

#include <cmath>
#include <sstream>

namespace dyncontact
{
StepGuards::StepGuards(const GuardParameters& parameters,
                       const bool plain_energy_checked,
                       std::vector<std::string> track_names)
    : parameters(parameters), plain_energy_checked(plain_energy_checked),
      track_names(std::move(track_names))
{
}

void StepGuards::initialize(const Figures& initial)
{
  initial_energy       = initial.energy;
  initial_plain_energy = initial.plain_energy;
  initial_momenta      = initial.momenta;
  energy_scale         = std::abs(initial.energy);
  accepted_dissipation = initial.frictional_dissipation;
  force_scale          = 0.;
  momentum_scale       = initial.momentum_magnitude;
}

bool StepGuards::enabled(const Guard guard) const
{
  switch (guard)
  {
  case energy:
    return parameters.energy;
  case tensile_force:
    return parameters.tensile_force;
  default:
    return parameters.momentum;
  }
}

std::pair<std::string, double> StepGuards::violation(const Guard guard, const Figures& step) const
{
  std::ostringstream reason;
  if (guard == energy)
  {
    // The initial energy (and the external work); the largest energy seen only for bodies that
    // start at rest, so that a blow-up is measured against the start, not against itself.
    const double scale = std::max(initial_energy != 0. ? std::abs(initial_energy) : energy_scale,
                                  std::abs(step.external_work));
    // Friction dissipates: a step whose tangential forces did positive work fails.
    const double friction_work =
        scale > 0. ? (accepted_dissipation - step.frictional_dissipation) / scale : 0.;
    if (friction_work > parameters.energy_tolerance)
    {
      reason << "energy guard: friction did positive work in the step, "
             << accepted_dissipation - step.frictional_dissipation << ", " << friction_work
             << " of the energy scale (Guards/energy tolerance = " << parameters.energy_tolerance
             << ")";
      return {reason.str(), friction_work};
    }
    // E + D: the energy friction dissipated is gone from E and counted in D.
    const double gain =
        scale > 0.
            ? (step.energy + step.frictional_dissipation - initial_energy - step.external_work) /
                  scale
            : 0.;
    if (gain > parameters.energy_tolerance)
    {
      reason << "energy guard: the algorithmic energy " << step.energy
             << (step.frictional_dissipation != 0. ? " plus the frictional dissipation " +
                                                         format_number(step.frictional_dissipation)
                                                   : std::string())
             << " exceeds the initial " << initial_energy << " plus the external work "
             << step.external_work << " by " << gain
             << " of the energy scale (Guards/energy tolerance = " << parameters.energy_tolerance
             << ")";
      return {reason.str(), gain};
    }
    const double plain_gain = scale > 0. ? (step.plain_energy + step.frictional_dissipation -
                                            initial_plain_energy - step.external_work) /
                                               scale
                                         : 0.;
    if (!plain_energy_checked || plain_gain <= parameters.plain_energy_tolerance)
      return {"", 0.};
    reason << "energy guard: the plain energy (kinetic + strain) " << step.plain_energy
           << " exceeds the initial " << initial_plain_energy << " plus the external work "
           << step.external_work << " by " << plain_gain
           << " of the energy scale (Guards/plain energy tolerance = "
           << parameters.plain_energy_tolerance
           << "; with beta < gamma/2 the algorithmic energy does not bound it)";
    return {reason.str(), plain_gain};
  }
  if (guard == tensile_force)
  {
    const double scale   = std::max(force_scale, step.multiplier_magnitude);
    const double tension = scale > 0. ? -step.contact_force / scale : 0.;
    if (tension <= parameters.tensile_force_tolerance)
      return {"", 0.};
    reason << "tensile force guard: the recovered contact force " << step.contact_force
           << " is tensile, " << tension << " of the force scale (Guards/tensile force tolerance = "
           << parameters.tensile_force_tolerance << ")";
    return {reason.str(), tension};
  }
  const double scale = std::max(momentum_scale, step.momentum_magnitude);
  for (unsigned int b = 0; b < step.momenta.size() && scale > 0.; ++b)
  {
    const double change     = step.momenta[b] - initial_momenta[b];
    const double difference = std::abs(change - step.impulses[b]) / scale;
    if (difference > parameters.momentum_tolerance)
    {
      reason << "momentum guard: " << track_names[b] << " changed its momentum by " << change
             << " but received an impulse of " << step.impulses[b] << ", a difference of "
             << difference << " of the momentum scale (Guards/momentum tolerance = "
             << parameters.momentum_tolerance << ")";
      return {reason.str(), difference};
    }
  }
  return {"", 0.};
}

std::string StepGuards::check(const Figures& step) const
{
  bool finite = std::isfinite(step.energy) && std::isfinite(step.plain_energy) &&
                std::isfinite(step.contact_force);
  for (unsigned int b = 0; b < step.momenta.size(); ++b)
    finite = finite && std::isfinite(step.momenta[b]) && std::isfinite(step.impulses[b]);
  if (!finite)
    return "the solution is not finite (energy " + format_number(step.energy) + ", contact force " +
           format_number(step.contact_force) +
           "): the time integration may be unstable (see the stability warning at start, if any)";
  for (const Guard guard : {energy, tensile_force, momentum})
    if (enabled(guard))
    {
      const auto [reason, amount] = violation(guard, step);
      if (!reason.empty())
        return reason;
    }
  return "";
}

void StepGuards::accept(const Figures& step)
{
  for (const Guard guard : {energy, tensile_force, momentum})
    if (!enabled(guard))
    {
      const auto [reason, amount] = violation(guard, step);
      Record& record              = disabled_violations[guard];
      if (!reason.empty() && record.first_reason.empty())
      {
        record.first_reason = reason;
        record.first_time   = step.time;
      }
      record.largest = std::max(record.largest, amount);
    }
  accepted_dissipation = step.frictional_dissipation;
  energy_scale         = std::max(energy_scale, std::abs(step.energy));
  force_scale          = std::max(force_scale, std::abs(step.contact_force));
  momentum_scale       = std::max(momentum_scale, step.momentum_magnitude);
}

std::vector<std::string> StepGuards::warnings() const
{
  const std::array<const char*, n_guards> names = {
      {"Guards/energy", "Guards/tensile force", "Guards/momentum"}};
  std::vector<std::string> lines;
  for (unsigned int guard = 0; guard < n_guards; ++guard)
  {
    const Record& record = disabled_violations[guard];
    if (record.first_reason.empty())
      continue;
    std::ostringstream line;
    line << "WARNING: " << names[guard]
         << " is off and was violated, first at t = " << record.first_time << " ("
         << record.first_reason << "); largest violation " << record.largest
         << ". These results break a physical law the code checks.";
    lines.push_back(line.str());
  }
  return lines;
}
} // namespace dyncontact
