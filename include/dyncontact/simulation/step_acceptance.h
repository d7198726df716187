#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact_dynamics/contact_dynamics.h>
#include <dyncontact/postprocess/body_impulses.h>
#include <dyncontact/postprocess/contact_fields.h>
#include <dyncontact/postprocess/step_measures.h>
#include <dyncontact/simulation/guard_parameters.h>
#include <dyncontact/simulation/step_guards.h>
#include <dyncontact/time_integration/generalized_alpha.h>

#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace dyncontact
{
/**
 * Whether a solved step is accepted: the StepGuards on its figures, and with massless contact
 * nodes (Contact/dynamics = mass-redistribution) the contact-event control, which cuts a step
 * whose closing or release does more work than Guards/contact event tolerance times the energy
 * (ContactFields::event_work(); doc/schemes.md, "Mass redistribution with resolved contact
 * events"). The energy guard reads E_0 plus the algorithmic-energy change of every accepted step,
 * each evaluated with that step's size h: the weight (beta - gamma/2) h^2 of a.Ma depends on h, so
 * E with the new h minus E with the old one would show a gain after every cut when
 * beta != gamma/2. Keeps the guards' records and the last accepted energy (serialize()). The
 * integrator, contact, treatment and impulses are the caller's and must outlive it.
 */
template <int dim>
class StepAcceptance
{
public:
  StepAcceptance(const GuardParameters& parameters,
                 const GeneralizedAlpha& integrator,
                 const ContactConstraints<dim>& contact,
                 const ContactDynamics<dim>& dynamics,
                 const BodyImpulses<dim>& impulses);

  /** Takes the initial state's `measures` as the guards' references and the accepted energy. */
  void initialize(const Measures& measures);

  /**
   * Why the step from `displacement_before` (with the pairs of `contact_before`) to the current
   * state, at the integrator's step size, must be cut: one line naming the guard and its prm
   * entry, or an empty string. `time` [time] is the step's end, `measures` those of its state;
   * `can_cut`: a smaller step exists (the event control applies only then). Collective.
   */
  std::string check(double time,
                    const Measures& measures,
                    const DistributedVector& displacement_before,
                    const typename ContactConstraints<dim>::State& contact_before,
                    const DistributedVector& displacement,
                    bool can_cut);

  /** Accepts the step last passed to check() (which returned no reason). */
  void accept();

  /** StepGuards::warnings(): the violations of guards switched off. */
  std::vector<std::string> warnings() const { return guards.warnings(); }

  /** The guards' records and the accepted energy (checkpoint). */
  template <class Archive>
  void serialize(Archive& archive, const unsigned int)
  {
    archive& guarded_energy;
    archive& accepted.kinetic_energy;
    archive& accepted.strain_energy;
    archive& accepted.acceleration_energy;
    archive& guards;
  }

private:
  /** The guards' figures of a state at `time` with `measures`. */
  StepGuards::Figures figures(double time, const Measures& measures) const;
  /** The event control's reason to cut, or an empty string (see the class). */
  std::string event_failure(const DistributedVector& displacement_before,
                            const typename ContactConstraints<dim>::State& contact_before,
                            const DistributedVector& displacement,
                            double energy) const;

  const GuardParameters parameters;
  const GeneralizedAlpha& integrator;
  const ContactConstraints<dim>& contact;
  const ContactFields<dim> fields;
  const ContactDynamics<dim>& dynamics;
  const BodyImpulses<dim>& impulses;
  StepGuards guards;
  /** The guarded energy of the last accepted state, and its measures. */
  double guarded_energy = 0.;
  Measures accepted{};
  /** The figures and measures of the step last checked. */
  StepGuards::Figures checked{};
  Measures checked_measures{};
};
} // namespace dyncontact
