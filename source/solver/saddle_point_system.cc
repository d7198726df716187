#include <dyncontact/solver/saddle_point_system.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_CrsMatrix.h>
#include <cmath>

namespace dyncontact
{
namespace
{
/**
 * The pattern of the rows this rank writes: those of its cells and, if it owns the multiplier
 * rows, the constraint rows with the DoFs they couple to. Each such row gets its full pattern
 * from every cell touching it (all cells are known on every rank of the shared triangulation).
 */
template <int dim>
DynamicSparsityPattern written_rows_pattern(const DoFHandler<dim>& dof_handler,
                                            const ContactConstraints<dim>& contact,
                                            const IndexSet& locally_owned_rows,
                                            const bool owns_multiplier_rows)
{
  const types::global_dof_index n_dofs  = dof_handler.n_dofs();
  const types::global_dof_index n_total = n_dofs + contact.n_pairs();
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
  return sparsity;
}
} // namespace

template <int dim>
SaddlePointSystem<dim>::SaddlePointSystem(const DoFHandler<dim>& dof_handler,
                                          const ContactConstraints<dim>& contact,
                                          const std::vector<types::global_dof_index>& fixed_dofs,
                                          const DirectSolverPackage package)
    : communicator(dof_handler.get_triangulation().get_communicator()),
      multiplier_rows_owner(Utilities::MPI::this_mpi_process(communicator) ==
                            Utilities::MPI::n_mpi_processes(communicator) - 1),
      locally_owned_dofs(dof_handler.locally_owned_dofs()), direct_solver(package, communicator)
{
  const types::global_dof_index n_dofs  = dof_handler.n_dofs();
  const types::global_dof_index n_total = n_dofs + contact.n_pairs();
  locally_owned_rows.set_size(n_total);
  locally_owned_rows.add_indices(locally_owned_dofs);
  if (multiplier_rows_owner)
    locally_owned_rows.add_range(n_dofs, n_total);
  locally_owned_rows.compress();
  for (const auto dof : fixed_dofs)
    if (locally_owned_rows.is_element(dof))
      locally_owned_fixed_rows.push_back(dof);
  system_matrix.reinit(
      locally_owned_rows,
      locally_owned_rows,
      written_rows_pattern(dof_handler, contact, locally_owned_rows, multiplier_rows_owner),
      communicator);
}

template <int dim>
void SaddlePointSystem<dim>::start_assembly()
{
  system_matrix = 0.;
}

template <int dim>
void SaddlePointSystem<dim>::finish_assembly(const double fixed_row_diagonal)
{
  system_matrix.compress(VectorOperation::add);
  system_matrix.clear_rows(locally_owned_fixed_rows, fixed_row_diagonal);
}

template <int dim>
void SaddlePointSystem<dim>::abandon_assembly()
{
  system_matrix.compress(VectorOperation::add);
}

template <int dim>
double SaddlePointSystem<dim>::largest_displacement_diagonal() const
{
  double largest_diagonal = 0.;
  for (const auto row : locally_owned_dofs)
    largest_diagonal = std::max(largest_diagonal, std::abs(system_matrix.diag_element(row)));
  return Utilities::MPI::max(largest_diagonal, communicator);
}

template <int dim>
bool SaddlePointSystem<dim>::factorize_if_changed()
{
  const Epetra_CrsMatrix& matrix = system_matrix.trilinos_matrix();
  bool changed                   = factorized_values.empty();
  std::size_t k                  = 0;
  for (int row = 0; row < matrix.NumMyRows() && !changed; ++row)
  {
    int n_entries;
    double* values;
    matrix.ExtractMyRowView(row, n_entries, values);
    // Bit for bit: != is false only for equal numbers (a NaN always counts as a change).
    for (int i = 0; i < n_entries && !changed; ++i, ++k)
      changed = values[i] != factorized_values[k];
  }
  if (Utilities::MPI::max(static_cast<int>(changed), communicator) == 0)
    return false;
  factorized_values.clear();
  for (int row = 0; row < matrix.NumMyRows(); ++row)
  {
    int n_entries;
    double* values;
    matrix.ExtractMyRowView(row, n_entries, values);
    factorized_values.insert(factorized_values.end(), values, values + n_entries);
  }
  try
  {
    direct_solver.factorize(system_matrix);
  }
  catch (const SolverFailure&)
  {
    factorized_values.clear(); // no valid factorization
    throw;
  }
  return true;
}

template <int dim>
Vector<double> SaddlePointSystem<dim>::solve(const Vector<double>& right_hand_side)
{
  TrilinosWrappers::MPI::Vector distributed_rhs(locally_owned_rows, communicator);
  TrilinosWrappers::MPI::Vector distributed_solution(locally_owned_rows, communicator);
  for (const auto row : locally_owned_rows)
    distributed_rhs[row] = right_hand_side[row];
  distributed_rhs.compress(VectorOperation::insert);
  direct_solver.solve(distributed_rhs, distributed_solution);
  // Every rank needs the whole solution: import all entries.
  TrilinosWrappers::MPI::Vector whole(
      locally_owned_rows, complete_index_set(right_hand_side.size()), communicator);
  whole = distributed_solution;
  Vector<double> solution(right_hand_side.size());
  for (types::global_dof_index i = 0; i < solution.size(); ++i)
    solution[i] = whole[i];
  return solution;
}

template class SaddlePointSystem<1>;
template class SaddlePointSystem<2>;
} // namespace dyncontact
