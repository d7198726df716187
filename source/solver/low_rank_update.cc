#include <dyncontact/solver/low_rank_update.h>

#include <deal.II/base/mpi.h>

namespace dyncontact
{
namespace
{
/** Below this reciprocal condition number of I + V^T Z the update is refused. */
constexpr double smallest_reciprocal_condition = 1e-12;

/** This rank's part of v^T x for a sparse column v: the sum over the rows x owns. */
double local_dot(const LowRankUpdate::SparseColumn& v, const DistributedVector& x)
{
  double sum = 0.;
  for (const auto& [row, value] : v)
    if (x.in_local_range(row))
      sum += value * x(row);
  return sum;
}

/** v_i^T x for each sparse column v_i of `columns_v`, summed over the ranks. Collective. */
Eigen::VectorXd dots(const std::vector<LowRankUpdate::SparseColumn>& columns_v,
                     const DistributedVector& x)
{
  Eigen::VectorXd sums(columns_v.size());
  for (unsigned int i = 0; i < columns_v.size(); ++i)
    sums(i) = local_dot(columns_v[i], x);
  Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()),
                      x.get_mpi_communicator(),
                      ArrayView<double>(sums.data(), sums.size()));
  return sums;
}
} // namespace

LowRankUpdate::LowRankUpdate(const std::vector<DistributedVector>& columns_u,
                             std::vector<SparseColumn> columns_v,
                             const Solver& solve_a0)
    : columns_z(solve_a0(columns_u)), columns_v(std::move(columns_v))
{
  const unsigned int k = columns_u.size();
  AssertThrow(k > 0 && this->columns_v.size() == k && columns_z.size() == k,
              ExcMessage("LowRankUpdate needs as many columns of V as of U, at least one."));
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Identity(k, k);
  for (unsigned int j = 0; j < k; ++j)
    matrix.col(j) += dots(this->columns_v, columns_z[j]);
  capacitance.compute(matrix);
  const double reciprocal_condition = capacitance.rcond();
  if (!(reciprocal_condition >= smallest_reciprocal_condition))
    throw SolverFailure("the low-rank update's capacitance matrix is singular (reciprocal "
                        "condition number " +
                        std::to_string(reciprocal_condition) + ")");
}

DistributedVector LowRankUpdate::correct(const DistributedVector& y) const
{
  const Eigen::VectorXd coefficients = capacitance.solve(dots(columns_v, y));
  DistributedVector x                = y;
  for (unsigned int j = 0; j < rank(); ++j)
    x.add(-coefficients(j), columns_z[j]);
  return x;
}
} // namespace dyncontact
