#include <dyncontact/solver/contact_newton_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

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
      communicator(dof_handler.get_triangulation().get_communicator()), timer(timer),
      owns_multiplier_rows(Utilities::MPI::this_mpi_process(communicator) ==
                           Utilities::MPI::n_mpi_processes(communicator) - 1),
      is_fixed(dof_handler.n_dofs(), false)
{
  const types::global_dof_index n_dofs  = dof_handler.n_dofs();
  const types::global_dof_index n_total = n_dofs + contact.n_pairs();
  locally_owned_rows.set_size(n_total);
  locally_owned_rows.add_indices(dof_handler.locally_owned_dofs());
  if (owns_multiplier_rows)
    locally_owned_rows.add_range(n_dofs, n_total);
  locally_owned_rows.compress();
  for (const auto dof : fixed_dofs)
  {
    is_fixed[dof] = true;
    if (locally_owned_rows.is_element(dof))
      locally_owned_fixed_rows.push_back(dof);
  }

  // Rows this rank writes: those of its cells and, on the last rank, the constraint rows with the
  // DoFs they couple to. Each such row gets its full pattern from every cell touching it (all
  // cells are known on every rank of the shared triangulation).
  std::vector<types::global_dof_index> local_dofs(dof_handler.get_fe().n_dofs_per_cell());
  IndexSet written_rows(n_total);
  written_rows.add_indices(locally_owned_rows);
  for (const auto& cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
    {
      cell->get_dof_indices(local_dofs);
      written_rows.add_indices(local_dofs.begin(), local_dofs.end());
    }
  DynamicSparsityPattern contact_couplings(n_total);
  contact.add_to_sparsity(contact_couplings, n_dofs);
  if (owns_multiplier_rows)
    for (types::global_dof_index row = n_dofs; row < n_total; ++row)
      for (auto entry = contact_couplings.begin(row); entry != contact_couplings.end(row); ++entry)
        written_rows.add_index(entry->column());
  written_rows.compress();

  DynamicSparsityPattern sparsity(n_total, n_total, written_rows);
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    cell->get_dof_indices(local_dofs);
    for (const auto row : local_dofs)
      if (written_rows.is_element(row))
        for (const auto column : local_dofs)
          sparsity.add(row, column);
  }
  for (const auto row : written_rows)
    for (auto entry = contact_couplings.begin(row); entry != contact_couplings.end(row); ++entry)
      sparsity.add(row, entry->column());
  matrix.reinit(locally_owned_rows, locally_owned_rows, sparsity, communicator);
}

template <int dim>
Vector<double>
ContactNewtonSolver<dim>::solve_linear_system(const Vector<double>& right_hand_side) const
{
  TrilinosWrappers::MPI::Vector distributed_rhs(locally_owned_rows, communicator);
  TrilinosWrappers::MPI::Vector distributed_solution(locally_owned_rows, communicator);
  for (const auto row : locally_owned_rows)
    distributed_rhs[row] = right_hand_side[row];
  distributed_rhs.compress(VectorOperation::insert);
  try
  {
    SolverControl solver_control;
    // KLU on any number of ranks (Amesos gathers the matrix to one process): MUMPS on 2 ranks gave
    // histories that differ in the last digits from run to run of the same input on a loaded
    // machine (3 of 3 concurrent coarse sphere runs), which breaks bitwise restart and regression
    // checks; KLU's are identical.
    TrilinosWrappers::SolverDirect::AdditionalData data(false, "Amesos_Klu");
    TrilinosWrappers::SolverDirect direct_solver(solver_control, data);
    direct_solver.solve(matrix, distributed_solution, distributed_rhs);
  }
  catch (const std::exception& error)
  {
    throw SolverFailure(std::string("the direct solver (Amesos) failed: ") + error.what());
  }
  // Every rank needs the whole solution: import all entries.
  TrilinosWrappers::MPI::Vector whole(
      locally_owned_rows, complete_index_set(right_hand_side.size()), communicator);
  whole = distributed_solution;
  Vector<double> solution(right_hand_side.size());
  for (types::global_dof_index i = 0; i < solution.size(); ++i)
    solution[i] = whole[i];
  return solution;
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
        matrix = 0.;
      bodies.assemble_internal_force(displacement,
                                     internal_force_values,
                                     with_tangent ? &matrix : nullptr,
                                     &strain_energy_value);
    }
    catch (const SolverFailure& failure)
    {
      evaluation_failure = failure.what();
      if (with_tangent)
        matrix.compress(VectorOperation::add); // flush entries added before the failure
    }
    if (evaluation_failure.empty())
    {
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
      {
        inertia[i] = inertia_factor * lumped_mass[i] * increment[i];
        if (with_tangent && dof_handler.locally_owned_dofs().is_element(i))
          matrix.add(i, i, inertia_factor * lumped_mass[i]);
      }
      contact_force = 0.;
      contact.add_contact_forces(contact_force);
      contact.assemble_constraint_rows(displacement,
                                       inactive_diagonal,
                                       with_tangent && owns_multiplier_rows ? &matrix : nullptr,
                                       constraint_residual);
      if (with_tangent)
      {
        matrix.compress(VectorOperation::add);
        matrix.clear_rows(locally_owned_fixed_rows, inactive_diagonal);
        double largest_diagonal = 0.;
        for (const auto row : dof_handler.locally_owned_dofs())
          largest_diagonal = std::max(largest_diagonal, std::abs(matrix.diag_element(row)));
        largest_tangent_diagonal = Utilities::MPI::max(largest_diagonal, communicator);
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
      newton_update = solve_linear_system(residual);
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
