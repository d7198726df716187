#include <dyncontact/contact/contact_factory.h>
#include <dyncontact/contact/penalty_sizing.h>
#include <dyncontact/simulation/checkpoint_file.h>
#include <dyncontact/simulation/interruption.h>
#include <dyncontact/simulation/simulation.h>
#include <dyncontact/time_integration/mode_resolution.h>
#include <dyncontact/time_integration/stability_check.h>

#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
namespace
{
/// Wall-clock seconds between two progress lines (active-set changes are reported at once).
constexpr double progress_interval = 3.;
} // namespace

template <int dim>
Simulation<dim>::Simulation(const RunParameters& parameters,
                            std::unique_ptr<ProblemModel<dim>> model,
                            std::ostream& log)
    : parameters(parameters), model(std::move(model)),
      is_root_rank(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0), log(log, is_root_rank),
      integrator(parameters.time), triangulation(MPI_COMM_WORLD),
      fe(FE_Q<dim>(this->model->element_degree()), dim), mapping(this->model->element_degree()),
      n_steps(0), time(0.), guards(parameters.guards, std::isfinite(integrator.stability_limit())),
      step_history(history_columns()), timer(this->log, TimerOutput::never, TimerOutput::wall_times)
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
                                      "force_imbalance",
                                      "velocity_jump",
                                      "acceleration_jump",
                                      "time_step",
                                      "step_cuts"};
  if (dim > 1)
    for (const std::string column : {"contact_radius", "centre_pressure"})
      columns.push_back(column);
  for (unsigned int b = 1; b <= model->n_bodies(); ++b)
    for (const std::string quantity : {"momentum_", "impulse_", "u_tip_", "v_tip_", "a_tip_"})
      columns.push_back(quantity + std::to_string(b));
  return columns;
}

template <int dim>
void Simulation<dim>::setup()
{
  build_discretization();
  build_contact_and_solver();
  index_dofs();
  schedule_and_log();
  check_time_step();
}

template <int dim>
void Simulation<dim>::build_discretization()
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
  std::vector<bool> fixed(dof_handler.n_dofs(), false);
  for (const auto dof : fixed_dofs)
    fixed[dof] = true;
  highest_frequency = bodies->highest_frequency_bound(fixed);
}

template <int dim>
void Simulation<dim>::build_contact_and_solver()
{
  const PenaltySizingInput sizing{
      mass, integrator.time_step(), highest_frequency * integrator.time_step()};
  const ContactDescription<dim> description = model->contact_description(*nodes);
  for (const auto& pair : description.surface_pairs)
    slave_surfaces.insert(pair.surface_a);
  for (const auto& pair : description.plane_pairs)
    slave_surfaces.insert(pair.surface);
  Contact<dim> built =
      create_contact(description, dof_handler, *kinematics, *nodes, parameters.contact, sizing);
  surface_contact  = std::move(built.surfaces);
  contact          = std::move(built.constraints);
  penalty_factor   = built.penalty_factor;
  penalty_lowered  = built.penalty_lowered_to_resolve_springs;
  contact_dynamics = create_contact_dynamics<dim>(parameters.contact.dynamics);
  // The multipliers as the contact force of the balance the step solves, on every integrator and
  // treatment (doc/method.md, "Contact forces on every integrator").
  contact->set_force_per_multiplier(contact_dynamics->contact_force_factor(integrator.rate_map()) *
                                    (1. - integrator.alpha_f()));
  // Mass redistribution: the contact nodes lose their mass only now, after the penalty sizing,
  // which weighs a pair's spring by its nodes' masses.
  if (contact_dynamics->contact_nodes_massless())
    mass = bodies->lumped_mass(contact->contact_dofs(dof_handler.n_dofs()));
  solver =
      std::make_unique<ContactNewtonSolver<dim>>(dof_handler,
                                                 *bodies,
                                                 *contact,
                                                 mass,
                                                 fixed_dofs,
                                                 parameters.newton,
                                                 GridTools::minimal_cell_diameter(triangulation),
                                                 timer,
                                                 integrator.alpha_f());
  stepper = std::make_unique<ImplicitStepper<dim>>(
      integrator, mass, is_fixed_dof, *loads, *contact, *contact_dynamics, *solver);
  body_impulses = std::make_unique<BodyImpulses<dim>>(integrator, mass, is_fixed_dof, *contact);
  step_measures = std::make_unique<StepMeasures<dim>>(integrator,
                                                      mass,
                                                      *bodies,
                                                      *solver,
                                                      *contact,
                                                      *contact_dynamics,
                                                      *stepper,
                                                      *body_impulses,
                                                      model->impact_direction());
}

