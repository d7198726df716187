// Acceptance tests of the two-sphere impact (Taylor & Papadopoulos 1993, section 6.4): the shipped
// prm files run in-process on the coarse member of the graded two-sphere mesh family and compared
// with Hertz's theory (HertzImpact, tested on its own) through measure_impact()
// (tested on its own), and with exact conservation properties of node-to-node contact.
#include <dyncontact/reference/hertz_impact.h>
#include <dyncontact/reference/impact_measures.h>

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
/** The paper's spheres of section 6.4 at rho = 0.001 (prm/spheres_rho0.001.prm). */
const ElasticSphere paper_sphere{8., 5e3, 0.3, 1e-3};

// The coarse mesh of paper_coarse_spheres(): 432 cells, pole edge 0.26, 5 surface nodes inside
// the Hertz radius 0.47 (rho = 0.001).

std::vector<std::string> linear_elastic(const std::string& dynamics)
{
  return paper_coarse_spheres({"Contact/dynamics=" + dynamics,
                               "Bodies/Body 1/material=linear elastic",
                               "Bodies/Body 2/material=linear elastic"});
}

ImpactMeasures measure(const MeshRun& run)
{
  return measure_impact(run.history().column("time"), run.history().column("contact_force"));
}

/** RMS over the steps in contact of the normal velocity of body 1's contact pole (exact: 0). */
double pole_velocity_rms(const MeshRun& run)
{
  const auto active    = run.history().column("active_constraints");
  const auto velocity  = run.history().column("v_tip_1");
  double sum           = 0.;
  unsigned int samples = 0;
  for (unsigned int row = 0; row < active.size(); ++row)
    if (active[row] > 0.)
    {
      sum += velocity[row] * velocity[row];
      ++samples;
    }
  return std::sqrt(sum / samples);
}

/**
 * The paper's rho = 1 impact with `scheme`, shared by the tests; small strain, so that the results
 * do not depend on how far the classical scheme's growing contact-node oscillations strain the
 * pole elements. The classical run reproduces the paper's defect, so its energy guard is off
 * (those oscillations gain energy; with the guard on, the steps would be cut until they do not).
 */
const MeshRun& hard_impact(const std::string& dynamics)
{
  static const MeshRun classical = []
  {
    auto overrides = linear_elastic("none");
    overrides.push_back("Guards/energy=false");
    return run_mesh_case("prm/spheres_rho1.prm", overrides);
  }();
  static const MeshRun modified =
      run_mesh_case("prm/spheres_rho1.prm", linear_elastic("taylor-papadopoulos"));
  return dynamics == "none" ? classical : modified;
}

/** Mid-contact of the soft impact: the step nearest Hertz's peak (t = 2.04098). */
const std::string mid_contact = "2.04";

/**
 * The paper's finite-strain rho = 0.001 impact with the modified scheme, shared by the tests, with
 * a profile at mid-contact.
 */
const MeshRun& soft_impact()
{
  static const MeshRun run = run_mesh_case(
      "prm/spheres_rho0.001.prm", paper_coarse_spheres({"Output/profile times=" + mid_contact}));
  return run;
}

} // namespace

