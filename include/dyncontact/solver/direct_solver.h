#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/solver/direct_solver_package.h>
#include <dyncontact/solver/mumps_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace dyncontact
{
/**
 * A sparse direct solver that keeps its factorization: factorize() factors a matrix, solve()
 * applies the factors to any number of right-hand sides until the next factorize(). The symbolic
 * analysis (ordering, elimination tree) is done on the first factorize() only: the matrix's
 * sparsity pattern must stay the same for the object's life (SaddlePointSystem's never changes);
 * its values may change between calls.
 *
 * The matrix is distributed (Trilinos, rows as the matrix's); right-hand sides and solutions are
 * whole vectors (all rows) on every rank. The packages:
 *  - KLU (Amesos_Klu): LU, the matrix gathered to rank 0; the same bits on any number of ranks;
 *  - MUMPS (MumpsSolver): LDL^T of the symmetric matrix, distributed over the ranks;
 *  - UMFPACK: LU on one rank only (the constructor throws InputError otherwise), on a serial copy.
 * Errors of the package (a singular matrix) are thrown as SolverFailure naming it.
 */
class DirectSolver
{
public:
  DirectSolver(DirectSolverPackage package, MPI_Comm communicator);

  ~DirectSolver();

  /** Numeric factorization of `matrix` (after the symbolic analysis on the first call). */
  void factorize(const TrilinosWrappers::SparseMatrix& matrix);

  /**
   * matrix^{-1} right_hand_side with the last factorization; both whole (matrix.m() entries) on
   * every rank. Collective.
   */
  Vector<double> solve(const Vector<double>& right_hand_side);

  /** The number of numeric factorizations so far. */
  unsigned int n_factorizations() const { return factorizations; }

private:
  const DirectSolverPackage package;
  const MPI_Comm communicator;
  unsigned int factorizations = 0;
  /** This rank's rows of the factorized matrix. */
  IndexSet locally_owned_rows;
  /** Amesos (KLU): the problem holds the matrix; symbolic analysis once. */
  std::unique_ptr<Epetra_LinearProblem> problem;
  std::unique_ptr<Amesos_BaseSolver> amesos;
  /** MUMPS. */
  std::unique_ptr<MumpsSolver> mumps;
  /** UMFPACK: a serial copy of the matrix, its pattern built on the first call. */
  SparsityPattern serial_pattern;
  SparseMatrix<double> serial_matrix;
  SparseDirectUMFPACK umfpack;
};
} // namespace dyncontact
