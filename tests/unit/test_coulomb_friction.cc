// CoulombFriction's rows against central finite differences of its own residuals and forces, on a
// pair of two nodes (node-to-node: one master node of weight 1) in 2D and 3D, in both branches
// (stick and slip) and both formulations. The residual is smooth in each branch away from |z| = b
// (the points below keep |z| - b at least 0.5), so central differences with h = 1e-6 are exact to
// O(h^2 |R'''|) ~ 1e-12 plus round-off 1e-16 / h ~ 1e-10: 1e-8 bounds the difference and any wrong
// entry (a sign, a missing P / |z| term, a dropped lambda_n coupling) is O(0.1) off.
// Also: the dissipation of a sliding pair is mu lambda_n |s| and it reverses to stick.
#include <dyncontact/contact/contact_border.h>
#include <dyncontact/contact/coulomb_friction.h>

#include <deal.II/lac/full_matrix.h>

#include <gtest/gtest.h>

namespace dyncontact::testing
{
namespace
{
constexpr double step = 1e-6, bound = 1e-8; // see the file comment

/** The rows the contact layer writes, into a dense matrix of n_dofs DoFs and the multipliers. */
struct DenseFrictionRows : MultiplierRows
{
  DenseFrictionRows(const unsigned int n_dofs, const unsigned int n_multipliers)
      : n_dofs(n_dofs), matrix(n_dofs + n_multipliers, n_dofs + n_multipliers)
  {
  }
  void
  add_coupling(const unsigned int m, const types::global_dof_index dof, const double v) override
  {
    matrix(n_dofs + m, dof) += v;
    matrix(dof, n_dofs + m) += v;
  }
  void
  add_row_coupling(const unsigned int m, const types::global_dof_index dof, const double v) override
  {
    matrix(n_dofs + m, dof) += v;
  }
  void add_column_coupling(const unsigned int m,
                           const types::global_dof_index dof,
                           const double v) override
  {
    matrix(dof, n_dofs + m) += v;
  }
  void
  add_multiplier_coupling(const unsigned int m, const unsigned int other, const double v) override
  {
    matrix(n_dofs + m, n_dofs + other) += v;
  }
  void add_diagonal(const unsigned int m, const double v) override
  {
    matrix(n_dofs + m, n_dofs + m) += v;
  }
  unsigned int n_dofs;
  FullMatrix<double> matrix;
};

/** A slave node against one master node along a tilted normal, with friction mu = 0.4. */
template <int dim>
struct FrictionPair
{
  FrictionPair()
  {
    Node<dim> slave{0, Point<dim>(), {}}, master{1, Point<dim>(), {}};
    for (unsigned int d = 0; d < dim; ++d)
    {
      slave.dofs[d]      = d;
      master.dofs[d]     = dim + d;
      master.position[d] = 0.1 * (d + 1);
    }
    border = ContactBorder<dim>({slave, master});
    ContactPair<dim> pair{};
    pair.slave   = slave;
    pair.masters = {{master, 1.}};
    for (unsigned int d = 0; d < dim; ++d)
      pair.normal[d] = 0.3 + d;
    pair.normal /= pair.normal.norm();
    pairs = {pair};
    start.reinit(2 * dim);
    for (unsigned int i = 0; i < start.size(); ++i)
      start[i] = 0.01 * std::sin(1. + i);
  }

  /** The tangential residuals (components 1 .. dim - 1) at (u, lambda). */
  Vector<double> residual(const CoulombFriction<dim>& friction,
                          const Vector<double>& u,
                          const Vector<double>& lambda,
                          const ContactFormulation formulation) const
  {
    Vector<double> r(dim);
    friction.assemble_rows(u, {true}, lambda, block, formulation, 1., border, nullptr, r);
    return r;
  }

