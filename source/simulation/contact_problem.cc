#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact/contact_factory.h>
#include <dyncontact/contact/penalty_sizing.h>
#include <dyncontact/simulation/contact_problem.h>
#include <dyncontact/time_integration/mode_resolution.h>
#include <dyncontact/time_integration/stability_check.h>

#include <deal.II/grid/grid_tools.h>

#include <cmath>

namespace dyncontact
{
template <int dim>
ContactProblem<dim>::ContactProblem(ProblemModel<dim>& model,
                                    const RunParameters& parameters,
                                    const GeneralizedAlpha& integrator,
                                    TimerOutput& timer)
    : discretization(model), mass(discretization.bodies->lumped_mass()), model(model),
      parameters(parameters), integrator(integrator)
{
  const BodyDiscretization<dim>& d = discretization;
  const PenaltySizingInput sizing{
      mass, integrator.time_step(), d.highest_frequency * integrator.time_step()};
  const ContactDescription<dim> description = model.contact_description(*d.nodes);
  for (const auto& pair : description.surface_pairs)
    slave_surfaces.insert(pair.surface_a);
  for (const auto& pair : description.plane_pairs)
    slave_surfaces.insert(pair.surface);
  Contact<dim> built = create_contact(
      description, d.dof_handler, *d.kinematics, *d.nodes, parameters.contact, sizing);
  surface_contact = std::move(built.surfaces);
  contact         = std::move(built.constraints);
  penalty_factor  = built.penalty_factor;
  penalty_lowered = built.penalty_lowered_to_resolve_springs;
  dynamics        = create_contact_dynamics<dim>(parameters.contact.dynamics);
  if (contact->has_friction() && !dynamics->carries_friction())
    throw InputError(
        "Contact/dynamics = " + contact_dynamics_names().name(parameters.contact.dynamics) +
        " does not carry friction (yet): with a friction coefficient > 0 choose "
        "Contact/dynamics = mass-redistribution, taylor-papadopoulos or none.");
  contact->set_prescribed_dofs(
      contact->border().gather(d.prescribed->flags(d.dof_handler.n_dofs())));
  contact->set_fixed_dofs(contact->border().gather(d.is_fixed_dof));
  contact->set_turning_normals(dynamics->turns_normals());
  // The multipliers as the contact force of the balance the step solves, on every integrator and
  // treatment (doc/method.md, "Contact forces on every integrator").
  contact->set_force_per_multiplier(dynamics->contact_force_factor(integrator.rate_map()) *
                                    (1. - integrator.alpha_f()));
  // Mass redistribution: the contact nodes lose their mass only now, after the penalty sizing,
  // which weighs a pair's spring by its nodes' masses.
  if (dynamics->contact_nodes_massless())
    mass = d.bodies->lumped_mass(contact->contact_dofs(d.dof_handler.n_dofs()));
  solver =
      std::make_unique<ContactNewtonSolver<dim>>(d.dof_handler,
                                                 *d.bodies,
                                                 *contact,
                                                 mass,
                                                 d.constraints,
                                                 parameters.newton,
                                                 GridTools::minimal_cell_diameter(d.triangulation),
                                                 timer,
                                                 integrator.alpha_f());
  stepper = std::make_unique<ImplicitStepper<dim>>(
      integrator, mass, d.is_fixed_dof, *d.prescribed, *d.loads, *contact, *dynamics, *solver);
  impulses = std::make_unique<BodyImpulses<dim>>(integrator, mass, d.is_fixed_dof, *contact);
  impulses->index(
      d.nodes->nodes(), model.momentum_directions(), model.impact_direction(), model.n_bodies());
  measures = std::make_unique<StepMeasures<dim>>(integrator,
                                                 mass,
                                                 *d.bodies,
                                                 *solver,
                                                 *contact,
                                                 *dynamics,
                                                 *stepper,
                                                 *impulses,
                                                 model.impact_direction(),
                                                 d.nodes->nodes());
}

template <int dim>
void ContactProblem<dim>::log_summary(const ConditionalOStream& log) const
{
  const double dt                = parameters.time.time_step;
  const unsigned int n_steps     = parameters.time.n_steps();
  const double highest_frequency = discretization.highest_frequency;
  log << "dyncontact: " << discretization.dof_handler.n_dofs() << " displacement DoFs, "
      << contact->n_pairs() << " contact candidate(s), " << n_steps << " steps of dt = " << dt
      << ", " << integrator.description() << ", contact dynamics "
      << contact_dynamics_names().name(parameters.contact.dynamics) << ", "
      << contact_formulation_names().name(parameters.contact.formulation) << " contact\n";
  if (std::abs(n_steps * dt - parameters.time.end_time) > 1e-9 * parameters.time.end_time)
    log << "  note: end time " << parameters.time.end_time
        << " is not a multiple of the time step; the run ends at t = " << n_steps * dt << "\n";
  if (log.is_active())
    model.print_summary(log.get_stream(), dt);
  log << "  direct solver " << direct_solver_names().name(parameters.newton.direct_solver)
      << ": symbolic analysis of the fixed pattern " << solver->analysis_time() << " s\n";
  log << "  highest mode (element eigenvalue bound): omega_max dt = " << highest_frequency * dt;
  if (std::isfinite(integrator.stability_limit()))
    log << ", stability limit " << integrator.stability_limit();
  log << "\n";
  if (parameters.contact.formulation == ContactFormulation::penalty &&
      parameters.contact.automatic_penalty)
    log << "  penalty factor (auto): " << penalty_factor
        << ", stiffest contact spring omega dt = " << penalty_spring_omega_dt(*contact, mass, dt)
        << ", bodies' highest mode omega dt = " << highest_frequency * dt << "\n";
}

template <int dim>
void ContactProblem<dim>::check_time_step(const ConditionalOStream& log) const
{
  const double body_omega_dt   = discretization.highest_frequency * integrator.time_step();
  const double spring_omega_dt = penalty_spring_omega_dt(*contact, mass, integrator.time_step());
  // A resolved mesh (omega dt <= 2, Courant number about 1) with an unresolved penalty spring: the
  // spring is the one frequency the step cannot follow, and the contact node chatters (see
  // size_automatic_penalty()).
  if (spring_omega_dt > resolved_omega_dt && is_resolved(body_omega_dt))
    log << "WARNING: the penalty spring (Contact/penalty factor = " << penalty_factor
        << ") has omega dt = " << spring_omega_dt << " while the bodies' highest mode has "
        << body_omega_dt
        << ": expect contact chatter and step cuts by the energy guard. A penalty factor <= "
        << penalty_factor * std::pow(1. / spring_omega_dt, 2)
        << " (or auto) resolves the spring (omega dt <= 1), at the cost of more penetration.\n";

  check_stability(integrator, body_omega_dt, spring_omega_dt, penalty_lowered);
}

template <int dim>
void ContactProblem<dim>::set_initial_conditions()
{
  Vector<double> velocity(discretization.dof_handler.n_dofs());
  for (const auto& node : discretization.nodes->nodes())
  {
    const Tensor<1, dim> v0 = model.initial_velocity(node.body, node.position);
    for (unsigned int d = 0; d < dim; ++d)
      velocity[node.dofs[d]] = v0[d];
  }
  stepper->start(velocity, *discretization.bodies);
  contact->update_geometry(contact->border().gather(stepper->state().displacement));
  impulses->start(stepper->state());
}

template <int dim>
std::string ContactProblem<dim>::description() const
{
  return "dimension " + std::to_string(dim) + ", " +
         std::to_string(discretization.dof_handler.n_dofs()) + " DoFs, " +
         std::to_string(contact->n_pairs()) + " contact candidates, " +
         std::to_string(model.n_bodies()) + " bodies, node positions " +
         discretization.node_checksum();
}

DYNCONTACT_INSTANTIATE_CLASS(ContactProblem)
} // namespace dyncontact