TEST(SphereImpact, CoarseMeshMatchesHertzWithinMeshBands)
{
  const MeshRun& run            = soft_impact();
  const HertzImpact hertz       = HertzImpact::two_spheres(paper_sphere, paper_sphere, 2., 2.);
  const ImpactMeasures computed = measure(run);
  const double peak_error       = computed.peak_force / hertz.maximum_force() - 1.;
  const double duration_error   = computed.duration / hertz.contact_duration() - 1.;
  const double impulse_error    = computed.impulse / hertz.impulse() - 1.;
  std::cout << "coarse rho = 0.001: peak " << computed.peak_force << " (" << peak_error
            << "), duration " << computed.duration << " (" << duration_error << "), impulse "
            << computed.impulse << " (" << impulse_error << ")\n";
  // Bands for this mesh: only 5 surface nodes lie inside the Hertz radius, so the force grows in
  // jumps as each ring of nodes closes and the contact radius is resolved to one node spacing
  // (0.13 of 0.47). Measured: peak +4.5 %, duration -2.0 %; the medium mesh (twice finer) gives
  // +1.1 % and -1.2 %. The bands, 7 % and 4 %, leave a margin of 1.5-2 over the coarse figures
  // and would catch a wrong contact stiffness or a lost ring of nodes. The impulse is the
  // momentum each sphere loses and regains; it depends on the mesh only through the vibration
  // energy left in the spheres (0.1 % of the kinetic energy here), measured -0.03 %: band 0.5 %.
  EXPECT_LT(std::abs(peak_error), 0.07);
  EXPECT_LT(std::abs(duration_error), 0.04);
  EXPECT_LT(std::abs(impulse_error), 0.005);
  // The contact starts on the step of first touch (t = 2 is a step) and the peak comes at half
  // the duration, within one time step (measured 0.0011 early).
  EXPECT_NEAR(computed.contact_start, 2., 1e-9);
  EXPECT_NEAR(computed.peak_time, 2. + 0.5 * hertz.contact_duration(), 0.0025);
}

TEST(SphereImpact, MomentumIsConservedForcesBalanceAndPairsDoNotPenetrate)
{
  const MeshRun& run            = soft_impact();
  const History& history        = run.history();
  const double initial_momentum = std::abs(history.value(0, "momentum_1"));
  const double peak_force       = measure(run).peak_force;
  // The gap tolerance of Newton is the residual tolerance times the smallest cell diameter,
  // below 1 on this mesh (shortest edge 0.18).
  const double gap_tolerance = run.parameters.newton.residual_tolerance * 1.;
  double momentum_drift = 0., imbalance = 0., penetration = 0.;
  for (unsigned int row = 0; row < history.n_rows(); ++row)
  {
    momentum_drift =
        std::max(momentum_drift,
                 std::abs(history.value(row, "momentum_1") + history.value(row, "momentum_2")));
    imbalance   = std::max(imbalance, std::abs(history.value(row, "force_imbalance")));
    penetration = std::max(penetration, history.value(row, "max_penetration"));
  }
  std::cout << "momentum drift " << momentum_drift / initial_momentum << ", force imbalance "
            << imbalance / peak_force << ", max penetration " << penetration << "\n";
  // Equal and opposite contact forces and rate corrections on the two spheres: exact up to the
  // round-off of sums over ~1e4 DoFs (1e-13 relative measured).
  EXPECT_LT(momentum_drift, 1e-10 * initial_momentum);
  EXPECT_LT(imbalance, 1e-10 * peak_force);
  EXPECT_LE(penetration, gap_tolerance);
  // The spheres separate: the last rows have no active pair.
  EXPECT_EQ(history.value(history.n_rows() - 1, "active_constraints"), 0.);
}

