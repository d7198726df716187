#include <dyncontact/base/dimensions.h>
#include <dyncontact/solver/contact_newton_solver.h>

#include <cmath>
#include <optional>
#include <sstream>

namespace dyncontact
{
namespace
{
/// How often the line search halves one Newton update at the most.
constexpr unsigned int max_backtracks = 10;
/// Modified Newton: an update with a reused tangent that reduced the residual by less than this
/// factor is followed by a fresh tangent.
constexpr double slow_contraction = 0.1;

/// The Newton updates of a step after which node-to-segment normals are held
/// (move_master_points()).
constexpr unsigned int normal_updates = 2;
} // namespace

template <int dim>
struct ContactNewtonSolver<dim>::Iteration
{
  /** The state before the last Newton update, to which the line search returns. */
  struct StateBeforeUpdate
  {
    DistributedVector increment;
    typename ContactConstraints<dim>::State contact;
    double merit; ///< the line search's measure of the residual, see DynamicResidual::Figures
    double force_residual; ///< |r| before the update, to tell convergence from round-off
    bool after_change;     ///< the active set (friction branches included) changed at that state
  };

  const typename DynamicResidual<dim>::Step step;
  DistributedVector increment;              ///< u - u~, this rank's owned DoFs
  DistributedVector restart_increment = {}; ///< u_n - u~, where Newton restarts (owned DoFs)
  Vector<double> last_configuration   = {}; ///< u_n on the contact border, for alpha_f > 0 only
  DistributedVector displacement      = {}; ///< u~ + increment, owned DoFs
  Vector<double> border_displacement  = {}; ///< u~ + increment on the contact border
  bool active_set_changed             = false;
  bool restarted                      = false;
  unsigned int linear_solves          = 0;
  /** Backtracking line search: the state before the last update, the update and its fraction. */
  std::optional<StateBeforeUpdate> before_update = {};
  /** Modified Newton: the active set at which this step's tangent was assembled (empty: none). */
  std::optional<std::vector<signed char>> tangent_active_set = {};
  DistributedVector newton_update  = {}; ///< of the displacement, owned DoFs
  Vector<double> multiplier_update = {};
  double step_length               = 1.;
};

template <int dim>
struct ContactNewtonSolver<dim>::Evaluation
{
  std::string failure; ///< empty unless the residual could not be evaluated
  typename DynamicResidual<dim>::Figures figures{};
};

template <int dim>
ContactNewtonSolver<dim>::ContactNewtonSolver(const DoFHandler<dim>& dof_handler,
                                              const ElasticBodies<dim>& bodies,
                                              ContactConstraints<dim>& contact,
                                              const Vector<double>& lumped_mass,
                                              const AffineConstraints<double>& constraints,
                                              const NewtonParameters& parameters,
                                              const double length_scale,
                                              TimerOutput& timer,
                                              const double alpha_f)
    : contact(contact), parameters(parameters),
      gap_tolerance((parameters.residual_tolerance + DynamicResidual<dim>::roundoff_factor) *
                    length_scale),
      timer(timer), alpha_f(alpha_f),
      owned_dofs(std::make_shared<Utilities::MPI::Partitioner>(
          dof_handler.locally_owned_dofs(), dof_handler.get_triangulation().get_communicator())),
      system(dof_handler, contact, constraints, parameters.direct_solver),
      residual(bodies, contact, lumped_mass, constraints)
{
  residual.keep_constant_tangent(system);
}

template <int dim>
typename ContactNewtonSolver<dim>::Report
ContactNewtonSolver<dim>::solve(const DistributedVector& predictor,
                                const double inertia_factor,
                                const DistributedVector& external_force,
                                const DistributedVector& last_displacement,
                                const DistributedVector& restart_displacement,
                                DistributedVector& increment)
{
  Iteration iteration{{predictor, inertia_factor, external_force}, increment};
  iteration.restart_increment = restart_displacement;
  iteration.restart_increment -= predictor;
  if (alpha_f != 0.) // u_n, rounded as u~ + (u_n - u~), the restart configuration without Dirichlet
  {
    DistributedVector configuration = last_displacement;
    configuration -= predictor;
    configuration += predictor;
    iteration.last_configuration = contact.border().gather(configuration);
  }
  // A pair enters when the unconstrained predicted gap is negative.
  enter(iteration);
  // The first evaluation of a step (the initial guess, which often is the answer, e.g. in free
  // flight) skips the tangent if an earlier step has supplied the tangent's diagonal for the force
  // scale.
  bool with_tangent = residual.tangent_scales().largest_diagonal == 0.;
  for (;;)
  {
    // An initial guess with active pairs is never the answer (has_converged() asks for a linear
    // solve then): restart at once, without the evaluation (a residual pass per contact step).
    if (!iteration.before_update && !iteration.restarted && contact.n_active() > 0)
    {
      with_tangent = true;
      restart(iteration);
      continue;
    }
    TimerOutput::Scope assembly_scope(timer, "assembly");
    const bool reuse_tangent = with_tangent && may_reuse_tangent(iteration);
    Evaluation evaluation    = evaluate(iteration, with_tangent && !reuse_tangent);
    if (evaluation.failure.empty() && has_converged(iteration, evaluation.figures))
    {
      increment = iteration.increment;
      return {iteration.linear_solves};
    }
    with_tangent = true;

    // The initial guess is not the answer (or cannot be evaluated): Newton starts from the last
    // converged configuration instead. See the class documentation for why not from the guess.
    if (!iteration.before_update && !iteration.restarted)
    {
      restart(iteration);
      continue;
    }
    if (must_backtrack(iteration, evaluation))
    {
      iteration.step_length /= 2.;
      move_along_update(iteration, evaluation.figures.reference_force);
      continue;
    }
    throw_if_stuck(iteration, evaluation);
    // Modified Newton: the tangent of this step's first update serves the later ones until the
    // active set changes or an update reduces the residual less than slow_contraction times.
    if (!reuse_tangent || converging_slowly(iteration, evaluation.figures))
    {
      if (reuse_tangent)
      {
        evaluation = evaluate(iteration, true); // a fresh tangent at the same iterate
        throw_if_stuck(iteration, evaluation);
      }
      iteration.tangent_active_set = contact.active_set();
    }

    assembly_scope.stop();
    take_newton_update(iteration, evaluation.figures);
  }
}

template <int dim>
void ContactNewtonSolver<dim>::restart(Iteration& iteration)
{
  iteration.restarted = true;
  iteration.increment = iteration.restart_increment;
  enter(iteration);
}

template <int dim>
bool ContactNewtonSolver<dim>::may_reuse_tangent(const Iteration& iteration) const
{
  return parameters.method == NewtonMethod::modified && iteration.tangent_active_set &&
         *iteration.tangent_active_set == contact.active_set();
}

template <int dim>
bool ContactNewtonSolver<dim>::converging_slowly(
    const Iteration& iteration, const typename DynamicResidual<dim>::Figures& figures) const
{
  return iteration.before_update &&
         figures.force_residual > slow_contraction * iteration.before_update->force_residual;
}

template <int dim>
void ContactNewtonSolver<dim>::enter(Iteration& iteration)
{
  set_displacement(iteration);
  move_master_points(iteration);
  iteration.active_set_changed =
      contact.update_active_set(iteration.border_displacement, gap_tolerance, 0.);
}

template <int dim>
void ContactNewtonSolver<dim>::set_displacement(Iteration& iteration) const
{
  iteration.displacement = iteration.increment;
  iteration.displacement += iteration.step.predictor; // u~ + increment: addition commutes
  iteration.border_displacement = contact.border().gather(iteration.displacement);
}

template <int dim>
void ContactNewtonSolver<dim>::move_master_points(const Iteration& iteration)
{
  // The tangent leaves out the normals' change with u: each update that moves them contracts the
  // residual only ~0.04 times (measured, coarse oblique spheres: a contact step took 7 updates
  // instead of 4). Moving them for the first normal_updates updates and holding them after
  // leaves them 0.04^2 of a step's turn behind the configuration (the energy and momenta of the
  // oblique impact as with normals moved at every iterate, to 2e-6; Newton updates 281 instead of
  // 357 there). CalculiX likewise re-pairs only in a contact step's first 8 iterations.
  const bool move_normals = iteration.linear_solves <= normal_updates;
  if (alpha_f == 0.)
  {
    contact.update_master_points(iteration.border_displacement, move_normals);
    return;
  }
  Vector<double> configuration = iteration.border_displacement;
  configuration.sadd(1. - alpha_f, alpha_f, iteration.last_configuration);
  contact.update_master_points(configuration, move_normals);
}

template <int dim>
typename ContactNewtonSolver<dim>::Evaluation
ContactNewtonSolver<dim>::evaluate(const Iteration& iteration, const bool with_tangent)
{
  Evaluation evaluation;
  try
  {
    evaluation.figures = residual.evaluate(iteration.step,
                                           iteration.increment,
                                           iteration.displacement,
                                           iteration.border_displacement,
                                           with_tangent ? &system : nullptr);
  }
  catch (const SolverFailure& failure)
  {
    evaluation.failure = failure.what(); // the line search or throw_if_stuck() decides
  }
  return evaluation;
}

template <int dim>
bool ContactNewtonSolver<dim>::has_converged(
    const Iteration& iteration, const typename DynamicResidual<dim>::Figures& figures) const
{
  // With active pairs at least one linear solve: the predictor never satisfies the
  // constraints of a pair by itself, and its residual can look small only because the
  // multipliers of the last step still balance it.
  // In the round-off band only once Newton stops converging (class documentation): accepting a
  // residual still falling fast left the recovered contact forces of non-matching spheres
  // unbalanced by 2e-9 of the peak force, where one more update reaches 1e-11. Falling fast means
  // 1000 times per update for full Newton, and 1 / slow_contraction times for modified Newton
  // (linear convergence: stopping it early in the band left first-contact forces 1e-7 off).
  const double fast_contraction =
      parameters.method == NewtonMethod::modified ? slow_contraction : 1e-3;
  const double tolerance = parameters.residual_tolerance * figures.reference_force;
  // A slow contraction is round-off's only on an update from an iterate whose normals were held:
  // while the updates move node-to-segment normals (move_master_points()), and on the first one
  // after, it is theirs. Accepting a residual in the band there (1e-4, the floor, on the
  // non-matching spheres with full Newton) left 1.2e-10 of the peak force unbalanced (5e-11 now).
  const bool converging =
      iteration.before_update &&
      ((contact.moves_normals() && iteration.linear_solves <= normal_updates + 1) ||
       figures.force_residual < fast_contraction * iteration.before_update->force_residual);
  const bool residual_small =
      figures.force_residual <= tolerance ||
      (figures.force_residual <= tolerance + figures.round_off_floor && !converging);
  // A residual that is not finite never passes (its tolerance may be infinite too).
  return !iteration.active_set_changed && std::isfinite(figures.force_residual) && residual_small &&
         figures.constraint_violation <= gap_tolerance &&
         (iteration.linear_solves > 0 || contact.n_active() == 0);
}

template <int dim>
bool ContactNewtonSolver<dim>::must_backtrack(const Iteration& iteration,
                                              const Evaluation& evaluation) const
{
  // An update is halved (up to max_backtracks times) when the residual at its end could not be
  // evaluated (an inverted element) or grew with the active set unchanged. With friction, not for
  // growth over the first update in a new branch: the semismooth Newton's residual is not monotone
  // after a stick-slip switch (on the oblique spheres the first full update in the new branch
  // raised it, and halving it 10 times stalled Newton with the gap at 1.6e-7; taken whole, the
  // next update converged).
  const auto& before             = iteration.before_update;
  const bool first_in_new_branch = before && before->after_change && contact.has_friction();
  const bool step_failed         = !evaluation.failure.empty() ||
                           !std::isfinite(evaluation.figures.force_residual) ||
                           (before && !iteration.active_set_changed && !first_in_new_branch &&
                            evaluation.figures.merit > before->merit);
  return step_failed && before && iteration.step_length > std::pow(0.5, max_backtracks);
}

template <int dim>
void ContactNewtonSolver<dim>::throw_if_stuck(const Iteration& iteration,
                                              const Evaluation& evaluation) const
{
  const auto& figures = evaluation.figures;
  // Here Newton has restarted (or taken an update): a failure without an update is one at u_n.
  if (!evaluation.failure.empty() || !std::isfinite(figures.force_residual))
    throw SolverFailure((evaluation.failure.empty() ? std::string("the residual is not finite")
                                                    : evaluation.failure) +
                        (iteration.before_update
                             ? " (the line search halved the last Newton update " +
                                   std::to_string(max_backtracks) + " times)"
                             : " (at the last converged configuration)"));
  if (iteration.linear_solves == parameters.max_iterations)
  {
    std::ostringstream message;
    message << "Newton did not converge in " << parameters.max_iterations
            << " linear solves (Newton/maximum iterations): residual " << figures.force_residual
            << " vs tolerance "
            << parameters.residual_tolerance * figures.reference_force + figures.round_off_floor
            << ", constraint violation " << figures.constraint_violation << " vs gap tolerance "
            << gap_tolerance << ", active pairs " << contact.n_active()
            << (iteration.active_set_changed ? ", active set still changing" : "") << ".";
    throw SolverFailure(message.str());
  }
}

template <int dim>
void ContactNewtonSolver<dim>::take_newton_update(
    Iteration& iteration, const typename DynamicResidual<dim>::Figures& figures)
{
  DistributedVector right_hand_side =
      system.stack(residual.force_rows(), residual.constraint_rows());
  if (iteration.newton_update.size() == 0)
    iteration.newton_update.reinit(owned_dofs);
  right_hand_side *= -1.;
  // Modified Newton reuses what it can: low-rank updates of the factors for pairs entering or
  // leaving; full Newton keeps fresh factorizations of every changed tangent (the reference).
  system.update_factorization(parameters.method == NewtonMethod::modified, &timer);
  {
    TimerOutput::Scope solve_scope(timer, "linear solve");
    system.split(
        system.solve(right_hand_side), iteration.newton_update, iteration.multiplier_update);
  }
  ++iteration.linear_solves;
  iteration.before_update = typename Iteration::StateBeforeUpdate{iteration.increment,
                                                                  contact.state(),
                                                                  figures.merit,
                                                                  figures.force_residual,
                                                                  iteration.active_set_changed};
  iteration.step_length   = 1.;
  move_along_update(iteration, figures.reference_force);
}

template <int dim>
void ContactNewtonSolver<dim>::move_along_update(Iteration& iteration, const double reference_force)
{
  const double length = iteration.step_length;
  iteration.increment = iteration.before_update->increment;
  for (unsigned int i = 0; i < iteration.increment.locally_owned_size(); ++i)
    iteration.increment.local_element(i) += length * iteration.newton_update.local_element(i);
  set_displacement(iteration);

  contact.restore(iteration.before_update->contact);
  Vector<double> multiplier_increment = iteration.multiplier_update;
  multiplier_increment *= length;
  contact.add_multiplier_increment(multiplier_increment);
  move_master_points(iteration);
  iteration.active_set_changed =
      contact.update_active_set(iteration.border_displacement,
                                gap_tolerance,
                                parameters.residual_tolerance * reference_force);
}

DYNCONTACT_INSTANTIATE_CLASS(ContactNewtonSolver)
} // namespace dyncontact
