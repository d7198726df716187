// Acceptance tests of the paper's modified Newmark on non-matching meshes (node-to-segment pairs):
// the identical spheres of section 6.4 at rho = 0.001, body 2 meshed with more divisions than
// body 1 (meshes/two_spheres_nonmatching.geo), so that no slave node faces a master node.
#include <dyncontact/models/mesh_model.h>
#include <dyncontact/reference/impact_measures.h>
#include <dyncontact/simulation/parameter_reader.h>

#include <deal.II/grid/tria.h>

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
 * The coarse non-matching pair: body 1 as the coarse matching mesh, body 2 four more divisions;
 * `discretization` node-to-segment or mortar.
 */
std::vector<std::string> non_matching(const std::string& dynamics,
                                      const std::string& discretization = "node-to-segment")
{
  return {"Mesh/file=" + source_path("meshes/two_spheres_nonmatching.geo"),
          "Mesh/geo parameters=Refinement: 0, PoleGrading: 10, CoreOffset: 0.3",
          "Contact/discretization=" + discretization,
          "Newton/method=full",
          "Contact/dynamics=" + dynamics};
}

/** The modified-scheme run at the default Newton tolerance, shared by the tests. */
const MeshRun& modified_run()
{
  static const MeshRun run =
      run_mesh_case("prm/spheres_rho0.001.prm", non_matching("taylor-papadopoulos"));
  return run;
}

double peak_force(const History& history)
{
  return measure_impact(history.column("time"), history.column("contact_force")).peak_force;
}

/** The largest |value| of a history column over the rows with active pairs. */
double largest_in_contact(const History& history, const std::string& column)
{
  double largest = 0.;
  for (unsigned int row = 0; row < history.n_rows(); ++row)
    if (history.value(row, "active_constraints") > 0.)
      largest = std::max(largest, std::abs(history.value(row, column)));
  return largest;
}

/** Acceptance B on the runs of one discretization: the modified and the classical scheme. */
void expect_rate_constraints(const std::string& discretization,
                             const MeshRun& modified,
                             const MeshRun& classical)
{
  SCOPED_TRACE(discretization);
  const History& history    = modified.history();
  const double impact_speed = 1.; // each sphere's initial speed towards the other
  const double dt           = modified.parameters.time.time_step;
  const double peak         = peak_force(history);
  // The meshes of the two bodies differ, so do their masses: momentum is measured from its start.
  const auto total_momentum = [&](const unsigned int row)
  { return history.value(row, "momentum_1") + history.value(row, "momentum_2"); };
  const double initial_momentum = std::abs(history.value(0, "momentum_1"));
  double momentum_drift = 0., penetration = 0.;
  for (unsigned int row = 0; row < history.n_rows(); ++row)
  {
    momentum_drift = std::max(momentum_drift, std::abs(total_momentum(row) - total_momentum(0)));
    penetration    = std::max(penetration, history.value(row, "max_penetration"));
  }
  const double velocity_jump     = largest_in_contact(history, "velocity_jump");
  const double acceleration_jump = largest_in_contact(history, "acceleration_jump");
  const double imbalance         = largest_in_contact(history, "force_imbalance");
  const double classical_jump    = largest_in_contact(classical.history(), "velocity_jump");
  std::cout << discretization << ", modified: velocity jump " << velocity_jump
            << ", acceleration jump " << acceleration_jump << ", momentum drift "
            << momentum_drift / initial_momentum << " of m v, force imbalance " << imbalance / peak
            << " of the peak " << peak << ", penetration " << penetration
            << "; classical velocity jump " << classical_jump << "\n";

  // Jumps: the joint correction of all active pairs solves S lambda = r exactly, so what is left
  // is the round-off of sums of nodal velocities of size 1 (measured 1.3e-12) and accelerations of
  // size 1e5 (measured 1.1e-9, i.e. 3e-12 of v / dt = 400, the acceleration scale of the step).
  EXPECT_LT(velocity_jump, 1e-10 * impact_speed);
  EXPECT_LT(acceleration_jump, 1e-10 * impact_speed / dt);
  // Momentum and balance: the constraint rows of a slave node and its master point's nodes have
  // weights summing to zero along the normal, and Newton takes an update as long as it still
  // reduces the residual fast, so the residual left at the contact nodes is round-off (measured:
  // drift 5.8e-12 of m v, imbalance 5.0e-11 of the peak; 1.2e-10 when the solver accepted a
  // residual in its round-off band on the update after the normals last moved).
  EXPECT_LT(momentum_drift, 1e-10 * initial_momentum);
  EXPECT_LT(imbalance, 1e-10 * peak);
  // Penetration: the active constraints hold to the gap tolerance of Newton, the residual
  // tolerance times the smallest cell diameter, itself below 1 on this mesh (measured 4e-15).
  EXPECT_LE(penetration, modified.parameters.newton.residual_tolerance * 1.);
  // The classical scheme leaves the slave nodes' normal velocity jumping by up to twice the
  // impact speed (eq. 18 with beta = 1/4: the contact nodes reverse their velocity; measured 2).
  EXPECT_GT(classical_jump, 0.5 * impact_speed);
  EXPECT_EQ(history.value(history.n_rows() - 1, "active_constraints"), 0.);
}
} // namespace

