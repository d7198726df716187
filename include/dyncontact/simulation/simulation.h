#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact_dynamics/contact_dynamics.h>
#include <dyncontact/models/problem_model.h>
#include <dyncontact/postprocess/body_impulses.h>
#include <dyncontact/postprocess/history.h>
#include <dyncontact/postprocess/step_measures.h>
#include <dyncontact/postprocess/step_recorder.h>
#include <dyncontact/simulation/contact_problem.h>
#include <dyncontact/simulation/problem_fingerprint.h>
#include <dyncontact/simulation/run_parameters.h>
#include <dyncontact/simulation/run_progress.h>
#include <dyncontact/simulation/step_acceptance.h>
#include <dyncontact/solver/contact_newton_solver.h>
#include <dyncontact/time_integration/generalized_alpha.h>
#include <dyncontact/time_integration/implicit_stepper.h>
#include <dyncontact/time_integration/step_controller.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>

namespace dyncontact
{
/**
 * One run of an elastodynamic contact problem, the same code for every dimension. prepare()
 * assembles the ProblemModel (ContactProblem: discretization, contact, treatment, solver, stepper),
 * then run() advances the ImplicitStepper step by step; the StepRecorder writes the history
 * (history.csv), the reference solution, profiles and VTU fields into Output/directory. Like the
 * tutorial programs it has setup / do_time_step / output phases; the physics lives in the classes
 * it composes.
 *
 * Every solved step passes StepAcceptance (the StepGuards: energy, tensile force, momentum; the
 * contact-event control) before it is accepted; a step that fails (Newton, an inverted element, a
 * guard) is taken back and cut in half by the StepController, down to the minimum of Time
 * integration/maximum step cuts. history.csv has one row per accepted (sub-)step, with its size
 * and the number of cuts before it. A checkpoint holds the state of every owner (serialize_state).
 */
template <int dim>
class Simulation
{
public:
  /**
   * `log` receives the progress report (std::cout for the executable), from rank 0 only. All
   * ranks of MPI_COMM_WORLD take part; files are written by rank 0 (VTU: one piece per rank).
   */
  Simulation(const RunParameters& parameters,
             std::unique_ptr<ProblemModel<dim>> model,
             std::ostream& log);

  /**
   * Runs from t = 0 (or, with a `resume_directory`, from the checkpoint.bin written there) to the
   * end time. Output/directory must exist. Throws SolverFailure if a step cannot be solved,
   * InputError if the checkpoint is missing or belongs to another problem, and RunInterrupted
   * after writing a checkpoint when SIGINT or SIGTERM arrived; everything recorded up to that
   * step is already on disk.
   */
  void run(const std::string& resume_directory = "");

  /**
   * Everything run() does before its first step, writing no file: builds the mesh, DoFs, bodies,
   * contact candidates and monitor nodes, sizes an automatic penalty, checks the time step against
   * the stability limit and sets the initial conditions. Throws the InputError a run would throw;
   * `--validate` calls it, and the program before it clears an earlier run's results. run() calls
   * it first unless it was called already (it does its work once).
   */
  void prepare();

  /**
   * Checks, after prepare(), that `directory`/checkpoint.bin exists and belongs to this problem
   * and rank count, reading nothing else and writing nothing; throws the InputError
   * run(directory) would (the program calls it before it touches the directory's files).
   */
  void check_checkpoint(const std::string& directory);

  /** Whether run() prints the progress line (default true; `--quiet` switches it off). */
  void set_progress(const bool show) { progress.set_shown(show); }

  /**
   * "complete" if the summaries (impact_summary.csv, exact_summary.csv) cover the whole run and
   * its whole contact, else "incomplete: <why>" (stopped early, or still in contact at the end
   * time); empty before they are written.
   */
  const std::string& summary_status() const;

  /** Wall time [s] of each timed phase so far (assembly, factorization, output, ...). */
  std::map<std::string, double> wall_times() const
  {
    return timer.get_summary_data(TimerOutput::total_wall_time);
  }

  /** The recorded history, one row per accepted (sub-)step including t = 0. */
  const History& history() const { return recorder->history(); }

  /**
   * The rows of history() on the nominal time grid (t = n dt, uniform: what the impact measures
   * and the Hertz comparison take); the sub-steps of cut steps are left out.
   */
  History nominal_history() const { return recorder->nominal_history(); }