  ContactBorder<dim> border;
  std::vector<ContactPair<dim>> pairs;
  MultiplierBlock block{std::vector<unsigned int>{dim}};
  Vector<double> start;
};

/**
 * The largest difference between the assembled tangential rows and columns and central
 * differences, at `u` and `lambda`, in the branch `slipping`.
 */
template <int dim>
double tangent_error(const ContactFormulation formulation, const bool slipping)
{
  FrictionPair<dim> p;
  CoulombFriction<dim> friction({0.4});
  Vector<double> old_lambda(dim);
  for (unsigned int c = 0; c < dim; ++c)
    old_lambda[c] = 0.5 + 0.3 * c;
  friction.start_step(p.pairs, p.start, {true}, old_lambda, p.block, {2.5});
  // An iterate well inside the branch: sliding, |z| - b >= 0.5; stuck, |z| - b <= -0.5.
  Vector<double> u = p.start, lambda(dim);
  lambda[0]        = slipping ? 1. : 5.;
  for (unsigned int c = 1; c < dim; ++c)
    lambda[c] = 0.2 * c;
  for (unsigned int i = 0; i < u.size(); ++i)
    u[i] += (slipping ? 0.4 : 0.05) * std::cos(2. + 3. * i);
  friction.set_states({static_cast<signed char>(slipping ? 1 : 0)});
  EXPECT_FALSE(friction.update_states(u, {true}, lambda, p.block, formulation, 0.5))
      << "the iterate is not inside the branch";

  DenseFrictionRows rows(2 * dim, dim);
  Vector<double> r(dim);
  friction.assemble_rows(u, {true}, lambda, p.block, formulation, 1., p.border, &rows, r);
  double error = 0.;
  for (unsigned int m = 1; m < dim; ++m)
  {
    for (unsigned int j = 0; j < 2 * dim; ++j) // d R_m / d u_j
    {
      Vector<double> plus = u, minus = u;
      plus[j] += step, minus[j] -= step;
      const double difference = (p.residual(friction, plus, lambda, formulation)[m] -
                                 p.residual(friction, minus, lambda, formulation)[m]) /
                                (2. * step);
      error = std::max(error, std::abs(rows.matrix(2 * dim + m, j) - difference));
    }
    for (unsigned int c = 0; c < dim; ++c) // d R_m / d lambda_c
    {
      Vector<double> plus = lambda, minus = lambda;
      plus[c] += step, minus[c] -= step;
      const double difference = (p.residual(friction, u, plus, formulation)[m] -
                                 p.residual(friction, u, minus, formulation)[m]) /
                                (2. * step);
      error = std::max(error, std::abs(rows.matrix(2 * dim + m, 2 * dim + c) - difference));
    }
    // The column: the displacement rows hold -G^T lambda, minus the forces' derivative.
    for (unsigned int j = 0; j < 2 * dim; ++j)
    {
      Vector<double> force(2 * dim), unit(dim);
      unit[m] = 1.;
      friction.add_forces({true}, unit, p.block, force);
      error = std::max(error, std::abs(rows.matrix(j, 2 * dim + m) + force[j]));
    }
  }
  return error;
}
} // namespace

TEST(CoulombFriction, RowsAreTheDerivativesOfTheResidualsInEveryBranch)
{
  for (const auto formulation :
       {ContactFormulation::lagrange_multiplier, ContactFormulation::penalty})
    for (const bool slipping : {false, true})
    {
      EXPECT_LT(tangent_error<2>(formulation, slipping), bound) << "2D, slipping " << slipping;
      EXPECT_LT(tangent_error<3>(formulation, slipping), bound) << "3D, slipping " << slipping;
    }
}

// A pair held at lambda_t = mu lambda_n tau by its slip row dissipates mu lambda_n |s| with the
// new force alone (weight 1), and with Newmark's weights half of it from a pair that was open at
// the step's start (F^n = 0); its trial pointing against its force sends it to stick.
TEST(CoulombFriction, SlidingPairDissipatesMuLambdaTimesSlipAndReversesToStick)
{
  FrictionPair<3> p;
  CoulombFriction<3> friction({0.4});
  friction.start_step(p.pairs, p.start, {false}, Vector<double>(3), p.block, {2.5});
  Vector<double> u = p.start;
  u[3] += 0.3, u[4] -= 0.1; // the master node moves: s != 0
  const double s[2]   = {friction.slip(0, 0, u), friction.slip(0, 1, u)};
  const double s_norm = std::hypot(s[0], s[1]);
  ASSERT_GT(s_norm, 0.05);
  Vector<double> lambda(3);
  lambda[0] = 2.;
  lambda[1] = -0.4 * 2. * s[0] / s_norm, lambda[2] = -0.4 * 2. * s[1] / s_norm;
  EXPECT_NEAR(friction.dissipation(u, {true}, lambda, p.block, 1., 1.), 0.8 * s_norm, 1e-14);
  EXPECT_NEAR(friction.dissipation(u, {true}, lambda, p.block, 1., 0.5), 0.4 * s_norm, 1e-14);
  friction.set_states({1});
  EXPECT_FALSE(friction.update_states(
      u, {true}, lambda, p.block, ContactFormulation::lagrange_multiplier, 0.));
  lambda[1] *= -1., lambda[2] *= -1.; // the force now along the slip: the trial opposes it
  EXPECT_TRUE(friction.update_states(
      u, {true}, lambda, p.block, ContactFormulation::lagrange_multiplier, 0.));
  EXPECT_EQ(friction.states()[0], 0);
}
} // namespace dyncontact::testing