TEST(SphereImpact, ContactPressureIsHertzianOnTheContactZoneAndZeroOutside)
{
  const MeshRun& run = soft_impact();
  const auto file    = run.files.find("contact_pressure_t" + mid_contact + ".csv");
  ASSERT_NE(file, run.files.end());
  const std::vector<PressureRow> rows = pressure_rows(file->second);

  // Hertz's pressure at this time: p(r) = p0 sqrt(1 - r^2 / a^2), a = sqrt(R* d), p0 = 3 F / (2
  // pi a^2), from the force F and approach d of the quasi-static impact.
  const HertzImpact hertz = HertzImpact::two_spheres(paper_sphere, paper_sphere, 2., 2.);
  const double t          = std::stod(mid_contact);
  const double a          = std::sqrt(hertz.effective_radius() * hertz.approach(t));
  const double p0         = 3. * hertz.contact_force(t) / (2. * numbers::PI * a * a);
  unsigned int active     = 0;
  for (const PressureRow& row : rows)
  {
    const double p_hertz = row.x < a ? p0 * std::sqrt(1. - row.x * row.x / (a * a)) : 0.;
    if (!row.active)
    {
      // An open pair carries no pressure, not even the tail of the recovery's smoothing.
      EXPECT_EQ(row.pressure, 0.) << "open pair at r = " << row.x;
      continue;
    }
    ++active;
    std::cout << "active pair at r = " << row.x << ": p = " << row.pressure << ", Hertz " << p_hertz
              << " (p0 = " << p0 << ", a = " << a << ")\n";
    // Band: the coarse mesh's peak force is 4.5 % above Hertz and its contact radius is resolved
    // to one node spacing (0.13 of a = 0.47), so the pressure at each active node may differ from
    // Hertz's ellipse by up to about a tenth of p0 (measured: centre +1.3 %, at most 4 % of p0, at
    // the outermost active node, r = 0.41, where the ellipse drops steeply). 10 % of p0 would
    // catch a pressure recovered from the wrong nodal forces, areas or zone.
    EXPECT_GT(row.pressure, 0.) << "active pair at r = " << row.x;
    EXPECT_NEAR(row.pressure, p_hertz, 0.1 * p0) << "active pair at r = " << row.x;
  }
  EXPECT_GE(active, 4u); // the nodes at r = 0, 0.13, 0.26, 0.41 lie inside a = 0.47
  EXPECT_LT(active, rows.size());
}

TEST(SphereImpact, ModifiedSchemeKeepsTheInterfaceVelocityContinuous)
{
  // By symmetry the contact poles are at rest while in contact.
  const MeshRun& classical       = hard_impact("none");
  const MeshRun& modified        = hard_impact("taylor-papadopoulos");
  const double classical_rms     = pole_velocity_rms(classical);
  const double modified_rms      = pole_velocity_rms(modified);
  const double classical_ringing = measure(classical).ringing;
  const double modified_ringing  = measure(modified).ringing;
  std::cout << "pole velocity RMS in contact: classical " << classical_rms << ", modified "
            << modified_rms << "; total force ringing: classical " << classical_ringing
            << ", modified " << modified_ringing << "\n";
  // Classical Newmark reverses the pole velocity every step (v = -1, +1, -1, ..., the paper's
  // eq. (18) with beta = 1/4; RMS 1.000 measured); the modified scheme sets the normal velocity
  // jump to zero and, the two sides being mirror images, each pole's normal velocity with it, to
  // round-off (measured 1.9e-12). The bound 1e-8 also catches the axis pair leaving the active
  // set, which let the pole vibrate (RMS 0.004 before that was fixed).
  EXPECT_GT(classical_rms, 0.9);
  EXPECT_LT(modified_rms, 1e-8);
  // The total force of the classical scheme carries the inertia of the oscillating contact nodes
  // on top of the force jumps of pairs closing one ring at a time, which both schemes share.
  EXPECT_LT(modified_ringing, classical_ringing);
}

TEST(SphereImpact, ContactZoneGrowsSteadilyUntilThePeak)
{
  // While the spheres approach, the Hertz contact radius grows, so pairs may join the active set
  // but none should leave it. The axis pair is the test case: its Q2 vertex has zero tributary
  // area, so its multiplier is a near-zero nodal force of either sign. When the sign alone
  // decided its release, it left and rejoined the active set every other step from t = 2.3 on
  // (12, 11, 12, 11 active pairs), dimpling the pole and making the total force zig-zag.
  for (const std::string dynamics : {"none", "taylor-papadopoulos"})
  {
    const History& history      = hard_impact(dynamics).history();
    const auto force            = history.column("contact_force");
    const auto active           = history.column("active_constraints");
    const unsigned int peak_row = std::max_element(force.begin(), force.end()) - force.begin();
    unsigned int departures     = 0;
    for (unsigned int row = 1; row <= peak_row; ++row)
      if (active[row] < active[row - 1])
        ++departures;
    std::cout << dynamics << ": active pairs at the peak " << active[peak_row]
              << ", steps before it "
              << "with fewer active pairs than the step before " << departures << "\n";
    EXPECT_EQ(departures, 0u) << dynamics;
    EXPECT_GE(active[peak_row], 10.) << dynamics; // measured 12: the rings inside the Hertz radius
  }
}

