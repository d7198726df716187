// Contact of 3D bodies (Problem/geometry = 3d mesh, issue 28): the patch tests of acceptance A on
// 27-node hexahedra (a block on a rigid plane; two blocks with matching faces, node-to-node), a
// free impact of two blocks with the paper's rate constraints, whose momentum, force balance and
// velocity and acceleration jumps are checked against their exact values, and a quarter sphere
// striking a rigid plane against the finite-sphere law (acceptance B, coarse).
#include <dyncontact/base/global.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <sstream>
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
// with the paper's rate constraints (Contact/dynamics = taylor-papadopoulos). No external force:
// each component of the total momentum is constant to 1e-10 of the momentum scale 4 (measured
// 4.2e-15), the history's angular momentum about the common centre of mass is the exact one at
// t = 0 (to round-off, 1e-12; it is not constant here, measured 10 % change over the impact:
// node-to-node pairs are held while block 1 slides 0.0055 along x, so a pair's two forces are not
// collinear, and the small-strain law is not invariant under rotation), and the contact forces
// balance to 1e-10 of the peak force (measured 6e-13 against about 200); after each correction the
// active pairs' normal velocity and acceleration jumps vanish to 1e-10 of the impact speed 2 and of
// v / dt (measured 5e-15 and 5e-12); with Contact/dynamics = none the velocity jump is of the order
// of the impact speed (measured 2.2 in the first 0.03; the classical scheme's chatter later gains
// energy, which the energy guard stops at t = 0.053 with MUMPS's round-off), so the test can fail.
TEST(SolidContact, FreeBlocksKeepMomentumAndTheRateConstraints)
{
  const SolidRun run      = run_solid_case("tests/cases/free_blocks_3d.prm");
  const History& history  = run.history();
  const double peak_force = largest_magnitude(history, "contact_force");
  ASSERT_GT(peak_force, 10.); // they do collide
  const double momentum_change = largest_change_of_sum(history, {"momentum_1", "momentum_2"});
  double component_change      = 0.;
  for (const std::string axis : {"x", "y", "z"})
    component_change =
        std::max(component_change, largest_change_of_sum(history, {"momentum_" + axis}));
  // At t = 0 each block translates: L = sum_b m_b (c_b - x_c) x v_b
  // = 4 (0, 0, -0.505) x (0.1, 0, 1) = (0, -0.202, 0) about the centre of mass (1, 1, 1.005).
  const double angular_x = history.column("angular_momentum_x").front(),
               angular_y = history.column("angular_momentum_y").front(),
               angular_z = history.column("angular_momentum_z").front();
  std::cout << "  free blocks: momentum components change by " << component_change
            << ", angular momentum at t = 0 (" << angular_x << ", " << angular_y << ", "
            << angular_z << "), change " << largest_change_of_sum(history, {"angular_momentum_y"})
            << " (node-to-node pairs held while sliding: their forces are not collinear)\n";
  EXPECT_LE(component_change, 4e-10);
  EXPECT_NEAR(angular_y, -0.202, 1e-12);
  EXPECT_NEAR(angular_x, 0., 1e-12);
  EXPECT_NEAR(angular_z, 0., 1e-12);
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
      run_solid_case("tests/cases/free_blocks_3d.prm",
                     {"Contact/dynamics=none", "Time integration/end time=0.03"});
  const double uncorrected_jump = largest_magnitude(uncorrected.history(), "velocity_jump");
  std::cout << "  free blocks without rate constraints: velocity jump " << uncorrected_jump << "\n";
  EXPECT_GE(uncorrected_jump, 0.1);
}

