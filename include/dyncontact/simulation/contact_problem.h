#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact_dynamics/contact_dynamics.h>
#include <dyncontact/models/problem_model.h>
#include <dyncontact/postprocess/body_impulses.h>
#include <dyncontact/postprocess/step_measures.h>
#include <dyncontact/simulation/body_discretization.h>
#include <dyncontact/simulation/run_parameters.h>
#include <dyncontact/solver/contact_newton_solver.h>
#include <dyncontact/time_integration/generalized_alpha.h>
#include <dyncontact/time_integration/implicit_stepper.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <set>
#include <string>

namespace dyncontact
{
/**
 * A ProblemModel assembled for time stepping: its BodyDiscretization, the contact of its
 * description (create_contact, penalties sized against the bodies' highest mode), the
 * contact-dynamics treatment (Contact/dynamics) and the lumped mass it asks for, the Newton solver,
 * the ImplicitStepper and the post-processing of the state (BodyImpulses, StepMeasures). What a
 * run has before its first step; the Simulation owns one and drives it. The integrator and timer
 * are the caller's and must outlive it. Throws the InputError of a bad mesh or contact.
 */
template <int dim>
class ContactProblem
{
public:
  ContactProblem(ProblemModel<dim>& model,
                 const RunParameters& parameters,
                 const GeneralizedAlpha& integrator,
                 TimerOutput& timer);

  /** The run's summary lines: sizes, integrator, treatment, the model's, highest mode, penalty. */
  void log_summary(const ConditionalOStream& log) const;
  /**
   * Warns when a penalty spring is the one unresolved frequency; throws InputError when the time
   * step exceeds the stability limit of conditionally stable Newmark (2 beta < gamma), for the
   * mesh alone or with the penalty springs (check_stability()).
   */
  void check_time_step(const ConditionalOStream& log) const;
  /** The model's initial velocity, the equilibrium acceleration, the pairs and impulses at t = 0.
   */
  void set_initial_conditions();
  /** Dimension, DoFs, candidate pairs, bodies and the node checksum (ProblemFingerprint). */
  std::string description() const;

  const BodyDiscretization<dim> discretization;
  /** The lumped mass per DoF the run uses (zero at massless contact nodes). */
  Vector<double> mass;
  /** The boundary ids of the slave contact surfaces (surface pairs and rigid planes). */
  std::set<types::boundary_id> slave_surfaces;
  std::unique_ptr<ContactGeometry<dim>> surface_contact; ///< null: fixed-normal pairs only
  std::unique_ptr<ContactConstraints<dim>> contact;
  std::unique_ptr<ContactDynamics<dim>> dynamics; ///< Contact/dynamics
  std::unique_ptr<ContactNewtonSolver<dim>> solver;
  /** The step and its state (u, v, a, Q, W at the current time). */
  std::unique_ptr<ImplicitStepper<dim>> stepper;
  /** Per body: the forces that change its momentum, their impulses, the external work. */
  std::unique_ptr<BodyImpulses<dim>> impulses;
  std::unique_ptr<StepMeasures<dim>> measures;

private:
  const ProblemModel<dim>& model;
  const RunParameters& parameters;
  const GeneralizedAlpha& integrator;
  double penalty_factor = 0.;    ///< the factor in force (Contact/penalty factor, or the auto one)
  bool penalty_lowered  = false; ///< Contact/penalty factor = auto lowered the springs
};
} // namespace dyncontact