template <int dim>
void Simulation<dim>::index_dofs()
{
  monitors = model->monitor_nodes(*nodes);
  is_fixed_dof.assign(dof_handler.n_dofs(), false);
  for (const auto dof : fixed_dofs)
    is_fixed_dof[dof] = true;
  body_impulses->index(nodes->nodes(), model->impact_direction(), model->n_bodies());
  // The pair nearest to the axis (axisymmetry: r = 0), whose pressure is centre_pressure.
  const auto& pairs = contact->candidate_pairs();
  innermost_pair    = std::min_element(pairs.begin(),
                                    pairs.end(),
                                    [](const ContactPair<dim>& a, const ContactPair<dim>& b) {
                                      return distance_from_axis(a.slave.position) <
                                             distance_from_axis(b.slave.position);
                                    }) -
                   pairs.begin();
}

template <int dim>
void Simulation<dim>::schedule_and_log()
{
  const double dt     = parameters.time.time_step;
  n_steps             = parameters.time.n_steps();
  const auto schedule = [&](const std::vector<double>& times, const std::string& entry)
  {
    std::set<unsigned int> steps;
    for (const double t : times)
      if (t > (n_steps + 0.5) * dt)
        log << "WARNING: Output/" << entry << ": " << t
            << " lies after the end of the run (t = " << n_steps * dt
            << "); nothing is written for it.\n";
      else
        steps.insert(static_cast<unsigned int>(std::lround(t / dt)));
    return steps;
  };
  profile_steps = schedule(parameters.output.profile_times, "profile times");
  vtu_steps     = schedule(parameters.output.vtu_times, "vtu times");

  log << "dyncontact: " << dof_handler.n_dofs() << " displacement DoFs, " << contact->n_pairs()
      << " contact candidate(s), " << n_steps << " steps of dt = " << dt << ", "
      << integrator.description() << ", contact dynamics "
      << contact_dynamics_names().name(parameters.contact.dynamics) << ", "
      << contact_formulation_names().name(parameters.contact.formulation) << " contact\n";
  if (std::abs(n_steps * dt - parameters.time.end_time) > 1e-9 * parameters.time.end_time)
    log << "  note: end time " << parameters.time.end_time
        << " is not a multiple of the time step; the run ends at t = " << n_steps * dt << "\n";
  if (is_root_rank)
    model->print_summary(log.get_stream(), dt);
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
void Simulation<dim>::check_time_step() const
{
  const double body_omega_dt   = highest_frequency * integrator.time_step();
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
void Simulation<dim>::set_initial_conditions()
{
  StepState& state = stepper->state();
  state.reinit(dof_handler.n_dofs());
  Vector<double>&velocity = state.velocity, &acceleration = state.acceleration;
  for (const auto& node : nodes->nodes())
  {
    const Tensor<1, dim> v0 = model->initial_velocity(node.body, node.position);
    for (unsigned int d = 0; d < dim; ++d)
      velocity[node.dofs[d]] = v0[d];
  }
  // Initial acceleration from equilibrium, M a_0 = W(0) - Q(u_0) (no contact at t = 0); zero at
  // massless DoFs (Contact/dynamics = mass-redistribution), whose rates carry no momentum.
  bodies->assemble_internal_force(state.displacement, state.internal_force, nullptr);
  state.external_force = loads->force(0.);
  for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
    acceleration[i] =
        mass[i] > 0. ? (state.external_force[i] - state.internal_force[i]) / mass[i] : 0.;
  for (const auto dof : fixed_dofs)
    velocity[dof] = acceleration[dof] = 0.;
  contact->update_geometry(state.displacement);
  body_impulses->start(state);
}

template <int dim>
typename Simulation<dim>::State Simulation<dim>::current_state() const
{
  return {stepper->state(), contact->state(), solver->tangent_scale(), body_impulses->ledger()};
}

template <int dim>
void Simulation<dim>::restore(const State& state)
{
  stepper->state() = state.step;
  solver->set_tangent_scale(state.tangent_scale);
  body_impulses->ledger() = state.impulses;
  contact->restore(state.contact);
}

template <int dim>
unsigned int Simulation<dim>::do_time_step(const State& before)
{
  Vector<double> increment;
  const unsigned int linear_solves = stepper->solve(before.step, time, increment);
  body_impulses->balance_momenta(increment, solver->last_residual(), integrator.inertia_factor());
  stepper->finish(before.step, increment);
  body_impulses->accumulate(before.step, before.impulses, stepper->state(), stepper->step_load());
  return linear_solves;
}

template <int dim>
Vector<double> Simulation<dim>::contact_traction(const std::vector<double>& pressures) const
{
  Vector<double> traction(dof_handler.n_dofs());
  // The slave node's pressure along -n on body A; on body B distributed to the master nodes by
  // their weights (node-to-node: the facing node's own pressure).
  for (unsigned int k = 0; k < contact->n_pairs(); ++k)
    contact->candidate_pairs()[k].for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          for (unsigned int d = 0; d < dim; ++d)
            traction[node.dofs[d]] +=
                coefficient * pressures[k] * contact->candidate_pairs()[k].normal[d];
        });
  return traction;
}

