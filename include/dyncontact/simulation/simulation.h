#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/parameters.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact_dynamics/contact_dynamics.h>
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/discretization/surface_tractions.h>
#include <dyncontact/models/problem_model.h>
#include <dyncontact/postprocess/body_impulses.h>
#include <dyncontact/postprocess/field_output.h>
#include <dyncontact/postprocess/history.h>
#include <dyncontact/postprocess/step_measures.h>
#include <dyncontact/simulation/problem_fingerprint.h>
#include <dyncontact/simulation/step_guards.h>
#include <dyncontact/solver/contact_newton_solver.h>
#include <dyncontact/time_integration/generalized_alpha.h>
#include <dyncontact/time_integration/implicit_stepper.h>
#include <dyncontact/time_integration/step_controller.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <chrono>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <set>

namespace dyncontact
{
/**
 * One run of an elastodynamic contact problem, the same code for every dimension: sets up the
 * mesh and DoFs of the ProblemModel, the lumped mass, the contact layer and the Newton solver, then
 * advances Newmark (classical or modified) step by step, recording the history (history.csv), the
 * reference solution, profiles and VTU fields in Output/directory. Like the tutorial programs it
 * has setup / do_time_step / output phases; the physics lives in the classes it composes.
 *
 * Every solved step passes the StepGuards (energy, tensile force, momentum) before it is accepted;
 * a step that fails (Newton, an inverted element, a guard) is taken back and cut in half by the
 * StepController, down to the minimum of Time integration/maximum step cuts. history.csv has one
 * row per accepted (sub-)step, with its size and the number of cuts before it.
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
  void set_progress(const bool show) { show_progress = show; }

  /**
   * "complete" if the summaries (impact_summary.csv, exact_summary.csv) cover the whole run and
   * its whole contact, else "incomplete: <why>" (stopped early, or still in contact at the end
   * time); empty before they are written.
   */
  const std::string& summary_status() const { return summaries; }

  /** Wall time [s] of each timed phase so far (assembly, factorization, output, ...). */
  std::map<std::string, double> wall_times() const
  {
    return timer.get_summary_data(TimerOutput::total_wall_time);
  }

  /** The recorded history, one row per accepted (sub-)step including t = 0. */
  const History& history() const { return step_history; }

  /**
   * The rows of history() on the nominal time grid (t = n dt, uniform: what the impact measures
   * and the Hertz comparison take); the sub-steps of cut steps are left out.
   */
  History nominal_history() const;

  /** The numeric factorizations of the Newton matrix so far (Newton/method, Newton/direct solver).
   */
  unsigned int n_factorizations() const;

  /** Lumped nodal masses per DoF. */
  const Vector<double>& lumped_mass() const { return mass; }

  /** All nodes (body, reference position, DoFs); valid after run(). */
  const std::vector<Node<dim>>& all_nodes() const { return nodes->nodes(); }

  /** State at the last completed step; valid after run(). */
  const Vector<double>& current_displacement() const { return stepper->state().displacement; }
  const Vector<double>& current_velocity() const { return stepper->state().velocity; }

  /** The node whose motion is recorded as u_tip_<b>, v_tip_<b>, a_tip_<b>, per body. */
  const std::vector<Node<dim>>& monitor_nodes() const { return monitors; }

private:
  /** The state a failed step returns to. */
  struct State
  {
    StepState step;
    typename ContactConstraints<dim>::State contact;
    double tangent_scale; ///< the solver's, see ContactNewtonSolver::tangent_scale()
    typename BodyImpulses<dim>::Ledger impulses;
  };
  State current_state() const;
  void restore(const State& state);

  /** The measures of the current state (StepMeasures). */
  Measures measure() const;
  StepGuards::Figures guard_figures(const Measures& measures) const;

