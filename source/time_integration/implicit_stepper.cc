#include <dyncontact/base/dimensions.h>
#include <dyncontact/time_integration/implicit_stepper.h>

namespace dyncontact
{
template <int dim>
ImplicitStepper<dim>::ImplicitStepper(const GeneralizedAlpha& integrator,
                                      const Vector<double>& lumped_mass,
                                      const std::vector<bool>& is_fixed_dof,
                                      const PrescribedDisplacements<dim>& prescribed,
                                      const ExternalLoads<dim>& loads,
                                      ContactConstraints<dim>& contact,
                                      const ContactDynamics<dim>& dynamics,
                                      ContactNewtonSolver<dim>& solver)
    : integrator(integrator), mass(lumped_mass), is_fixed_dof(is_fixed_dof), prescribed(prescribed),
      loads(loads), contact(contact), dynamics(dynamics), solver(solver),
      border_mass(contact.border().gather(lumped_mass)),
      border_fixed(contact.border().gather(is_fixed_dof))
{
}

template <int dim>
void ImplicitStepper<dim>::start(const Vector<double>& initial_velocity,
                                 const ElasticBodies<dim>& bodies)
{
  current.reinit(solver.dof_layout());
  copy_owned_entries(initial_velocity, current.velocity);
  DistributedVector internal_force;
  bodies.assemble_internal_force(current.displacement, internal_force, nullptr); // Q(u_0 = 0)
  current.internal_force.copy_locally_owned_data_from(internal_force);
  copy_owned_entries(loads.force(0., mass), current.external_force);
  for_each_owned_row(current.velocity,
                     [&](const types::global_dof_index i, const unsigned int j)
                     {
                       double &v = current.velocity.local_element(j),
                              &a = current.acceleration.local_element(j);
                       a         = mass[i] > 0. ? (current.external_force.local_element(j) -
                                           current.internal_force.local_element(j)) /
                                              mass[i]
                                                : 0.;
                       if (is_fixed_dof[i])
                         v = a = 0.;
                     });
  // A thousandth of a step: the rates' one-sided differences are then exact to far below the
  // integrator's own error at the boundary.
  prescribed.set_rates(0., 1e-3 * integrator.time_step(), current.velocity, current.acceleration);
}

template <int dim>
unsigned int ImplicitStepper<dim>::solve(const StepState& before,
                                         const double time,
                                         DistributedVector& increment)
{
  increment.reinit(before.displacement);
  integrator.predict(before.displacement, before.velocity, before.acceleration, predictor);
  // The acceleration at t_n the step uses (a contact-dynamics treatment may replace it).
  start_acceleration                   = before.acceleration;
  const ContactBorder<dim>& border     = contact.border();
  std::vector<Vector<double>> at_start = border.gather_all({&before.displacement,
                                                            &before.velocity,
                                                            &before.internal_force,
                                                            &before.external_force,
                                                            &start_acceleration,
                                                            &predictor});
  // The pairs (normals, master points) of u_n, held over the step: the solve, the rate
  // correction and the step's measures (gaps, jumps, recovered forces) all see the same pairs.
  contact.update_geometry(at_start[0]);
  const typename ContactDynamics<dim>::StepStart start{
      at_start[0], at_start[1], at_start[2], at_start[3], border_fixed};
  Vector<double>&border_acceleration = at_start[4], &border_predictor = at_start[5];
  dynamics.adjust_predictor(
      integrator.rate_map(), contact, border_mass, start, border_acceleration, border_predictor);
  border.scatter(border_acceleration, start_acceleration);
  border.scatter(border_predictor, predictor);
  contact.hold_gaps(at_start[0], dynamics.persistent_pairs(contact, border_predictor));
  copy_owned_entries(loads.force(time, mass), current.external_force);
  // A dissipative member balances at t_{n+1-alpha_f}: the solve takes W_eff (GeneralizedAlpha).
  DistributedVector effective_force;
  if (integrator.family() != IntegratorFamily::newmark)
  {
    load_at_balance.reinit(before.displacement, true);
    copy_owned_entries(loads.force(integrator.load_time(time), mass), load_at_balance);
    DistributedVector old_inertia_force(start_acceleration);
    for_each_owned_row(old_inertia_force,
                       [&](const types::global_dof_index i, const unsigned int j) {
                         old_inertia_force.local_element(j) =
                             mass[i] * start_acceleration.local_element(j);
                       });
    integrator.effective_force(
        load_at_balance, old_inertia_force, before.internal_force, effective_force);
    old_balance_acceleration = start_acceleration;
    old_balance_net_force    = before.internal_force;
    old_balance_net_force *= integrator.alpha_f();
    old_balance_net_force -= load_at_balance;
  }
  // Dirichlet boundaries: their DoFs are fixed (Newton never updates them), so they take g(t_{n+1})
  // in the configuration Newton restarts from and in the initial guess u~ + increment.
  DistributedVector restart_configuration = before.displacement;
  prescribed.set_displacement(time, restart_configuration);
  for_each_owned_row(increment,
                     [&](const types::global_dof_index i, const unsigned int j)
                     {
                       if (is_fixed_dof[i])
                         increment.local_element(j) =
                             restart_configuration.local_element(j) - predictor.local_element(j);
                     });
  const auto report =
      solver.solve(predictor,
                   integrator.inertia_factor(),
                   effective_force.size() > 0 ? effective_force : current.external_force,
                   before.displacement,
                   restart_configuration,
                   increment);
  current.internal_force.copy_locally_owned_data_from(solver.internal_force());
  const unsigned int pair = contact.first_prescribed_active_pair();
  if (pair < contact.n_pairs())
  {
    const Point<dim>& node = contact.candidate_pairs()[pair].slave.position;
    std::string where;
    for (unsigned int d = 0; d < dim; ++d)
      where += (d == 0 ? "(" : ", ") + format_number(node[d]);
    throw SolverFailure("the contact pair of the slave node at " + where +
                        ") closed with its normal along a displacement a Dirichlet boundary "
                        "prescribes, which is not supported (its constraint lacks the DoF that "
                        "moves it): prescribe that boundary away from the contact surfaces or "
                        "across their normal");
  }
  return report.linear_solves;
}

template <int dim>
void ImplicitStepper<dim>::finish(const StepState& before, const DistributedVector& increment)
{
  current.displacement = predictor;
  current.displacement += increment;
  integrator.update_rates(
      increment, before.velocity, start_acceleration, current.velocity, current.acceleration);
  const ContactBorder<dim>& border      = contact.border();
  std::vector<Vector<double>> on_border = border.gather_all({&current.velocity,
                                                             &current.acceleration,
                                                             &before.displacement,
                                                             &before.velocity,
                                                             &start_acceleration,
                                                             &current.displacement,
                                                             &increment});
  Vector<double>&border_velocity = on_border[0], &border_acceleration = on_border[1];
  dynamics.correct_rates(
      integrator.rate_map(),
      contact,
      border_mass,
      {on_border[2], on_border[3], on_border[4], on_border[5], on_border[6], border_fixed},
      border_velocity,
      border_acceleration);
  border.scatter(border_velocity, current.velocity);
  border.scatter(border_acceleration, current.acceleration);
}

template <int dim>
void ImplicitStepper<dim>::solved_balance(DistributedVector& acceleration,
                                          DistributedVector& net_force) const
{
  acceleration = current.acceleration;
  net_force    = current.internal_force;
  if (old_balance_acceleration.size() > 0)
  {
    acceleration.sadd(1. - integrator.alpha_m(), integrator.alpha_m(), old_balance_acceleration);
    net_force.sadd(1. - integrator.alpha_f(), 1., old_balance_net_force);
  }
  else
    net_force -= current.external_force;
}

DYNCONTACT_INSTANTIATE_CLASS(ImplicitStepper)
} // namespace dyncontact
