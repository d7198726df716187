// Unit tests of the contact constraint set apart from any mesh: its saddle-point rows against
// finite differences of the gap, and the active-set update on a toy set of pairs.
#include <dyncontact/contact/contact_border.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact/multiplier_block.h>
#include <dyncontact/contact/penalty_sizing.h>
#include <dyncontact/postprocess/contact_fields.h>
#include <dyncontact/postprocess/pairs_across_ranks.h>

#include <deal.II/lac/full_matrix.h>

#include <gtest/gtest.h>

namespace dyncontact::testing
{
namespace
{
/** Node `index` of a 2D toy problem: DoFs 2 index and 2 index + 1, at `position`. */
Node<2> toy_node(const unsigned int index, const Point<2>& position)
{
  return {static_cast<types::material_id>(index), position, {{2 * index, 2 * index + 1}}};
}

/** A pair of node `a` against node `b` (or, with b < 0, a wall through `wall`) along `normal`. */
ContactPair<2> toy_pair(const Node<2>& a,
                        const std::optional<Node<2>>& b,
                        const Tensor<1, 2>& normal,
                        const Point<2>& wall = Point<2>())
{
  ContactPair<2> pair;
  pair.slave = a;
  if (b)
    pair.masters = {{*b, 1.}};
  pair.wall_point        = wall;
  pair.normal            = normal;
  pair.penalty_stiffness = 0.;
  return pair;
}

/** The saddle-point matrix of `n_dofs` DoFs and the multipliers after them, dense. */
struct DenseRows : MultiplierRows
{
  DenseRows(const unsigned int n_dofs, const unsigned int n_multipliers)
      : n_dofs(n_dofs), matrix(n_dofs + n_multipliers, n_dofs + n_multipliers)
  {
  }
  void add_coupling(const unsigned int multiplier,
                    const types::global_dof_index dof,
                    const double value) override
  {
    matrix(n_dofs + multiplier, dof) += value;
    matrix(dof, n_dofs + multiplier) += value;
  }
  void add_row_coupling(const unsigned int multiplier,
                        const types::global_dof_index dof,
                        const double value) override
  {
    matrix(n_dofs + multiplier, dof) += value;
  }
  void add_column_coupling(const unsigned int multiplier,
                           const types::global_dof_index dof,
                           const double value) override
  {
    matrix(dof, n_dofs + multiplier) += value;
  }
  void add_multiplier_coupling(const unsigned int multiplier,
                               const unsigned int other,
                               const double value) override
  {
    matrix(n_dofs + multiplier, n_dofs + other) += value;
  }
  void add_diagonal(const unsigned int multiplier, const double value) override
  {
    matrix(n_dofs + multiplier, n_dofs + multiplier) += value;
  }
  unsigned int n_dofs;
  FullMatrix<double> matrix;
};
} // namespace

// The constraint row of an active pair is -dg/du (the symmetric system [K, -G^T; -G, -D] with
// G = dg/du), its residual -g, and an inactive pair's row is the trivial lambda = 0 with the given
// diagonal. Reference: central differences of ContactConstraints::gap(), exact for the gap, which
// is linear in u at fixed normals (bound 1e-10 absolute on coefficients of order 1). An oblique
// node-to-node pair and an oblique wall pair, at a displacement that leaves them penetrating. The
// three nodes are nodes 3, 1 and 5 of a volume of 6 nodes, so that the rows reach the volume DoFs
// through the contact border (which numbers volume nodes 1, 3, 5 as 0, 1, 2) and no other.
TEST(ContactConstraints, RowsAreMinusTheGapGradient)
{
  const Tensor<1, 2> n1({0.6, 0.8}), n2({-0.28, 0.96});
  const Node<2> a = toy_node(3, Point<2>(0., 0.)), b = toy_node(1, Point<2>(0.3, 0.4));
  const Node<2> c = toy_node(5, Point<2>(2., 1.));
  ContactConstraints<2> contact({toy_pair(a, b, n1), toy_pair(c, {}, n2, Point<2>(1.9, 1.5))},
                                ContactFormulation::lagrange_multiplier);
  const ContactBorder<2>& border = contact.border();
  ASSERT_EQ(border.n_nodes(), 3u);
  EXPECT_EQ(border.volume_node(0).dofs[0], 2u);
  EXPECT_EQ(border.volume_node(2).dofs[1], 11u);
  const unsigned int n_dofs = 12;
  Vector<double> u(n_dofs);
  u[6] = 0.5, u[7] = 0.6, u[10] = 0.3, u[11] = 0.9; // both pairs penetrate
  const auto gap = [&](const unsigned int k, const Vector<double>& volume)
  { return contact.gap(k, border.gather(volume)); };
  ASSERT_LT(gap(0, u), 0.);
  ASSERT_LT(gap(1, u), 0.);
  contact.update_active_set(contact.border().gather(u), 1e-12, 0.);
  ASSERT_TRUE(contact.is_active(0) && contact.is_active(1));

  std::vector<bool> coupled(n_dofs + 2, false);
  contact.for_each_coupling([&](const unsigned int multiplier, const types::global_dof_index dof)
                            { coupled[dof] = coupled[n_dofs + multiplier] = true; });
  DenseRows rows(n_dofs, contact.multiplier_block().n_multipliers());
  Vector<double> residual(2);
  contact.assemble_constraint_rows(border.gather(u), 7., &rows, residual);
  for (unsigned int k = 0; k < 2; ++k)
  {
    EXPECT_NEAR(residual[k], -gap(k, u), 1e-14);
    for (unsigned int dof = 0; dof < n_dofs; ++dof)
    {
      Vector<double> plus = u, minus = u;
      plus[dof] += 1e-3;
      minus[dof] -= 1e-3;
      const double gradient = (gap(k, plus) - gap(k, minus)) / 2e-3;
      EXPECT_NEAR(rows.matrix(n_dofs + k, dof), -gradient, 1e-10) << "pair " << k << " dof " << dof;
      EXPECT_NEAR(rows.matrix(dof, n_dofs + k), -gradient, 1e-10) << "pair " << k << " dof " << dof;
      if (gradient != 0.)
      {
        EXPECT_TRUE(coupled[dof]) << "the pattern misses dof " << dof;
      }
    }
    EXPECT_EQ(rows.matrix(n_dofs + k, n_dofs + k), 0.); // Lagrange multipliers: no compliance
  }
  // Nothing couples to the DoFs of the three nodes that are in no pair.
  for (const unsigned int dof : {0u, 1u, 4u, 5u, 8u, 9u})
    EXPECT_FALSE(coupled[dof]) << "dof " << dof;
}

// The contact forces G^T lambda of the border reach the volume at the pairs' nodes only, and
// balance: a node pair with multiplier 2 along n = (0.6, 0.8) pushes its slave node (volume node
// 4) by -2 n and its master node (volume node 2) by +2 n; the wall pair on volume node 0 by -3 n2.
// Exact in binary up to one rounding of each product (bound 1e-15).
TEST(ContactBorder, ContactForcesScatterToTheVolumeNodesOfThePairs)
{
  const Tensor<1, 2> n1({0.6, 0.8}), n2({0., 1.});
  ContactConstraints<2> contact(
      {toy_pair(toy_node(4, Point<2>(0., 0.)), toy_node(2, Point<2>(0., 1.)), n1),
       toy_pair(toy_node(0, Point<2>(1., 0.)), {}, n2, Point<2>(1., -1.))},
      ContactFormulation::lagrange_multiplier);
  Vector<double> penetrating(10);
  penetrating[9] = 2.; // the wall pair penetrates at rest
  contact.update_active_set(contact.border().gather(penetrating), 1e-12, 0.);
  Vector<double> multipliers(2);
  multipliers[0] = 2., multipliers[1] = 3.;
  contact.add_multiplier_increment(multipliers);
  Vector<double> border_force(contact.border().n_dofs()), force(10);
  contact.add_contact_forces(border_force);
  contact.border().scatter_add(border_force, force);
  const std::vector<double> expected = {0., -3., 0., 0., 1.2, 1.6, 0., 0., -1.2, -1.6};
  for (unsigned int i = 0; i < 10; ++i)
    EXPECT_NEAR(force[i], expected[i], 1e-15) << "dof " << i;
  // gather() then scatter() gives the volume vector back at the contact nodes, untouched elsewhere.
  DistributedVector volume(10);
  for (unsigned int i = 0; i < 10; ++i)
    volume[i] = i + 0.5;
  DistributedVector copy(10);
  contact.border().scatter(contact.border().gather(volume), copy);
  for (unsigned int i = 0; i < 10; ++i)
    EXPECT_EQ(copy[i], (i == 2 || i == 3 || i == 6 || i == 7) ? 0. : volume[i]) << "dof " << i;
}

// pairs_across_ranks() counts an active pair on the rank that owns its slave node when that rank
// owns none of its master nodes. Contact nodes 0-5 stand for volume nodes 1, 3, ..., 11 (DoFs
// 2, 3, 6, 7, ... of 24), so that a border DoF read as a volume DoF would count wrongly. Three
// active pairs and one inactive, each rank's owned DoFs as an IndexSet (one rank here:
// MPI_COMM_SELF sums nothing else in): a node-to-node pair 0 -> 1, a pair whose slave 2 sees a
// two-node master face {3, 4}, a wall pair of node 5, and an inactive pair 3 -> 0 (exact counts).
TEST(PairsAcrossRanks, CountsActivePairsWhoseWholeMasterSideAnotherRankOwns)
{
  const Tensor<1, 2> n({0., 1.});
  std::vector<Node<2>> nodes;
  for (unsigned int i = 0; i < 6; ++i)
    nodes.push_back(toy_node(2 * i + 1, Point<2>(i, 0.)));
  ContactPair<2> face_pair = toy_pair(nodes[2], nodes[3], n);
  face_pair.masters        = {{nodes[3], 0.5}, {nodes[4], 0.5}};
  ContactConstraints<2> contact({toy_pair(nodes[0], nodes[1], n),
                                 face_pair,
                                 toy_pair(nodes[5], {}, n, Point<2>(5., -1.)),
                                 toy_pair(nodes[3], nodes[0], n)},
                                ContactFormulation::lagrange_multiplier);
  Vector<double> u(24);
  for (const unsigned int slave : {0, 2, 5}) // move up through their master sides
    u[nodes[slave].dofs[1]] = 2.;
  contact.update_active_set(contact.border().gather(u), 1e-12, 0.);
  ASSERT_EQ(contact.n_active(), 3u);
  const auto count = [&](const std::vector<unsigned int>& owned_nodes)
  {
    IndexSet owned(24);
    for (const unsigned int node : owned_nodes)
      owned.add_range(nodes[node].dofs[0], nodes[node].dofs[1] + 1);
    return pairs_across_ranks(contact, owned, MPI_COMM_SELF);
  };
  EXPECT_EQ(count({0, 1, 2, 3, 4, 5}), 0u); // one rank owns everything
  EXPECT_EQ(count({0, 2, 5}), 2u);          // slaves here, every master elsewhere (wall: none)
  EXPECT_EQ(count({0, 2, 3}), 1u);          // node 3 of face {3, 4} is here: not across
  EXPECT_EQ(count({1, 3, 4}), 0u);          // the other rank's share: it owns no active slave
}

// The multiplier block's layout: consecutive multipliers per pair, as many as each pair declares
// (1 for a normal constraint, dim for a pair with tangential constraints).
TEST(MultiplierBlock, PairsOwnConsecutiveMultipliers)
{
  const MultiplierBlock block({1, 2, 1});
  EXPECT_EQ(block.n_pairs(), 3u);
  EXPECT_EQ(block.n_multipliers(), 4u);
  EXPECT_EQ(block.n_components(1), 2u);
  EXPECT_EQ(block.index(1, 1), 2u);
  EXPECT_EQ(block.index(2), 3u);
  EXPECT_THROW(MultiplierBlock({1, 0}), ExceptionBase);
}

// The active set on a toy set of four wall pairs in 1D terms (normal +y, gaps set by u): a pair
// enters when it penetrates beyond the gap tolerance, an open or barely touching one stays out,
// an active pair leaves when its multiplier is tensile beyond the force tolerance and stays with
// a compressive one; a second update with nothing new changes nothing. (Hughes et al. 1976.)
TEST(ContactConstraints, ActiveSetEntersOnPenetrationAndLeavesOnTension)
{
  const Tensor<1, 2> up({0., 1.});
  std::vector<ContactPair<2>> pairs;
  for (unsigned int k = 0; k < 4; ++k)
    pairs.push_back(toy_pair(toy_node(k, Point<2>(k, 0.)), {}, up, Point<2>(k, 0.)));
  ContactConstraints<2> contact(pairs, ContactFormulation::lagrange_multiplier);
  Vector<double> u(8);
  u[3] = 1e-3;  // pair 1 penetrates by 1e-3: enters
  u[1] = -1e-3; // pair 0 open
  u[5] = 1e-3;  // pair 2 penetrates: enters, then turns tensile below
  u[7] = 1e-3;  // pair 3 penetrates: enters, stays compressive
  EXPECT_TRUE(contact.update_active_set(contact.border().gather(u), 1e-6, 0.));
  EXPECT_FALSE(contact.is_active(0));
  EXPECT_TRUE(contact.is_active(1) && contact.is_active(2) && contact.is_active(3));

  Vector<double> multipliers(4);
  multipliers[1] = 2e-9;  // compressive
  multipliers[2] = -0.5;  // tensile beyond the tolerance 1e-6
  multipliers[3] = -1e-7; // tensile within the tolerance: stays
  contact.add_multiplier_increment(multipliers);
  Vector<double> closed(8); // all gaps zero now
  EXPECT_TRUE(contact.update_active_set(contact.border().gather(closed), 1e-6, 1e-6));
  EXPECT_FALSE(contact.is_active(0));
  EXPECT_TRUE(contact.is_active(1));
  EXPECT_FALSE(contact.is_active(2));
  EXPECT_EQ(contact.pair_force(2), 0.); // a released pair carries no force
  EXPECT_TRUE(contact.is_active(3));
  EXPECT_FALSE(contact.update_active_set(contact.border().gather(closed), 1e-6, 1e-6));
}
// The event work of a step (ContactFields::event_work()): (1/2) F_{n+1} g(u_n) for a pair that
// closed and (1/2) F_n g(u_{n+1}) for one that opened, nothing for a pair that stayed closed or
// open. Three wall pairs, by hand: pair 0 closes across the gap 0.02 with force 3 (work 0.03),
// pair 1 opens to the gap 0.01 from force 4 (work 0.02), pair 2 stays closed (force 5, gap 0).
// Exact in binary up to the round-off of the sums (bound 1e-15).
TEST(ContactFields, EventWorkIsHalfTheForceTimesTheGapTheEventCrosses)
{
  const Tensor<1, 2> up({0., 1.});
  std::vector<ContactPair<2>> pairs;
  for (unsigned int k = 0; k < 3; ++k)
    pairs.push_back(toy_pair(toy_node(k, Point<2>(k, 0.)), {}, up, Point<2>(k, 0.)));
  ContactConstraints<2> contact(pairs, ContactFormulation::lagrange_multiplier);
  // The step's start: pair 0 open at the gap 0.02, pairs 1 and 2 closed with forces 4 and 5.
  DistributedVector old_u(6), new_u(6);
  old_u[1] = -0.02;
  Vector<double> old_multipliers(3);
  old_multipliers[1] = 4., old_multipliers[2] = 5.;
  const typename ContactConstraints<2>::State old{
      {false, true, true}, old_multipliers, {0, 0, 0}, {}};
  // Its end: pair 0 closed with force 3, pair 1 open at the gap 0.01, pair 2 still closed.
  new_u[3] = -0.01;
  Vector<double> penetrating(6);
  penetrating[3] = -0.01, penetrating[1] = 1e-3, penetrating[5] = 1e-3;
  contact.update_active_set(contact.border().gather(penetrating), 1e-6, 0.);
  Vector<double> multipliers(3);
  multipliers[0] = 3., multipliers[2] = 5.;
  contact.add_multiplier_increment(multipliers);
  ASSERT_TRUE(contact.is_active(0) && !contact.is_active(1) && contact.is_active(2));
  const ContactFields<2> fields(contact);
  EXPECT_NEAR(fields.event_work(old_u, new_u, old), 0.5 * 3. * 0.02 + 0.5 * 4. * 0.01, 1e-15);
  // The force per multiplier scales both (the alpha members report f lambda).
  contact.set_force_per_multiplier(0.5);
  EXPECT_NEAR(fields.event_work(old_u, new_u, old), 0.5 * (0.03 + 0.02), 1e-15);
}

// Penalty springs against the time step: omega dt = dt sqrt(k / m_r), m_r = m_a m_b / (m_a + m_b)
// for a node pair and m_a against a wall, computed here by hand (masses 2 and 6: m_r = 1.5; wall
// node mass 4). Contact/penalty factor = auto lowers every spring by the one factor that puts the
// stiffest at omega dt = 1 when the bodies' mode is resolved (omega dt <= 2), and keeps them when
// it is not or when they are already soft. Round-off bound 1e-14 on numbers of order 1.
TEST(PenaltySizing, SpringFrequenciesAndAutomaticLowering)
{
  const Tensor<1, 2> up({0., 1.});
  const Node<2> a = toy_node(0, Point<2>(0., 0.)), b = toy_node(1, Point<2>(0., 0.));
  const Node<2> c = toy_node(2, Point<2>(1., 0.));
  auto node_pair = toy_pair(a, b, up), wall_pair = toy_pair(c, {}, up, Point<2>(1., -1.));
  node_pair.penalty_stiffness = 600.; // omega dt = 0.1 sqrt(600 / 1.5) = 2
  wall_pair.penalty_stiffness = 100.; // omega dt = 0.1 sqrt(100 / 4) = 0.5
  Vector<double> mass(6);
  mass[0] = mass[1] = 2., mass[2] = mass[3] = 6., mass[4] = mass[5] = 4.;
  const auto make = [&](const ContactFormulation formulation) {
    return ContactConstraints<2>({node_pair, wall_pair}, formulation);
  };

  EXPECT_EQ(penalty_spring_omega_dt(make(ContactFormulation::lagrange_multiplier), mass, 0.1), 0.);
  ContactConstraints<2> resolved = make(ContactFormulation::penalty);
  EXPECT_NEAR(penalty_spring_omega_dt(resolved, mass, 0.1), 2., 1e-14);
  EXPECT_NEAR(size_automatic_penalty(resolved, {mass, 0.1, 2.}), 0.25, 1e-14);
  EXPECT_NEAR(penalty_spring_omega_dt(resolved, mass, 0.1), 1., 1e-14);
  EXPECT_NEAR(resolved.candidate_pairs()[1].penalty_stiffness, 25., 1e-12);

  ContactConstraints<2> quasi_static = make(ContactFormulation::penalty);
  EXPECT_EQ(size_automatic_penalty(quasi_static, {mass, 0.1, 2.5}), 1.);
  EXPECT_NEAR(penalty_spring_omega_dt(quasi_static, mass, 0.1), 2., 1e-14);
  ContactConstraints<2> soft = make(ContactFormulation::penalty);
  EXPECT_EQ(size_automatic_penalty(soft, {mass, 0.04, 0.5}), 1.); // stiffest at omega dt = 0.8
}
} // namespace dyncontact::testing
