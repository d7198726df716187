// Unit tests of the contact-dynamics treatments on two masses, apart from any mesh or solver: the
// paper's rate correction (Taylor & Papadopoulos 1993, eqs. 21-22) must leave no normal velocity
// or acceleration jump across an active pair and conserve linear momentum, which together fix the
// corrected normal rates of both nodes to the mass-weighted means of the classical ones: an
// independent reference computed here from the classical rates alone. Unequal masses (1 and 3)
// catch a correction that weights both sides alike, and gamma = 0.6, beta = 0.3 one that uses the
// trapezoidal coefficients.
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact_dynamics/contact_dynamics.h>

#include <array>
#include <cmath>
#include <gtest/gtest.h>

namespace dyncontact::testing
{
namespace
{
/**
 * One step of two point masses (or one against a wall) meeting along `normal`: the old state, the
 * converged new displacement with the pair closed, the predictor increment and the classical
 * rates. In 2D the tangential components differ between the nodes, which the correction must
 * keep. Both nodes are contact nodes with the DoFs 0 .. 2 dim - 1, so these vectors are the
 * contact border's (ContactBorder numbers its nodes by their first DoF) and the treatments, which
 * work on border vectors, take them as they are.
 */
template <int dim>
struct TwoMassStep
{
  TwoMassStep(const Tensor<1, dim>& normal, const bool against_wall)
      : rates{0.1, 0.3, 0.6}, mass(2 * dim), old_u(2 * dim), old_v(2 * dim), old_a(2 * dim),
        new_u(2 * dim), increment(2 * dim), v(2 * dim), a(2 * dim)
  {
    ContactPair<dim> pair;
    pair.slave = {0, Point<dim>(), {}};
    for (unsigned int d = 0; d < dim; ++d)
      pair.slave.dofs[d] = d;
    if (against_wall)
      pair.wall_point = Point<dim>() + 0.05 * normal;
    else
    {
      Node<dim> node_b{1, Point<dim>(), {}};
      for (unsigned int d = 0; d < dim; ++d)
        node_b.dofs[d] = dim + d;
      pair.masters = {{node_b, 1.}};
    }
    pair.normal            = normal;
    pair.penalty_stiffness = 0.;
    contact = std::make_unique<ContactConstraints<dim>>(std::vector<ContactPair<dim>>{pair},
                                                        ContactFormulation::lagrange_multiplier);
    for (unsigned int i = 0; i < 2 * dim; ++i)
    {
      mass[i]  = i < dim ? 1. : 3.;
      old_v[i] = i < dim ? 2. - 0.3 * i : -1. + 0.2 * i;
      old_a[i] = i < dim ? 0.5 + 0.1 * i : -0.2 - 0.4 * i;
    }
    // Closed at t_{n+1}: both nodes at 0.05 n (the wall's position), tangentially apart.
    for (unsigned int d = 0; d < dim; ++d)
      new_u[d] = new_u[dim + d] = 0.05 * normal[d];
    if constexpr (dim == 2)
    {
      const Tensor<1, dim> tangent = cross_product_2d(normal);
      for (unsigned int d = 0; d < dim; ++d)
      {
        new_u[d]       = 0.05 * normal[d] + 0.02 * tangent[d];
        new_u[dim + d] = 0.05 * normal[d] - 0.01 * tangent[d];
      }
    }
    Vector<double> penetrating(2 * dim);
    for (unsigned int d = 0; d < dim; ++d)
      penetrating[d] = 0.2 * normal[d];
    contact->update_active_set(contact->border().gather(penetrating), 1e-12, 0.);
    for (unsigned int i = 0; i < 2 * dim; ++i)
    {
      increment[i] = new_u[i] - rates.predicted_displacement(old_u[i], old_v[i], old_a[i]);
      a[i]         = rates.acceleration(increment[i]);
      v[i]         = rates.velocity(old_v[i], old_a[i], a[i]);
    }
  }

  /** n . f at node 0 (A) or 1 (B). */
  double normal_part(const Vector<double>& field, const unsigned int node, const Tensor<1, dim>& n)
  {
    double value = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      value += n[d] * field[node * dim + d];
    return value;
  }

