// Mortar contact (MortarContact, Contact/discretization = mortar) against the contact patch test:
// two blocks with non-matching facing faces (meshes/two_blocks.geo, 4 and 5 cells across, so that
// only the faces' ends coincide) pressed together by a uniform traction, quasi-static
// (tests/cases/blocks_patch.prm). The exact solution is a uniform stress: the contact pressure is
// the force over the current face area at every slave node. Node-to-segment contact fails this test
// (its master nodes get the point forces N_m(xi_j) lambda_j, not those of a uniform traction), so
// the test can fail.
#include <dyncontact/base/global.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "case_run.h"
#include "mesh_set_up.h"

namespace dyncontact::testing
{
namespace
{
/** The rows of the run's one contact_pressure_t<T>.csv. */
std::vector<PressureRow> slave_pressures(const MeshRun& run)
{
  std::vector<PressureRow> rows;
  for (const auto& [name, text] : run.files)
    if (name.rfind("contact_pressure_t", 0) == 0)
    {
      const std::vector<PressureRow> file = pressure_rows(text);
      rows.insert(rows.end(), file.begin(), file.end());
    }
  return rows;
}

/**
 * The largest |p / p_exact - 1| over the slave nodes of the patch test run with `overrides`, every
 * slave node active: p_exact = 1 / (1 + eps)^k, the traction 1 over the face's current area, which
 * has grown by the lateral strain eps in k directions.
 */
double patch_test_error(const std::vector<std::string>& overrides,
                        const double lateral_strain,
                        const unsigned int widened_directions)
{
  const MeshRun run                   = run_mesh_case("tests/cases/blocks_patch.prm", overrides);
  const std::vector<PressureRow> rows = slave_pressures(run);
  EXPECT_EQ(rows.size(), 11u); // the 2 x 5 + 1 nodes of block 2's bottom face
  const double exact = std::pow(1. + lateral_strain, -static_cast<double>(widened_directions));
  double error       = 0.;
  for (const PressureRow& row : rows)
  {
    EXPECT_TRUE(row.active) << "x = " << row.x;
    error = std::max(error, std::abs(row.pressure / exact - 1.));
  }
  return error;
}

/** Plane strain, the blocks on a symmetry plane x = 0 (curves 1 and 8). */
const std::vector<std::string> plane_strain = {"Problem/geometry=plane strain mesh",
                                               "Mesh/geo parameters=NX1: 4, NX2: 5, NY: 2",
                                               "Boundary/number of symmetry planes=2",
                                               "Boundary/Symmetry 1/boundary=1",
                                               "Boundary/Symmetry 2/boundary=8"};
} // namespace

// Plane strain: both blocks widen by nu (1 + nu) / E = 2.4e-4. Mortar gives the uniform pressure
// to 1e-10 (measured 1.2e-12: what is left is round-off, the quasi-static run's remaining inertia
// and the Newton tolerance), node-to-segment misses it by more than 10 % (measured 28 %).
TEST(MortarContact, PatchTestOnNonMatchingFacesInPlaneStrain)
{
  const double mortar = patch_test_error(plane_strain, 2.4e-4, 1);
  const double point =
      patch_test_error(with(plane_strain, {"Contact/discretization=node-to-segment"}), 2.4e-4, 1);
  std::cout << "  plane strain patch test: mortar " << mortar << ", node-to-segment " << point
            << "\n";
  EXPECT_LE(mortar, 1e-10);
  EXPECT_GE(point, 0.1);
}

// The same blocks as two cylinders on the axis (axisymmetric: the integrals carry 2 pi r, and the
// slave vertex on the axis, whose dual area is zero, keeps its projected point), block 2 with
// nu = 0.4 so that both widen by nu / E = 2e-4 in r (and the face's area by (1 + 2e-4)^2): the
// uniform pressure to 1e-10 again (measured 7.9e-13; node-to-segment 38 %).
TEST(MortarContact, PatchTestOnNonMatchingFacesInAxisymmetry)
{
  const double mortar = patch_test_error({"Bodies/Body 2/Poisson's ratio=0.4"}, 2e-4, 2);
  std::cout << "  axisymmetric patch test: mortar " << mortar << "\n";
  EXPECT_LE(mortar, 1e-10);
}

namespace
{
/** What a line-contact run gives against Hertz's (the whole model's load P from the run). */
struct LineContactErrors
{
  double centre_pressure;  ///< (p(0) - p0) / p0
  double largest_pressure; ///< max over active nodes with x < 0.8 a of |p - p_Hertz(x)| / p0
  double last_active, first_inactive, half_width; ///< x of the zone's edge nodes, Hertz's a
  double fitted_half_width; ///< a of Hertz's ellipse p^2 = p0^2 (1 - x^2 / a^2) fitted to the
                            ///< active nodes (least squares in p^2), relative to Hertz's, - 1
};

/**
 * prm/cylinder_on_block_plane_strain.prm on its coarse mesh (ContactSize 0.1, 13156 DoFs), with
 * `discretization`, against Hertz's line contact of a cylinder (R = 10, E = 1000, nu = 0.3) on a
 * flat body of the same material: 1/E* = 2 (1 - nu^2) / E, a = sqrt(4 P R / (pi E*)),
 * p0 = 2 P / (pi a), p(x) = p0 sqrt(1 - x^2 / a^2), with P twice the half model's contact force
 * (the sum of the slave nodes' forces: half the discrete weight).
 */
LineContactErrors cylinder_on_block(const std::string& discretization)
{
  const MeshRun run =
      run_mesh_case("prm/cylinder_on_block_plane_strain.prm",
                    {"Mesh/geo parameters=R: 10, Gap: 0, Width: 10, Height: 10, ContactSize: 0.1, "
                     "BlockSizeRatio: 1.25, ZoneRadius: 2, FarSize: 2",
                     "Contact/discretization=" + discretization});
  std::vector<PressureRow> rows = slave_pressures(run);
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  double half_load = 0.;
  for (const PressureRow& row : rows)
    half_load += row.multiplier;
  const double R = 10., E = 1000., nu = 0.3, P = 2. * half_load;
  const double effective_modulus = E / (2. * (1. - nu * nu));
  const double a                 = std::sqrt(4. * P * R / (numbers::PI * effective_modulus));
  const double p0                = 2. * P / (numbers::PI * a);
  LineContactErrors errors{(rows.front().pressure - p0) / p0, 0., 0., 0., a, 0.};
  // p^2 = c0 - c1 x^2 by least squares: the normal equations of the two coefficients.
  double n = 0., sx = 0., sxx = 0., sy = 0., sxy = 0.;
  for (const PressureRow& row : rows)
  {
    if (row.active)
    {
      const double x2 = row.x * row.x, y = row.pressure * row.pressure;
      n += 1.;
      sx += x2;
      sxx += x2 * x2;
      sy += y;
      sxy += x2 * y;
    }
    if (row.active)
      errors.last_active = row.x;
    else if (errors.first_inactive == 0.)
      errors.first_inactive = row.x;
    if (row.active && row.x < 0.8 * a)
      errors.largest_pressure =
          std::max(errors.largest_pressure,
                   std::abs(row.pressure - p0 * std::sqrt(1. - row.x * row.x / (a * a))) / p0);
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), intercept = (sy - slope * sx) / n;
  errors.fitted_half_width = std::sqrt(-intercept / slope) / a - 1.;
  return errors;
}
} // namespace

// Issue 28, E, as a ctest on the coarse mesh (the shipped one, ContactSize 0.05, in the prm's
// header: p(0) +1.41 %, 0.0141 p0): mortar contact between the non-matching elastic Q2 surfaces
// gives Hertz's pressure, p(0) within 2 % of p0 and every active node with x < 0.8 a within
// 0.02 p0 (measured +1.44 % and 0.0144; the band is the issue's; the edge, where Hertz's pressure
// falls as a square root within one node spacing, is left out), Hertz's half-width a between
// the outermost active node and the next, inactive, one (measured -4.1 % and +1.5 % of a, the
// node spacing at the contact being 5.7 % of a), and the half-width of Hertz's ellipse fitted to
// the active nodes' pressures within 2 % of a (measured -1.56 %; -1.23 % on the shipped mesh: the
// block, 10 deep and clamped, is stiffer than Hertz's half-space). Node-to-segment contact on the
// same mesh carries the same load but its pressure departs from Hertz's by more than 0.05 p0
// (measured 0.12, +5.4 % at x = 0).
TEST(MortarContact, CylinderOnBlockGivesHertzLineContact)
{
  const LineContactErrors mortar = cylinder_on_block("mortar");
  const LineContactErrors point  = cylinder_on_block("node-to-segment");
  std::cout << "  cylinder on block, mortar: p(0) " << mortar.centre_pressure << ", largest "
            << mortar.largest_pressure << ", edge nodes at "
            << mortar.last_active / mortar.half_width << " and "
            << mortar.first_inactive / mortar.half_width << " of a, fitted a "
            << mortar.fitted_half_width << "; node-to-segment: p(0) " << point.centre_pressure
            << ", largest " << point.largest_pressure << "\n";
  EXPECT_LE(std::abs(mortar.centre_pressure), 0.02);
  EXPECT_LE(mortar.largest_pressure, 0.02);
  EXPECT_LE(mortar.last_active, mortar.half_width);
  EXPECT_GE(mortar.first_inactive, mortar.half_width);
  EXPECT_LE(std::abs(mortar.fitted_half_width), 0.02);
  EXPECT_GE(point.largest_pressure, 0.05);
}

// On matching flat faces a slave node's dual-weighted mean of the master surface is its facing
// node (the patch test's matching variant gives node-to-node's pressure to 1e-12); on curved ones
// not quite: the ray from a slave point along the interpolated normal meets the mirrored face at
// its mirror point only where the faces touch, so the weights differ from the facing node's by
// the gap times the normal's tilt over a cell. The paper's spheres at rho = 0.001 on the structured
// coarse mesh, mortar against node-to-node on the paper's modified scheme and on the default one,
// agree in every history column to 1e-3 of the column's largest value (measured 7.5e-5 and
// 8.5e-5), far inside the mesh's own band against Hertz (2 % in peak force).
TEST(MortarContact, MatchesNodeToNodeOnMatchingSphereMeshes)
{
  for (const std::string dynamics : {"taylor-papadopoulos", "mass-redistribution"})
  {
    const auto run = [&](const std::string& discretization)
    {
      return run_mesh_case("prm/spheres_rho0.001.prm",
                           paper_coarse_spheres({"Contact/discretization=" + discretization,
                                                 "Contact/dynamics=" + dynamics}));
    };
    const double difference =
        largest_relative_difference(run("mortar").history(), run("node-to-node").history());
    std::cout << "  matching spheres, " << dynamics << ": mortar against node-to-node "
              << difference << "\n";
    EXPECT_LE(difference, 1e-3) << dynamics;
  }
}

// The shipped sphere on a block (prm/sphere_on_block.prm: the paper's sphere at speed 1 onto a
// thick block, non-matching meshes, mortar contact) near its peak force, t = 2.05: the recovered
// pressure follows Hertz's for the run's own contact force F (quasi-static at rho = 0.001:
// a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2), R = 8, E* = E / (2 (1 - nu^2))) within 0.03 p0
// at every active node with r < 0.8 a (measured 0.025 with the dual multiplier's nodal values
// lambda_j / D_j, 0.013 with the consistent recovery before 2026-12-07; the pole +0.08 % with
// both; the band leaves room for
// the impact's inertia and the mesh: 8 active nodes). Node-to-segment contact on the same mesh is
// off by up to 0.61 p0 (+61 % at the pole), alternating between vertex and mid-side nodes.
TEST(MortarContact, SphereOnBlockPressureIsHertzian)
{
  const MeshRun run = run_mesh_case(
      "prm/sphere_on_block.prm", {"Time integration/end time=2.055", "Output/profile times=2.05"});
  std::vector<PressureRow> rows = slave_pressures(run);
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  const History& history = run.history();
  unsigned int row       = 0;
  while (row + 1 < history.n_rows() && std::abs(history.value(row + 1, "time") - 2.05) <
                                           std::abs(history.value(row, "time") - 2.05))
    ++row;
  const double F = history.value(row, "contact_force"), R = 8., E = 5e3, nu = 0.3;
  const double effective_modulus = E / (2. * (1. - nu * nu));
  const double a                 = std::cbrt(3. * F * R / (4. * effective_modulus));
  const double p0                = 3. * F / (2. * numbers::PI * a * a);
  double largest                 = 0.;
  unsigned int active            = 0;
  for (const PressureRow& pressure : rows)
    if (pressure.active)
    {
      ++active;
      if (pressure.x < 0.8 * a)
        largest = std::max(
            largest,
            std::abs(pressure.pressure - p0 * std::sqrt(1. - pressure.x * pressure.x / (a * a))) /
                p0);
    }
  std::cout << "  sphere on block at t = " << history.value(row, "time") << ": F = " << F
            << ", a = " << a << ", " << active << " active nodes, largest |p - p_Hertz| / p0 "
            << largest << ", pole " << rows.front().pressure / p0 - 1. << "\n";
  EXPECT_GE(active, 6u);
  EXPECT_LE(largest, 0.03);
}

// Flat, matching rod ends in long sliding contact (prm/rods_flat_ends.prm, the default scheme):
// with E = 100 the impact strain is 5 % (rho c v / 2 / E with c = 10) and mortar contact gives
// node-to-node's history over the whole run (the prm's 25 transit times, scaled by c) to 1e-6 of
// each column's largest value (measured 1.3e-9, contact force). At E = 1, the prm's own, the
// impact strain is 50 %, far beyond small strain, and a sliding mode grows from round-off until
// Newton stops the run at t = 5.73 (exit 3; doc/method.md, section 4.2); it ran to the end at
// E = 3 (29 %), 10 and 1000.
TEST(MortarContact, FlatRodEndsAtSmallStrainMatchNodeToNode)
{
  const auto run = [](const std::string& discretization)
  {
    return run_mesh_case("prm/rods_flat_ends.prm",
                         {"Bodies/Body 1/Young's modulus=100",
                          "Bodies/Body 2/Young's modulus=100",
                          "Time integration/time step=0.005",
                          "Time integration/end time=2.5",
                          "Contact/discretization=" + discretization});
  };
  const double difference =
      largest_relative_difference(run("mortar").history(), run("node-to-node").history());
  std::cout << "  flat rod ends at E = 100: mortar against node-to-node " << difference << "\n";
  EXPECT_LE(difference, 1e-6);
}

// The mortar pairs themselves, without a run, on the patch test's touching flat faces (4 and 5
// cells across, axisymmetric and plane strain) and with block 1, the master, cut to 0.85 of the
// width, so that the master surface ends a quarter into the slave's last face [0.8, 1]:
//  - every pair's weights sum to one (to 1e-14): its forces balance;
//  - every master node of a pair is among the nodes coupled_nodes() declares (the sparsity is
//    built from them once);
//  - where the master surface covers a slave node's faces, the pair's master point is the slave
//    node itself (to 1e-14 of the width): biorthogonality makes the dual-weighted mean of a linear
//    field its value at the node, sum_m M_jm x_m = int psi_j x dA = D_j x_j, on any meshes and with
//    2 pi r; node-to-segment gets this too, so the check is on the weights' arithmetic;
//  - where the master surface ends under the slave face, the slave nodes beyond its end (0.9, 1)
//    have less than half of their dual area over it and keep node-to-segment's projected point,
//    clamped to the master's end (x = 0.85); the vertex at 0.8, more than half covered, has
//    mortar weights normalized by the covered part, its master point on the master surface
//    between 0.6 and 0.85 (not at the node: the covered part is not symmetric about it).
TEST(MortarContact, PairsBalanceReproduceFlatFacesAndFallBackBeyondTheMaster)
{
  const std::vector<std::vector<std::string>> cases = {{},
                                                       {"Problem/geometry=plane strain mesh",
                                                        "Mesh/geo parameters=NX1: 4, NX2: 5, NY: 2",
                                                        "Boundary/number of symmetry planes=2",
                                                        "Boundary/Symmetry 1/boundary=1",
                                                        "Boundary/Symmetry 2/boundary=8"}};
  for (const bool shorter_master : {false, true})
    for (const auto& section : cases)
    {
      std::vector<std::string> overrides = section;
      if (shorter_master)
        overrides.push_back("Mesh/geo parameters=NX1: 4, NX2: 5, NY: 2, Width1: 0.85" +
                            std::string(section.empty() ? ", OnAxis: 1" : ""));
      SCOPED_TRACE((section.empty() ? "axisymmetric" : "plane strain") +
                   std::string(shorter_master ? ", master 0.85 wide" : ""));
      const MeshSetUp setup("tests/cases/blocks_patch.prm", overrides);
      const Contact<2> contact                 = setup.contact();
      const ContactGeometry<2>& geometry       = *contact.surfaces;
      const std::vector<ContactPair<2>>& pairs = geometry.pairs();
      // The slave node at x = 1 lies 0.15 from the shorter master, beyond the search radius
      // (the gap plus a quarter of the blocks' height, 0.125): no pair.
      ASSERT_EQ(pairs.size(), shorter_master ? 10u : 11u);
      unsigned int mortar = 0;
      for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        double sum = 0.;
        Point<2> master_point;
        std::vector<types::global_dof_index> coupled;
        for (const Node<2>& node : geometry.coupled_nodes(k))
          coupled.push_back(node.dofs[0]);
        for (const MasterNode<2>& master : pairs[k].masters)
        {
          sum += master.weight;
          master_point += master.weight * master.node.position;
          EXPECT_NE(std::find(coupled.begin(), coupled.end(), master.node.dofs[0]), coupled.end())
              << "pair " << k;
        }
        EXPECT_NEAR(sum, 1., 1e-14) << "pair " << k;
        const Point<2> slave = pairs[k].slave.position;
        EXPECT_NEAR(master_point[1], 0., 1e-14) << "pair " << k;
        mortar += pairs[k].masters.size() > 3;
        if (!shorter_master || slave[0] < 0.75) // faces wholly over the master surface
          EXPECT_NEAR(master_point[0], slave[0], 1e-14) << "pair " << k;
        else if (slave[0] > 0.85) // less than half of the dual area covered: projected, clamped
          EXPECT_NEAR(master_point[0], 0.85, 1e-14) << "pair " << k;
        else // the vertex at 0.8: its face [0.8, 1] covered to 0.85, the weights normalized
        {
          EXPECT_GT(pairs[k].masters.size(), 3u) << "pair " << k;
          EXPECT_GE(master_point[0], 0.6) << "pair " << k;
          EXPECT_LE(master_point[0], 0.85) << "pair " << k;
        }
      }
      EXPECT_GE(mortar, 7u); // the interior pairs span two master faces
    }
}
} // namespace dyncontact::testing
