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
  // Twice: the first sets the basis old_lambda is in, the second carries it into the step.
  for (unsigned int call = 0; call < 2; ++call)
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
  EXPECT_NEAR(friction.dissipation(
                  u, {true}, lambda, p.block, 1., 1., ContactFormulation::lagrange_multiplier),
              0.8 * s_norm,
              1e-14);
  EXPECT_NEAR(friction.dissipation(
                  u, {true}, lambda, p.block, 1., 0.5, ContactFormulation::lagrange_multiplier),
              0.4 * s_norm,
              1e-14);
  friction.set_states({1});
  EXPECT_FALSE(friction.update_states(
      u, {true}, lambda, p.block, ContactFormulation::lagrange_multiplier, 0.));
  lambda[1] *= -1., lambda[2] *= -1.; // the force now along the slip: the trial opposes it
  EXPECT_TRUE(friction.update_states(
      u, {true}, lambda, p.block, ContactFormulation::lagrange_multiplier, 0.));
  EXPECT_EQ(friction.states()[0], 0);
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
// The old tangential force a step starts from is the multipliers read in the basis they were
// solved in, also after a restore (bases()/set_bases()), and the penalty spring's force is carried
// into a new basis by projection: here the normal turns 0.008 degrees and its smallest component
// moves to another axis, which turns the 3D basis by about 110 degrees. With the new weight 0 the
// dissipation is -F^n . [[u - u^n]], so it shows which force was taken.
TEST(CoulombFriction, OldForceIsReadInItsOwnBasisAcrossBasisJumpsAndRestores)
{
  FrictionPair<3> p;
  p.pairs[0].normal = Tensor<1, 3>({0.5, 0.5001, 0.707});
  p.pairs[0].normal /= p.pairs[0].normal.norm();
  CoulombFriction<3> friction({0.4});
  Vector<double> lambda(3);
  lambda[0] = 2., lambda[1] = 0.3, lambda[2] = -0.2;
  friction.start_step(p.pairs, p.start, {true}, lambda, p.block, {2.5}); // basis T1
  const std::vector<double> saved    = friction.bases();
  const std::vector<Tensor<1, 3>> t1 = friction.friction_directions(0);
  const Tensor<1, 3> force           = 0.3 * t1[0] - 0.2 * t1[1];
  Vector<double> u                   = p.start;
  u[3] += 0.01, u[4] -= 0.02, u[5] += 0.005; // the master node moves
  Tensor<1, 3> relative;
  for (unsigned int d = 0; d < 3; ++d)
    relative[d] = u[3 + d] - p.start[3 + d];
  const auto old_force_work = [&]()
  {
    return friction.dissipation(
        u, {true}, lambda, p.block, 1., 0., ContactFormulation::lagrange_multiplier);
  };

  FrictionPair<3> turned = p;
  turned.pairs[0].normal = Tensor<1, 3>({0.5001, 0.5, 0.707});
  turned.pairs[0].normal /= turned.pairs[0].normal.norm();
  friction.start_step(turned.pairs, p.start, {true}, lambda, p.block, {2.5}); // T1 -> T2
  EXPECT_NEAR(old_force_work(), -(force * relative), 1e-15);
  const std::vector<Tensor<1, 3>> t2 = friction.friction_directions(0);
  EXPECT_LT(t1[0] * t2[0], 0.) << "the basis did not jump: the test shows nothing";
  // A step retried from the saved state: the multipliers are T1's again, not T2's.
  friction.set_bases(saved);
  friction.start_step(turned.pairs, p.start, {true}, lambda, p.block, {2.5});
  EXPECT_NEAR(old_force_work(), -(force * relative), 1e-15);
  // Without the restore the retry would read them in T2.
  friction.start_step(turned.pairs, p.start, {true}, lambda, p.block, {2.5});
  EXPECT_GT(std::abs(old_force_work() + force * relative), 1e-3);
}

// A penalty pair that sticks is an elastic spring: loaded and unloaded along the same path, the
// frictional dissipation of the two steps sums to zero (to round-off); each step's is not negative
// beyond it (the energy it stores is not dissipated).
TEST(CoulombFriction, PenaltyStickSpringDissipatesNothing)
{
  FrictionPair<2> p;
  CoulombFriction<2> friction({0.4});
  friction.set_states({0});
  const double c = 2.5; // eps / f
  Vector<double> lambda(2), u = p.start;
  lambda[0] = 10.;
  friction.start_step(p.pairs, p.start, {true}, lambda, p.block, {c});
  u[2] += 0.01; // the master node moves along x: a slip increment s
  const double s = friction.slip(0, 0, u);
  lambda[1]      = -c * s; // the stick spring's force
  const double loading =
      friction.dissipation(u, {true}, lambda, p.block, 1., 0.5, ContactFormulation::penalty);
  friction.start_step(p.pairs, u, {true}, lambda, p.block, {c});
  Vector<double> back = p.start, unloaded = lambda;
  unloaded[1] = 0.;
  const double unloading =
      friction.dissipation(back, {true}, unloaded, p.block, 1., 0.5, ContactFormulation::penalty);
  EXPECT_NEAR(loading, 0., 1e-15);
  EXPECT_NEAR(unloading, 0., 1e-15);
  EXPECT_NEAR(loading + unloading, 0., 1e-15);
}
} // namespace dyncontact::testing