// Node-to-surface contact (Contact/discretization = node-to-segment in 3D: each slave node
// projected onto the curved 9-node faces of the master body) between non-matching faces, block 1
// with 4 x 4 cells across, block 2 with 3 x 5 (acceptance A): pressed together as in the patch
// test, the forces on the two bodies are equal and opposite at every step to 1e-10 of the load 4
// (measured 3.3e-13) and carry the whole load (4 to 1e-5: what is left of the step load's inertia
// in the node-to-surface run, whose contact stiffness differs, after 24 steps; measured 3.1e-6).
// Its pressure is not uniform (node-to-surface fails the patch test: measured -83 % to +133 %), so
// it is not asserted. The free blocks of tests/cases/free_blocks_3d.prm with 2 x 2 against 3 x 5
// cells and the paper's rate constraints: each momentum component constant to 1e-10 of 4
// (measured 1e-14), the forces balanced to 1e-10 of the peak (measured 3.6e-13 of 192), the
// velocity and acceleration jumps of the active pairs zero to 1e-10 of 2 and 2 / dt (measured
// 9.9e-15 and 9.9e-12).
TEST(SolidContact, NodeToSurfaceOnNonMatchingFacesBalancesTheForces)
{
  const std::vector<std::string> non_matching = {
      "Contact/discretization=node-to-segment",
      "Mesh/geo parameters=NX1: 4, NY1: 4, NX2: 3, NY2: 5"};
  const SolidRun pressed         = run_solid_case("tests/cases/blocks_3d_patch.prm", non_matching);
  const double pressed_imbalance = largest_magnitude(pressed.history(), "force_imbalance");
  const double load              = pressed.history().column("contact_force").back();
  std::cout << "  non-matching blocks pressed: force imbalance " << pressed_imbalance
            << ", contact force " << load << "\n";
  EXPECT_LE(pressed_imbalance, 4e-10);
  EXPECT_NEAR(load, 4., 4e-5);

  const SolidRun run =
      run_solid_case("tests/cases/free_blocks_3d.prm",
                     {"Contact/discretization=node-to-segment",
                      "Mesh/geo parameters=Gap: 0.01, NX1: 2, NY1: 2, NX2: 3, NY2: 5"});
  const History& history  = run.history();
  const double peak_force = largest_magnitude(history, "contact_force");
  ASSERT_GT(peak_force, 10.); // they do collide
  double component_change = 0.;
  for (const std::string axis : {"x", "y", "z"})
    component_change =
        std::max(component_change, largest_change_of_sum(history, {"momentum_" + axis}));
  const double imbalance         = largest_magnitude(history, "force_imbalance");
  const double velocity_jump     = largest_magnitude(history, "velocity_jump");
  const double acceleration_jump = largest_magnitude(history, "acceleration_jump");
  std::cout << "  non-matching free blocks: momentum components change by " << component_change
            << ", force imbalance " << imbalance << " (peak force " << peak_force
            << "), velocity jump " << velocity_jump << ", acceleration jump " << acceleration_jump
            << "\n";
  EXPECT_LE(component_change, 4e-10);
  EXPECT_LE(imbalance, 1e-10 * peak_force);
  EXPECT_LE(velocity_jump, 2e-10);
  EXPECT_LE(acceleration_jump, 1e-10 * 2. / 0.002);
}

// tests/cases/spinning_block_3d.prm: a free neo-Hookean block spinning about its vertical axis.
// The history's angular momentum about the centre of mass is I_zz omega = 0.8/3 at t = 0 (to
// round-off, 1e-12) with x and y components zero, and stays so within 1e-4 of it over 40 steps:
// the trapezoidal rule conserves angular momentum only up to its O(dt^2) error, omega dt = 0.005
// (measured 3.1e-6 absolute, 1.2e-5 relative); the momentum stays zero to 1e-12.
TEST(SolidContact, SpinningBlockReportsItsAngularMomentum)
{
  const SolidRun run     = run_solid_case("tests/cases/spinning_block_3d.prm");
  const History& history = run.history();
  const double exact     = 0.8 / 3.;
  const double angular_z = history.column("angular_momentum_z").front();
  const double drift     = largest_change_of_sum(history, {"angular_momentum_z"});
  std::cout << "  spinning block: angular momentum " << angular_z << " (exact " << exact
            << "), drift " << drift << "\n";
  EXPECT_NEAR(angular_z, exact, 1e-12);
  EXPECT_LE(drift, 1e-4 * exact);
  for (const std::string column :
       {"angular_momentum_x", "angular_momentum_y", "momentum_x", "momentum_y", "momentum_z"})
    EXPECT_LE(largest_magnitude(history, column), 1e-12) << column;
}

