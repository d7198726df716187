#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>

#include <Eigen/Dense>
#include <functional>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * The solution of (A0 + U V^T) x = b for a few columns U, V (n x k each, k small) from a solver of
 * A0 alone, by the Sherman-Morrison-Woodbury formula
 *
 *   x = y - Z (I_k + V^T Z)^{-1} V^T y,   y = A0^{-1} b,   Z = A0^{-1} U.
 *
 * Z (one solve with A0 for k right-hand sides) and the LU factors of the k x k capacitance matrix
 * I_k + V^T Z (Eigen) are computed at construction; each correct() is then k sparse dot products
 * (V's columns are given by their nonzero entries) and k vector updates. It serves
 * SaddlePointSystem, whose matrix changes in a few multiplier rows and columns when contact pairs
 * enter or leave the active set: a rank-2 change per multiplier instead of a new factorization.
 * Vectors are distributed over the ranks (DistributedVector, each rank its owned rows, as the
 * direct solver takes them); the k sums V^T y are made over the ranks (collective calls).
 */
class LowRankUpdate
{
public:
  /** The columns A0^{-1} b of each column b (distributed, n entries in all), in one call. */
  using Solver =
      std::function<std::vector<DistributedVector>(const std::vector<DistributedVector>&)>;

  /** A sparse column of n entries: its nonzero entries (row, value), each row once. */
  using SparseColumn = std::vector<std::pair<types::global_dof_index, double>>;

  /**
   * `columns_u`: the k columns of U (n entries each, distributed); `columns_v`: the k sparse
   * columns of V (rows < n; the same on every rank; k >= 1, the same k).
   * Calls `solve_a0` once, with the k columns of U. Collective. Throws SolverFailure if the
   * capacitance matrix is singular or so ill-conditioned (reciprocal condition number below 1e-12)
   * that the formula would lose the solution's digits; the caller then factorizes A0 + U V^T
   * itself.
   */
  LowRankUpdate(const std::vector<DistributedVector>& columns_u,
                std::vector<SparseColumn> columns_v,
                const Solver& solve_a0);

  /** x = (A0 + U V^T)^{-1} b from y = A0^{-1} b (distributed as U's columns). Collective. */
  DistributedVector correct(const DistributedVector& y) const;

  /** k, the number of columns of U and V. */
  unsigned int rank() const { return columns_v.size(); }

private:
  std::vector<DistributedVector> columns_z;
  std::vector<SparseColumn> columns_v;
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance;
};
} // namespace dyncontact