template <int dim>
std::vector<typename FieldOutput<dim>::PressureSample>
Simulation<dim>::pressure_samples(const std::vector<double>& pressures) const
{
  std::vector<typename FieldOutput<dim>::PressureSample> samples;
  for (unsigned int k = 0; k < contact->n_pairs(); ++k)
  {
    const Node<dim>& slave = contact->candidate_pairs()[k].slave;
    samples.push_back({slave,
                       current_position(slave, stepper->state().displacement),
                       contact->gap(k, stepper->state().displacement),
                       contact->pair_force(k),
                       pressures[k],
                       contact->is_active(k)});
  }
  return samples;
}

template <int dim>
Measures Simulation<dim>::measure() const
{
  return step_measures->measure(step_history.n_rows() > 0);
}

template <int dim>
StepGuards::Figures Simulation<dim>::guard_figures(const Measures& measures) const
{
  double multiplier_magnitude = 0.;
  for (unsigned int k = 0; k < contact->n_pairs(); ++k)
    multiplier_magnitude += std::abs(contact->pair_force(k));
  const auto energy_at_this_step_size = [this](const Measures& state)
  {
    return integrator.algorithmic_energy(
        state.kinetic_energy, state.strain_energy, state.acceleration_energy);
  };
  return {time,
          guarded_energy + energy_at_this_step_size(measures) -
              energy_at_this_step_size(accepted_measures),
          body_impulses->ledger().external_work,
          measures.contact_force,
          multiplier_magnitude,
          measures.momenta,
          body_impulses->ledger().impulses,
          measures.momentum_magnitude,
          measures.kinetic_energy + measures.strain_energy};
}

