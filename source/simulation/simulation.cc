#include <dyncontact/contact/contact_factory.h>
#include <dyncontact/contact/penalty_sizing.h>
#include <dyncontact/simulation/checkpoint_file.h>
#include <dyncontact/simulation/interruption.h>
#include <dyncontact/simulation/simulation.h>
#include <dyncontact/time_integration/mode_resolution.h>
#include <dyncontact/time_integration/stability_check.h>

#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <cmath>
#include <filesystem>

namespace dyncontact
{
template <int dim>
Simulation<dim>::Simulation(const RunParameters& parameters,
                            std::unique_ptr<ProblemModel<dim>> model,
                            std::ostream& log)
    : parameters(parameters), model(std::move(model)),
      is_root_rank(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0), log(log, is_root_rank),
      integrator(parameters.time), n_steps(parameters.time.n_steps()),
      timer(this->log, TimerOutput::never, TimerOutput::wall_times),
      progress(this->log, n_steps, parameters.time.time_step)
{
}

template <int dim>
void Simulation<dim>::prepare()
{
  if (prepared)
    return;
  discretization                            = std::make_unique<BodyDiscretization<dim>>(*model);
  mass                                      = discretization->bodies->lumped_mass();
  const ContactDescription<dim> description = model->contact_description(*discretization->nodes);
  build_contact_and_solver(description);
  std::set<types::boundary_id> slave_surfaces;
  for (const auto& pair : description.surface_pairs)
    slave_surfaces.insert(pair.surface_a);
  for (const auto& pair : description.plane_pairs)
    slave_surfaces.insert(pair.surface);
  build_recorder(slave_surfaces);
  log_summary();
  check_time_step();
  set_initial_conditions();
  prepared = true;
}

template <int dim>
void Simulation<dim>::build_contact_and_solver(const ContactDescription<dim>& description)
{
  const BodyDiscretization<dim>& d = *discretization;
  const PenaltySizingInput sizing{
      mass, integrator.time_step(), d.highest_frequency * integrator.time_step()};
  Contact<dim> built = create_contact(
      description, d.dof_handler, *d.kinematics, *d.nodes, parameters.contact, sizing);
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
    mass = d.bodies->lumped_mass(contact->contact_dofs(d.dof_handler.n_dofs()));
  solver =
      std::make_unique<ContactNewtonSolver<dim>>(d.dof_handler,
                                                 *d.bodies,
                                                 *contact,
                                                 mass,
                                                 d.fixed_dofs,
                                                 parameters.newton,
                                                 GridTools::minimal_cell_diameter(d.triangulation),
                                                 timer,
                                                 integrator.alpha_f());
  stepper = std::make_unique<ImplicitStepper<dim>>(
      integrator, mass, d.is_fixed_dof, *d.loads, *contact, *contact_dynamics, *solver);
  body_impulses = std::make_unique<BodyImpulses<dim>>(integrator, mass, d.is_fixed_dof, *contact);
  body_impulses->index(d.nodes->nodes(), model->impact_direction(), model->n_bodies());
  step_measures = std::make_unique<StepMeasures<dim>>(integrator,
                                                      mass,
                                                      *d.bodies,
                                                      *solver,
                                                      *contact,
                                                      *contact_dynamics,
                                                      *stepper,
                                                      *body_impulses,
                                                      model->impact_direction());
  acceptance    = std::make_unique<StepAcceptance<dim>>(
      parameters.guards, integrator, *contact, *contact_dynamics, *body_impulses);
}

template <int dim>
void Simulation<dim>::build_recorder(const std::set<types::boundary_id>& slave_surfaces)
{
  const BodyDiscretization<dim>& d = *discretization;
  std::vector<std::shared_ptr<const Material>> materials;
  for (const BodyMaterial& body : model->body_materials())
    materials.push_back(body.material);
  recorder = std::make_unique<StepRecorder<dim>>(
      *model,
      *d.nodes,
      *contact,
      surface_contact != nullptr,
      std::make_unique<FieldOutput<dim>>(d.dof_handler,
                                         d.mapping,
                                         *d.kinematics,
                                         materials,
                                         slave_surfaces,
                                         parameters.output.directory),
      parameters.output,
      parameters.time.time_step,
      n_steps,
      timer,
      log);
}

template <int dim>
void Simulation<dim>::log_summary() const
{
  const double dt                = parameters.time.time_step;
  const double highest_frequency = discretization->highest_frequency;
  log << "dyncontact: " << discretization->dof_handler.n_dofs() << " displacement DoFs, "
      << contact->n_pairs() << " contact candidate(s), " << n_steps << " steps of dt = " << dt
      << ", " << integrator.description() << ", contact dynamics "
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
  const double body_omega_dt   = discretization->highest_frequency * integrator.time_step();
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
  Vector<double> velocity(discretization->dof_handler.n_dofs());
  for (const auto& node : discretization->nodes->nodes())
  {
    const Tensor<1, dim> v0 = model->initial_velocity(node.body, node.position);
    for (unsigned int d = 0; d < dim; ++d)
      velocity[node.dofs[d]] = v0[d];
  }
  stepper->start(velocity, *discretization->bodies);
  contact->update_geometry(stepper->state().displacement);
  body_impulses->start(stepper->state());
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
void Simulation<dim>::record(const Measures& measures,
                             const unsigned int nominal_step,
                             const unsigned int linear_solves,
                             const unsigned int cuts)
{
  const double size = recorder->history().n_rows() == 0 ? 0. : integrator.time_step();
  recorder->record({time, size, nominal_step, linear_solves, cuts},
                   measures,
                   stepper->state(),
                   body_impulses->ledger().impulses);
}

template <int dim>
void Simulation<dim>::write_summaries(const std::string& stop)
{
  recorder->write_summaries(stop,
                            n_steps * parameters.time.time_step,
                            body_impulses->ledger().contact_impulses,
                            log.get_stream());
}

template <int dim>
const std::string& Simulation<dim>::summary_status() const
{
  static const std::string none;
  return recorder ? recorder->status() : none;
}

template <int dim>
ProblemFingerprint Simulation<dim>::problem_fingerprint() const
{
  ProblemFingerprint fingerprint;
  fingerprint.n_ranks        = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  fingerprint.entries        = parameters.problem_entries;
  fingerprint.discretization = "dimension " + std::to_string(dim) + ", " +
                               std::to_string(discretization->dof_handler.n_dofs()) + " DoFs, " +
                               std::to_string(contact->n_pairs()) + " contact candidates, " +
                               std::to_string(model->n_bodies()) + " bodies, node positions " +
                               discretization->node_checksum();
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
  archive&* acceptance;
  archive&* controller;
  archive&* recorder;
  archive& progress;
  archive& tangent_scale;
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
void Simulation<dim>::check_checkpoint(const std::string& directory)
{
  checkpoint_file::read(directory, problem_fingerprint(), [](boost::archive::binary_iarchive&) {});
}

template <int dim>
void Simulation<dim>::start(const std::string& resume_directory)
{
  prepare();
  controller = std::make_unique<StepController>(
      parameters.time.time_step, n_steps, parameters.time.max_step_cuts);
  const Measures initial = step_measures->measure(false);
  acceptance->initialize(initial);
  if (resume_directory.empty())
    record(initial, 0, 0, 0);
  else
  {
    checkpoint_file::read(resume_directory,
                          problem_fingerprint(),
                          [this](boost::archive::binary_iarchive& archive)
                          { serialize_state(archive); });
    checkpoint_time = time;
    log << "dyncontact: resumed from " << resume_directory << "/checkpoint.bin at t = " << time
        << "\n";
  }
  recorder->open();
  progress.start(time);
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
      measures = step_measures->measure(true);
      failure  = acceptance->check(time,
                                  measures,
                                  before.step.displacement,
                                  before.contact,
                                  stepper->state().displacement,
                                  controller->can_cut());
      if (failure.empty())
      {
        acceptance->accept();
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
void Simulation<dim>::cut_after_failure(std::string failure)
{
  while (!failure.empty() && (failure.back() == '.' || failure.back() == ' '))
    failure.pop_back();
  const double failed_size = controller->step_size();
  if (!controller->cut())
  {
    write_summaries("the solve failed");
    throw SolverFailure(
        "step " + std::to_string(controller->nominal_step()) + " (t = " + format_number(time) +
        "): " + failure + ", still at the smallest step " + format_number(failed_size) +
        " (dt / 2^" + std::to_string(parameters.time.max_step_cuts) +
        ", Time integration/maximum step cuts). Results up to t = " +
        format_number(controller->start_time()) + " are in " + parameters.output.directory + ".");
  }
  progress.count_cut(controller->start_time());
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
    write_summaries("interrupted by signal " + std::to_string(signal));
    throw RunInterrupted("signal " + std::to_string(signal) + " at t = " + format_number(time) +
                             ": checkpoint written to " + parameters.output.directory +
                             "/checkpoint.bin",
                         signal,
                         parameters.output.directory);
  }
}

template <int dim>
void Simulation<dim>::finish()
{
  write_summaries();
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
  for (const auto& warning : acceptance->warnings())
    log << warning << "\n";
  // Contact candidates that never closed: most often a velocity of the wrong sign or a gap the
  // run is too short to cross (the run is right, but not the problem meant).
  const std::vector<double> active = history().column("active_constraints");
  if (contact->n_pairs() > 0 &&
      std::all_of(active.begin(), active.end(), [](double n) { return n == 0.; }))
    log << "WARNING: no contact pair closed during the run (" << contact->n_pairs()
        << " candidates): check the initial velocities' directions, the gap and the end time.\n";
  progress.report_totals(n_factorizations(),
                         solver->n_low_rank_updates(),
                         timer.get_summary_data(TimerOutput::total_wall_time),
                         parameters.output.directory);
}

template <int dim>
void Simulation<dim>::run(const std::string& resume_directory)
{
  start(resume_directory);
  while (!controller->finished())
  {
    progress.begin_step();
    const State before              = current_state();
    const unsigned int nominal_step = controller->nominal_step();
    Measures measures;
    unsigned int cuts                = 0;
    const unsigned int linear_solves = solve_step(before, measures, cuts);
    const bool nominal_time_reached  = controller->accept();
    progress.count_step(linear_solves);
    record(measures, nominal_time_reached ? nominal_step : 0, linear_solves, cuts);
    checkpoint_or_stop(nominal_time_reached, nominal_step);
    const auto active_before =
        std::count(before.contact.active.begin(), before.contact.active.end(), true);
    progress.end_step(active_before > 0 || contact->n_active() > 0);
    progress.report(nominal_step,
                    time,
                    controller->finished(),
                    static_cast<long>(contact->n_active()) != active_before,
                    contact->n_active(),
                    history().value(history().n_rows() - 1, "algorithmic_energy"));
  }
  finish();
}

template class Simulation<1>;
template class Simulation<2>;
} // namespace dyncontact