namespace
{
/** The `column` entry (computed, hertz, finite_sphere, ...) of `quantity` in impact_summary.csv. */
double summary_value(const SolidRun& run, const std::string& quantity, const std::string& column)
{
  const std::string& text = run.files.at("impact_summary.csv");
  std::istringstream lines(text);
  std::string header, line;
  std::getline(lines, header);
  std::vector<std::string> names;
  std::istringstream header_fields(header);
  for (std::string name; std::getline(header_fields, name, ',');)
    names.push_back(name);
  const auto index = std::find(names.begin(), names.end(), column) - names.begin();
  while (std::getline(lines, line))
    if (line.rfind(quantity + ",", 0) == 0)
    {
      std::istringstream fields(line);
      std::string field;
      for (long i = 0; i <= index; ++i)
        std::getline(fields, field, ',');
      return std::stod(field);
    }
  ADD_FAILURE() << "no row " << quantity << " in impact_summary.csv";
  return 0.;
}
} // namespace

// prm/sphere_on_rigid_plane_3d.prm on the coarse cubed sphere (N = 4, NR = 3, PoleGrading 3:
// 416 cells, 11,637 DoFs, cell edge about 0.85 at the pole against the contact radius 1.6): the
// quarter sphere's impact, times 4, against the finite-sphere law of the whole sphere. The impulse
// is the momentum change 2 m v of an almost elastic impact, which no mesh error changes much: 1e-3
// (measured -3.4e-4; the law's own impulse is that of a perfectly elastic impact). The peak force
// and the duration carry the coarse mesh's error: 3 % and 7 % (measured +2.1 % and +5.7 %; on the
// shipped mesh, 86,247 DoFs, the benchmark's figures are in the README). Also the model's
// momentum along z at the end: the rebound, between 0.99 and 1 of the quarter's initial momentum
// m v / 4 reversed (measured 0.9993).
TEST(SolidContact, QuarterSphereOnRigidPlaneFollowsTheFiniteSphereLaw)
{
  const SolidRun run =
      run_solid_case("prm/sphere_on_rigid_plane_3d.prm",
                     {"Mesh/geo parameters=R: 8, CentreZ: 8.005, N: 4, NR: 3, PoleGrading: 3"});
  const auto difference = [&run](const std::string& quantity)
  { return summary_value(run, quantity, "finite_sphere_difference"); };
  std::cout << "  quarter sphere against the finite-sphere law: peak force "
            << difference("peak_force") << ", duration " << difference("duration") << ", impulse "
            << difference("impulse") << "\n";
  EXPECT_LE(std::abs(difference("impulse")), 1e-3);
  EXPECT_LE(std::abs(difference("peak_force")), 0.03);
  EXPECT_LE(std::abs(difference("duration")), 0.07);
  const std::vector<double> momentum = run.history().column("momentum_1");
  const double rebound               = -momentum.back() / momentum.front();
  std::cout << "  rebound momentum / initial momentum " << rebound << "\n";
  EXPECT_GE(rebound, 0.99);
  EXPECT_LE(rebound, 1.);
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
namespace
{
/** The largest |x - x at t = 0| of a history column, relative to the scale. */
double
largest_relative_change(const History& history, const std::string& column, const double scale)
{
  return largest_change_of_sum(history, {column}) / scale;
}
} // namespace

// prm/oblique_spheres_3d.prm (acceptance C) on coarse non-matching meshes (N1 = 3, NR1 = 2,
// N2 = 2, NR2 = 2, PoleGrading 2: 12,756 DoFs, 15 s), to t = 0.07, past the peak force: ball 2
// strikes ball 1 at speed 1 along -z, the line of centres 30 degrees from z, frictionless
// node-to-surface contact with the paper's rate constraints.
// - The momentum's x and z components (no support acts along them; the symmetry plane y = 0
//   takes y) stay constant to 1e-10 of the initial m v / 2 (measured 9.1e-14 and 5.0e-13).
// - After the correction every active pair's normal velocity jump is below 1e-10 of the impact
//   speed and its acceleration jump below 1e-10 of v / dt = 400 (measured 1.4e-14 and 2.8e-14 v /
//   dt).
// - The recovered contact forces on the two balls balance along z to 1e-10 of the peak force
//   (measured 1.4e-12).
// - The algorithmic energy never exceeds its initial value by 1e-4 of it, the energy guard's
//   tolerance (measured: never above it): the pair normals are the master
//   faces' (with the averaged normals of the two surfaces, which are not normal to a face, the
//   sliding pair did work: +3.3 % on the coarse meshes of doc/method.md section 4.1).
// - The angular momentum about y (about the common centre of mass; the half model's other
//   components are not the whole balls') changes by the trapezoidal rule's O(dt^2) error only, not
//   1e-8: the rule does not conserve angular momentum under the large, moving contact forces
//   (measured 2.7e-6, and 6.7e-7 with dt halved; bound 1e-5).
// With Contact/dynamics = none the velocity jump is of the order of the normal approach speed
// cos 30 (measured 0.21 by t = 0.02): the test can fail.
TEST(SolidContact, ObliqueSpheresKeepMomentumAndTheRateConstraints)
{
  const std::vector<std::string> coarse = {
      "Mesh/geo parameters=Angle: 30, Gap: 0.01, N1: 3, NR1: 2, N2: 2, NR2: 2, PoleGrading: 2",
      "Time integration/end time=0.07"};
  const SolidRun run     = run_solid_case("prm/oblique_spheres_3d.prm", coarse);
  const History& history = run.history();
  const double momentum  = std::abs(history.column("momentum_z").front());
  const double peak      = largest_magnitude(history, "contact_force");
  ASSERT_GT(peak, 1.); // they do collide
  const double change_x            = largest_relative_change(history, "momentum_x", momentum);
  const double change_z            = largest_relative_change(history, "momentum_z", momentum);
  const double imbalance           = largest_magnitude(history, "force_imbalance") / peak;
  const double velocity_jump       = largest_magnitude(history, "velocity_jump");
  const double acceleration_jump   = largest_magnitude(history, "acceleration_jump") * 0.0025;
  const std::vector<double> energy = history.column("algorithmic_energy");
  double energy_gain               = 0.;
  for (const double value : energy)
    energy_gain = std::max(energy_gain, value / energy.front() - 1.);
  const double angular = largest_relative_change(
      history, "angular_momentum_y", std::abs(history.column("angular_momentum_y").front()));
  std::cout << "  oblique spheres: momentum x, z change " << change_x << ", " << change_z
            << " of m v / 2; force imbalance " << imbalance << " of the peak " << peak << "; jumps "
            << velocity_jump << " (velocity), " << acceleration_jump
            << " (acceleration dt); energy gain " << energy_gain << "; angular momentum change "
            << angular << "\n";
  EXPECT_LE(change_x, 1e-10);
  EXPECT_LE(change_z, 1e-10);
  EXPECT_LE(imbalance, 1e-10);
  EXPECT_LE(velocity_jump, 1e-10);
  EXPECT_LE(acceleration_jump, 1e-10);
  EXPECT_LE(energy_gain, 1e-4);
  EXPECT_LE(angular, 1e-5);

  const SolidRun classical =
      run_solid_case("prm/oblique_spheres_3d.prm",
                     with(coarse, {"Contact/dynamics=none", "Time integration/end time=0.02"}));
  const double classical_jump = largest_magnitude(classical.history(), "velocity_jump");
  std::cout << "  with Contact/dynamics = none: velocity jump " << classical_jump << "\n";
  EXPECT_GE(classical_jump, 0.1);
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
namespace
{
/**
 * The summed energy rise, relative to the initial algorithmic energy, over the steps that begin
 * and end with the same nonzero number of active pairs (the pairs closing or opening within a
 * step are the contact event guard's).
 */
double energy_rise_in_persistent_contact(const History& history)
{
  const std::vector<double> energy = history.column("algorithmic_energy");
  const std::vector<double> active = history.column("active_constraints");
  double rise                      = 0.;
  for (unsigned int i = 1; i < energy.size(); ++i)
    if (active[i - 1] > 0. && active[i] == active[i - 1])
      rise += std::max(0., energy[i] - energy[i - 1]);
  return rise / energy.front();
}
} // namespace

// The kind of issue 28's first open item: a sliding node-to-segment pair whose normal was held at
// u_n over the step did the work lambda (n_n . x_,xi) dxi while the loaded face turned, an O(dt)
// energy error that rose and fell with the force (doc/method.md section 4.1, "Normals that turn
// within the step"). The coarse oblique spheres of the test above, through the whole impact
// (t = 0.12, the release at 0.109; 20 s a run), on the treatments without rate constraints:
// - Mass-redistribution and persistency on the trapezoidal rule (beta = 1/4, gamma = 1/2, which
//   conserves energy): the energy rises by at most 2e-5 of it, summed over the steps in
//   persistent contact (mass-redistribution measured 6.7e-6, 1.6e-5 with dt halved: the work of
//   sliding through the 0.01 zones where the normal turns to the averaged one; held normals:
//   3.95e-4, and 2.1e-4 with dt halved; persistency measured 6.5e-7; with its gap of u_n measured
//   by u_n's pair, 4.3e-4).
// - Contact-stabilized and velocity-update, whose one force per step needs the pair's gradient
//   held over the step (ContactDynamics::turns_normals()): at most 3e-5 (measured 1.84e-5
//   and 1.89e-5, and 1.94e-5 for contact-stabilized with dt halved; with the normals turned, as
//   the other treatments turn them, 4.5e-4 each).
// - The product default (mass-redistribution, its own beta and gamma) and generalized-alpha run
//   the whole impact with the default guards (held normals: both stopped by the energy guard,
//   exit 3 at t = 0.033 and 0.049); the momentum's x and z components stay constant to 1e-10 of
//   m v / 2 (measured 1.4e-13 and 6.6e-13; generalized-alpha 7.8e-14 and 5.3e-13).
TEST(SlidingEnergy, ObliqueSpheresSlideWithoutEnergyGainOnTheDefaultTreatment)
{
  const std::vector<std::string> coarse = {
      "Mesh/geo parameters=Angle: 30, Gap: 0.01, N1: 3, NR1: 2, N2: 2, NR2: 2, PoleGrading: 2",
      "Time integration/end time=0.12",
      "Output/vtu times="};
  const std::vector<std::pair<std::string, double>> bounds = {{"mass-redistribution", 2e-5},
                                                              {"persistency", 2e-5},
                                                              {"contact-stabilized", 3e-5},
                                                              {"velocity-update", 3e-5}};
  for (const auto& [treatment, bound] : bounds)
  {
    const SolidRun trapezoidal = run_solid_case("prm/oblique_spheres_3d.prm",
                                                with(coarse, {"Contact/dynamics=" + treatment}));
    const double rise          = energy_rise_in_persistent_contact(trapezoidal.history());
    std::cout << "  " << treatment << ", beta = 1/4: energy rise in persistent contact " << rise
              << "\n";
    EXPECT_LE(rise, bound) << treatment;
  }

  for (const std::string integrator : {"newmark", "generalized-alpha"})
  {
    const SolidRun run     = run_solid_case("prm/oblique_spheres_3d.prm",
                                        with(coarse,
                                             {"Contact/dynamics=mass-redistribution",
                                                  "Time integration/integrator=" + integrator,
                                                  "Time integration/beta=",
                                                  "Time integration/gamma="}));
    const History& history = run.history();
    const double momentum  = std::abs(history.column("momentum_z").front());
    const double change_x  = largest_relative_change(history, "momentum_x", momentum);
    const double change_z  = largest_relative_change(history, "momentum_z", momentum);
    std::cout << "  " << integrator
              << " (default beta, gamma): reached t = " << history.column("time").back()
              << ", momentum x, z change " << change_x << ", " << change_z << " of m v / 2\n";
    EXPECT_NEAR(history.column("time").back(), 0.12, 1e-12);
    EXPECT_LE(change_x, 1e-10);
    EXPECT_LE(change_z, 1e-10);
  }
}
} // namespace dyncontact::testing
