// Contact between flat faces (issue 25, item 6): two rods end-on, prm/rods_flat_ends.prm on
// meshes/two_rods.geo (rod radius 0.5, NR = 3 cells across, so 7 Q2 nodes on each end face).
//  - Set-up: with the end faces touching their node centroids coincide, which once made the
//    node-to-node approach direction 0/0 = NaN and no pair at all (a segmentation fault at the
//    first history row). Every facing node must be paired with a finite normal, in both
//    discretizations; a declared pair that makes no candidate pair is an InputError naming it.
//  - Runs: the rod impact against 1D wave theory (shared case 21), and node-to-segment between
//    the flat ends against node-to-node and energy conservation (shared case 22).
#include <dyncontact/contact/contact_factory.h>
#include <dyncontact/models/mesh_model.h>
#include <dyncontact/simulation/parameter_reader.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

#include "case_run.h"
#include "mesh_set_up.h"

namespace dyncontact::testing
{
namespace
{
/// The rods, shortened to 10 cells each: the set-up tests need only the end faces.
const std::string short_rods = "Mesh/geo parameters=NL: 10";

/// 1D wave theory of the rods (E = rho = v = 1, c0 = 1, A = pi R^2 with R = 0.5, L = 10):
/// contact force rho c0 A v / 2 while the waves cross the rods (to 2 L / c0 = 20), and the
/// striker's momentum rho A L v, all of it in rod 2 after the release.
const double rod_area         = M_PI * 0.25;
const double one_d_force      = rod_area / 2.;
const double striker_momentum = rod_area * 10.;
const double one_d_release    = 20.;

/** The mean of history column `name` over the rows with time in [`from`, `to`]. */
double window_mean(const History& history, const std::string& name, double from, double to)
{
  const auto times  = history.column("time");
  const auto values = history.column(name);
  double sum        = 0.;
  unsigned int rows = 0;
  for (unsigned int row = 0; row < times.size(); ++row)
    if (times[row] >= from && times[row] <= to)
    {
      sum += values[row];
      ++rows;
    }
  EXPECT_GT(rows, 0u);
  return sum / rows;
}

/** The time of the last history row with an active pair. */
double last_contact_time(const History& history)
{
  const auto times  = history.column("time");
  const auto active = history.column("active_constraints");
  double last       = 0.;
  for (unsigned int row = 0; row < times.size(); ++row)
    if (active[row] > 0.)
      last = times[row];
  return last;
}

/** The rods 0.001 apart on Newmark (beta = 1/4, gamma = 1/2) to t = 14, in `discretization`. */
MeshRun rods_on_newmark(const std::string& discretization)
{
  return run_mesh_case("prm/rods_flat_ends.prm",
                       {"Mesh/geo parameters=Gap: 0.001",
                        "Time integration/integrator=newmark",
                        "Time integration/beta=0.25",
                        "Time integration/gamma=0.5",
                        "Time integration/end time=14",
                        "Contact/discretization=" + discretization});
}
} // namespace

// Touching end faces (Gap 0, centroids coincide) and a gap of 0.001 (centroids 0.001 apart along
// the axis), node-to-node and node-to-segment: 7 pairs, one per node of the slave end face, each
// with the axis direction (0, 1) as its normal (the faces are flat and mirrored: exact up to the
// round-off of normalizing, bound 1e-12), a reference gap of exactly 0 resp. 0.001 (1e-12), and
// for node-to-segment a master point at the mirror node: its weight 1 to 1e-9 (measured 2e-11:
// gmsh places the mirrored nodes at the same r only to about 3e-12 of the rod radius, and the
// weight changes by that over the face length 1/6).
TEST(FlatFaces, RodEndsPairEveryFacingNodeAlongTheAxis)
{
  for (const std::string discretization : {"node-to-node", "node-to-segment"})
    for (const double gap : {0., 0.001})
    {
      const MeshSetUp rods("prm/rods_flat_ends.prm",
                           {short_rods + ", Gap: " + format_number(gap),
                            "Contact/discretization=" + discretization});
      const Contact<2> contact = rods.contact();
      ASSERT_TRUE(contact.surfaces);
      const auto& pairs = contact.constraints->candidate_pairs();
      ASSERT_EQ(pairs.size(), 7u) << discretization << ", gap " << gap;
      for (const ContactPair<2>& pair : pairs)
      {
        const std::string where = discretization + ", gap " + format_number(gap) +
                                  ", slave node at r = " + format_number(pair.slave.position[0]);
        ASSERT_TRUE(std::isfinite(pair.normal[0]) && std::isfinite(pair.normal[1])) << where;
        EXPECT_NEAR(pair.normal[0], 0., 1e-12) << where;
        EXPECT_NEAR(pair.normal[1], 1., 1e-12) << where;
        EXPECT_NEAR(pair.reference_gap(), gap, 1e-12) << where;
        double largest_weight = 0.;
        for (const MasterNode<2>& master : pair.masters)
          largest_weight = std::max(largest_weight, master.weight);
        EXPECT_NEAR(largest_weight, 1., 1e-9) << where;
      }
    }
}

// End faces that point the same way (the top of rod 1 against the top of rod 2, both outward
// normals +z): no approach direction, hence no pair. An InputError naming the declared pair, not
// a run without contact.
TEST(FlatFaces, FacesPointingTheSameWayAreAnInputErrorNamingThePair)
{
  const MeshSetUp rods("prm/rods_flat_ends.prm", {short_rods, "Contact/Pair 1/master boundary=7"});
  const std::string message = rods.contact_error();
  EXPECT_NE(message.find("Contact/Pair 1"), std::string::npos) << message;
  EXPECT_NE(message.find("do not face each other"), std::string::npos) << message;
}

// A declared pair whose set-up makes no candidate pair is an InputError naming it, in both
// discretizations:
//  - node-to-node, the bottom face of the block (outward normal -z) against the sphere above it
//    (prm/sphere_on_block.prm's mesh): the approach direction (centroid to centroid) is +z, and
//    no node of the bottom face faces the sphere;
//  - node-to-segment, the top of rod 1 against the far end of rod 2, 10 away: no slave node lies
//    within the search radius of the master face.
TEST(FlatFaces, DeclaredPairWithoutCandidatesIsAnInputErrorNamingThePair)
{
  const MeshSetUp block("prm/sphere_on_block.prm",
                        {"Mesh/geo parameters=Gap: 2, Refinement: 0",
                         "Contact/discretization=node-to-node",
                         "Contact/Pair 1/slave boundary=5",
                         "Contact/Pair 1/master boundary=2"});
  const std::string node_to_node = block.contact_error();
  EXPECT_NE(node_to_node.find("Contact/Pair 1"), std::string::npos) << node_to_node;
  EXPECT_NE(node_to_node.find("node-to-node contact has no candidate pairs"), std::string::npos)
      << node_to_node;

  const MeshSetUp rods(
      "prm/rods_flat_ends.prm",
      {short_rods, "Contact/discretization=node-to-segment", "Contact/Pair 1/master boundary=7"});
  const std::string node_to_segment = rods.contact_error();
  EXPECT_NE(node_to_segment.find("Contact/Pair 1"), std::string::npos) << node_to_segment;
  EXPECT_NE(node_to_segment.find("node-to-segment contact has no candidate pairs"),
            std::string::npos)
      << node_to_segment;
}
// Shared case 21: prm/rods_flat_ends.prm as shipped (end faces touching at t = 0, node-to-node,
// the default integrator, to t = 25), which crashed (0 pairs). Against 1D wave theory:
//  - one contact episode from the first step, released between 2 L / c0 = 20 and 21: the
//    continuum's front disperses (radial inertia, Pochhammer-Chree), so it arrives later than a
//    bar's (measured 20.3);
//  - the mean contact force over [2, 18] (the plateau, after the first ringing) within 1 % of
//    rho c0 A v / 2 = 0.3927: the ringing about the plateau (period about 2 pi R / c ~ 3) averages
//    out over the window (measured -0.14 %; -0.11 % on the trapezoidal rule, -0.15 % on
//    generalized-alpha 0.8);
//  - total momentum conserved to 1e-10 of the striker's (no external force; Newton's round-off);
//    at the end rod 2 carries the striker's momentum and rod 1 none, each within 3 % of it: the
//    dispersed tail of the wave leaves rod 1 a little of it (measured 1.8 %), which a bar does not;
//  - the energy never above its start beyond round-off (1e-9, the Newton tolerance's share), and
//    at the end within 1 % below it (measured -0.23 %: the default, mass redistribution on Newmark
//    gamma = 0.502, damps the highest modes slightly; on the trapezoidal rule it ended +2.3e-6, the
//    release's opening work, which Guards/contact event tolerance bounds to 1e-4; -0.19 % on the
//    previous default, generalized-alpha 0.8).
TEST(FlatFaces, RodsTouchingAtTheStartGiveTheOneDimensionalImpact)
{
  const MeshRun run         = run_mesh_case("prm/rods_flat_ends.prm");
  const History& history    = run.history();
  const unsigned int end    = history.n_rows() - 1;
  const double start_energy = history.value(0, "total_energy");
  EXPECT_NEAR(history.value(end, "time"), 25., 1e-9);
  EXPECT_EQ(contact_episodes(history), 1u);
  EXPECT_GT(history.value(1, "active_constraints"), 0.);
  EXPECT_GE(last_contact_time(history), one_d_release);
  EXPECT_LE(last_contact_time(history), one_d_release + 1.);
  EXPECT_NEAR(window_mean(history, "contact_force", 2., 18.) / one_d_force, 1., 0.01);
  for (unsigned int row = 0; row <= end; ++row)
  {
    EXPECT_NEAR(history.value(row, "momentum_1") + history.value(row, "momentum_2"),
                striker_momentum,
                1e-10 * striker_momentum);
    EXPECT_LE(history.value(row, "total_energy"), start_energy * (1. + 1e-9));
  }
  EXPECT_NEAR(history.value(end, "momentum_1"), 0., 0.03 * striker_momentum);
  EXPECT_NEAR(history.value(end, "momentum_2"), striker_momentum, 0.03 * striker_momentum);
  EXPECT_GE(history.value(end, "total_energy"), 0.99 * start_energy);
}

// Shared case 22, command B to t = 14: node-to-segment between the flat rod ends (0.001 apart),
// on the energy-conserving trapezoidal rule. Once the slave nodes are closed the active set stays
// the same and the total energy must stay what it is after the first contact step (the modified
// scheme's impact loss, 3.5e-3); its largest change over the rows after that within 1e-9 of it
// (measured 3.4e-11: Newton's tolerance, 1e-10 of the forces). With master points held over the
// step an antisymmetric sliding mode of the rims grew from round-off: +3e-5 of the energy at
// t = 14, +7e-4 at 15 (doc/method.md, section 4.1). The rods as a whole (contact force, energies,
// momenta) as node-to-node's on the same mesh to 1e-6 of each column's largest value (measured
// 1.5e-8, contact force; the energies and momenta 3e-11). The node on the axis is not compared:
// the frictionless sliding mode, which node-to-node does not excite, grows there from round-off
// (measured 7e-5 of the tip velocity at t = 14, 1.5e-2 at t = 20) without changing the energy.
TEST(FlatFaces, NodeToSegmentBetweenFlatEndsConservesEnergyAndMatchesNodeToNode)
{
  const MeshRun segment  = rods_on_newmark("node-to-segment");
  const MeshRun node     = rods_on_newmark("node-to-node");
  const History& history = segment.history();
  ASSERT_NEAR(history.value(history.n_rows() - 1, "time"), 14., 1e-9);
  const double after_impact = history.value(1, "total_energy");
  for (unsigned int row = 1; row < history.n_rows(); ++row)
  {
    ASSERT_GT(history.value(row, "active_constraints"), 0.) << "t = " << history.value(row, "time");
    EXPECT_NEAR(history.value(row, "total_energy"), after_impact, 1e-9 * after_impact)
        << "t = " << history.value(row, "time");
  }
  EXPECT_LE(largest_relative_difference(history, node.history()), 1e-6);
}

// Shared case 22, command A (the default scheme; the end faces touching) to t = 14. On the previous
// default, generalized-alpha rho_inf = 0.8, held master points stopped it at t = 13.8 (energy
// guard, exit 3), and master points taken at u_{n+1} instead of the configuration the balance
// holds at, u_{n+1-alpha_f}, at t = 18.35. On the default (mass redistribution, Newmark gamma =
// 0.502) it completes, its energy never above the start beyond round-off (1e-9; measured 0, on the
// trapezoidal rule 5.6e-15), and the rods as a whole as node-to-node's (shared case 21) to 1e-6
// (measured 3.1e-13).
TEST(FlatFaces, NodeToSegmentBetweenTouchingFlatEndsMatchesNodeToNodeOnTheDefaultIntegrator)
{
  const auto run = [](const std::string& discretization)
  {
    return run_mesh_case(
        "prm/rods_flat_ends.prm",
        {"Time integration/end time=14", "Contact/discretization=" + discretization});
  };
  const MeshRun segment  = run("node-to-segment");
  const MeshRun node     = run("node-to-node");
  const History& history = segment.history();
  ASSERT_NEAR(history.value(history.n_rows() - 1, "time"), 14., 1e-9);
  double largest_gain = 0.;
  for (unsigned int row = 1; row < history.n_rows(); ++row)
    largest_gain = std::max(
        largest_gain, history.value(row, "total_energy") / history.value(0, "total_energy") - 1.);
  const double difference = largest_relative_difference(history, node.history());
  std::cout << "  touching rods, default scheme: largest energy gain " << largest_gain
            << ", node-to-segment against node-to-node " << difference << "\n";
  EXPECT_LE(largest_gain, 1e-9);
  EXPECT_LE(difference, 1e-6);
}
} // namespace dyncontact::testing