  void correct(const ContactDynamicsKind kind)
  {
    create_contact_dynamics<dim>(kind)->correct_rates(
        rates, *contact, mass, {old_u, old_v, old_a, new_u, increment, is_fixed}, v, a);
  }

  RateMap rates;
  std::unique_ptr<ContactConstraints<dim>> contact;
  Vector<double> mass, old_u, old_v, old_a, new_u, increment, v, a;
  std::vector<bool> is_fixed = std::vector<bool>(2 * dim, false); ///< per DoF (none by default)
};

/**
 * The corrected normal rates of both nodes equal the mass-weighted means of the classical ones
 * (relative 1e-13: a few roundings of numbers of order 10); tangential components unchanged
 * (exactly up to the normal's rounding, 1e-14). Taylor-Papadopoulos corrects velocities and
 * accelerations; the velocity update (Laursen & Love 2002) corrects the velocities only and keeps
 * the accelerations bit for bit.
 */
template <int dim>
void expect_mean_normal_rates(const Tensor<1, dim>& normal, const ContactDynamicsKind kind)
{
  TwoMassStep<dim> step(normal, false);
  ASSERT_TRUE(step.contact->is_active(0));
  const Vector<double> classical_v = step.v, classical_a = step.a;
  step.correct(kind);
  std::vector<std::pair<const Vector<double>*, const Vector<double>*>> corrected_fields{
      {&step.v, &classical_v}};
  if (kind == ContactDynamicsKind::taylor_papadopoulos)
    corrected_fields.emplace_back(&step.a, &classical_a);
  else
    for (unsigned int i = 0; i < 2 * dim; ++i)
      EXPECT_EQ(step.a[i], classical_a[i]);
  for (const auto& [corrected, classical] : corrected_fields)
  {
    const double mean = (1. * step.normal_part(*classical, 0, normal) +
                         3. * step.normal_part(*classical, 1, normal)) /
                        4.;
    const double scale = std::abs(step.normal_part(*classical, 0, normal)) + std::abs(mean);
    EXPECT_NEAR(step.normal_part(*corrected, 0, normal), mean, 1e-13 * scale);
    EXPECT_NEAR(step.normal_part(*corrected, 1, normal), mean, 1e-13 * scale);
    for (unsigned int i = 0; i < 2 * dim; ++i)
    {
      // The change is along n only.
      const unsigned int node = i / dim, d = i % dim;
      const double shift =
          step.normal_part(*corrected, node, normal) - step.normal_part(*classical, node, normal);
      EXPECT_NEAR((*corrected)[i], (*classical)[i] + shift * normal[d], 1e-14 * (1. + scale));
    }
  }
}
} // namespace

TEST(ContactDynamics, TaylorPapadopoulosGivesBothNodesTheMassWeightedMeanNormalRates1D)
{
  expect_mean_normal_rates<1>(Tensor<1, 1>({1.}), ContactDynamicsKind::taylor_papadopoulos);
}

TEST(ContactDynamics, TaylorPapadopoulosGivesBothNodesTheMassWeightedMeanNormalRates2D)
{
  // An oblique normal: the correction acts along it and keeps the tangential rates.
  expect_mean_normal_rates<2>(Tensor<1, 2>({0.6, 0.8}), ContactDynamicsKind::taylor_papadopoulos);
}

// The velocity update's defining property (Laursen & Love 2002): after the step the pair's
// relative normal velocity is zero, by a momentum-conserving jump, the mass-weighted mean.
TEST(ContactDynamics, VelocityUpdateGivesBothNodesTheMassWeightedMeanNormalVelocity)
{
  expect_mean_normal_rates<1>(Tensor<1, 1>({1.}), ContactDynamicsKind::velocity_update);
  expect_mean_normal_rates<2>(Tensor<1, 2>({0.6, 0.8}), ContactDynamicsKind::velocity_update);
}

// Against a rigid wall (infinite weight) the corrected normal rates of the node are the wall's,
// zero; the classical ones are not (that is the defect the correction removes).
TEST(ContactDynamics, TaylorPapadopoulosStopsANodeAgainstAWall)
{
  const Tensor<1, 2> normal({0.6, 0.8});
  TwoMassStep<2> step(normal, true);
  ASSERT_TRUE(step.contact->is_active(0));
  EXPECT_GT(std::abs(step.normal_part(step.v, 0, normal)), 0.1);
  EXPECT_GT(std::abs(step.normal_part(step.a, 0, normal)), 0.1);
  step.correct(ContactDynamicsKind::taylor_papadopoulos);
  EXPECT_NEAR(step.normal_part(step.v, 0, normal), 0., 1e-13);
  EXPECT_NEAR(step.normal_part(step.a, 0, normal), 0., 1e-12);
}

// A fixed DoF (u_r = 0 of a node on the symmetry axis) takes no part in the correction: with an
// oblique normal and node 0's first component fixed (its classical rates zero there), the fixed
// component keeps its zero rates exactly and the free components alone close the normal jumps
// (1e-13 relative, as above); before the fixed DoFs were excluded, the non-matching spheres' axis
// node got a radial velocity of 1.4e-3 that outlived the contact.
TEST(ContactDynamics, TaylorPapadopoulosLeavesFixedDofsAtRest)
{
  const Tensor<1, 2> normal({0.6, 0.8});
  TwoMassStep<2> step(normal, false);
  // The fixed DoF's state: at rest and not moved by the step (increment zero), as Simulation keeps
  // it.
  step.is_fixed[0] = true;
  step.old_v[0] = step.old_a[0] = step.new_u[0] = step.increment[0] = 0.;
  step.v[0] = step.a[0] = 0.;
  step.correct(ContactDynamicsKind::taylor_papadopoulos);
  EXPECT_EQ(step.v[0], 0.);
  EXPECT_EQ(step.a[0], 0.);
  const double scale = std::abs(step.normal_part(step.v, 1, normal)) + 1.;
  EXPECT_NEAR(
      step.normal_part(step.v, 0, normal), step.normal_part(step.v, 1, normal), 1e-13 * scale);
  EXPECT_NEAR(step.normal_part(step.a, 0, normal),
              step.normal_part(step.a, 1, normal),
              1e-13 * (std::abs(step.normal_part(step.a, 1, normal)) + 1.));
}

// Contact/dynamics = none keeps the classical rates, jumps included.
TEST(ContactDynamics, NoneKeepsTheClassicalRates)
{
  TwoMassStep<1> step(Tensor<1, 1>({1.}), false);
  const Vector<double> classical_v = step.v, classical_a = step.a;
  step.correct(ContactDynamicsKind::none);
  for (unsigned int i = 0; i < 2; ++i)
  {
    EXPECT_EQ(step.v[i], classical_v[i]);
    EXPECT_EQ(step.a[i], classical_a[i]);
  }
  EXPECT_GT(std::abs(step.v[1] - step.v[0]), 0.1); // the jump the paper's correction removes
}
// Mass redistribution: a massless node's rates are the step's backward differences,
// v = (u_{n+1} - u_n)/dt and a = (v_{n+1} - v_n)/dt, computed here independently; the node with
// mass keeps its classical rates bit for bit. 1e-13 relative: two roundings of numbers of order 10.
TEST(ContactDynamics, MassRedistributionGivesMasslessNodesTheirBackwardDifferences)
{
  TwoMassStep<2> step(Tensor<1, 2>({0.6, 0.8}), false);
  for (unsigned int d = 0; d < 2; ++d)
    step.mass[d] = 0.; // node 0 massless, node 1 keeps 3
  const Vector<double> classical_v = step.v, classical_a = step.a;
  step.correct(ContactDynamicsKind::mass_redistribution);
  for (unsigned int d = 0; d < 2; ++d)
  {
    const double dt = step.rates.time_step;
    const double v  = (step.new_u[d] - step.old_u[d]) / dt;
    EXPECT_NEAR(step.v[d], v, 1e-13 * (std::abs(v) + 1.));
    EXPECT_NEAR(step.a[d], (v - step.old_v[d]) / dt, 1e-13 * (std::abs(v) / dt + 1.));
    EXPECT_EQ(step.v[2 + d], classical_v[2 + d]);
    EXPECT_EQ(step.a[2 + d], classical_a[2 + d]);
  }
  EXPECT_TRUE(create_contact_dynamics<2>(ContactDynamicsKind::mass_redistribution)
                  ->contact_nodes_massless());
  EXPECT_FALSE(create_contact_dynamics<2>(ContactDynamicsKind::taylor_papadopoulos)
                   ->contact_nodes_massless());
}

// Contact-stabilized Newmark (Deuflhard, Krause & Ertel 2008): two masses (1 and 3) on a line,
// 0.01 apart and closing at relative speed 1, so that u_n + dt v_n (dt = 0.1) overlaps by 0.09.
// The predictor's position part is projected onto g >= 0 in the mass norm: the pair closes
// exactly, the lighter mass moves 3 times as far as the heavier one, and the momentum of the
// shifts is zero; the rest of the predictor is Newmark's with a_n. Where a contact force acts at
// t_n, a_n is replaced by the free acceleration (W_n - Q(u_n)) / m. Bounds: 1e-15 absolute on
// positions of order 1 (a few roundings), exact where nothing is replaced.
TEST(ContactDynamics, ContactStabilizedProjectsThePredictorAndDropsTheOldContactForce)
{
  ContactPair<1> pair;
  pair.slave             = {0, Point<1>(0.), {{0}}};
  pair.masters           = {{Node<1>{1, Point<1>(0.01), {{1}}}, 1.}};
  pair.normal            = Tensor<1, 1>({1.});
  pair.penalty_stiffness = 0.;
  ContactConstraints<1> contact({pair}, ContactFormulation::lagrange_multiplier);
  const RateMap rates{0.1, 0.25, 0.5};
  Vector<double> mass(2), u(2), v(2), a(2), internal_force(2), external_force(2);
  mass[0]               = 1.;
  mass[1]               = 3.;
  v[0]                  = 0.75; // momentum 0.75 - 0.75 = 0
  v[1]                  = -0.25;
  a[0]                  = 0.5;
  a[1]                  = -0.1;
  internal_force[0]     = 0.2;
  internal_force[1]     = -0.3;
  const auto stabilized = create_contact_dynamics<1>(ContactDynamicsKind::contact_stabilized);
  const std::vector<bool> no_fixed_dofs(2, false);
  for (const bool with_old_force : {false, true})
  {
    if (with_old_force)
    {
      Vector<double> multiplier(1);
      multiplier[0] = 2.;
      contact.add_multiplier_increment(multiplier);
    }
    Vector<double> acceleration = a, predictor(2);
    for (unsigned int i = 0; i < 2; ++i)
      predictor[i] = rates.predicted_displacement(u[i], v[i], a[i]);
    stabilized->adjust_predictor(rates,
                                 contact,
                                 mass,
                                 {u, v, internal_force, external_force, no_fixed_dofs},
                                 acceleration,
                                 predictor);
    Vector<double> expected_acceleration = a;
    if (with_old_force)
      for (unsigned int i = 0; i < 2; ++i)
        expected_acceleration[i] = (external_force[i] - internal_force[i]) / mass[i];
    // The projection of u + dt v = (0.075, -0.025): overlap 0.09, split 3 : 1 by the masses.
    const std::array<double, 2> shift{{-0.0675, 0.0225}};
    for (unsigned int i = 0; i < 2; ++i)
    {
      EXPECT_EQ(acceleration[i], expected_acceleration[i]) << with_old_force;
      EXPECT_NEAR(predictor[i],
                  rates.predicted_displacement(u[i], v[i], expected_acceleration[i]) + shift[i],
                  1e-15)
          << with_old_force;
    }
    Vector<double> projected = u;
    projected.add(rates.time_step, v);
    projected[0] += shift[0];
    projected[1] += shift[1];
    EXPECT_NEAR(contact.gap(0, projected), 0., 1e-15);
    EXPECT_NEAR(mass[0] * shift[0] + mass[1] * shift[1], 0., 1e-15);
  }
  EXPECT_DOUBLE_EQ(stabilized->contact_force_factor(rates), 0.5);
}

// Persistency (Laursen & Chawla 1997): two masses 0.01 apart on a line. Closing at relative speed
// 1 with dt = 0.1, the predictor overlaps them, so the pair persists: its constraint becomes the
// gap rate, g_{n+1} - g_n >= 0 with g_n = 0.01, and it enters the active set at g = 0.005 > 0
// (a gap decrease) and is driven back to g = 0.01 (residual -(g - g_n)). Opening, the predictor
// keeps them apart and the pair keeps the impenetrability condition g >= 0. Exact: a subtraction
// of numbers of order 0.01 (1e-17).
TEST(ContactDynamics, PersistencyTurnsThePairsPredictedToCloseIntoGapRateConstraints)
{
  ContactPair<1> pair;
  pair.slave             = {0, Point<1>(0.), {{0}}};
  pair.masters           = {{Node<1>{1, Point<1>(0.01), {{1}}}, 1.}};
  pair.normal            = Tensor<1, 1>({1.});
  pair.penalty_stiffness = 0.;
  const auto persistency = create_contact_dynamics<1>(ContactDynamicsKind::persistency);
  Vector<double> u(2), halfway(2), predictor(2), residual(1);
  halfway[0] = 0.005; // the gap halved: 0.005
  for (const double approach_speed : {1., -1.})
  {
    ContactConstraints<1> contact({pair}, ContactFormulation::lagrange_multiplier);
    Vector<double> v(2);
    v[0]      = 0.75 * approach_speed;
    v[1]      = -0.25 * approach_speed;
    predictor = u;
    predictor.add(0.1, v);
    const auto persistent = persistency->persistent_pairs(contact, predictor);
    ASSERT_EQ(persistent.size(), 1u);
    const bool closing = approach_speed > 0.;
    EXPECT_EQ(persistent[0], closing) << approach_speed;
    contact.hold_gaps(contact.border().gather(u), persistent);
    EXPECT_EQ(contact.update_active_set(contact.border().gather(halfway), 1e-12, 0.), closing)
        << approach_speed;
    contact.assemble_constraint_rows(halfway, 1., nullptr, residual);
    if (closing)
    {
      EXPECT_NEAR(residual[0], 0.005, 1e-17);
    }
  }
}

// Node-to-segment pairs sharing a master face: two slave nodes against the same three master nodes
// (quadratic shape-function weights, one negative), along different normals, with unequal masses.
// The correction must close both pairs' normal velocity and acceleration jumps at once (a pairwise
// correction would reopen the first pair's jump when correcting the second) and conserve linear
// momentum: sum_j m_j (corrected - classical) = 0 per component, since each pair's coefficients
// sum to zero. Bounds: 1e-12 relative to the rates' scale (order 10), a few roundings of a 2 x 2
// solve and of sums over five nodes. Every node is a contact node with DoFs 0 .. 9, so the vectors
// are the contact border's as they are.
TEST(ContactDynamics, TaylorPapadopoulosClosesPairsSharingAMasterFace)
{
  constexpr unsigned int n_nodes = 5; // masters 0, 1, 2; slaves 3, 4
  std::vector<Node<2>> nodes;
  for (unsigned int j = 0; j < n_nodes; ++j)
    nodes.push_back(
        {static_cast<types::material_id>(j < 3 ? 1 : 0), Point<2>(), {{2 * j, 2 * j + 1}}});
  const std::array<Tensor<1, 2>, 2> normals{
      {Tensor<1, 2>({0.6, 0.8}), Tensor<1, 2>({-0.28, 0.96})}};
  const std::array<std::array<double, 3>, 2> weights{{{{0.6, 0.5, -0.1}}, {{-0.05, 0.3, 0.75}}}};
  std::vector<ContactPair<2>> pairs(2);
  for (unsigned int k = 0; k < 2; ++k)
  {
    pairs[k].slave = nodes[3 + k];
    for (unsigned int i = 0; i < 3; ++i)
      pairs[k].masters.push_back({nodes[i], weights[k][i]});
    pairs[k].normal            = normals[k];
    pairs[k].penalty_stiffness = 0.;
  }
  ContactConstraints<2> contact(pairs, ContactFormulation::lagrange_multiplier);

  const RateMap rates{0.1, 0.3, 0.6};
  Vector<double> mass(2 * n_nodes), old_u(2 * n_nodes), old_v(2 * n_nodes), old_a(2 * n_nodes),
      new_u(2 * n_nodes), increment(2 * n_nodes), v(2 * n_nodes), a(2 * n_nodes);
  const std::vector<bool> no_fixed_dofs(2 * n_nodes, false);
  for (unsigned int i = 0; i < 2 * n_nodes; ++i)
  {
    mass[i]  = 1. + 0.5 * (i / 2);
    old_v[i] = 2. - 0.7 * i + 0.03 * i * i;
    old_a[i] = -1. + 0.4 * i - 0.05 * i * i;
    new_u[i] = 0.01 * i - 0.002 * i * i;
  }
  // Both pairs closed at t_{n+1}: each slave node on its master point along n, moved tangentially.
  for (unsigned int k = 0; k < 2; ++k)
  {
    const Tensor<1, 2> tangent = cross_product_2d(normals[k]);
    Tensor<1, 2> master_point;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int d = 0; d < 2; ++d)
        master_point[d] += weights[k][i] * new_u[2 * i + d];
    for (unsigned int d = 0; d < 2; ++d)
      new_u[2 * (3 + k) + d] = master_point[d] + 0.02 * (k + 1.) * tangent[d];
  }
  Vector<double> penetrating = new_u;
  for (unsigned int k = 0; k < 2; ++k)
    for (unsigned int d = 0; d < 2; ++d)
      penetrating[2 * (3 + k) + d] += 0.2 * normals[k][d];
  contact.update_active_set(contact.border().gather(penetrating), 1e-12, 0.);
  ASSERT_TRUE(contact.is_active(0) && contact.is_active(1));
  for (unsigned int k = 0; k < 2; ++k)
    ASSERT_NEAR(contact.gap(k, new_u), 0., 1e-15);
  for (unsigned int i = 0; i < 2 * n_nodes; ++i)
  {
    increment[i] = new_u[i] - rates.predicted_displacement(old_u[i], old_v[i], old_a[i]);
    a[i]         = rates.acceleration(increment[i]);
    v[i]         = rates.velocity(old_v[i], old_a[i], a[i]);
  }
  const Vector<double> classical_v = v, classical_a = a;
  for (unsigned int k = 0; k < 2; ++k)
    EXPECT_GT(std::abs(pairs[k].normal_jump(classical_v)), 0.1); // the jumps to be removed

  create_contact_dynamics<2>(ContactDynamicsKind::taylor_papadopoulos)
      ->correct_rates(
          rates, contact, mass, {old_u, old_v, old_a, new_u, increment, no_fixed_dofs}, v, a);
  const double scale = classical_a.linfty_norm() + classical_v.linfty_norm();
  for (unsigned int k = 0; k < 2; ++k)
  {
    EXPECT_NEAR(pairs[k].normal_jump(v), 0., 1e-12 * scale) << "pair " << k;
    EXPECT_NEAR(pairs[k].normal_jump(a), 0., 1e-12 * scale) << "pair " << k;
  }
  for (unsigned int d = 0; d < 2; ++d)
  {
    double momentum_change = 0., force_change = 0.;
    for (unsigned int j = 0; j < n_nodes; ++j)
    {
      momentum_change += mass[2 * j + d] * (v[2 * j + d] - classical_v[2 * j + d]);
      force_change += mass[2 * j + d] * (a[2 * j + d] - classical_a[2 * j + d]);
    }
    EXPECT_NEAR(momentum_change, 0., 1e-12 * scale) << "component " << d;
    EXPECT_NEAR(force_change, 0., 1e-12 * scale) << "component " << d;
  }
}
} // namespace dyncontact::testing
