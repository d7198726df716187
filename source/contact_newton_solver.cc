#include <dyncontact/contact_newton_solver.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <cmath>
#include <sstream>

namespace dyncontact
{
template <int dim>
ContactNewtonSolver<dim>::ContactNewtonSolver(const DoFHandler<dim>& dof_handler,
                                              const ElasticBodies<dim>& bodies,
                                              ContactConstraints<dim>& contact,
                                              const Vector<double>& lumped_mass,
                                              const NewtonParameters& parameters,
                                              const double length_scale)
    : dof_handler(dof_handler), bodies(bodies), contact(contact), lumped_mass(lumped_mass),
      parameters(parameters), gap_tolerance(parameters.residual_tolerance * length_scale)
{
  const types::global_dof_index n_dofs = dof_handler.n_dofs();
  DynamicSparsityPattern dynamic_sparsity(n_dofs + contact.n_pairs());
  std::vector<types::global_dof_index> local_dofs(dof_handler.get_fe().n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    cell->get_dof_indices(local_dofs);
    for (const auto row : local_dofs)
      for (const auto column : local_dofs)
        dynamic_sparsity.add(row, column);
  }
  contact.add_to_sparsity(dynamic_sparsity, n_dofs);
  sparsity.copy_from(dynamic_sparsity);
  matrix.reinit(sparsity);
}

template <int dim>
typename ContactNewtonSolver<dim>::Report ContactNewtonSolver<dim>::solve(
    const Vector<double>& predictor, const double inertia_factor, Vector<double>& increment)
{
  const types::global_dof_index n_dofs = dof_handler.n_dofs();
  const unsigned int n_pairs           = contact.n_pairs();
  const double inactive_diagonal       = inertia_factor * lumped_mass.mean_value();
  Vector<double> displacement(n_dofs), inertia(n_dofs), contact_force(n_dofs),
      residual(n_dofs + n_pairs), newton_update(n_dofs + n_pairs), constraint_residual(n_pairs),
      multiplier_increment(n_pairs);
  displacement = predictor;
  displacement += increment;

  // A pair enters when the unconstrained predicted gap is negative.
  bool active_set_changed = contact.update_active_set(displacement, gap_tolerance, 0.);
  for (unsigned int linear_solves = 0;; ++linear_solves)
  {
    matrix = 0.;
    bodies.assemble_internal_force(displacement, internal_force_values, &matrix);
    for (types::global_dof_index i = 0; i < n_dofs; ++i)
    {
      inertia[i] = inertia_factor * lumped_mass[i] * increment[i];
      matrix.add(i, i, inertia_factor * lumped_mass[i]);
    }
    contact_force = 0.;
    contact.add_contact_forces(contact_force);
    contact.assemble_constraint_rows(displacement, inactive_diagonal, matrix, constraint_residual);
    matrix.compress(VectorOperation::add);

    for (types::global_dof_index i = 0; i < n_dofs; ++i)
      residual[i] = inertia[i] + internal_force_values[i] - contact_force[i];
    for (unsigned int k = 0; k < n_pairs; ++k)
      residual[n_dofs + k] = constraint_residual[k];

    double force_residual_squared = 0.;
    for (types::global_dof_index i = 0; i < n_dofs; ++i)
      force_residual_squared += residual[i] * residual[i];
    const double force_scale =
        inertia.l2_norm() + internal_force_values.l2_norm() + contact_force.l2_norm();
    const double residual_norm  = std::sqrt(force_residual_squared);
    double constraint_violation = 0.;
    for (unsigned int k = 0; k < n_pairs; ++k)
      if (contact.is_active(k))
        constraint_violation = std::max(constraint_violation, std::abs(constraint_residual[k]));

    if (!active_set_changed && residual_norm <= parameters.residual_tolerance * force_scale &&
        constraint_violation <= gap_tolerance)
      return {linear_solves, residual_norm};
    if (linear_solves == parameters.max_iterations)
    {
      std::ostringstream message;
      message << "Newton did not converge in " << parameters.max_iterations
              << " linear solves (Newton/maximum iterations): residual " << residual_norm
              << " vs tolerance " << parameters.residual_tolerance * force_scale
              << ", constraint violation " << constraint_violation << ", active pairs "
              << contact.n_active() << (active_set_changed ? ", active set still changing" : "")
              << ".";
      throw SolverFailure(message.str());
    }

    residual *= -1.;
    newton_update = 0.;
    try
    {
      SolverControl solver_control;
      TrilinosWrappers::SolverDirect::AdditionalData data(false, "Amesos_Klu");
      TrilinosWrappers::SolverDirect direct_solver(solver_control, data);
      direct_solver.solve(matrix, newton_update, residual);
    }
    catch (const std::exception& error)
    {
      throw SolverFailure(std::string("the direct solver (Amesos KLU) failed: ") + error.what());
    }
    for (types::global_dof_index i = 0; i < n_dofs; ++i)
      increment[i] += newton_update[i];
    displacement = predictor;
    displacement += increment;
    for (unsigned int k = 0; k < n_pairs; ++k)
      multiplier_increment[k] = newton_update[n_dofs + k];
    contact.add_multiplier_increment(multiplier_increment);
    active_set_changed = contact.update_active_set(
        displacement, gap_tolerance, parameters.residual_tolerance * force_scale);
  }
}

template class ContactNewtonSolver<1>;
} // namespace dyncontact
