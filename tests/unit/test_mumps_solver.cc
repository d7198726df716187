// MumpsSolver (MUMPS's symmetric indefinite LDL^T) against a dense LU solve (Eigen) of the same
// matrix: a saddle-point matrix [K, B^T; B, -D] of the contact problems' shape, K symmetric
// positive definite and diagonally dominant (a 1D stiffness plus a mass-like diagonal), B two
// constraint rows coupling a few DoFs, D = 0 on one row (a Lagrange multiplier) and a small
// positive number on the other (a penalty row): indefinite, so LDL^T needs its 2x2 pivots. The
// matrix is well conditioned (kappa < 100, entries O(1)): both solvers' forward errors are below
// kappa n eps ~ 1e-13, so 1e-12 bounds their difference; a lost triangle (MUMPS summing both
// triangles, or reading only the diagonal block) changes the answer by O(0.1). Also: new values on
// the same pattern refactorize without a new analysis, several right-hand sides solved in one call
// (NRHS > 1) each match the dense solve, and a singular matrix is a SolverFailure.
#include <dyncontact/solver/mumps_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Eigen/Dense>
#include <cmath>
#include <gtest/gtest.h>
#include <regex>

namespace dyncontact::testing
{
namespace
{
constexpr double tolerance = 1e-12; // see the file comment
constexpr unsigned int n   = 12;    // 10 displacement-like DoFs and 2 constraint rows

/** The dense matrix of the file comment; `scale` varies the values on the same pattern. */
Eigen::MatrixXd saddle_point_matrix(const double scale)
{
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(n, n);
  for (unsigned int i = 0; i < 10; ++i)
  {
    matrix(i, i) = scale * (2. + 1. + 0.1 * i); // stiffness 2 on the diagonal, mass 1 + 0.1 i
    if (i + 1 < 10)
      matrix(i, i + 1) = matrix(i + 1, i) = -scale;
  }
  const double b[2][3]             = {{1., -0.5, 0.25}, {-1., 0.7, 0.3}};
  const unsigned int coupled[2][3] = {{2, 3, 4}, {6, 7, 9}};
  for (unsigned int row = 0; row < 2; ++row)
    for (unsigned int k = 0; k < 3; ++k)
      matrix(10 + row, coupled[row][k]) = matrix(coupled[row][k], 10 + row) = b[row][k];
  matrix(11, 11) = -0.05; // the penalty row; row 10 keeps its zero diagonal
  return matrix;
}

/** The Trilinos matrix with the pattern and values of `dense` (one rank). */
void fill(const Eigen::MatrixXd& dense, TrilinosWrappers::SparseMatrix& matrix)
{
  if (matrix.m() == 0)
  {
    DynamicSparsityPattern pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (dense(i, j) != 0. || dense(j, i) != 0. || i == j)
          pattern.add(i, j); // structurally symmetric, as SaddlePointSystem's
    matrix.reinit(complete_index_set(n), complete_index_set(n), pattern, MPI_COMM_WORLD);
  }
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      if (dense(i, j) != 0. || dense(j, i) != 0. || i == j)
        matrix.set(i, j, dense(i, j));
  matrix.compress(VectorOperation::insert);
}

/** Right-hand side number `column`: a different smooth vector for each. */
DistributedVector right_hand_side(const unsigned int column)
{
  DistributedVector rhs(n);
  for (unsigned int i = 0; i < n; ++i)
    rhs[i] = std::cos(1. + 2. * i + 0.9 * column);
  return rhs;
}

double largest_difference_from_dense_solve(const Eigen::MatrixXd& dense,
                                           const DistributedVector& rhs,
                                           const DistributedVector& solution)
{
  const Eigen::VectorXd reference =
      dense.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(rhs.begin(), n));
  double largest = 0.;
  for (unsigned int i = 0; i < n; ++i)
    largest = std::max(largest, std::abs(solution[i] - reference(i)));
  return largest;
}
} // namespace

TEST(MumpsSolver, SolvesASymmetricIndefiniteSaddlePointSystemLikeDenseLU)
{
  TrilinosWrappers::SparseMatrix matrix;
  MumpsSolver solver(MPI_COMM_WORLD, true);
  for (const double scale : {1., 1.7}) // the second refactorizes on the analysed pattern
  {
    const Eigen::MatrixXd dense = saddle_point_matrix(scale);
    fill(dense, matrix);
    solver.factorize(matrix.trilinos_matrix());
    const std::vector<DistributedVector> rhs = {right_hand_side(0)};
    EXPECT_LT(largest_difference_from_dense_solve(dense, rhs[0], solver.solve(rhs)[0]), tolerance)
        << "scale " << scale;
  }
}

