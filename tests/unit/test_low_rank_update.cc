// LowRankUpdate against direct solves of the updated matrix, on small dense matrices (Eigen LU as
// the solver of A0 and as the reference). The matrices are well conditioned (diagonally dominant
// A0, kappa < 10, entries O(1)): LU's forward error is below kappa n eps ~ 1e-14, and the
// Woodbury formula adds one k x k solve of O(1) numbers, so 1e-12 bounds the difference from the
// direct solve; a dropped or mis-signed correction term changes the answer by O(0.1).
#include <dyncontact/solver/low_rank_update.h>

#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace dyncontact::testing
{
namespace
{
constexpr double tolerance = 1e-12; // see the file comment

DistributedVector to_vector(const Eigen::VectorXd& values)
{
  DistributedVector result(values.size()); // one rank: every entry owned
  for (unsigned int i = 0; i < result.size(); ++i)
    result[i] = values(i);
  return result;
}

/** The nonzero entries of `values`. */
LowRankUpdate::SparseColumn to_sparse(const Eigen::VectorXd& values)
{
  LowRankUpdate::SparseColumn result;
  for (unsigned int i = 0; i < values.size(); ++i)
    if (values(i) != 0.)
      result.emplace_back(i, values(i));
  return result;
}

Eigen::VectorXd to_eigen(const DistributedVector& values)
{
  Eigen::VectorXd result(values.size());
  for (unsigned int i = 0; i < values.size(); ++i)
    result(i) = values[i];
  return result;
}

/** A0 = 6 I plus a fixed pattern of O(1) entries (diagonally dominant, not symmetric). */
Eigen::MatrixXd base_matrix(const unsigned int n)
{
  Eigen::MatrixXd matrix = 6. * Eigen::MatrixXd::Identity(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      matrix(i, j) += std::sin(1. + 3. * i + 7. * j) * (i == j ? 0.5 : 0.6);
  return matrix;
}
} // namespace

// Rank 1, 2 and 3 updates of a 7 x 7 matrix: the corrected solution equals the direct solution
// of A0 + U V^T, and A0's own solution (no correction) is far from it.
TEST(LowRankUpdate, SolvesTheUpdatedMatrixAsADirectSolveDoes)
{
  const unsigned int n     = 7;
  const Eigen::MatrixXd a0 = base_matrix(n);
  const Eigen::PartialPivLU<Eigen::MatrixXd> a0_lu(a0);
  const LowRankUpdate::Solver solve_a0 = [&](const std::vector<DistributedVector>& columns)
  {
    std::vector<DistributedVector> solutions;
    for (const auto& b : columns)
      solutions.push_back(to_vector(a0_lu.solve(to_eigen(b))));
    return solutions;
  };
  Eigen::VectorXd b(n);
  for (unsigned int i = 0; i < n; ++i)
    b(i) = std::cos(2. * i);
  for (unsigned int k = 1; k <= 3; ++k)
  {
    SCOPED_TRACE("rank " + std::to_string(k));
    Eigen::MatrixXd u(n, k), v(n, k);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < k; ++j)
      {
        u(i, j) = std::cos(0.3 + i + 2. * j);
        v(i, j) = (i + j) % 3 == 0 ? 0. : std::sin(0.7 + 2. * i + j); // sparse, as in contact
      }
    std::vector<DistributedVector> columns_u;
    std::vector<LowRankUpdate::SparseColumn> columns_v;
    for (unsigned int j = 0; j < k; ++j)
    {
      columns_u.push_back(to_vector(u.col(j)));
      columns_v.push_back(to_sparse(v.col(j)));
    }
    const LowRankUpdate update(columns_u, columns_v, solve_a0);
    EXPECT_EQ(update.rank(), k);
    const DistributedVector y      = solve_a0({to_vector(b)})[0];
    const DistributedVector x      = update.correct(y);
    const Eigen::VectorXd expected = (a0 + u * v.transpose()).fullPivLu().solve(b);
    double largest_correction      = 0.;
    for (unsigned int i = 0; i < n; ++i)
    {
      EXPECT_NEAR(x[i], expected(i), tolerance) << "entry " << i;
      largest_correction = std::max(largest_correction, std::abs(y[i] - expected(i)));
    }
    EXPECT_GT(largest_correction, 0.01);
  }
}

// A0 = I, U = e_0, V = -e_0: A0 + U V^T has a zero row, and the capacitance 1 + V^T A0^-1 U is 0.
TEST(LowRankUpdate, SingularUpdateIsASolverFailure)
{
  const unsigned int n = 3;
  DistributedVector e0(n);
  e0[0] = 1.;
  const LowRankUpdate::SparseColumn minus_e0{{0, -1.}};
  const LowRankUpdate::Solver identity = [](const std::vector<DistributedVector>& b) { return b; };
  try
  {
    const LowRankUpdate update({e0}, {minus_e0}, identity);
    ADD_FAILURE() << "no SolverFailure";
  }
  catch (const SolverFailure& failure)
  {
    EXPECT_NE(std::string(failure.what()).find("capacitance matrix is singular"), std::string::npos)
        << failure.what();
  }
}
} // namespace dyncontact::testing