// Acceptance B of the non-matching issue: after the modified correction every active slave node
// moves with its master point along the normal (velocity and acceleration), total momentum is
// constant, the contact forces on the two bodies balance and no pair penetrates; the classical
// scheme keeps the paper's jumps (eqs. 17-18), so the assertions can fail.
// Mortar pairs (master points of up to 7 nodes, shared between pairs) are held to the same bounds
// (measured: velocity jump 1.7e-12, acceleration jump 1.4e-9, drift 1.1e-13 of m v, imbalance
// 6.9e-13 of the peak, penetration 4.0e-13; classical jump 2).
TEST(NonMatchingImpact, RateConstraintsHoldMomentumAndForcesBalanceAndPairsDoNotPenetrate)
{
  expect_rate_constraints("node-to-segment",
                          modified_run(),
                          run_mesh_case("prm/spheres_rho0.001.prm", non_matching("none")));
  expect_rate_constraints(
      "mortar",
      run_mesh_case("prm/spheres_rho0.001.prm", non_matching("taylor-papadopoulos", "mortar")),
      run_mesh_case("prm/spheres_rho0.001.prm", non_matching("none", "mortar")));
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
// Newton/residual tolerance = 1e-16, the tightest the input allows, asked for gaps of 1e-16 times
// the smallest cell (3e-17) while the gaps of positions of size 8 carry round-off of 1e-15: every
// step was cut to the smallest size and the run stopped (exit 3). The gap tolerance now has the
// round-off floor of the forces (1e3 eps of the length scale): the run completes and agrees with
// the default tolerance's to the latter's convergence: Newton converges linearly where slave nodes
// slide (the tangent leaves out the moving master points and, since the pair normals are the master
// faces', the turn of the face normal along the ray), and stops at 1e-10 of the force scale with
// the largest force sample 1.6e-8 of itself from the converged one (measured; at 1e-12 1.1e-10,
// at 1e-14 and 1e-16 the same to all digits), so 5e-8.
TEST(NonMatchingImpact, TightestNewtonToleranceCompletesWithTheSameAnswer)
{
  auto overrides = non_matching("taylor-papadopoulos");
  overrides.push_back("Newton/residual tolerance=1e-16");
  const MeshRun tight       = run_mesh_case("prm/spheres_rho0.001.prm", overrides);
  const double default_peak = peak_force(modified_run().history());
  const double tight_peak   = peak_force(tight.history());
  std::cout << "peak at tolerance 1e-16: " << tight_peak << ", at 1e-10: " << default_peak << "\n";
  EXPECT_EQ(tight.history().n_rows(), modified_run().history().n_rows());
  EXPECT_NEAR(tight_peak, default_peak, 5e-8 * default_peak);
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
// Acceptance D of the non-matching issue, pinned on the coarsest mesh: the dissimilar spheres
// (prm/dissimilar_spheres.prm: R1 = 8, R2 = 4, E and rho differing by 2, meshes matching nothing,
// mortar contact, modified scheme) against their two references, Hertz and the finite-sphere law
// (each sphere its own approach, doc/method.md). The law, not Hertz, is what the run converges to
// (bench/non_matching_hertz.sh: peak +1.74, +1.74, +2.20 % from Hertz on Refinement 0, 1, 2 against
// the law's +2.41 %; Refinement 2 at dt / 2 is -0.09 % from the law).
TEST(NonMatchingImpact, DissimilarSpheresFollowTheFiniteSphereLawNotHertz)
{
  const std::vector<std::string> coarse = {
      "Mesh/geo parameters=Refinement: 0, PoleGrading: 10, CoreOffset: 0.3",
      "Output/vtu interval=0"};
  const MeshRun run = run_mesh_case("prm/dissimilar_spheres.prm", coarse);
  MeshModel model(run.parameters.mesh, run.parameters.bodies, run.parameters.contact.pairs);
  Triangulation<2> mesh;
  model.create_triangulation(mesh);
  const auto hertz = model.hertz_reference();
  const auto law   = model.finite_sphere_reference();
  ASSERT_TRUE(hertz && law);
  // The energy guard cuts two steps at release (to 0.00125): the measures take the nominal grid.
  const History history = run.simulation->nominal_history();
  const ImpactMeasures computed =
      measure_impact(history.column("time"), history.column("contact_force"));
  const auto relative = [](const double value, const double reference)
  { return value / reference - 1.; };
  std::cout << "peak " << computed.peak_force << ": law "
            << 100 * relative(computed.peak_force, law->maximum_force()) << " %, Hertz "
            << 100 * relative(computed.peak_force, hertz->maximum_force()) << " %; duration "
            << computed.duration << ": law "
            << 100 * relative(computed.duration, law->contact_duration()) << " %, Hertz "
            << 100 * relative(computed.duration, hertz->contact_duration()) << " %; impulse "
            << computed.impulse << ": law " << 100 * relative(computed.impulse, law->impulse())
            << " %\n";
  // The law lies 2.4 % above Hertz in peak and 1.7 % below in duration; this coarse mesh (about 4
  // Q2 elements across the contact radius of the smaller sphere) is within 0.7 % of the law in
  // both (measured with mortar contact: peak -0.65 %, duration +0.35 %; with node-to-segment -0.30
  // and +0.30 %), so 1 % holds it to the law and fails if the run follows Hertz instead (2.4 % and
  // 1.7 % away) or a refactoring moves it by more than its discretization error.
  EXPECT_LT(std::abs(relative(computed.peak_force, law->maximum_force())), 1e-2);
  EXPECT_LT(std::abs(relative(computed.duration, law->contact_duration())), 1e-2);
  EXPECT_GT(relative(computed.peak_force, hertz->maximum_force()), 1.2e-2);
  // Impulse: the momenta exchanged, 2 m* v in both references (the bodies separate elastically);
  // the trapezoid over the samples misses the force between the last sample and the release
  // within the step (measured +0.079 %), so 0.2 %.
  EXPECT_LT(std::abs(relative(computed.impulse, law->impulse())), 2e-3);
}
} // namespace dyncontact::testing
