#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{
/**
 * The linear system of one Newton iteration of a contact step: the symmetric saddle-point matrix
 * [K_eff, -G^T; -G, -D] of size (n_dofs + n_pairs)^2, unknowns ordered as the n_dofs displacement
 * DoFs of the DoFHandler followed by one multiplier per candidate contact pair (row n_dofs + k for
 * pair k), and its direct solve.
 *
 * The sparsity pattern is fixed at construction and never changes: the couplings of the
 * DoFHandler's cells plus those the contact layer declares (ContactConstraints::add_to_sparsity(),
 * every candidate pair, active or not). Parallel layout: rows are distributed like the DoFs, the
 * multiplier rows belong to the last MPI rank; each rank's pattern holds the full rows it writes
 * (those of its locally owned cells and, on the last rank, the constraint rows and the DoFs they
 * couple to); entries in rows owned elsewhere are sent on finish_assembly(). The direct solver is
 * Amesos KLU on every number of ranks (bitwise reproducible; MUMPS was not, run to run, on 2
 * ranks). Vectors passed in and out are whole (all n_dofs + n_pairs entries) on every rank.
 *
 * Rows of fixed DoFs (e.g. u_r = 0 on a symmetry axis) are replaced by a diagonal row on
 * finish_assembly(), so that a zero right-hand side there gives a zero increment.
 *
 * It owns the matrix, not its entries' meaning: what is assembled into it is the caller's
 * (DynamicResidual); it knows neither the bodies nor Newton's method.
 */
template <int dim>
class SaddlePointSystem
{
public:
  /** The distributed matrix type (Epetra, through deal.II's wrapper). */
  using Matrix = TrilinosWrappers::SparseMatrix;

  /**
   * Builds the pattern and the distributed matrix (all entries zero) for the DoFs of
   * `dof_handler` and the candidate pairs of `contact` (the number of pairs is fixed from here
   * on). `fixed_dofs` are DoF indices < n_dofs whose rows finish_assembly() replaces. The
   * communicator is the triangulation's.
   */
  SaddlePointSystem(const DoFHandler<dim>& dof_handler,
                    const ContactConstraints<dim>& contact,
                    const std::vector<types::global_dof_index>& fixed_dofs);

  /** The matrix, for adding entries of the leading block and the constraint rows. */
  Matrix& matrix() { return system_matrix; }

  /** Whether this rank owns the multiplier rows (the last rank): only it writes them. */
  bool owns_multiplier_rows() const { return multiplier_rows_owner; }

  /** Whether `row` (< n_dofs + n_pairs) is one of this rank's rows. */
  bool owns_row(const types::global_dof_index row) const
  {
    return locally_owned_rows.is_element(row);
  }

  /** Sets every entry to zero before an assembly (the pattern stays). */
  void start_assembly();

  /**
   * Ends an assembly: exchanges the entries added into rows owned by other ranks (a collective
   * call) and replaces every locally owned fixed DoF's row by `fixed_row_diagonal` on the
   * diagonal, zero elsewhere (the columns keep their entries).
   */
  void finish_assembly(double fixed_row_diagonal);

  /**
   * Exchanges the entries added so far without touching the fixed rows: for an assembly that
   * stopped early (a failed evaluation), so that every rank's pending additions are flushed
   * (collective, like finish_assembly()).
   */
  void abandon_assembly();

  /**
   * max |diag| over the displacement rows (index < n_dofs) of all ranks: the stiffness scale of
   * the assembled K_eff (fixed rows included, with their replaced diagonal). Collective.
   */
  double largest_displacement_diagonal() const;

  /**
   * Solves matrix * solution = right_hand_side by the direct solver (Amesos KLU); both vectors have
   * n_dofs + n_pairs entries and are whole on every rank. Throws SolverFailure ("the direct solver
   * (Amesos) failed: ...") if the factorization or solve fails, e.g. for a singular matrix.
   */
  Vector<double> solve(const Vector<double>& right_hand_side) const;

private:
  const MPI_Comm communicator;
  const bool multiplier_rows_owner;
  /** The locally owned DoFs of the DoFHandler (the displacement rows of this rank). */
  const IndexSet locally_owned_dofs;
  /** This rank's rows: its DoFs and, on the last rank, the multiplier rows. */
  IndexSet locally_owned_rows;
  std::vector<types::global_dof_index> locally_owned_fixed_rows;
  Matrix system_matrix;
};
} // namespace dyncontact
