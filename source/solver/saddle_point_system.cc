#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/join_over_ranks.h>
#include <dyncontact/solver/saddle_point_system.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cmath>

namespace dyncontact
{
namespace
{
/**
 * The pattern of the rows this rank writes: those of its cells and, if it owns the multiplier
 * rows, the constraint rows with the DoFs they couple to. Each such row gets its full pattern
 * from every cell touching it: this rank's own cells and its ghost cells (one layer around them).
 */
template <int dim>
DynamicSparsityPattern written_rows_pattern(const DoFHandler<dim>& dof_handler,
                                            const ContactConstraints<dim>& contact,
                                            const IndexSet& locally_owned_rows,
                                            const bool owns_multiplier_rows)
{
  const types::global_dof_index n_dofs  = dof_handler.n_dofs();
  const types::global_dof_index n_total = n_dofs + contact.multiplier_block().n_multipliers();
  std::vector<types::global_dof_index> local_dofs(dof_handler.get_fe().n_dofs_per_cell());
  IndexSet written_rows(n_total);
  written_rows.add_indices(locally_owned_rows);
  for (const auto& cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
    {
      cell->get_dof_indices(local_dofs);
      written_rows.add_indices(local_dofs.begin(), local_dofs.end());
    }
  // The multipliers' rows follow the displacement DoFs: row n_dofs + j for multiplier j.
  DynamicSparsityPattern contact_couplings(n_total);
  for (types::global_dof_index row = n_dofs; row < n_total; ++row)
    contact_couplings.add(row, row);
  contact.for_each_coupling(
      [&](const unsigned int multiplier, const types::global_dof_index dof)
      {
        contact_couplings.add(n_dofs + multiplier, dof);
        contact_couplings.add(dof, n_dofs + multiplier);
      });
  // A pair's multipliers couple among themselves (a sliding pair's tangential rows, friction).
  const MultiplierBlock& block = contact.multiplier_block();
  for (unsigned int k = 0; k < block.n_pairs(); ++k)
    for (unsigned int a = 0; a < block.n_components(k); ++a)
      for (unsigned int b = 0; b < block.n_components(k); ++b)
        contact_couplings.add(n_dofs + block.index(k, a), n_dofs + block.index(k, b));
  // Rows by row_length() and column_number(), both O(1): DynamicSparsityPattern::begin(row) of an
  // empty row searches on to the next non-empty one, which made this quadratic in the DoFs.
  if (owns_multiplier_rows)
    for (types::global_dof_index row = n_dofs; row < n_total; ++row)
      for (types::global_dof_index k = 0; k < contact_couplings.row_length(row); ++k)
        written_rows.add_index(contact_couplings.column_number(row, k));
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
    for (types::global_dof_index k = 0; k < contact_couplings.row_length(row); ++k)
      sparsity.add(row, contact_couplings.column_number(row, k));
  return sparsity;
}

/** A changed matrix entry: new - factorized value at (row, column); sent between ranks. */
struct MatrixChange
{
  types::global_dof_index row, column;
  double difference;

  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& row;
    archive& column;
    archive& difference;
  }
};
} // namespace

template <int dim>
SaddlePointSystem<dim>::SaddlePointSystem(const DoFHandler<dim>& dof_handler,
                                          const ContactConstraints<dim>& contact,
                                          const AffineConstraints<double>& constraints,
                                          const DirectSolverPackage package)
    : communicator(dof_handler.get_triangulation().get_communicator()),
      n_dofs(dof_handler.n_dofs()), n_multipliers(contact.multiplier_block().n_multipliers()),
      multiplier_rows_owner(Utilities::MPI::this_mpi_process(communicator) ==
                            Utilities::MPI::n_mpi_processes(communicator) - 1),
      locally_owned_dofs(dof_handler.locally_owned_dofs()), constraints(constraints),
      direct_solver(package, communicator, !contact.has_friction())
{
  const types::global_dof_index n_total = n_dofs + n_multipliers;
  locally_owned_rows.set_size(n_total);
  locally_owned_rows.add_indices(locally_owned_dofs);
  if (multiplier_rows_owner)
    locally_owned_rows.add_range(n_dofs, n_total);
  locally_owned_rows.compress();
  // Checked on all ranks at once, so that no rank goes on alone into the collective set-up.
  AssertThrow(
      Utilities::MPI::min(static_cast<int>(locally_owned_rows.is_contiguous()), communicator) == 1,
      ExcMessage("SaddlePointSystem needs each rank's DoFs to be one range, the last "
                 "rank's the highest (as the DoFHandler numbers them by subdomain)"));
  row_partitioner = std::make_shared<Utilities::MPI::Partitioner>(locally_owned_rows, communicator);
  system_matrix.reinit(
      locally_owned_rows,
      locally_owned_rows,
      written_rows_pattern(dof_handler, contact, locally_owned_rows, multiplier_rows_owner),
      communicator);
  const Epetra_CrsMatrix& matrix = system_matrix.trilinos_matrix();
  diagonal_position.assign(matrix.NumMyRows(), -1);
  for (int row = 0; row < matrix.NumMyRows(); ++row)
  {
    const auto global_row = TrilinosWrappers::global_row_index(matrix, row);
    if (static_cast<types::global_dof_index>(global_row) >= n_dofs)
      continue; // a multiplier row
    int n_entries;
    double* values;
    int* columns;
    matrix.ExtractMyRowView(row, n_entries, values, columns);
    const int* diagonal = std::find(columns, columns + n_entries, matrix.LCID(global_row));
    AssertThrow(diagonal != columns + n_entries,
                ExcMessage("a displacement row without its diagonal"));
    diagonal_position[row] = static_cast<int>(diagonal - columns);
  }
  // The pattern is final: its symbolic analysis belongs to the set-up, not to the first step.
  Timer timer(communicator, true);
  direct_solver.analyse(system_matrix);
  analysis_wall_time = timer.wall_time();
}

template <int dim>
void SaddlePointSystem<dim>::add_coupling(const unsigned int multiplier,
                                          const types::global_dof_index dof,
                                          const double value)
{
  if (constraints.is_constrained(dof))
    return;
  system_matrix.add(n_dofs + multiplier, dof, value);
  system_matrix.add(dof, n_dofs + multiplier, value);
}

template <int dim>
void SaddlePointSystem<dim>::add_row_coupling(const unsigned int multiplier,
                                              const types::global_dof_index dof,
                                              const double value)
{
  if (!constraints.is_constrained(dof))
    system_matrix.add(n_dofs + multiplier, dof, value);
}

template <int dim>
void SaddlePointSystem<dim>::add_column_coupling(const unsigned int multiplier,
                                                 const types::global_dof_index dof,
                                                 const double value)
{
  if (!constraints.is_constrained(dof))
    system_matrix.add(dof, n_dofs + multiplier, value);
}

template <int dim>
void SaddlePointSystem<dim>::add_multiplier_coupling(const unsigned int multiplier,
                                                     const unsigned int other,
                                                     const double value)
{
  system_matrix.add(n_dofs + multiplier, n_dofs + other, value);
}

template <int dim>
void SaddlePointSystem<dim>::add_diagonal(const unsigned int multiplier, const double value)
{
  system_matrix.add(n_dofs + multiplier, n_dofs + multiplier, value);
}

template <int dim>
DistributedVector SaddlePointSystem<dim>::stack(const DistributedVector& displacement_rows,
                                                const Vector<double>& multiplier_rows) const
{
  AssertDimension(displacement_rows.size(), n_dofs);
  AssertDimension(displacement_rows.locally_owned_size(), locally_owned_dofs.n_elements());
  AssertDimension(multiplier_rows.size(), n_multipliers);
  DistributedVector stacked(row_partitioner);
  // The rows are the owned DoFs (in the same order), then on the last rank the multipliers.
  std::copy_n(displacement_rows.begin(), displacement_rows.locally_owned_size(), stacked.begin());
  if (multiplier_rows_owner)
    std::copy(multiplier_rows.begin(),
              multiplier_rows.end(),
              stacked.begin() + displacement_rows.locally_owned_size());
  return stacked;
}

template <int dim>
void SaddlePointSystem<dim>::split(const DistributedVector& stacked,
                                   DistributedVector& displacement_part,
                                   Vector<double>& multiplier_part) const
{
  AssertDimension(stacked.size(), n_dofs + n_multipliers);
  AssertDimension(displacement_part.locally_owned_size(), locally_owned_dofs.n_elements());
  const auto n_owned_dofs = displacement_part.locally_owned_size();
  std::copy_n(stacked.begin(), n_owned_dofs, displacement_part.begin());
  multiplier_part.reinit(n_multipliers);
  if (multiplier_rows_owner)
    std::copy_n(stacked.begin() + n_owned_dofs, n_multipliers, multiplier_part.begin());
  const int last_rank = static_cast<int>(Utilities::MPI::n_mpi_processes(communicator)) - 1;
  const int rc        = MPI_Bcast(multiplier_part.begin(),
                           static_cast<int>(n_multipliers),
                           MPI_DOUBLE,
                           last_rank,
                           communicator);
  AssertThrowMPI(rc);
}

template <int dim>
void SaddlePointSystem<dim>::start_assembly()
{
  if (constant_part.empty())
    system_matrix = 0.;
  else
    set_local_values(constant_part);
}

template <int dim>
void SaddlePointSystem<dim>::finish_assembly()
{
  system_matrix.compress(VectorOperation::add);
}

template <int dim>
TangentScales SaddlePointSystem<dim>::displacement_scales() const
{
  TangentScales scales;
  const Epetra_CrsMatrix& matrix = system_matrix.trilinos_matrix();
  for (int row = 0; row < matrix.NumMyRows(); ++row)
  {
    if (diagonal_position[row] < 0)
      continue; // a multiplier row
    int n_entries;
    double* values;
    matrix.ExtractMyRowView(row, n_entries, values);
    double row_sum = 0.;
    for (int k = 0; k < n_entries; ++k)
      row_sum += std::abs(values[k]);
    scales.largest_row_sum = std::max(scales.largest_row_sum, row_sum);
    scales.largest_diagonal =
        std::max(scales.largest_diagonal, std::abs(values[diagonal_position[row]]));
  }
  scales.largest_diagonal = Utilities::MPI::max(scales.largest_diagonal, communicator);
  scales.largest_row_sum  = Utilities::MPI::max(scales.largest_row_sum, communicator);
  return scales;
}

template <int dim>
std::vector<double> SaddlePointSystem<dim>::local_values() const
{
  const Epetra_CrsMatrix& matrix = system_matrix.trilinos_matrix();
  std::vector<double> values;
  values.reserve(matrix.NumMyNonzeros());
  for (int row = 0; row < matrix.NumMyRows(); ++row)
  {
    int n_entries;
    double* row_values;
    matrix.ExtractMyRowView(row, n_entries, row_values);
    values.insert(values.end(), row_values, row_values + n_entries);
  }
  return values;
}

template <int dim>
void SaddlePointSystem<dim>::add_to_diagonal(const Vector<double>& diagonal, const double factor)
{
  AssertDimension(diagonal.size(), n_dofs);
  // Epetra's row views point into the matrix's own storage (writable, though the view is const).
  const Epetra_CrsMatrix& matrix = system_matrix.trilinos_matrix();
  for (int row = 0; row < matrix.NumMyRows(); ++row)
    if (diagonal_position[row] >= 0)
    {
      int n_entries;
      double* values;
      matrix.ExtractMyRowView(row, n_entries, values);
      values[diagonal_position[row]] +=
          factor * diagonal[TrilinosWrappers::global_row_index(matrix, row)];
    }
}

template <int dim>
void SaddlePointSystem<dim>::set_local_values(const std::vector<double>& values)
{
  const Epetra_CrsMatrix& matrix = system_matrix.trilinos_matrix(); // see add_to_diagonal()
  AssertDimension(values.size(), static_cast<std::size_t>(matrix.NumMyNonzeros()));
  auto value = values.begin();
  for (int row = 0; row < matrix.NumMyRows(); ++row)
  {
    int n_entries;
    double* row_values;
    matrix.ExtractMyRowView(row, n_entries, row_values);
    std::copy_n(value, n_entries, row_values);
    value += n_entries;
  }
}

template <int dim>
typename SaddlePointSystem<dim>::Update
SaddlePointSystem<dim>::update_factorization(const bool allow_low_rank, TimerOutput* timer)
{
  std::vector<double> values = local_values();
  // Bit for bit: == is true only for equal numbers (a NaN always counts as a change).
  const bool changed = factorized_values.empty() || values != served_values;
  if (Utilities::MPI::max(static_cast<int>(changed), communicator) == 0)
    return Update::none;
  served_values                   = std::move(values);
  const bool is_factorized_matrix = served_values == factorized_values;
  if (Utilities::MPI::min(static_cast<int>(is_factorized_matrix), communicator) == 1)
  {
    low_rank.reset(); // back to the factorized matrix (e.g. the active set of the factorization)
    return Update::none;
  }
  std::optional<TimerOutput::Scope> scope;
  if (allow_low_rank && !factorized_values.empty())
  {
    if (timer != nullptr)
      scope.emplace(*timer, "low-rank update");
    low_rank = low_rank_update_of_changes();
    if (low_rank)
    {
      ++low_rank_updates;
      return Update::low_rank;
    }
  }
  if (timer != nullptr)
    scope.emplace(*timer, "factorization");
  low_rank.reset();
  factorized_values.clear();
  try
  {
    direct_solver.factorize(system_matrix);
  }
  catch (const SolverFailure&)
  {
    served_values.clear(); // no valid factorization
    throw;
  }
  factorized_values = served_values;
  return Update::factorization;
}

template <int dim>
std::optional<LowRankUpdate> SaddlePointSystem<dim>::low_rank_update_of_changes()
{
  // The changed entries of this rank's rows; any change in the leading block, or a change that is
  // not a number, calls for a factorization.
  std::vector<MatrixChange> changes;
  bool leading_block_changed     = false;
  const Epetra_CrsMatrix& matrix = system_matrix.trilinos_matrix();
  std::size_t k                  = 0;
  for (int row = 0; row < matrix.NumMyRows() && !leading_block_changed; ++row)
  {
    int n_entries;
    double* row_values;
    int* columns;
    matrix.ExtractMyRowView(row, n_entries, row_values, columns);
    for (int i = 0; i < n_entries; ++i, ++k)
      if (served_values[k] != factorized_values[k])
      {
        const MatrixChange change{
            static_cast<types::global_dof_index>(TrilinosWrappers::global_row_index(matrix, row)),
            static_cast<types::global_dof_index>(
                TrilinosWrappers::global_column_index(matrix, columns[i])),
            served_values[k] - factorized_values[k]};
        leading_block_changed = leading_block_changed || !std::isfinite(change.difference) ||
                                (change.row < n_dofs && change.column < n_dofs);
        changes.push_back(change);
      }
  }
  if (Utilities::MPI::max(static_cast<int>(leading_block_changed), communicator) > 0)
    return {};
  // Every rank builds the whole U and V from all ranks' changes (a few per multiplier).
  const std::vector<MatrixChange> all_changes = join_over_ranks(communicator, changes);
  // The multipliers whose rows and columns hold the changes.
  std::vector<types::global_dof_index> multipliers;
  for (const MatrixChange& change : all_changes)
    multipliers.push_back(change.row >= n_dofs ? change.row : change.column);
  std::sort(multipliers.begin(), multipliers.end());
  multipliers.erase(std::unique(multipliers.begin(), multipliers.end()), multipliers.end());
  if (multipliers.empty() || multipliers.size() > max_low_rank_multipliers)
    return {};

  // dA = sum_j e_j (row j of dA)^T + sum_j (column j of dA outside the rows j) e_j^T over the
  // multipliers j: U = [e_j, column_j], V = [row_j, e_j].
  const unsigned int m = multipliers.size();
  const auto index_of  = [&](const types::global_dof_index row)
  { return std::lower_bound(multipliers.begin(), multipliers.end(), row) - multipliers.begin(); };
  // U's columns hold this rank's rows only.
  std::vector<DistributedVector> columns_u(2 * m, DistributedVector(row_partitioner));
  std::vector<LowRankUpdate::SparseColumn> columns_v(2 * m);
  const auto set_u = [&](const unsigned int column, const types::global_dof_index row, double value)
  {
    if (locally_owned_rows.is_element(row))
      columns_u[column](row) = value;
  };
  for (const MatrixChange& change : all_changes)
    if (change.row >= n_dofs)
      columns_v[index_of(change.row)].emplace_back(change.column, change.difference);
    else
      set_u(m + index_of(change.column), change.row, change.difference);
  for (unsigned int j = 0; j < m; ++j)
  {
    set_u(j, multipliers[j], 1.);
    columns_v[m + j] = {{multipliers[j], 1.}};
  }
  try
  {
    return LowRankUpdate(columns_u,
                         std::move(columns_v),
                         [this](const std::vector<DistributedVector>& b)
                         { return direct_solver.solve(b); });
  }
  catch (const SolverFailure&)
  {
    return {}; // ill-conditioned: factorize instead
  }
}

template <int dim>
DistributedVector SaddlePointSystem<dim>::solve(const DistributedVector& right_hand_side)
{
  DistributedVector solution = direct_solver.solve(right_hand_side);
  return low_rank ? low_rank->correct(solution) : solution;
}

DYNCONTACT_INSTANTIATE_CLASS(SaddlePointSystem)
} // namespace dyncontact