  /** Builds the discretization, the contact, the solver and the output schedule; logs a summary. */
  void setup();
  /** Mesh, DoFs, nodes, kinematics, bodies and their lumped mass, fixed DoFs, loads. */
  void build_discretization();
  /** Contact (create_contact, penalties sized), its dynamics treatment and the Newton solver. */
  void build_contact_and_solver();
  /** The monitor nodes, the fixed flags, the bodies' DoF tables (BodyImpulses), the innermost pair.
   */
  void index_dofs();
  /** The steps of the profile times (warning for those after the end); the run's summary line. */
  void schedule_and_log();
  /**
   * Warns when a penalty spring is the one unresolved frequency; throws InputError when the time
   * step exceeds the stability limit of conditionally stable Newmark (2 beta < gamma), for the
   * mesh alone or with the penalty springs.
   */
  void check_time_step() const;
  void set_initial_conditions();
  /**
   * The step from `before` to `time` at the integrator's step size (the stepper's solve, the
   * momentum balance, its finish), then the impulses; throws SolverFailure.
   */
  unsigned int do_time_step(const State& before);
  /**
   * Appends a history row for the current state; `nominal_step` is the nominal step index if the
   * state lies on the nominal time grid (profiles and VTU are written only there), else 0.
   */
  void record_step(const Measures& measures,
                   unsigned int nominal_step,
                   unsigned int linear_solves,
                   unsigned int cuts);
  /**
   * Writes the reference solution at the recorded times and the run's summary, marked with
   * summary_status(): `stop` says why a run ends before its end time (empty when it reached it).
   */
  void write_reference_and_summary(const std::string& stop = "");

  /** What must match between a checkpoint and the run that resumes it. */
  ProblemFingerprint problem_fingerprint() const;
  /** Writes or reads everything a resumed run needs to repeat the uninterrupted one exactly. */
  template <class Archive>
  void serialize_state(Archive& archive);
  /** Writes Output/directory/checkpoint.bin atomically (rank 0). */
  void write_checkpoint();
  /** Reads `directory`/checkpoint.bin; throws InputError if missing or of another problem. */
  void read_checkpoint(const std::string& directory);

  /** prepare(), the output writers, the step controller, the initial record or the checkpoint. */
  void start(const std::string& resume_directory);
  /**
   * Solves the step from `before` at the controller's size, cutting and retrying until Newton
   * converges and the guards pass; sets `measures` and the number of `cuts`, returns the linear
   * solves of all attempts. Throws SolverFailure when the smallest step still fails.
   */
  unsigned int solve_step(const State& before, Measures& measures, unsigned int& cuts);
  /**
   * With massless contact nodes: why the solved step from `before` must be cut to resolve a
   * closing or a release (ContactConstraints::event_work() above Guards/contact event tolerance
   * times |`energy`|), or an empty string (also at the smallest step size).
   */
  std::string contact_event_failure(const State& before, double energy) const;
  /** Halves the step after `failure`, logs it; throws SolverFailure at the smallest step. */
  void cut_after_failure(std::string failure);
  /** Writes a checkpoint when due; on a signal also the results, then throws RunInterrupted. */
  void checkpoint_or_stop(bool nominal_time_reached, unsigned int nominal_step);
  /** The progress line, at most every few seconds and whenever the active set changed. */
  void report_progress(unsigned int nominal_step, bool active_set_changed);
  /** The reference, the summary, the warnings of switched-off guards and the final line. */
  void finish();

  /** Wall-clock bookkeeping of the progress line. */
  struct Progress
  {
    std::chrono::steady_clock::time_point wall_start, last_report;
    unsigned int steps_this_run = 0;
    double start_fraction       = 0.; ///< of the run, done before this one started (resume)
    /** Wall time [s] and number of the steps of this run without ([0]) and with ([1]) active
     *  pairs at their start or end, for the cost per step in the final lines. */
    double step_wall[2]        = {0., 0.};
    unsigned int step_count[2] = {0, 0};
  };

