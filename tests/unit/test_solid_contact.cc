// Contact of 3D bodies (Problem/geometry = 3d mesh, issue 28): the patch tests of acceptance A on
// 27-node hexahedra (a block on a rigid plane; two blocks with matching faces, node-to-node) and a
// free impact of two blocks with the paper's rate constraints, whose momentum, force balance and
// velocity and acceleration jumps are checked against their exact values.
#include <dyncontact/base/global.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "case_run.h"

namespace dyncontact::testing
{
namespace
{
/**
 * The largest |p / p_exact - 1| over the slave nodes of the run's one contact_pressure_t<T>.csv,
 * each of them active, with p_exact = 1 / (1 + eps)^2: the traction 1 over the face's current
 * area, which has grown by the lateral strain eps in x and y. `n_slave_nodes` is the number of
 * nodes the file must have.
 */
double uniform_pressure_error(const SolidRun& run,
                              const double lateral_strain,
                              const unsigned int n_slave_nodes)
{
  std::vector<PressureRow> rows;
  for (const auto& [name, text] : run.files)
    if (name.rfind("contact_pressure_t", 0) == 0)
      rows = pressure_rows(text);
  EXPECT_EQ(rows.size(), n_slave_nodes);
  const double exact = 1. / ((1. + lateral_strain) * (1. + lateral_strain));
  double error       = 0.;
  for (const PressureRow& row : rows)
  {
    EXPECT_TRUE(row.active) << "at (" << row.x << ", " << row.y << ", " << row.z << ")";
    error = std::max(error, std::abs(row.pressure / exact - 1.));
  }
  return error;
}

/** The largest |value - value at t = 0| of the sum of the given columns over the history. */
double largest_change_of_sum(const History& history, const std::vector<std::string>& columns)
{
  std::vector<double> sum(history.n_rows(), 0.);
  for (const std::string& column : columns)
  {
    const std::vector<double> values = history.column(column);
    for (unsigned int row = 0; row < values.size(); ++row)
      sum[row] += values[row];
  }
  double change = 0.;
  for (const double value : sum)
    change = std::max(change, std::abs(value - sum.front()));
  return change;
}

/** The largest |entry| of a history column. */
double largest_magnitude(const History& history, const std::string& column)
{
  double largest = 0.;
  for (const double value : history.column(column))
    largest = std::max(largest, std::abs(value));
  return largest;
}
} // namespace

// tests/cases/block_3d_on_plane.prm: a box of 4 x 4 x 2 cells pressed onto the rigid plane z = 0
// by a uniform traction 1; linear elastic, nu / E = 3e-4 lateral strain. The exact static solution
// is a uniform stress, so the pressure at every one of the 9 x 9 bottom nodes is 1 / (1 + 3e-4)^2.
// 1e-10: what is left of the step load's inertia after 24 quasi-static steps and the Newton
// tolerance (1e-10 of the load); measured 2.5e-13 to 4.5e-13 over the four runs (a penalty contact
// carries the same uniform pressure at a uniform penetration). Each contact
// treatment and formulation the code has in 3D is run: they differ only where a pair opens or
// closes, which a pressed block never does.
TEST(SolidContact, BlockOnRigidPlaneCarriesTheUniformPressure)
{
  for (const std::vector<std::string>& overrides :
       std::vector<std::vector<std::string>>{{},
                                             {"Contact/dynamics=taylor-papadopoulos"},
                                             {"Contact/dynamics=none"},
                                             {"Contact/formulation=penalty"}})
  {
    const SolidRun run = run_solid_case("tests/cases/block_3d_on_plane.prm", overrides);
    const double error = uniform_pressure_error(run, 3e-4, 81);
    std::cout << "  block on a rigid plane" << (overrides.empty() ? "" : ", " + overrides.front())
              << ": pressure error " << error << "\n";
    EXPECT_LE(error, 1e-10);
    // The plane carries the whole load 1 x 2 x 2 = 4 at the end.
    EXPECT_NEAR(run.history().column("contact_force").back(), 4., 4e-10);
  }
}

// tests/cases/blocks_3d_patch.prm: two boxes with matching 4 x 4 faces (node-to-node), different
// materials widening alike (nu / E = 2e-4), the upper one pressed onto the lower one: the uniform
// pressure at every slave node to 1e-10 (measured 8.1e-13), and the forces on the two bodies
// equal and opposite at every step to 1e-10 of the load 4 (the history's force imbalance,
// measured 2.8e-12).
TEST(SolidContact, MatchingBlocksPassThePatchTest)
{
  const SolidRun run = run_solid_case("tests/cases/blocks_3d_patch.prm");
  const double error = uniform_pressure_error(run, 2e-4, 81);
  std::cout << "  matching blocks: pressure error " << error << ", largest force imbalance "
            << largest_magnitude(run.history(), "force_imbalance") << "\n";
  EXPECT_LE(error, 1e-10);
  EXPECT_LE(largest_magnitude(run.history(), "force_imbalance"), 4e-10);
}

// tests/cases/free_blocks_3d.prm: two free blocks (2 x 2 cells across, matching) approach at
// relative speed 2 along z, body 1 also sliding along x at 0.1, and collide across the gap 0.01
// with the paper's rate constraints (Contact/dynamics = taylor-papadopoulos): the total momentum
// along z is constant to 1e-10 of the bodies' momentum 4 (no external force; measured 2.7e-15), the
// contact forces balance to 1e-10 of the peak force (measured 8e-13 against about 200), and after
// each correction the active pairs' normal velocity and acceleration jumps vanish to 1e-10 of the
// impact speed 2 and of v / dt (measured 5e-15 and 5e-12); with Contact/dynamics = none the
// velocity jump is of the order of the impact speed (measured 2.2), so the test can fail.
TEST(SolidContact, FreeBlocksKeepMomentumAndTheRateConstraints)
{
  const SolidRun run      = run_solid_case("tests/cases/free_blocks_3d.prm");
  const History& history  = run.history();
  const double peak_force = largest_magnitude(history, "contact_force");
  ASSERT_GT(peak_force, 10.); // they do collide
  const double momentum_change   = largest_change_of_sum(history, {"momentum_1", "momentum_2"});
  const double imbalance         = largest_magnitude(history, "force_imbalance");
  const double velocity_jump     = largest_magnitude(history, "velocity_jump");
  const double acceleration_jump = largest_magnitude(history, "acceleration_jump");
  std::cout << "  free blocks: momentum change " << momentum_change << ", force imbalance "
            << imbalance << " (peak force " << peak_force << "), velocity jump " << velocity_jump
            << ", acceleration jump " << acceleration_jump << "\n";
  EXPECT_LE(momentum_change, 4e-10);
  EXPECT_LE(imbalance, 1e-10 * peak_force);
  EXPECT_LE(velocity_jump, 2e-10);
  EXPECT_LE(acceleration_jump, 1e-10 * 2. / 0.002);

  const SolidRun uncorrected =
      run_solid_case("tests/cases/free_blocks_3d.prm", {"Contact/dynamics=none"});
  const double uncorrected_jump = largest_magnitude(uncorrected.history(), "velocity_jump");
  std::cout << "  free blocks without rate constraints: velocity jump " << uncorrected_jump << "\n";
  EXPECT_GE(uncorrected_jump, 0.1);
}
} // namespace dyncontact::testing