  /** The numeric factorizations of the Newton matrix so far (Newton/method, Newton/direct solver).
   */
  unsigned int n_factorizations() const { return problem->solver->n_factorizations(); }

  /** Lumped nodal masses per DoF. */
  const Vector<double>& lumped_mass() const { return problem->mass; }

  /** All nodes (body, reference position, DoFs); valid after run(). */
  const std::vector<Node<dim>>& all_nodes() const { return problem->discretization.nodes->nodes(); }

  /** State at the last completed step, whole (collective); valid after run(). */
  Vector<double> current_displacement() const
  {
    return gather_whole(problem->stepper->state().displacement);
  }
  Vector<double> current_velocity() const
  {
    return gather_whole(problem->stepper->state().velocity);
  }

  /** The node whose motion is recorded as u_tip_<b>, v_tip_<b>, a_tip_<b>, per body. */
  const std::vector<Node<dim>>& monitor_nodes() const { return recorder->monitor_nodes(); }

private:
  /** The state a failed step returns to. */
  struct State
  {
    StepState step;
    typename ContactConstraints<dim>::State contact;
    TangentScales tangent_scales; ///< the solver's, see ContactNewtonSolver::tangent_scales()
    typename BodyImpulses<dim>::Ledger impulses;
  };
  State current_state() const;
  void restore(const State& state);

  /** The step recorder and its field output. */
  void build_recorder();
  /**
   * The step from `before` to `time` at the integrator's step size (the stepper's solve, the
   * momentum balance, its finish), then the impulses; throws SolverFailure.
   */
  unsigned int do_time_step(const State& before);
  /** Records the current state as a row after `linear_solves` solves and `cuts` cuts. */
  void record(const Measures& measures,
              unsigned int nominal_step,
              unsigned int linear_solves,
              unsigned int cuts);
  /** StepRecorder::write_summaries(): `stop` says why the run ends early (empty: it did not). */
  void write_summaries(const std::string& stop = "");

  /** What must match between a checkpoint and the run that resumes it. */
  ProblemFingerprint problem_fingerprint() const;
  /**
   * Writes or reads everything a resumed run needs to repeat the uninterrupted one exactly, the
   * step's state as `step` (whole: gathered before writing, assigned after reading).
   */
  template <class Archive>
  void serialize_state(Archive& archive, StepState::Whole& step);
  /** Writes Output/directory/checkpoint.bin atomically (rank 0; collective). */
  void write_checkpoint();

  /** prepare(), the step controller, the initial record or the checkpoint, the history file. */
  void start(const std::string& resume_directory);
  /**
   * Solves the step from `before` at the controller's size, cutting and retrying until Newton
   * converges and the step is accepted (StepAcceptance); sets `measures` and the number of
   * `cuts`, returns the linear solves of all attempts. Throws SolverFailure when the smallest
   * step still fails.
   */
  unsigned int solve_step(const State& before, Measures& measures, unsigned int& cuts);
  /** Halves the step after `failure`, logs it; throws SolverFailure at the smallest step. */
  void cut_after_failure(std::string failure);
  /** Writes a checkpoint when due; on a signal also the results, then throws RunInterrupted. */
  void checkpoint_or_stop(bool nominal_time_reached, unsigned int nominal_step);
  /** The summaries, the checkpoint kept or removed, the warnings and the final lines. */
  void finish();

  const RunParameters parameters;
  const std::unique_ptr<ProblemModel<dim>> model;
  const bool is_root_rank;
  ConditionalOStream log;
  GeneralizedAlpha integrator;
  const unsigned int n_steps;
  /** Whether prepare() has done its work. */
  bool prepared = false;
  std::unique_ptr<ContactProblem<dim>> problem; ///< built by prepare()
  double time = 0.;
  std::unique_ptr<StepAcceptance<dim>> acceptance;
  std::unique_ptr<StepRecorder<dim>> recorder;
  TimerOutput timer;
  std::unique_ptr<StepController> controller;
  RunProgress progress;
  /** Time of the state in checkpoint.bin, written or resumed by this run (NaN: none). */
  double checkpoint_time = std::numeric_limits<double>::quiet_NaN();
};
} // namespace dyncontact