template <int dim>
void Simulation<dim>::record_step(const Measures& measures,
                                  const unsigned int nominal_step,
                                  const unsigned int linear_solves,
                                  const unsigned int cuts)
{
  const StepState& state  = stepper->state();
  std::vector<double> row = {time,
                             measures.contact_force,
                             contact->total_pair_force(),
                             static_cast<double>(contact->n_active()),
                             static_cast<double>(linear_solves),
                             measures.kinetic_energy,
                             measures.strain_energy,
                             measures.kinetic_energy + measures.strain_energy,
                             measures.algorithmic_energy,
                             contact->max_penetration(state.displacement),
                             measures.force_imbalance,
                             measures.velocity_jump,
                             measures.acceleration_jump,
                             step_history.n_rows() == 0 ? 0. : integrator.time_step(),
                             static_cast<double>(cuts)};
  // Contact pressures (surface contact only): one solve per step, skipped without contact.
  const std::vector<double> pressures = surface_contact && contact->n_active() > 0
                                            ? contact->contact_pressures(state.displacement)
                                            : std::vector<double>(contact->n_pairs(), 0.);
  if (dim > 1)
  {
    row.push_back(contact->contact_radius(state.displacement));
    row.push_back(surface_contact ? pressures[innermost_pair] : 0.);
  }
  const Tensor<1, dim> direction = model->impact_direction();
  for (unsigned int b = 0; b < monitors.size(); ++b)
  {
    double u_tip = 0., v_tip = 0., a_tip = 0.;
    for (unsigned int d = 0; d < dim; ++d)
    {
      u_tip += direction[d] * state.displacement[monitors[b].dofs[d]];
      v_tip += direction[d] * state.velocity[monitors[b].dofs[d]];
      a_tip += direction[d] * state.acceleration[monitors[b].dofs[d]];
    }
    row.insert(row.end(),
               {measures.momenta[b], body_impulses->ledger().impulses[b], u_tip, v_tip, a_tip});
  }
  step_history.add_row(row);
  const unsigned int frame   = step_history.n_rows() - 1; // VTU files are numbered by row
  const bool on_nominal_grid = frame == 0 || nominal_step > 0;
  if (on_nominal_grid)
    nominal_rows.push_back(frame);

  const unsigned int step        = frame == 0 ? 0 : nominal_step;
  const OutputParameters& output = parameters.output;
  const bool vtu_on              = output.vtu_interval > 0 || !vtu_steps.empty();
  const bool vtu_frame =
      (on_nominal_grid && ((output.vtu_interval > 0 && step % output.vtu_interval == 0) ||
                           vtu_steps.count(step) > 0)) ||
      (vtu_on && output.vtu_during_contact && contact->n_active() > 0);
  const bool profile = on_nominal_grid && profile_steps.count(step) > 0 && is_root_rank;
  TimerOutput::Scope scope(timer, "output");
  const auto samples = surface_contact && (vtu_frame || profile)
                           ? pressure_samples(pressures)
                           : std::vector<typename FieldOutput<dim>::PressureSample>();
  if (vtu_frame)
  {
    const Vector<double> traction =
        surface_contact ? contact_traction(pressures) : Vector<double>();
    field_output->write_fields(frame,
                               time,
                               state.displacement,
                               state.velocity,
                               state.acceleration,
                               surface_contact ? &traction : nullptr);
    if (surface_contact)
      field_output->write_contact_surface(frame, time, state.displacement, samples);
  }
  if (profile) // on the nominal grid only
  {
    field_output->write_profile(
        time, nodes->nodes(), state.displacement, state.velocity, state.acceleration);
    if (surface_contact)
      field_output->write_contact_pressure(time, samples);
  }
}

template <int dim>
void Simulation<dim>::write_reference_and_summary(const std::string& stop)
{
  const unsigned int rows = step_history.n_rows();
  const double last_time  = rows > 0 ? step_history.value(rows - 1, "time") : 0.;
  summaries               = "complete";
  if (!stop.empty())
    summaries = "incomplete: " + stop + " after t = " + format_number(last_time) +
                " before the end time " + format_number(n_steps * parameters.time.time_step);
  else if (rows > 0 && step_history.value(rows - 1, "contact_force") != 0.)
    summaries = "incomplete: still in contact at the end time " + format_number(last_time);
  if (!is_root_rank)
    return;
  const std::string& directory = parameters.output.directory;
  if (parameters.output.write_exact_solution)
    model->write_reference(directory, step_history.column("time"), monitors);
  // Every accepted row, the sub-steps of cut steps included, and the contact impulses the run
  // accumulated (equal to the momentum changes they caused, see the momentum guard).
  model->summarize_run(directory,
                       step_history,
                       body_impulses->ledger().contact_impulses,
                       summaries,
                       log.get_stream());
}

template <int dim>
unsigned int Simulation<dim>::n_factorizations() const
{
  return solver->n_factorizations();
}

template <int dim>
History Simulation<dim>::nominal_history() const
{
  History nominal(step_history.column_names());
  for (const unsigned int row : nominal_rows)
    nominal.add_row(step_history.row(row));
  return nominal;
}

template <int dim>
ProblemFingerprint Simulation<dim>::problem_fingerprint() const
{
  std::vector<double> coordinates;
  for (const auto& node : nodes->nodes())
    for (unsigned int d = 0; d < dim; ++d)
      coordinates.push_back(node.position[d]);
  ProblemFingerprint fingerprint;
  fingerprint.n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  fingerprint.entries = parameters.problem_entries;
  fingerprint.discretization =
      "dimension " + std::to_string(dim) + ", " + std::to_string(dof_handler.n_dofs()) + " DoFs, " +
      std::to_string(contact->n_pairs()) + " contact candidates, " +
      std::to_string(model->n_bodies()) + " bodies, node positions " + checksum(coordinates);
  return fingerprint;
}

