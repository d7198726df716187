#include <dyncontact/base/dimensions.h>
#include <dyncontact/postprocess/pairs_across_ranks.h>
#include <dyncontact/simulation/checkpoint_file.h>
#include <dyncontact/simulation/interruption.h>
#include <dyncontact/simulation/simulation.h>

#include <deal.II/base/utilities.h>

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
  problem    = std::make_unique<ContactProblem<dim>>(*model, parameters, integrator, timer);
  acceptance = std::make_unique<StepAcceptance<dim>>(
      parameters.guards, integrator, *problem->contact, *problem->dynamics, *problem->impulses);
  build_recorder();
  problem->log_summary(log);
  problem->check_time_step(log);
  problem->set_initial_conditions();
  prepared = true;
}

template <int dim>
void Simulation<dim>::build_recorder()
{
  const BodyDiscretization<dim>& d = problem->discretization;
  std::vector<std::shared_ptr<const Material>> materials;
  for (const BodyMaterial& body : model->body_materials())
    materials.push_back(body.material);
  recorder = std::make_unique<StepRecorder<dim>>(
      *model,
      *d.nodes,
      *problem->contact,
      problem->surface_contact != nullptr,
      std::make_unique<FieldOutput<dim>>(d.dof_handler,
                                         d.mapping,
                                         *d.kinematics,
                                         materials,
                                         problem->slave_surfaces,
                                         parameters.output.directory),
      parameters.output,
      parameters.time.time_step,
      n_steps,
      timer,
      log);
}

template <int dim>
typename Simulation<dim>::State Simulation<dim>::current_state() const
{
  return {problem->stepper->state(),
          problem->contact->state(),
          problem->solver->tangent_scales(),
          problem->impulses->ledger()};
}

template <int dim>
void Simulation<dim>::restore(const State& state)
{
  problem->stepper->state() = state.step;
  problem->solver->set_tangent_scales(state.tangent_scales);
  problem->impulses->ledger() = state.impulses;
  problem->contact->restore(state.contact);
}

template <int dim>
unsigned int Simulation<dim>::do_time_step(const State& before)
{
  DistributedVector increment;
  const unsigned int linear_solves = problem->stepper->solve(before.step, time, increment);
  problem->impulses->balance_momenta(
      increment, problem->solver->last_residual(), integrator.inertia_factor());
  problem->stepper->finish(before.step, increment);
  problem->impulses->accumulate(
      before.step, before.impulses, problem->stepper->state(), problem->stepper->step_load());
  return linear_solves;
}

template <int dim>
void Simulation<dim>::record(const Measures& measures,
                             const unsigned int nominal_step,
                             const unsigned int linear_solves,
                             const unsigned int cuts)
{
  const double size = recorder->history().n_rows() == 0 ? 0. : integrator.time_step();
  const BodyImpulses<dim>& impulses = *problem->impulses;
  recorder->record({time, size, nominal_step, linear_solves, cuts},
                   measures,
                   problem->stepper->state(),
                   impulses.along_impact(impulses.ledger().impulses),
                   impulses.ledger().external_work,
                   impulses.ledger().frictional_dissipation);
}

template <int dim>
void Simulation<dim>::write_summaries(const std::string& stop)
{
  recorder->write_summaries(
      stop,
      n_steps * parameters.time.time_step,
      problem->impulses->along_impact(problem->impulses->ledger().contact_impulses),
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
  return {Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
          parameters.problem_entries,
          problem->description()};
}

template <int dim>
template <class Archive>
void Simulation<dim>::serialize_state(Archive& archive, StepState::Whole& step)
{
  typename ContactConstraints<dim>::State contact_state = problem->contact->state();
  TangentScales tangent_scales                          = problem->solver->tangent_scales();
  archive& time;
  archive& step;
  archive& contact_state.active;
  archive& contact_state.multipliers;
  archive& contact_state.slip_states;    // friction's branches (CoulombFriction::states())
  archive& contact_state.friction_bases; // the bases the tangential multipliers are in
  archive & problem->impulses->ledger();
  archive&* acceptance;
  archive&* controller;
  archive&* recorder;
  archive& progress;
  archive& tangent_scales;
  if (Archive::is_loading::value)
  {
    if (problem->impulses->ledger().impulses.size() != problem->impulses->n_tracks())
      throw InputError("--resume: the checkpoint keeps " +
                       std::to_string(problem->impulses->ledger().impulses.size()) +
                       " momentum balances where this version keeps " +
                       std::to_string(problem->impulses->n_tracks()) +
                       " (one per body and direction): it was written by an older dyncontact; "
                       "run the problem again from the start.");
    problem->stepper->state().assign(step);
    problem->contact->restore(contact_state);
    problem->solver->set_tangent_scales(tangent_scales);
  }
}

template <int dim>
void Simulation<dim>::write_checkpoint()
{
  StepState::Whole step = problem->stepper->state().gather_on_root(); // collective
  if (!is_root_rank)
    return;
  TimerOutput::Scope scope(timer, "output");
  checkpoint_file::write(parameters.output.directory,
                         problem_fingerprint(),
                         [this, &step](boost::archive::binary_oarchive& archive)
                         { serialize_state(archive, step); });
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
  const Measures initial = problem->measures->measure(false);
  acceptance->initialize(initial);
  if (resume_directory.empty())
    record(initial, 0, 0, 0);
  else
  {
    StepState::Whole step;
    checkpoint_file::read(resume_directory,
                          problem_fingerprint(),
                          [this, &step](boost::archive::binary_iarchive& archive)
                          { serialize_state(archive, step); });
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
      measures = problem->measures->measure(true);
      failure  = acceptance->check(time,
                                  measures,
                                  before.step.displacement,
                                  before.contact,
                                  problem->stepper->state().displacement,
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
  if (problem->contact->n_pairs() > 0 &&
      std::all_of(active.begin(), active.end(), [](double n) { return n == 0.; }))
    log << "WARNING: no contact pair closed during the run (" << problem->contact->n_pairs()
        << " candidates): check the initial velocities' directions, the gap and the end time.\n";
  Utilities::System::MemoryStats memory;
  Utilities::System::get_memory_stats(memory); // VmHWM: this rank's peak resident memory [kB]
  progress.report_totals(n_factorizations(),
                         problem->solver->n_low_rank_updates(),
                         problem->solver->last_factorization_statistics(),
                         timer.get_summary_data(TimerOutput::total_wall_time),
                         Utilities::MPI::min_max_avg(memory.VmHWM / 1024., MPI_COMM_WORLD),
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
    progress.end_step(active_before > 0 || problem->contact->n_active() > 0);
    progress.count_pairs_across_ranks(
        pairs_across_ranks(*problem->contact,
                           problem->discretization.dof_handler.locally_owned_dofs(),
                           MPI_COMM_WORLD));
    progress.report(nominal_step,
                    time,
                    controller->finished(),
                    static_cast<long>(problem->contact->n_active()) != active_before,
                    problem->contact->n_active(),
                    measures.algorithmic_energy);
  }
  finish();
}

DYNCONTACT_INSTANTIATE_CLASS(Simulation)
} // namespace dyncontact
