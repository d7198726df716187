#include <dyncontact/simulation.h>

#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <iomanip>

namespace dyncontact
{
template <int dim>
Simulation<dim>::Simulation(const RunParameters& parameters,
                            std::unique_ptr<ProblemModel<dim>> model,
                            std::ostream& log)
    : parameters(parameters), model(std::move(model)),
      is_root_rank(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0), log(log, is_root_rank),
      newmark(parameters.time), triangulation(MPI_COMM_WORLD),
      fe(FE_Q<dim>(this->model->element_degree()), dim), mapping(this->model->element_degree()),
      n_steps(0), time(0.), step_history(history_columns())
{
}

template <int dim>
std::vector<std::string> Simulation<dim>::history_columns() const
{
  std::vector<std::string> columns = {"time",
                                      "contact_force",
                                      "contact_multiplier",
                                      "active_constraints",
                                      "newton_iterations",
                                      "kinetic_energy",
                                      "strain_energy",
                                      "total_energy",
                                      "algorithmic_energy",
                                      "max_penetration",
                                      "force_imbalance"};
  if (dim > 1)
    for (const std::string column : {"contact_radius", "centre_pressure"})
      columns.push_back(column);
  for (unsigned int b = 1; b <= model->n_bodies(); ++b)
    for (const std::string quantity : {"momentum_", "u_tip_", "v_tip_", "a_tip_"})
      columns.push_back(quantity + std::to_string(b));
  return columns;
}

template <int dim>
void Simulation<dim>::setup()
{
  model->create_triangulation(triangulation);
  mapping.initialize(MappingQ<dim>(model->element_degree()), triangulation);
  dof_handler.reinit(triangulation);
  dof_handler.distribute_dofs(fe);
  nodes      = std::make_unique<NodeIndex<dim>>(dof_handler, mapping);
  kinematics = model->create_kinematics();
  bodies     = std::make_unique<ElasticBodies<dim>>(
      dof_handler, mapping, *kinematics, model->body_materials());
  mass       = bodies->lumped_mass();
  fixed_dofs = model->fixed_dofs(*nodes);
  loads      = std::make_unique<SurfaceTractions<dim>>(
      dof_handler, mapping, *kinematics, model->surface_tractions());
  surface_contact = model->create_surface_contact(dof_handler, *kinematics, *nodes);
  if (surface_contact)
    contact =
        std::make_unique<ContactConstraints<dim>>(*surface_contact, parameters.contact.formulation);
  else
    contact = std::make_unique<ContactConstraints<dim>>(model->contact_pairs(*nodes),
                                                        parameters.contact.formulation);
  solver =
      std::make_unique<ContactNewtonSolver<dim>>(dof_handler,
                                                 *bodies,
                                                 *contact,
                                                 mass,
                                                 fixed_dofs,
                                                 parameters.newton,
                                                 GridTools::minimal_cell_diameter(triangulation));
  monitors = model->monitor_nodes(*nodes);
  // The pair nearest to the axis (axisymmetry: r = 0), whose pressure is centre_pressure.
  const auto& pairs = contact->candidate_pairs();
  innermost_pair    = std::min_element(pairs.begin(),
                                    pairs.end(),
                                    [](const ContactPair<dim>& a, const ContactPair<dim>& b) {
                                      return distance_from_axis(a.node_a.position) <
                                             distance_from_axis(b.node_a.position);
                                    }) -
                   pairs.begin();

  const double dt = parameters.time.time_step;
  n_steps         = parameters.time.n_steps();
  for (const double profile_time : parameters.output.profile_times)
    if (profile_time > (n_steps + 0.5) * dt)
      log << "WARNING: Output/profile times: " << profile_time
          << " lies after the end of the run (t = " << n_steps * dt
          << "); no profile is written for it.\n";
    else
      profile_steps.insert(static_cast<unsigned int>(std::lround(profile_time / dt)));

  log << "dyncontact: " << dof_handler.n_dofs() << " displacement DoFs, " << contact->n_pairs()
      << " contact candidate(s), " << n_steps << " steps of dt = " << dt << ", "
      << (newmark.scheme() == NewmarkScheme::modified ? "modified" : "classical")
      << " Newmark (beta = " << newmark.beta() << ", gamma = " << newmark.gamma() << "), "
      << (parameters.contact.formulation == ContactFormulation::penalty ? "penalty"
                                                                        : "Lagrange multiplier")
      << " contact\n";
  if (std::abs(n_steps * dt - parameters.time.end_time) > 1e-9 * parameters.time.end_time)
    log << "  note: end time " << parameters.time.end_time
        << " is not a multiple of the time step; the run ends at t = " << n_steps * dt << "\n";
  if (is_root_rank)
    model->print_summary(log.get_stream(), dt);
  warn_about_stability();
}

template <int dim>
void Simulation<dim>::warn_about_stability() const
{
  // With 2 beta < gamma Newmark is stable only for omega dt <= 1/sqrt(gamma/2 - beta). The
  // bodies' highest frequency and, for the penalty, the spring between two lumped masses,
  // omega = sqrt(eps / m_reduced), must both stay below it.
  if (2. * newmark.beta() >= newmark.gamma())
    return;
  const double limit = 1. / std::sqrt(newmark.gamma() / 2. - newmark.beta());
  const auto warn = [&](const std::string& what, const double omega_dt, const std::string& remedy)
  {
    log << "WARNING: " << what << " has omega dt = " << omega_dt << ", above the stability limit "
        << limit << " of Newmark with beta = " << newmark.beta() << ", gamma = " << newmark.gamma()
        << "; expect the solution to blow up. Use 2 beta >= gamma, a smaller time step" << remedy
        << ".\n";
  };
  const double body_omega_dt = model->highest_frequency() * newmark.time_step();
  if (body_omega_dt > limit * (1. + 1e-12))
    warn("the mesh's highest mode", body_omega_dt, "");
  if (parameters.contact.formulation != ContactFormulation::penalty)
    return;
  for (const auto& pair : contact->candidate_pairs())
  {
    const double mass_a   = mass[pair.node_a.dofs[0]];
    const double reduced  = pair.against_wall() ? mass_a
                                                : mass_a * mass[pair.node_b->dofs[0]] /
                                                     (mass_a + mass[pair.node_b->dofs[0]]);
    const double omega_dt = newmark.time_step() * std::sqrt(pair.penalty_stiffness / reduced);
    if (omega_dt > limit)
    {
      warn("the penalty spring (Contact/penalty factor)", omega_dt, " or a smaller penalty factor");
      return;
    }
  }
}

template <int dim>
void Simulation<dim>::set_initial_conditions()
{
  displacement.reinit(dof_handler.n_dofs());
  velocity.reinit(dof_handler.n_dofs());
  acceleration.reinit(dof_handler.n_dofs());
  for (const auto& node : nodes->nodes())
  {
    const Tensor<1, dim> v0 = model->initial_velocity(node.body, node.position);
    for (unsigned int d = 0; d < dim; ++d)
      velocity[node.dofs[d]] = v0[d];
  }
  // Initial acceleration from equilibrium, M a_0 = W(0) - Q(u_0) (no contact at t = 0).
  Vector<double> internal_force;
  bodies->assemble_internal_force(displacement, internal_force, nullptr);
  external_force = loads->force(0.);
  for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
    acceleration[i] = (external_force[i] - internal_force[i]) / mass[i];
  for (const auto dof : fixed_dofs)
    velocity[dof] = acceleration[dof] = 0.;
  contact->update_geometry(displacement);
}

template <int dim>
unsigned int Simulation<dim>::do_time_step()
{
  const Vector<double> old_displacement = displacement, old_velocity = velocity,
                       old_acceleration = acceleration;
  Vector<double> predictor, increment(dof_handler.n_dofs());
  newmark.predict(old_displacement, old_velocity, old_acceleration, predictor);
  Vector<double> last_configuration = old_displacement; // as an increment over the predictor
  last_configuration -= predictor;
  external_force    = loads->force(time);
  const auto report = solver->solve(
      predictor, newmark.inertia_factor(), external_force, last_configuration, increment);
  displacement = predictor;
  displacement += increment;
  newmark.update_rates(increment, old_velocity, old_acceleration, velocity, acceleration);
  if (newmark.scheme() == NewmarkScheme::modified)
    contact->apply_rate_correction(
        newmark,
        mass,
        {old_displacement, old_velocity, old_acceleration, displacement, increment},
        velocity,
        acceleration);
  return report.linear_solves;
}

template <int dim>
Vector<double> Simulation<dim>::net_internal_force() const
{
  Vector<double> net = solver->internal_force();
  net -= external_force;
  return net;
}

template <int dim>
Vector<double> Simulation<dim>::contact_traction(const std::vector<double>& pressures) const
{
  Vector<double> traction(dof_handler.n_dofs());
  for (unsigned int k = 0; k < contact->n_pairs(); ++k)
  {
    const ContactPair<dim>& pair = contact->candidate_pairs()[k];
    for (unsigned int d = 0; d < dim; ++d)
    {
      traction[pair.node_a.dofs[d]]  = -pressures[k] * pair.normal[d];
      traction[pair.node_b->dofs[d]] = pressures[k] * pair.normal[d];
    }
  }
  return traction;
}

template <int dim>
void Simulation<dim>::write_contact_pressure(const std::vector<double>& pressures) const
{
  std::vector<typename FieldOutput<dim>::PressureSample> samples;
  for (unsigned int k = 0; k < contact->n_pairs(); ++k)
    samples.push_back({current_position(contact->candidate_pairs()[k].node_a, displacement),
                       contact->gap(k, displacement),
                       contact->active_multiplier(k),
                       pressures[k],
                       contact->is_active(k)});
  field_output->write_contact_pressure(time, samples);
}

template <int dim>
void Simulation<dim>::record_step(const unsigned int step, const unsigned int linear_solves)
{
  double kinetic = 0., acceleration_energy = 0.;
  for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
  {
    kinetic += 0.5 * mass[i] * velocity[i] * velocity[i];
    acceleration_energy += 0.5 * mass[i] * acceleration[i] * acceleration[i];
  }
  // After a step the solver's last evaluation was at this displacement: reuse its pass.
  const double strain  = step == 0 ? bodies->strain_energy(displacement) : solver->strain_energy();
  double contact_force = 0., force_imbalance = 0.;
  if (step > 0)
  {
    const Vector<double> net_force = net_internal_force();
    contact_force          = contact->recovered_contact_force(mass, acceleration, net_force);
    const auto side_forces = contact->recovered_side_forces(mass, acceleration, net_force);
    force_imbalance        = side_forces.on_a - side_forces.on_b;
  }

  std::vector<double> row = {time,
                             contact_force,
                             contact->total_multiplier(),
                             static_cast<double>(contact->n_active()),
                             static_cast<double>(linear_solves),
                             kinetic,
                             strain,
                             kinetic + strain,
                             newmark.algorithmic_energy(kinetic, strain, acceleration_energy),
                             contact->max_penetration(displacement),
                             force_imbalance};
  // Contact pressures (surface contact only): one dense solve per step, skipped without contact.
  const std::vector<double> pressures = surface_contact && contact->n_active() > 0
                                            ? contact->contact_pressures(displacement)
                                            : std::vector<double>(contact->n_pairs(), 0.);
  if (dim > 1)
  {
    row.push_back(contact->contact_radius(displacement));
    row.push_back(surface_contact ? pressures[innermost_pair] : 0.);
  }
  const Tensor<1, dim> direction = model->impact_direction();
  std::vector<double> momentum(monitors.size(), 0.);
  for (const auto& node : nodes->nodes())
    for (unsigned int d = 0; d < dim; ++d)
      momentum[node.body] += mass[node.dofs[d]] * direction[d] * velocity[node.dofs[d]];
  for (unsigned int b = 0; b < monitors.size(); ++b)
  {
    double u_tip = 0., v_tip = 0., a_tip = 0.;
    for (unsigned int d = 0; d < dim; ++d)
    {
      u_tip += direction[d] * displacement[monitors[b].dofs[d]];
      v_tip += direction[d] * velocity[monitors[b].dofs[d]];
      a_tip += direction[d] * acceleration[monitors[b].dofs[d]];
    }
    row.insert(row.end(), {momentum[b], u_tip, v_tip, a_tip});
  }
  step_history.add_row(row);

  if (parameters.output.vtu_interval > 0 && step % parameters.output.vtu_interval == 0)
  {
    const Vector<double> traction =
        surface_contact ? contact_traction(pressures) : Vector<double>();
    field_output->write_fields(
        step, time, displacement, velocity, acceleration, surface_contact ? &traction : nullptr);
  }
  if (profile_steps.count(step) > 0 && is_root_rank)
  {
    field_output->write_profile(time, nodes->nodes(), displacement, velocity, acceleration);
    if (surface_contact)
      write_contact_pressure(pressures);
  }
}

template <int dim>
void Simulation<dim>::run()
{
  setup();
  set_initial_conditions();
  const std::string& directory = parameters.output.directory;
  field_output = std::make_unique<FieldOutput<dim>>(dof_handler, mapping, directory);
  if (dim == 2 && is_root_rank)
    field_output->write_cell_outlines(nodes->nodes());
  if (is_root_rank)
    step_history.attach_file(directory + "/history.csv");
  if (parameters.output.write_exact_solution && is_root_rank)
  {
    std::vector<double> times(n_steps + 1);
    for (unsigned int step = 0; step <= n_steps; ++step)
      times[step] = step * parameters.time.time_step;
    model->write_reference(directory, times, monitors);
  }

  record_step(0, 0);
  const unsigned int report_interval = std::max(1u, n_steps / 10);
  unsigned int total_solves          = 0;
  for (unsigned int step = 1; step <= n_steps; ++step)
  {
    time                             = step * parameters.time.time_step;
    const unsigned int active_before = contact->n_active();
    unsigned int linear_solves       = 0;
    try
    {
      linear_solves = do_time_step();
    }
    catch (const SolverFailure& failure)
    {
      throw SolverFailure("step " + std::to_string(step) + " (t = " + format_number(time) +
                          "): " + failure.what() +
                          " Results up to t = " + format_number(time - parameters.time.time_step) +
                          " are in " + directory + ".");
    }
    total_solves += linear_solves;
    record_step(step, linear_solves);
    if (!std::isfinite(step_history.value(step, "algorithmic_energy")))
      throw SolverFailure("step " + std::to_string(step) + " (t = " + format_number(time) +
                          "): the solution is no longer finite; the time integration is unstable "
                          "(see the stability warning at start, if any). Results up to this step "
                          "are in " +
                          directory + ".");
    if (step % report_interval == 0 || contact->n_active() != active_before)
      log << "  step " << std::setw(6) << step << "  t = " << std::setw(10) << time
          << "  active pairs " << contact->n_active() << "  linear solves " << linear_solves
          << "  total energy " << step_history.value(step, "total_energy") << "\n";
  }
  if (is_root_rank)
    model->summarize_run(directory, step_history, log.get_stream());
  log << "dyncontact: done, " << n_steps << " steps, " << total_solves
      << " linear solves. Results in " << directory << "\n";
}

template class Simulation<1>;
template class Simulation<2>;
} // namespace dyncontact