template <int dim>
template <class Archive>
void Simulation<dim>::serialize_state(Archive& archive)
{
  typename ContactConstraints<dim>::State contact_state = contact->state();
  double tangent_scale                                  = solver->tangent_scale();
  archive& time;
  archive & stepper->state();
  archive& contact_state.active;
  archive& contact_state.multipliers;
  archive & body_impulses->ledger();
  archive& guarded_energy;
  archive& accepted_measures.kinetic_energy;
  archive& accepted_measures.strain_energy;
  archive& accepted_measures.acceleration_energy;
  archive&* controller;
  archive& guards;
  archive& step_history;
  archive& nominal_rows;
  archive& counters.total_solves;
  archive& counters.total_cuts;
  archive& counters.steps_taken;
  archive& counters.cut_places;
  archive& tangent_scale;
  archive&* field_output;
  if (Archive::is_loading::value)
  {
    contact->restore(contact_state);
    solver->set_tangent_scale(tangent_scale);
  }
}

template <int dim>
void Simulation<dim>::write_checkpoint()
{
  if (!is_root_rank)
    return;
  TimerOutput::Scope scope(timer, "output");
  checkpoint_file::write(parameters.output.directory,
                         problem_fingerprint(),
                         [this](boost::archive::binary_oarchive& archive)
                         { serialize_state(archive); });
  checkpoint_time = time;
}

template <int dim>
void Simulation<dim>::read_checkpoint(const std::string& directory)
{
  checkpoint_file::read(directory,
                        problem_fingerprint(),
                        [this](boost::archive::binary_iarchive& archive)
                        { serialize_state(archive); });
}

template <int dim>
void Simulation<dim>::check_checkpoint(const std::string& directory)
{
  checkpoint_file::read(directory, problem_fingerprint(), [](boost::archive::binary_iarchive&) {});
}

template <int dim>
void Simulation<dim>::prepare()
{
  if (prepared)
    return;
  setup();
  set_initial_conditions();
  prepared = true;
}

template <int dim>
void Simulation<dim>::start(const std::string& resume_directory)
{
  prepare();
  const std::string& directory = parameters.output.directory;
  std::vector<std::shared_ptr<const Material>> materials;
  for (const BodyMaterial& body : model->body_materials())
    materials.push_back(body.material);
  field_output = std::make_unique<FieldOutput<dim>>(
      dof_handler, mapping, *kinematics, materials, slave_surfaces, directory);
  if (dim == 2 && is_root_rank)
    field_output->write_cell_outlines(nodes->nodes());

  controller = std::make_unique<StepController>(
      parameters.time.time_step, n_steps, parameters.time.max_step_cuts);
  const Measures initial = measure();
  guarded_energy         = initial.algorithmic_energy;
  accepted_measures      = initial;
  guards.initialize(guard_figures(initial));
  if (resume_directory.empty())
  {
    if (is_root_rank)
      step_history.attach_file(directory + "/history.csv");
    record_step(initial, 0, 0, 0);
  }
  else
  {
    read_checkpoint(resume_directory);
    checkpoint_time = time;
    if (is_root_rank)
      step_history.attach_file(directory + "/history.csv");
    log << "dyncontact: resumed from " << resume_directory << "/checkpoint.bin at t = " << time
        << "\n";
  }
  progress.wall_start     = std::chrono::steady_clock::now();
  progress.last_report    = progress.wall_start;
  progress.steps_this_run = 0;
  progress.start_fraction = time / (n_steps * parameters.time.time_step);
}

template <int dim>
unsigned int
Simulation<dim>::solve_step(const State& before, Measures& measures, unsigned int& cuts)
{
  unsigned int linear_solves = 0;
  for (cuts = 0;; ++cuts)
  {
    integrator.set_time_step(controller->step_size());
    time = controller->end_time();
    std::string failure;
    try
    {
      linear_solves += do_time_step(before);
      measures                          = measure();
      const StepGuards::Figures figures = guard_figures(measures);
      failure                           = guards.check(figures);
      if (failure.empty())
        failure = contact_event_failure(before, figures.energy);
      if (failure.empty())
      {
        guards.accept(figures);
        guarded_energy    = figures.energy;
        accepted_measures = measures;
        return linear_solves;
      }
    }
    catch (const SolverFailure& solver_failure)
    {
      failure = solver_failure.what();
    }
    restore(before);
    cut_after_failure(failure);
  }
}