// With friction a sliding pair's tangential row differs from its column and couples the pair's
// normal multiplier (CoulombFriction): the unsymmetric mode (SYM = 0) must read both triangles.
// The symmetric mode on the same matrix reads the upper one only and misses by O(0.1).
TEST(MumpsSolver, SolvesAnUnsymmetricSaddlePointSystemLikeDenseLU)
{
  Eigen::MatrixXd dense = saddle_point_matrix(1.2);
  dense(10, 2)          = 0.4; // the row, not its column (2, 10) = 1
  dense(10, 3)          = 0.;  // a row without the coupling its column has
  dense(11, 10)         = -0.3;
  dense(11, 11)         = 1.1;
  TrilinosWrappers::SparseMatrix matrix;
  fill(dense, matrix);
  const std::vector<DistributedVector> rhs = {right_hand_side(1)};
  MumpsSolver unsymmetric(MPI_COMM_WORLD, false);
  unsymmetric.factorize(matrix.trilinos_matrix());
  EXPECT_LT(largest_difference_from_dense_solve(dense, rhs[0], unsymmetric.solve(rhs)[0]),
            tolerance);
  // New values on the analysed pattern (a sliding pair's row changes every iterate).
  dense(10, 2)  = -0.7;
  dense(11, 10) = 0.45;
  fill(dense, matrix);
  unsymmetric.factorize(matrix.trilinos_matrix());
  EXPECT_LT(largest_difference_from_dense_solve(dense, rhs[0], unsymmetric.solve(rhs)[0]),
            tolerance)
      << "refactorized";
  MumpsSolver symmetric(MPI_COMM_WORLD, true);
  symmetric.factorize(matrix.trilinos_matrix());
  EXPECT_GT(largest_difference_from_dense_solve(dense, rhs[0], symmetric.solve(rhs)[0]), 1e-3);
}

TEST(MumpsSolver, SolvesSeveralRightHandSidesInOneCall)
{
  TrilinosWrappers::SparseMatrix matrix;
  MumpsSolver solver(MPI_COMM_WORLD, true);
  const Eigen::MatrixXd dense = saddle_point_matrix(1.3);
  fill(dense, matrix);
  solver.factorize(matrix.trilinos_matrix());
  const std::vector<DistributedVector> rhs = {
      right_hand_side(0), right_hand_side(1), right_hand_side(2)};
  const std::vector<DistributedVector> solutions = solver.solve(rhs);
  ASSERT_EQ(solutions.size(), rhs.size());
  for (unsigned int column = 0; column < rhs.size(); ++column)
    EXPECT_LT(largest_difference_from_dense_solve(dense, rhs[column], solutions[column]), tolerance)
        << "column " << column;
}

// MUMPS's figures of the factorization, as MumpsSolver reports them, against bounds the matrix
// gives: the factors hold at least the matrix's own upper triangle (12 diagonal, 9 tridiagonal and
// 6 constraint entries: 27; fill only adds) and at most the dense triangle (n(n+1)/2 = 78); the
// elimination takes at least one operation and at most a dense LDL^T's (about n^3/3 multiply-adds,
// counted twice: 2 n^3 / 3 = 1152); one rank does all of it (100.0 %). A report that read the
// wrong array (the analysis's estimates, another rank's share, memory as entries) leaves a range.
TEST(MumpsSolver, ReportsTheFactorizationsFlopsFactorEntriesAndBalance)
{
  TrilinosWrappers::SparseMatrix matrix;
  MumpsSolver solver(MPI_COMM_WORLD, true);
  EXPECT_EQ(solver.last_factorization_statistics(), "");
  fill(saddle_point_matrix(1.), matrix);
  solver.factorize(matrix.trilinos_matrix());
  const std::string line = solver.last_factorization_statistics();
  std::smatch match;
  ASSERT_TRUE(
      std::regex_search(line,
                        match,
                        std::regex(R"(: ([\d.e+]+) flops, ([\d.]+) % of them on the busiest )"
                                   R"(of 1 rank\(s\); ([\d.e+]+) entries in the factors)")))
      << line;
  const double flops = std::stod(match[1]), share = std::stod(match[2]);
  const double entries = std::stod(match[3]);
  EXPECT_GE(flops, 1.) << line;
  EXPECT_LE(flops, 2. * n * n * n / 3.) << line;
  EXPECT_EQ(share, 100.) << line;
  EXPECT_GE(entries, 27.) << line;
  EXPECT_LE(entries, n * (n + 1) / 2.) << line;
}

TEST(MumpsSolver, SingularMatrixIsASolverFailureNamingMumps)
{
  Eigen::MatrixXd dense = saddle_point_matrix(1.);
  dense.row(11).setZero(); // the penalty row and column become zero: singular
  dense.col(11).setZero();
  TrilinosWrappers::SparseMatrix matrix;
  fill(dense, matrix);
  MumpsSolver solver(MPI_COMM_WORLD, true);
  try
  {
    solver.factorize(matrix.trilinos_matrix());
    FAIL() << "a singular matrix was factorized";
  }
  catch (const SolverFailure& failure)
  {
    EXPECT_NE(std::string(failure.what()).find("MUMPS"), std::string::npos) << failure.what();
  }
}
} // namespace dyncontact::testing
