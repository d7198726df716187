#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/solver/dynamic_residual.h>
#include <dyncontact/solver/newton_parameters.h>
#include <dyncontact/solver/saddle_point_system.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{
/**
 * Solves one implicit time step with contact: find the increment over the Newmark predictor and
 * the multipliers such that
 *   c M (u - u~) + Q(u) - W - G^T lambda = 0,  and the constraint rows of ContactConstraints,
 * with c = 1/(beta dt^2) and u = u~ + increment, by Newton's method on the symmetric saddle-point
 * system [K_eff, -G^T; -G, -D]. The active set is updated after every linear solve (a semi-smooth
 * Newton); the step has converged when the residual is below the tolerance times the reference
 * force |Q(u)| + |W| + |G^T lambda| (elastic, external and contact forces; not the inertia, whose
 * unresolved high-frequency part can be arbitrarily large), or below that plus a round-off floor
 * of 1e3 eps (max diag(K_eff) |u| + |c M (u - u~)|) once the last update reduced it less than
 * 1000 times (the floor is a bound, often far above the actual round-off; a residual still falling
 * fast is reduced further), the active constraints hold to the gap tolerance, the
 * last update left the active set unchanged (discrete complementarity: active pairs compressive
 * and closed, inactive pairs open), and, if any pair is active, at least one linear solve was
 * made. Fixed DoFs (e.g. u_r = 0 on a symmetry axis) keep a zero increment. The pairs' rays
 * are those the contact layer holds on entry (the last converged configuration's); the solver
 * never moves them. It moves the master points, and over a step's first two updates the
 * node-to-segment normals with them unless the contact-dynamics treatment holds them
 * (ContactConstraints::update_master_points(), set_turning_normals(); node-to-segment pairs
 * only, doc/method.md section 4.1) at every iterate u to the configuration
 * whose forces the step balances, (1 - alpha_f) u + alpha_f u_n (Newmark: u itself), so that
 * the step's contact forces are those of its own configuration; the tangent leaves out the change
 * of the master points' weights with u (a quasi-Newton step there, converging linearly;
 * node-to-node and fixed pairs keep rows linear in u and an exact tangent).
 *
 * Initial guess: the residual is first evaluated at the given guess (the Newmark predictor),
 * without the tangent (using the diagonal of the last tangent for the force scale), so that steps
 * the predictor already solves, such as free flight, cost no linear solve. Otherwise Newton starts
 * from the last converged configuration u_n, not from the predictor: at time steps far beyond the
 * periods of the small elements of a contact zone (omega dt >> 1) the trapezoidal rule keeps their
 * high-frequency response undamped, with accelerations so large that the predictor's term
 * dt^2 (1/2 - beta) a_n throws the contact zone a sizeable fraction of an element away (4 to 8
 * times the step's strain energy on the finest sphere mesh). From there Newton converged to
 * spurious roots of the nonconvex finite-strain energy: the total energy doubled in one step. u_n
 * is a valid configuration, and in that regime a close one.
 * A backtracking line search halves an update (up to 10 times) when the residual at its end cannot
 * be evaluated (an inverted element) or grows while the active set stays the same, the residual
 * measured as the force residual together with the active gaps times the largest tangent diagonal.
 *
 * Vectors passed in and out hold each rank's owned DoFs (DistributedVector, the layout of
 * dof_layout()), and so do the increments, the Newton update and the residual's force vectors
 * inside; the contact layer reads an iterate's displacement on the contact border, gathered once
 * per update (the parallel layout of the matrix and the direct solver are SaddlePointSystem's).
 * solve() is collective.
 *
 * The class is the Newton driver of three units: a SaddlePointSystem (the matrix, its fixed
 * sparsity pattern and the direct solve), a DynamicResidual (the residual, the tangent and the
 * figures of the convergence test) and, here, the iteration itself: initial-guess evaluation, the
 * restart from u_n, the line search, the active-set updates, the convergence test and the error
 * messages. It keeps the name ContactNewtonSolver (rather than a name of the method alone) because
 * it is what Simulation builds and calls, with the constructor and solve() unchanged, and the
 * checkpoint's tangent scale is documented as its own. It does not know Newmark's update formulas.
 */
template <int dim>
class ContactNewtonSolver
{
public:
  /** What one step's solve did, for histories and logs. */
  struct Report
  {
    unsigned int linear_solves;
  };

  /**
   * The DoFs `constraints` holds at zero keep a zero increment. `length_scale` (e.g. the smallest
   * element size) turns the relative tolerance, plus the round-off floor 1e3 eps, into the gap
   * tolerance used for activation and constraint convergence (without the floor a tolerance of
   * 1e-16 asked for gaps below the round-off of the positions: measured 8.9e-16 left vs 3.2e-17
   * asked). `timer` receives the phases "assembly", "factorization", "low-rank update" (of the
   * factors, SaddlePointSystem::update_factorization()) and "linear solve" (with the factors).
   * `alpha_f` in [0, 1): the integrator's weight of u_n in the configuration its balance holds at,
   * GeneralizedAlpha::alpha_f() (0: Newmark); the master points are taken there.
   */
  ContactNewtonSolver(const DoFHandler<dim>& dof_handler,
                      const ElasticBodies<dim>& bodies,
                      ContactConstraints<dim>& contact,
                      const Vector<double>& lumped_mass,
                      const AffineConstraints<double>& constraints,
                      const NewtonParameters& parameters,
                      double length_scale,
                      TimerOutput& timer,
                      double alpha_f = 0.);