template <int dim>
std::string Simulation<dim>::contact_event_failure(const State& before, const double energy) const
{
  // With massless contact nodes the bodies do not impact: a pair's force rises and falls
  // elastically, and the step's energy error at a closing or a release is the event work.
  // Resolve the event by halving the step while it is above its tolerance. With massive contact
  // nodes part of the closing loss is the semi-discrete impact's own, which no step size
  // removes, so the control is for massless nodes only.
  // Without energy (bodies at rest) there is no scale to resolve the events to.
  if (!contact_dynamics->contact_nodes_massless() || !controller->can_cut() ||
      parameters.guards.contact_event_tolerance >= 1. || energy == 0.)
    return "";
  const double work =
      contact->event_work(before.step.displacement, stepper->state().displacement, before.contact);
  if (!(work > parameters.guards.contact_event_tolerance * std::abs(energy)))
    return "";
  return "contact event work " + format_number(work / std::abs(energy)) +
         " of the energy, above Guards/contact event tolerance = " +
         format_number(parameters.guards.contact_event_tolerance) +
         " (a pair closed or opened within the step)";
}

template <int dim>
void Simulation<dim>::cut_after_failure(std::string failure)
{
  while (!failure.empty() && (failure.back() == '.' || failure.back() == ' '))
    failure.pop_back();
  const double failed_size = controller->step_size();
  if (!controller->cut())
  {
    write_reference_and_summary("the solve failed");
    throw SolverFailure(
        "step " + std::to_string(controller->nominal_step()) + " (t = " + format_number(time) +
        "): " + failure + ", still at the smallest step " + format_number(failed_size) +
        " (dt / 2^" + std::to_string(parameters.time.max_step_cuts) +
        ", Time integration/maximum step cuts). Results up to t = " +
        format_number(controller->start_time()) + " are in " + parameters.output.directory + ".");
  }
  ++counters.total_cuts;
  if (counters.cut_places.size() < 10)
    counters.cut_places.push_back(format_number(controller->start_time()));
  log << "  step " << controller->nominal_step() << " (t = " << time << "): " << failure
      << "; cutting the step to " << controller->step_size() << "\n";
}

template <int dim>
void Simulation<dim>::checkpoint_or_stop(const bool nominal_time_reached,
                                         const unsigned int nominal_step)
{
  // Every rank stops at the same step, whichever received the signal.
  const int signal            = Utilities::MPI::max(interrupt_signal(), MPI_COMM_WORLD);
  const bool stop             = signal != 0 && !controller->finished();
  const unsigned int interval = parameters.output.checkpoint_interval;
  if (stop || (interval > 0 && nominal_time_reached && nominal_step % interval == 0))
    write_checkpoint();
  if (stop)
  {
    write_reference_and_summary("interrupted by signal " + std::to_string(signal));
    throw RunInterrupted("signal " + std::to_string(signal) + " at t = " + format_number(time) +
                             ": checkpoint written to " + parameters.output.directory +
                             "/checkpoint.bin",
                         signal,
                         parameters.output.directory);
  }
}

template <int dim>
void Simulation<dim>::report_progress(const unsigned int nominal_step,
                                      const bool active_set_changed)
{
  const auto now              = std::chrono::steady_clock::now();
  const double since_progress = std::chrono::duration<double>(now - progress.last_report).count();
  if (!show_progress ||
      !(active_set_changed || since_progress >= progress_interval || controller->finished()))
    return;
  progress.last_report       = now;
  const double elapsed       = std::chrono::duration<double>(now - progress.wall_start).count();
  const double done          = time / (n_steps * parameters.time.time_step);
  const double done_this_run = std::max(done - progress.start_fraction, 1e-9);
  log << "  step " << std::setw(6) << nominal_step << "/" << n_steps << "  t = " << std::setw(10)
      << time << "  " << std::fixed << std::setprecision(1) << std::setw(5) << 100. * done << "%  "
      << std::setw(7) << progress.steps_this_run / std::max(elapsed, 1e-9) << " steps/s  ETA "
      << std::setw(6) << elapsed * (1. - done) / done_this_run << " s  " << std::setprecision(2)
      << static_cast<double>(counters.total_solves) / counters.steps_taken << " solves/step"
      << std::defaultfloat << std::setprecision(6) << "  active pairs " << contact->n_active()
      << "  energy " << step_history.value(step_history.n_rows() - 1, "algorithmic_energy") << "\n";
}