TEST(SphereImpact, PenaltyContactMatchesHertzWithinMeshBands)
{
  // The penalty formulation (with the classical scheme, see doc/method.md) on the coarse mesh.
  const MeshRun run =
      run_mesh_case("prm/spheres_rho0.001.prm",
                    paper_coarse_spheres({"Contact/dynamics=none", "Contact/formulation=penalty"}));
  const HertzImpact hertz          = HertzImpact::two_spheres(paper_sphere, paper_sphere, 2., 2.);
  const ImpactMeasures computed    = measure(run);
  const auto penetration           = run.history().column("max_penetration");
  const double largest_penetration = *std::max_element(penetration.begin(), penetration.end());
  std::cout << "penalty: peak " << computed.peak_force / hertz.maximum_force() - 1. << ", duration "
            << computed.duration / hertz.contact_duration() - 1. << ", impulse "
            << computed.impulse / hertz.impulse() - 1. << ", max penetration "
            << largest_penetration << "\n";
  // The same mesh bands as the multiplier run (measured +4.7 %, -2.1 %, -0.03 %): a stiff penalty
  // changes the force by the springs' compliance only.
  EXPECT_LT(std::abs(computed.peak_force / hertz.maximum_force() - 1.), 0.07);
  EXPECT_LT(std::abs(computed.duration / hertz.contact_duration() - 1.), 0.04);
  EXPECT_LT(std::abs(computed.impulse / hertz.impulse() - 1.), 0.005);
  // Spring stiffness per area = factor E / h_min, so the penetration under the Hertz centre
  // pressure p0 = 207 is about p0 h_min / (factor E) = 207 * 0.18 / (100 * 5e3) = 7.5e-5
  // (measured 6.7e-5); bound: twice that. Springs sized by the consistent nodal areas gave the axis
  // node almost none, and it penetrated by 2.2e-3.
  EXPECT_LT(largest_penetration, 1.5e-4);
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
// Newton/method = modified (issue 13) on the coarse neo-Hookean impact: the step's first tangent
// serves its later updates, so it factorizes far less often (measured 64 factorizations against
// 177, one per update, for full Newton; bound: half), and both stop inside the same Newton
// tolerance, so the impact is the same (peak force 1e-9 relative; histories: ctest
// cli.modified_newton_matches_full_newton).
TEST(SphereImpact, ModifiedNewtonFactorizesLessForTheSameImpact)
{
  const MeshRun full = run_mesh_case("prm/spheres_rho0.001.prm", paper_coarse_spheres());
  const MeshRun modified =
      run_mesh_case("prm/spheres_rho0.001.prm", paper_coarse_spheres({"Newton/method=modified"}));
  const unsigned int full_factorizations     = full.simulation->n_factorizations();
  const unsigned int modified_factorizations = modified.simulation->n_factorizations();
  const double full_peak = measure(full).peak_force, modified_peak = measure(modified).peak_force;
  std::cout << "factorizations: full " << full_factorizations << ", modified "
            << modified_factorizations << "; peak " << full_peak << " vs " << modified_peak << "\n";
  EXPECT_LE(2 * modified_factorizations, full_factorizations);
  EXPECT_GT(modified_factorizations, 0u);
  EXPECT_NEAR(modified_peak, full_peak, 1e-9 * full_peak);
}
} // namespace dyncontact::testing
