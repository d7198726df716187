#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <memory>
#include <string>
#include <vector>

class Epetra_CrsMatrix;

namespace dyncontact
{
/**
 * MUMPS (5.5, its C interface) on a symmetric, possibly indefinite matrix: the LDL^T
 * factorization with 1x1 and 2x2 pivots (MUMPS's SYM = 2), which needs half the flops and half
 * the factor storage of the LU factorization that Amesos_Mumps makes (Amesos fixes SYM = 0).
 * Measured on the 1.09M-DoF sphere impact (doc/performance.md).
 *
 * The matrix is given as a distributed Epetra matrix; each rank passes the entries of its rows on
 * and above the diagonal (column >= row) to MUMPS as distributed assembled input (ICNTL(18) = 3),
 * so no rank ever holds the whole matrix. The entries below the diagonal are not read: the matrix
 * must be symmetric (SaddlePointSystem's is, by construction). The symbolic analysis (analyse(),
 * or the first factorize()) reads the sparsity pattern only, in the pivot order of METIS's nested
 * dissection (METIS_NodeND, computed on rank 0 from the gathered graph); the pattern must then
 * stay the same.
 * Right-hand sides and solutions are distributed like the matrix's rows (DistributedVector).
 * MUMPS solves with them distributed (each rank passes its matrix rows of the right-hand sides and
 * receives the rows of its factors), all columns of a call at once; the solution rows are then
 * sent to the ranks that own them (MPI_Alltoallv).
 *
 * The root front is not given to ScaLAPACK (ICNTL(13) = 1: its rows are split over the ranks
 * instead): ScaLAPACK has no LDL^T and factorized it as LU, and its triangular solves were the
 * slowest phase of a 2-rank step (doc/performance.md, "Contact geometry on the border").
 *
 * With friction the matrix is unsymmetric (CoulombFriction's sliding rows): then SYM = 0 and every
 * entry is passed (the constructor's `symmetric`).
 *
 * Errors of MUMPS (a singular matrix: INFOG(1) = -10; out of memory) are thrown as SolverFailure
 * with MUMPS's error code; a factorization that ran out of its estimated workspace (INFOG(1) = -8
 * or -9) is retried with twice the relaxation (ICNTL(14)), up to three times.
 */
class MumpsSolver
{
public:
  /**
   * Starts a MUMPS instance on all ranks of `communicator` (collective). `symmetric` false: an
   * unsymmetric matrix (SYM = 0, LU with pivoting, every entry passed; a structurally symmetric
   * pattern, as SaddlePointSystem's with friction), whose pivot order is made from the entries
   * on and above the diagonal as for a symmetric one.
   */
  MumpsSolver(MPI_Comm communicator, bool symmetric);

  /** Ends the MUMPS instance (collective). */
  ~MumpsSolver();

  MumpsSolver(const MumpsSolver&)            = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  /**
   * The symbolic analysis of `matrix`'s pattern (its values are not read): METIS's pivot order and
   * MUMPS's elimination tree and workspace estimates. Once, before any factorize() (which calls
   * it if it was not). Collective; throws SolverFailure.
   */
  void analyse(const Epetra_CrsMatrix& matrix);

  /**
   * The LDL^T factorization of the symmetric `matrix` (its upper triangle), on the pattern of the
   * analysis. Collective; throws SolverFailure.
   */
  void factorize(const Epetra_CrsMatrix& matrix);

  /**
   * matrix^{-1} b for each b of `right_hand_sides` with the last factorization, in one MUMPS solve
   * (NRHS = their number: the factors are read once for all). Each right-hand side is distributed
   * like the matrix's rows, and so is each solution. Collective; throws SolverFailure.
   */
  std::vector<DistributedVector> solve(const std::vector<DistributedVector>& right_hand_sides);

  /**
   * MUMPS's own figures of the last factorization, as one line: the flops of the elimination in
   * all (RINFOG(3)) and the share of the busiest rank (the largest RINFO(3); 1/ranks is a perfect
   * balance), the entries of the factors (INFOG(29)), and the memory MUMPS used, largest rank and
   * all ranks (INFOG(21), INFOG(22), MB). Empty before the first factorization.
   */
  std::string last_factorization_statistics() const;

private:
  /** The MUMPS instance (DMUMPS_STRUC_C), kept out of this header. */
  struct Instance;

  /** Runs MUMPS's `job` and throws SolverFailure naming `phase` if it failed. */
  void run(int job, const char* phase);

  /**
   * Sends the n_solution_rows rows `solution_rows` (1-based) of MUMPS's distributed solution
   * (`local_solution`, column j at j * LSOL_loc) to the ranks that own them and writes them
   * into `solutions` (one per column). Collective (MPI_Alltoallv).
   */
  void send_to_owners(const std::vector<int>& solution_rows,
                      const std::vector<double>& local_solution,
                      int n_solution_rows,
                      std::vector<DistributedVector>& solutions) const;

  const MPI_Comm communicator;
  std::unique_ptr<Instance> instance;
  const bool symmetric; ///< SYM = 2 (LDL^T) or 0 (LU), see the constructor
  /**
   * This rank's entries (symmetric: those on and above the diagonal), 1-based global indices, in
   * row order.
   */
  std::vector<int> rows, columns;
  std::vector<double> values;
  /** This rank's rows of the matrix, 1-based: its rows of the right-hand sides. */
  std::vector<int> owned_rows;
  /** Every rank's runs of consecutive owned rows: (first row, 1-based; rank), sorted. */
  std::vector<std::pair<int, int>> owner_runs;
  bool analysed = false;
  /** The largest rank's elimination flops of the last factorization (RINFO(3) over the ranks). */
  double busiest_rank_flops = 0;
};
} // namespace dyncontact