template <int dim>
void Simulation<dim>::finish()
{
  write_reference_and_summary();
  // A checkpoint of the end time can extend the run; one from before (the resumed one, or a
  // periodic one) could only repeat the finished steps.
  const std::string checkpoint = parameters.output.directory + "/checkpoint.bin";
  if (is_root_rank && std::filesystem::exists(checkpoint))
  {
    if (checkpoint_time == time)
      log << "  kept " << checkpoint << ", the state at the end time: --resume it with a later "
          << "Time integration/end time to extend the run.\n";
    else
    {
      std::filesystem::remove(checkpoint);
      log << "  removed " << checkpoint << " (the state at t = " << format_number(checkpoint_time)
          << "): the run is complete, resuming it would only repeat finished steps.\n";
    }
  }
  for (const auto& warning : guards.warnings())
    log << warning << "\n";
  // Contact candidates that never closed: most often a velocity of the wrong sign or a gap the
  // run is too short to cross (the run is right, but not the problem meant).
  const std::vector<double> active = step_history.column("active_constraints");
  if (contact->n_pairs() > 0 &&
      std::all_of(active.begin(), active.end(), [](double n) { return n == 0.; }))
    log << "WARNING: no contact pair closed during the run (" << contact->n_pairs()
        << " candidates): check the initial velocities' directions, the gap and the end time.\n";
  const double wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - progress.wall_start).count();
  log << "dyncontact: done, " << n_steps << " steps (" << counters.steps_taken << " taken, "
      << counters.total_cuts << " step cuts";
  for (unsigned int c = 0; c < counters.cut_places.size(); ++c)
    log << (c == 0 ? " at t = " : ", ") << counters.cut_places[c];
  if (counters.total_cuts > counters.cut_places.size())
    log << ", ...";
  log << "), " << counters.total_solves << " linear solves (" << n_factorizations()
      << " factorizations, " << solver->n_low_rank_updates() << " low-rank updates), wall time "
      << wall_time << " s (";
  const auto phases = timer.get_summary_data(TimerOutput::total_wall_time);
  for (auto phase = phases.begin(); phase != phases.end(); ++phase)
    log << (phase == phases.begin() ? "" : ", ") << phase->first << " " << phase->second << " s";
  log << "). Results in " << parameters.output.directory << "\n";
  log << "dyncontact: cost per step";
  for (const bool in_contact : {false, true})
    log << (in_contact ? ", " : " ")
        << 1e3 * progress.step_wall[in_contact] / std::max(progress.step_count[in_contact], 1u)
        << " ms " << (in_contact ? "with" : "without") << " active pairs ("
        << progress.step_count[in_contact] << " steps)";
  log << "\n";
}

template <int dim>
void Simulation<dim>::run(const std::string& resume_directory)
{
  start(resume_directory);
  while (!controller->finished())
  {
    const auto step_start           = std::chrono::steady_clock::now();
    const State before              = current_state();
    const unsigned int nominal_step = controller->nominal_step();
    Measures measures;
    unsigned int cuts                = 0;
    const unsigned int linear_solves = solve_step(before, measures, cuts);
    const bool nominal_time_reached  = controller->accept();
    ++counters.steps_taken;
    ++progress.steps_this_run;
    counters.total_solves += linear_solves;
    record_step(measures, nominal_time_reached ? nominal_step : 0, linear_solves, cuts);
    checkpoint_or_stop(nominal_time_reached, nominal_step);
    const auto active_before =
        std::count(before.contact.active.begin(), before.contact.active.end(), true);
    const bool in_contact = active_before > 0 || contact->n_active() > 0;
    progress.step_wall[in_contact] +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count();
    ++progress.step_count[in_contact];
    report_progress(nominal_step, static_cast<long>(contact->n_active()) != active_before);
  }
  finish();
}

template class Simulation<1>;
template class Simulation<2>;
} // namespace dyncontact