  /**
   * Solves the step, with external forces W at t_{n+1}, for the increment u_{n+1} - u~ over the
   * predictor u~ (initial guess: the value `increment` holds on entry, usually zero); on exit
   * u_{n+1} = predictor + increment. The contact multipliers and active set are updated in place.
   * Unless the initial guess is already the answer, Newton iterates from the last converged
   * configuration instead: `restart_displacement`, u_n with the prescribed DoFs at their value at
   * t_{n+1} (the increment restart_displacement - u~; see the class documentation), while the
   * master points of a dissipative member's balance are placed from `last_displacement` u_n. The
   * vectors hold the owned DoFs (the layout of dof_layout()).
   * Throws SolverFailure if Newton does not converge within the iteration limit or the linear
   * solver fails.
   */
  Report solve(const DistributedVector& predictor,
               double inertia_factor,
               const DistributedVector& external_force,
               const DistributedVector& last_displacement,
               const DistributedVector& restart_displacement,
               DistributedVector& increment);

  /** The layout of the displacement DoFs' vectors: each rank its owned DoFs. */
  const std::shared_ptr<const Utilities::MPI::Partitioner>& dof_layout() const
  {
    return owned_dofs;
  }

  /**
   * Q(u) at the displacement of the last residual evaluation (the converged one after solve):
   * ElasticBodies' layout (the owned DoFs, then ghosts), read by local_element(j) for the j-th
   * owned DoF or copied by copy_locally_owned_data_from().
   */
  const DistributedVector& internal_force() const { return residual.internal_force(); }

  /**
   * The force rows of the last evaluated residual (the converged one after solve):
   * c M (u - u~) + Q(u) - W - G^T lambda (zero at fixed DoFs), in the layout of internal_force().
   */
  const DistributedVector& last_residual() const { return residual.force_rows(); }

  /**
   * The scales of the last tangent (0: none yet), which scale the round-off floor and the merit
   * and decide whether a step's first evaluation needs a tangent; a checkpoint keeps them so that
   * a resumed run repeats the uninterrupted one exactly.
   */
  const TangentScales& tangent_scales() const { return residual.tangent_scales(); }
  void set_tangent_scales(const TangentScales& scales) { residual.set_tangent_scales(scales); }

  /** The numeric factorizations so far (a matrix that did not change is not refactorized). */
  unsigned int n_factorizations() const { return system.n_factorizations(); }

  /** The direct solver's figures of its last factorization (DirectSolver), or empty. */
  std::string last_factorization_statistics() const
  {
    return system.last_factorization_statistics();
  }

  /** The number of low-rank updates of a factorization so far (SaddlePointSystem). */
  unsigned int n_low_rank_updates() const { return system.n_low_rank_updates(); }

  /** Wall time [s] of the direct solver's symbolic analysis (at construction). */
  double analysis_time() const { return system.analysis_time(); }

  /** Strain energy at the same displacement as internal_force(). */
  double strain_energy() const { return residual.strain_energy(); }

private:
  /** One step's Newton iterate and the line search's memory (defined in the source file). */
  struct Iteration;
  /** An evaluation of the residual: its figures, or the message of the failure that stopped it. */
  struct Evaluation;

  /**
   * Sets the displacement to predictor + increment and updates the master points
   * (move_master_points()) and the active set there.
   */
  void enter(Iteration& iteration);

  /**
   * The iterate's displacement, the predictor plus the increment, and its entries on the contact
   * border (collective).
   */
  void set_displacement(Iteration& iteration) const;

  /** Moves the pairs' master points to the iterate's (1 - alpha_f) u + alpha_f u_n. */
  void move_master_points(const Iteration& iteration);

  /** Newton starts again from the last converged configuration u_n. */
  void restart(Iteration& iteration);

  /** The residual (with the tangent if `with_tangent`) at the iterate; catches SolverFailure. */
  Evaluation evaluate(const Iteration& iteration, bool with_tangent);

  /** The convergence test of the class documentation. */
  bool has_converged(const Iteration& iteration,
                     const typename DynamicResidual<dim>::Figures& figures) const;

  /**
   * Modified Newton (Newton/method): whether the tangent assembled earlier in this step, at the
   * same active set, is still in the matrix and may serve the next update.
   */
  bool may_reuse_tangent(const Iteration& iteration) const;

  /** Whether the last update reduced the force residual less than slow_contraction times. */
  bool converging_slowly(const Iteration& iteration,
                         const typename DynamicResidual<dim>::Figures& figures) const;

  /** Whether the last update is to be halved: its end failed or its merit grew. */
  bool must_backtrack(const Iteration& iteration, const Evaluation& evaluation) const;

  /**
   * Throws SolverFailure with the messages of the class: an evaluation that failed or a residual
   * that is not finite (after the line search or at u_n), or the iteration limit reached.
   */
  void throw_if_stuck(const Iteration& iteration, const Evaluation& evaluation) const;

  /** Solves for the Newton update at the iterate and takes all of it. */
  void take_newton_update(Iteration& iteration, const typename DynamicResidual<dim>::Figures& f);

  /**
   * Moves to the state before the update plus step_length times the update (increment and
   * multipliers) and updates the active set there with the force tolerance of `reference_force`.
   */
  void move_along_update(Iteration& iteration, double reference_force);

  ContactConstraints<dim>& contact;
  const NewtonParameters parameters;
  const double gap_tolerance;
  TimerOutput& timer;
  const double alpha_f;
  /** The layout of the iterate's increments: this rank's owned DoFs. */
  const std::shared_ptr<const Utilities::MPI::Partitioner> owned_dofs;
  SaddlePointSystem<dim> system;
  DynamicResidual<dim> residual;
};
} // namespace dyncontact
