#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/solver/direct_solver_package.h>
#include <dyncontact/solver/mumps_solver.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <memory>
#include <string>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace dyncontact
{
/**
 * A sparse direct solver that keeps its factorization: factorize() factors a matrix, solve()
 * applies the factors to any number of right-hand sides until the next factorize(). The symbolic
 * analysis (ordering, elimination tree) of the matrix's sparsity pattern is done once, by
 * analyse() or else on the first factorize(): the pattern must stay the same for the object's
 * life (SaddlePointSystem's never changes); the values may change between calls.
 *
 * The matrix is distributed (Trilinos); right-hand sides and solutions are distributed like its
 * rows (DistributedVector). The packages:
 *  - KLU (Amesos_Klu): LU, the matrix gathered to rank 0; the same bits on any number of ranks;
 *  - MUMPS (MumpsSolver): LDL^T of the symmetric matrix, distributed over the ranks;
 *  - UMFPACK: LU on one rank only (the constructor throws InputError otherwise), on a serial copy.
 * Errors of the package (a singular matrix) are thrown as SolverFailure naming it.
 */
class DirectSolver
{
public:
  /**
   * `symmetric` false: the matrices are unsymmetric (with friction), and MUMPS factorizes LU
   * instead of LDL^T; KLU and UMFPACK factorize LU always.
   */
  DirectSolver(DirectSolverPackage package, MPI_Comm communicator, bool symmetric = true);

  ~DirectSolver();

  /**
   * The symbolic analysis of `matrix`'s sparsity pattern (the values are not read), once, before
   * the first factorize(): MUMPS orders (METIS) and analyses, KLU orders (AMD); UMFPACK, which
   * analyses in every factorization, builds the pattern of its serial copy. Collective; throws
   * SolverFailure.
   */
  void analyse(const TrilinosWrappers::SparseMatrix& matrix);

  /** Numeric factorization of `matrix` (after analyse(), which it calls if it was not). */
  void factorize(const TrilinosWrappers::SparseMatrix& matrix);

  /**
   * matrix^{-1} right_hand_side with the last factorization; both distributed like the matrix's
   * rows. Collective; throws SolverFailure.
   */
  DistributedVector solve(const DistributedVector& right_hand_side);

  /**
   * matrix^{-1} b for each b of `right_hand_sides` (each distributed like the matrix's rows; so
   * are the solutions). MUMPS solves all columns at once (the factors are read once; blocked, so
   * equal to single solves to round-off); KLU and UMFPACK one column after the other. Collective;
   * throws SolverFailure.
   */
  std::vector<DistributedVector> solve(const std::vector<DistributedVector>& right_hand_sides);

  /** The number of numeric factorizations so far. */
  unsigned int n_factorizations() const { return factorizations; }

  /**
   * The solver package's own figures of its last factorization, one line (MUMPS: flops, their
   * balance over the ranks, factor entries, memory; MumpsSolver), or empty (KLU, UMFPACK).
   */
  std::string last_factorization_statistics() const;

private:
  const DirectSolverPackage package;
  const MPI_Comm communicator;
  const bool symmetric;
  unsigned int factorizations = 0;
  bool analysed               = false;
  /** Amesos (KLU): the problem holds the matrix; symbolic analysis once. */
  std::unique_ptr<Epetra_LinearProblem> problem;
  std::unique_ptr<Amesos_BaseSolver> amesos;
  /** MUMPS. */
  std::unique_ptr<MumpsSolver> mumps;
  /** UMFPACK: a serial copy of the matrix, its pattern built by analyse(). */
  SparsityPattern serial_pattern;
  SparseMatrix<double> serial_matrix;
  SparseDirectUMFPACK umfpack;
};
} // namespace dyncontact
