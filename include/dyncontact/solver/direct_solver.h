#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/solver/direct_solver_package.h>

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
 * A sparse direct solver that keeps its factorization: factorize() computes the LU factors of a
 * matrix, solve() applies them to any number of right-hand sides until the next factorize(). The
 * symbolic analysis (ordering, elimination tree) is done on the first factorize() only: the
 * matrix's sparsity pattern must stay the same for the object's life (SaddlePointSystem's never
 * changes); its values may change between calls.
 *
 * Matrix and vectors are distributed (Trilinos, rows as the matrix's); UMFPACK works on one rank
 * only (the constructor throws InputError otherwise) on a serial copy of the matrix. Errors of the
 * package (a singular matrix) are thrown as SolverFailure naming it.
 */
class DirectSolver
{
public:
  DirectSolver(DirectSolverPackage package, MPI_Comm communicator);
  ~DirectSolver();

  /** Numeric factorization of `matrix` (after the symbolic analysis on the first call). */
  void factorize(const TrilinosWrappers::SparseMatrix& matrix);

  /** solution = matrix^{-1} right_hand_side with the last factorization. */
  void solve(const TrilinosWrappers::MPI::Vector& right_hand_side,
             TrilinosWrappers::MPI::Vector& solution);

  /** The number of numeric factorizations so far. */
  unsigned int n_factorizations() const { return factorizations; }

private:
  const DirectSolverPackage package;
  unsigned int factorizations = 0;
  /** Amesos (KLU, MUMPS): the problem holds the matrix; symbolic analysis once. */
  std::unique_ptr<Epetra_LinearProblem> problem;
  std::unique_ptr<Amesos_BaseSolver> amesos;
  /** UMFPACK: a serial copy of the matrix, its pattern built on the first call. */
  SparsityPattern serial_pattern;
  SparseMatrix<double> serial_matrix;
  SparseDirectUMFPACK umfpack;
};
} // namespace dyncontact
