#include <dyncontact/solver/low_rank_update.h>

namespace dyncontact
{
namespace
{
/** Below this reciprocal condition number of I + V^T Z the update is refused. */
constexpr double smallest_reciprocal_condition = 1e-12;

/** v^T x for a sparse column v. */
double dot(const LowRankUpdate::SparseColumn& v, const Vector<double>& x)
{
  double sum = 0.;
  for (const auto& [row, value] : v)
    sum += value * x[row];
  return sum;
}
} // namespace

LowRankUpdate::LowRankUpdate(const std::vector<Vector<double>>& columns_u,
                             std::vector<SparseColumn> columns_v,
                             const Solver& solve_a0)
    : columns_z(solve_a0(columns_u)), columns_v(std::move(columns_v))
{
  const unsigned int k = columns_u.size();
  AssertThrow(k > 0 && this->columns_v.size() == k && columns_z.size() == k,
              ExcMessage("LowRankUpdate needs as many columns of V as of U, at least one."));
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Identity(k, k);
  for (unsigned int i = 0; i < k; ++i)
    for (unsigned int j = 0; j < k; ++j)
      matrix(i, j) += dot(this->columns_v[i], columns_z[j]);
  capacitance.compute(matrix);
  const double reciprocal_condition = capacitance.rcond();
  if (!(reciprocal_condition >= smallest_reciprocal_condition))
    throw SolverFailure("the low-rank update's capacitance matrix is singular (reciprocal "
                        "condition number " +
                        std::to_string(reciprocal_condition) + ")");
}

Vector<double> LowRankUpdate::correct(const Vector<double>& y) const
{
  const unsigned int k = rank();
  Eigen::VectorXd v_dot_y(k);
  for (unsigned int i = 0; i < k; ++i)
    v_dot_y(i) = dot(columns_v[i], y);
  const Eigen::VectorXd coefficients = capacitance.solve(v_dot_y);
  Vector<double> x                   = y;
  for (unsigned int j = 0; j < k; ++j)
    x.add(-coefficients(j), columns_z[j]);
  return x;
}
} // namespace dyncontact
