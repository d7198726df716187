#include <dyncontact/solver/contact_newton_solver.h>

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace dyncontact
{
template <int dim>
ContactNewtonSolver<dim>::ContactNewtonSolver(
    const DoFHandler<dim>& dof_handler,
    const ElasticBodies<dim>& bodies,
    ContactConstraints<dim>& contact,
    const Vector<double>& lumped_mass,
    const std::vector<types::global_dof_index>& fixed_dofs,
    const NewtonParameters& parameters,
    const double length_scale,
    TimerOutput& timer)
    : dof_handler(dof_handler), bodies(bodies), contact(contact), lumped_mass(lumped_mass),
      parameters(parameters), gap_tolerance(parameters.residual_tolerance * length_scale),
      timer(timer), is_fixed(dof_handler.n_dofs(), false), system(dof_handler, contact, fixed_dofs)
{
  for (const auto dof : fixed_dofs)
    is_fixed[dof] = true;
}

template <int dim>
typename ContactNewtonSolver<dim>::Report
ContactNewtonSolver<dim>::solve(const Vector<double>& predictor,
                                const double inertia_factor,
                                const Vector<double>& external_force,
                                const Vector<double>& restart_increment,
                                Vector<double>& increment)
{
  const types::global_dof_index n_dofs = dof_handler.n_dofs();
  const unsigned int n_pairs           = contact.n_pairs();
  const double inactive_diagonal       = inertia_factor * lumped_mass.mean_value();
  Vector<double> displacement(n_dofs), inertia(n_dofs), contact_force(n_dofs),
      residual(n_dofs + n_pairs), constraint_residual(n_pairs), multiplier_increment(n_pairs);
  displacement = predictor;
  displacement += increment;

  // A pair enters when the unconstrained predicted gap is negative.
  bool active_set_changed = contact.update_active_set(displacement, gap_tolerance, 0.);

  // Backtracking line search: the state before the last Newton update, the update itself and the
  // fraction of it taken. An update is halved (up to max_backtracks times) when the residual at
  // its end could not be evaluated (an inverted element) or grew with the active set unchanged.
  struct StateBeforeUpdate
  {
    Vector<double> increment;
    typename ContactConstraints<dim>::State contact;
    double merit; ///< the line search's measure of the residual, see `merit` below
  };
  std::optional<StateBeforeUpdate> before_update;
  // Round-off of a force evaluated from displacements of size |u|, relative: a thousand units of
  // double precision, far below any tolerance a user may set (>= 1e-16 relative to the forces).
  constexpr double roundoff_factor = 1e3 * std::numeric_limits<double>::epsilon();
  Vector<double> newton_update;
  double step_length                    = 1.;
  constexpr unsigned int max_backtracks = 10;
  const auto take_step                  = [&](const double length)
  {
    increment = before_update->increment;
    for (types::global_dof_index i = 0; i < n_dofs; ++i)
      increment[i] += length * newton_update[i];
    displacement = predictor;
    displacement += increment;

    contact.restore(before_update->contact);
    for (unsigned int k = 0; k < n_pairs; ++k)
      multiplier_increment[k] = length * newton_update[n_dofs + k];
    contact.add_multiplier_increment(multiplier_increment);
  };

  bool restarted = false;
  // The first evaluation of a step (the initial guess, which often is the answer, e.g. in free
  // flight) skips the tangent if an earlier step has supplied the tangent's diagonal for the force
  // scale.
  bool with_tangent = largest_tangent_diagonal == 0.;
  for (unsigned int linear_solves = 0;;)
  {
    std::string evaluation_failure;
    double residual_norm = 0., force_scale = 0., constraint_violation = 0., merit = 0.;
    double round_off_floor = 0.;
    TimerOutput::Scope assembly_scope(timer, "assembly");
    try
    {
      if (with_tangent)
        system.start_assembly();
      bodies.assemble_internal_force(displacement,
                                     internal_force_values,
                                     with_tangent ? &system.matrix() : nullptr,
                                     &strain_energy_value);
    }
    catch (const SolverFailure& failure)
    {
      evaluation_failure = failure.what();
      if (with_tangent)
        system.abandon_assembly(); // flush entries added before the failure
    }
    if (evaluation_failure.empty())
    {
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
      {
        inertia[i] = inertia_factor * lumped_mass[i] * increment[i];
        if (with_tangent && system.owns_row(i))
          system.matrix().add(i, i, inertia_factor * lumped_mass[i]);
      }
      contact_force = 0.;
      contact.add_contact_forces(contact_force);
      contact.assemble_constraint_rows(
          displacement,
          inactive_diagonal,
          with_tangent && system.owns_multiplier_rows() ? &system.matrix() : nullptr,
          constraint_residual);
      if (with_tangent)
      {
        system.finish_assembly(inactive_diagonal);
        largest_tangent_diagonal = system.largest_displacement_diagonal();
      }

      double force_residual_squared = 0.;
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
      {
        residual[i] = is_fixed[i] ? 0.
                                  : inertia[i] + internal_force_values[i] - external_force[i] -
                                        contact_force[i];
        force_residual_squared += residual[i] * residual[i];
      }
      for (unsigned int k = 0; k < n_pairs; ++k)
        residual[n_dofs + k] = constraint_residual[k];
      // The reference force: the elastic, external and contact forces, not the inertia. At time
      // steps far beyond the periods of the small elements of a contact zone their inertia
      // c M (u - u~) is huge and unresolved; measured against it, a residual as large as the
      // contact force itself passed a loose tolerance. Below the reference, a round-off floor:
      // the terms that cancel in K u and c M u (a rigid translation has Q = 0 up to round-off
      // of the size eps max diag(K_eff) |u|), which no tolerance can go under.
      force_scale =
          internal_force_values.l2_norm() + external_force.l2_norm() + contact_force.l2_norm();
      round_off_floor =
          roundoff_factor * (largest_tangent_diagonal * displacement.l2_norm() + inertia.l2_norm());
      residual_norm = std::sqrt(force_residual_squared);
      for (unsigned int k = 0; k < n_pairs; ++k)
        if (contact.is_active(k))
          constraint_violation = std::max(constraint_violation, std::abs(constraint_residual[k]));
      // The line search's merit: the force residual and the active constraints' violations
      // turned into forces by the stiffness scale; without the latter a step that closes a gap
      // but raises a small nonlinear force residual would be rejected forever.
      double constraint_force_squared = 0.;
      for (unsigned int k = 0; k < n_pairs; ++k)
        constraint_force_squared += std::pow(
            (contact.is_active(k) ? largest_tangent_diagonal : 1.) * constraint_residual[k], 2);
      merit = std::sqrt(force_residual_squared + constraint_force_squared);

      // With active pairs at least one linear solve: the predictor never satisfies the
      // constraints of a pair by itself, and its residual can look small only because the
      // multipliers of the last step still balance it.
      if (!active_set_changed &&
          residual_norm <= parameters.residual_tolerance * force_scale + round_off_floor &&
          constraint_violation <= gap_tolerance && (linear_solves > 0 || contact.n_active() == 0))
        return {linear_solves};
    }
    with_tangent = true;

    const bool step_failed = !evaluation_failure.empty() || !std::isfinite(residual_norm) ||
                             (before_update && !active_set_changed && merit > before_update->merit);
    // The initial guess is not the answer (or cannot be evaluated): Newton starts from the last
    // converged configuration instead. See the class documentation for why not from the guess.
    if (!before_update && !restarted)
    {
      restarted    = true;
      increment    = restart_increment;
      displacement = predictor;
      displacement += increment;

      active_set_changed = contact.update_active_set(displacement, gap_tolerance, 0.);
      continue;
    }
    if (step_failed && before_update && step_length > std::pow(0.5, max_backtracks))
    {
      step_length /= 2.;
      take_step(step_length);
      active_set_changed = contact.update_active_set(
          displacement, gap_tolerance, parameters.residual_tolerance * force_scale);
      continue;
    }
    // Here Newton has restarted (or taken an update): a failure without an update is one at u_n.
    if (!evaluation_failure.empty() || !std::isfinite(residual_norm))
      throw SolverFailure((evaluation_failure.empty() ? std::string("the residual is not finite")
                                                      : evaluation_failure) +
                          (before_update ? " (the line search halved the last Newton update " +
                                               std::to_string(max_backtracks) + " times)"
                                         : " (at the last converged configuration)"));
    if (linear_solves == parameters.max_iterations)
    {
      std::ostringstream message;
      message << "Newton did not converge in " << parameters.max_iterations
              << " linear solves (Newton/maximum iterations): residual " << residual_norm
              << " vs tolerance " << parameters.residual_tolerance * force_scale + round_off_floor
              << ", constraint violation " << constraint_violation << " vs gap tolerance "
              << gap_tolerance << ", active pairs " << contact.n_active()
              << (active_set_changed ? ", active set still changing" : "") << ".";
      throw SolverFailure(message.str());
    }

    assembly_scope.stop();
    residual *= -1.;
    {
      TimerOutput::Scope solve_scope(timer, "linear solve");
      newton_update = system.solve(residual);
    }
    ++linear_solves;
    before_update = StateBeforeUpdate{increment, contact.state(), merit};
    step_length   = 1.;
    take_step(step_length);
    active_set_changed = contact.update_active_set(
        displacement, gap_tolerance, parameters.residual_tolerance * force_scale);
  }
}

template class ContactNewtonSolver<1>;
template class ContactNewtonSolver<2>;
} // namespace dyncontact
