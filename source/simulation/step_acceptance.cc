#include <dyncontact/base/dimensions.h>
#include <dyncontact/simulation/step_acceptance.h>

#include <cmath>

namespace dyncontact
{
template <int dim>
StepAcceptance<dim>::StepAcceptance(const GuardParameters& parameters,
                                    const GeneralizedAlpha& integrator,
                                    const ContactConstraints<dim>& contact,
                                    const ContactDynamics<dim>& dynamics,
                                    const BodyImpulses<dim>& impulses)
    : parameters(parameters), integrator(integrator), contact(contact), fields(contact),
      dynamics(dynamics), impulses(impulses),
      guards(parameters, std::isfinite(integrator.stability_limit()), impulses.track_names())
{
}

template <int dim>
void StepAcceptance<dim>::initialize(const Measures& measures)
{
  guarded_energy = measures.algorithmic_energy;
  accepted       = measures;
  guards.initialize(figures(0., measures));
}

template <int dim>
std::string
StepAcceptance<dim>::check(const double time,
                           const Measures& measures,
                           const DistributedVector& displacement_before,
                           const typename ContactConstraints<dim>::State& contact_before,
                           const DistributedVector& displacement,
                           const bool can_cut)
{
  checked                   = figures(time, measures);
  checked_measures          = measures;
  const std::string failure = guards.check(checked);
  if (!failure.empty() || !can_cut)
    return failure;
  return event_failure(displacement_before, contact_before, displacement, checked.energy);
}

template <int dim>
void StepAcceptance<dim>::accept()
{
  guards.accept(checked);
  guarded_energy = checked.energy;
  accepted       = checked_measures;
}

template <int dim>
StepGuards::Figures StepAcceptance<dim>::figures(const double time, const Measures& measures) const
{
  double multiplier_magnitude = 0.;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    multiplier_magnitude += std::abs(contact.pair_force(k));
  const auto energy_at_this_step_size = [this](const Measures& state)
  {
    return integrator.algorithmic_energy(
        state.kinetic_energy, state.strain_energy, state.acceleration_energy);
  };
  return {time,
          guarded_energy + energy_at_this_step_size(measures) - energy_at_this_step_size(accepted),
          impulses.ledger().external_work,
          measures.contact_force,
          multiplier_magnitude,
          measures.momentum_tracks,
          impulses.ledger().impulses,
          measures.momentum_magnitude,
          measures.kinetic_energy + measures.strain_energy,
          impulses.ledger().frictional_dissipation};
}

template <int dim>
std::string
StepAcceptance<dim>::event_failure(const DistributedVector& displacement_before,
                                   const typename ContactConstraints<dim>::State& contact_before,
                                   const DistributedVector& displacement,
                                   const double energy) const
{
  // With massless contact nodes the bodies do not impact: a pair's force rises and falls
  // elastically, and the step's energy error at a closing or a release is the event work.
  // Resolve the event by halving the step while it is above its tolerance. With massive contact
  // nodes part of the closing loss is the semi-discrete impact's own, which no step size
  // removes, so the control is for massless nodes only.
  // Without energy (bodies at rest) there is no scale to resolve the events to.
  if (!dynamics.contact_nodes_massless() || parameters.contact_event_tolerance >= 1. ||
      energy == 0.)
    return "";
  const double work = fields.event_work(displacement_before, displacement, contact_before);
  if (!(work > parameters.contact_event_tolerance * std::abs(energy)))
    return "";
  return "contact event work " + format_number(work / std::abs(energy)) +
         " of the energy, above Guards/contact event tolerance = " +
         format_number(parameters.contact_event_tolerance) +
         " (a pair closed or opened within the step)";
}

DYNCONTACT_INSTANTIATE_CLASS(StepAcceptance)
} // namespace dyncontact