  /** Counters for the progress line and the summary. */
  struct Counters
  {
    unsigned int total_solves = 0, total_cuts = 0, steps_taken = 0;
    std::vector<std::string> cut_places; ///< times of the first cuts
  };
  /** The nodal traction -p n on body A and p n on body B of every pair, p = `pressures`. */
  Vector<double> contact_traction(const std::vector<double>& pressures) const;
  /** Per candidate pair: its slave node, gap, multiplier, `pressures[k]` and active flag. */
  std::vector<typename FieldOutput<dim>::PressureSample>
  pressure_samples(const std::vector<double>& pressures) const;
  std::vector<std::string> history_columns() const;

  const RunParameters parameters;
  const std::unique_ptr<ProblemModel<dim>> model;
  const bool is_root_rank;
  ConditionalOStream log;
  GeneralizedAlpha integrator;
  parallel::shared::Triangulation<dim> triangulation;
  const FESystem<dim> fe;
  /** The curved-cell mapping, its support points computed once from the manifolds. */
  MappingQCache<dim> mapping;
  DoFHandler<dim> dof_handler;
  std::unique_ptr<NodeIndex<dim>> nodes;
  std::unique_ptr<Kinematics<dim>> kinematics;
  std::unique_ptr<ElasticBodies<dim>> bodies;
  Vector<double> mass;
  /** ElasticBodies::highest_frequency_bound() of the bodies with their fixed DoFs [1/time]. */
  double highest_frequency = 0.;
  /** Whether prepare() has done its work. */
  bool prepared = false;
  std::vector<types::global_dof_index> fixed_dofs;
  std::unique_ptr<SurfaceTractions<dim>> loads;
  std::unique_ptr<ContactGeometry<dim>> surface_contact; ///< null: fixed-normal pairs only
  std::unique_ptr<ContactConstraints<dim>> contact;
  std::unique_ptr<ContactDynamics<dim>> contact_dynamics; ///< Contact/dynamics
  std::unique_ptr<ContactNewtonSolver<dim>> solver;
  /** The step and its state (u, v, a, Q, W at the current time). */
  std::unique_ptr<ImplicitStepper<dim>> stepper;
  std::vector<Node<dim>> monitors;
  unsigned int innermost_pair = 0; ///< candidate pair nearest to the axis (centre_pressure)
  std::unique_ptr<FieldOutput<dim>> field_output;
  std::set<unsigned int> profile_steps; ///< steps at which a profile is written
  std::set<unsigned int> vtu_steps;     ///< nominal steps of Output/vtu times
  /// boundary ids of the slave contact surfaces (surface pairs and rigid planes), for the output
  std::set<types::boundary_id> slave_surfaces;
  double penalty_factor =
      0.; ///< the factor in force (Contact/penalty factor, or the automatic one)
  bool penalty_lowered = false; ///< Contact/penalty factor = auto lowered the springs
  unsigned int n_steps;
  double time;
  std::vector<bool> is_fixed_dof; ///< per DoF: held at zero (fixed_dofs)
  /** Per body: the forces that change its momentum, their impulses, the external work. */
  std::unique_ptr<BodyImpulses<dim>> body_impulses;
  std::unique_ptr<StepMeasures<dim>> step_measures;
  StepGuards guards;
  /**
   * The energy the energy guard reads: E_0 plus the algorithmic-energy change of every accepted
   * step, each evaluated with that step's size h (the weight (beta - gamma/2) h^2 of a.Ma depends
   * on h, so E with the new h minus E with the old one would show a gain after every cut when beta
   * != gamma/2), and the energy parts of the last accepted state.
   */
  double guarded_energy = 0.;
  Measures accepted_measures{};
  History step_history;
  /** Rows of step_history on the nominal time grid (the Hertz comparison needs uniform steps). */
  std::vector<unsigned int> nominal_rows;
  TimerOutput timer;
  std::unique_ptr<StepController> controller;
  Counters counters;
  Progress progress;
  bool show_progress = true;
  /** summary_status() */
  std::string summaries;
  /** Time of the state in checkpoint.bin, written or resumed by this run (NaN: none). */
  double checkpoint_time = std::numeric_limits<double>::quiet_NaN();
};
} // namespace dyncontact
