// Tests of Contact/dynamics = mass-redistribution (Khenous, Laborde & Renard 2008): the contact
// nodes carry no mass, every cell keeps its mass, and the contact force of the bars of the paper's
// 6.1 and of a stiff striker follows the exact wave solution without oscillating (ExactBarSolution,
// tested on its own in test_exact_bar_solution.cc).
#include <cmath>
#include <gtest/gtest.h>
#include <numeric>
#include <string>
#include <utility>

#include "case_run.h"

namespace dyncontact::testing
{
namespace
{
const std::string identical = "prm/bars_identical.prm";
} // namespace

// Bars of 100 elements (h = 0.1, rho A = 1): the interface node of each bar (its lumped mass
// 0.05) becomes massless and its neighbour gets the whole end element's mass, 0.15; each bar keeps
// rho A L = 10. Exact up to the round-off of summing 100 lumped masses (1e-12 relative).
TEST(MassRedistribution, TakesTheMassOffTheContactNodesAndKeepsEachCellsMass)
{
  const BarRun run = run_bar_case(
      identical, {"Contact/dynamics=mass-redistribution", "Time integration/end time=0.1"});
  const Vector<double>& mass = run.simulation->lumped_mass();
  unsigned int massless = 0, heavier = 0;
  for (const double m : mass)
  {
    massless += m == 0.;
    heavier += std::abs(m - 0.15) < 1e-12;
  }
  EXPECT_EQ(massless, 2u);
  EXPECT_EQ(heavier, 2u);
  EXPECT_NEAR(std::accumulate(mass.begin(), mass.end(), 0.), 20., 1e-12 * 20.);
  // The initial momentum, 1 per unit length of bar 1, is that of the unmodified mass.
  EXPECT_NEAR(run.history().value(0, "momentum_1"), 10., 1e-12 * 10.);
}

// The defining property (Khenous, Laborde & Renard 2008, section 5): no contact-force oscillation.
// Exact force Z v = 1 on the rigid wall (6.1) and Z v / 2 = 0.5 between the identical bars (6.2),
// for 0 < t < 20. After a start-up transient that dies within the first time unit, the force stays
// within 2e-3 of it (measured 1.3e-3 on 6.1 and 7e-4 on 6.2 at the shipped beta = 0.001, 6e-3 on
// 6.2 at beta = 0.25); the classical scheme at beta = 0.25 opens and closes the contact of 6.2
// 123 times with forces up to 3.9.
TEST(MassRedistribution, BarContactForceDoesNotOscillate)
{
  for (const auto& [prm_file, exact_force] :
       {std::pair<std::string, double>("prm/bar_rigid_wall.prm", 1.), {identical, 0.5}})
  {
    const BarRun run       = run_bar_case(prm_file, {"Contact/dynamics=mass-redistribution"});
    const double deviation = max_force_deviation(run.history(), exact_force, 1., 19.);
    std::cout << "  " << prm_file << ", mass redistribution: max |F - " << exact_force
              << "| on (1, 19) = " << deviation << ", contact episodes "
              << contact_episodes(run.history()) << "\n";
    EXPECT_LE(deviation, 2e-3) << prm_file;
    EXPECT_EQ(contact_episodes(run.history()), 1u) << prm_file;
  }
}

// A stiff striker (E = 1e4, wave speed 100, Courant number 100) on the soft bar of 6.2 at
// dt = 0.1, trapezoidal rule: the exact solution has one contact episode on [0, 20), the force
// starting at Z1 Z2 v / (Z1 + Z2) = 0.990 and decaying in steps to 0.137 as the near-rigid striker
// slows. Issue 14's acceptance C: one episode, and the force within 0.1 of the exact one in
// window means over every time unit (measured: worst 0.090, in the last window, where the
// discrete release comes 0.4 early, as with every scheme at this mesh: the target's reflected
// wave front is smeared over a few elements).
TEST(MassRedistribution, StiffStrikerKeepsOneContactEpisodeWithTheExactForce)
{
  const BarRun run = run_bar_case(identical,
                                  {"Contact/dynamics=mass-redistribution",
                                   "Geometry/Bar 1/Young's modulus=1e4",
                                   "Time integration/beta=0.25"});
  EXPECT_EQ(contact_episodes(run.history()), 1u);
  const double worst = max_window_mean_force_error(run, 20);
  std::cout << "  stiff striker, mass redistribution: worst window-mean force error " << worst
            << "\n";
  EXPECT_LE(worst, 0.1);
}

// Mass redistribution's one known defect (doc/schemes.md, "The default"): at a release on coarse
// time steps the massless contact node springs off while its neighbours' step still carries the old
// contact force, a gain of (1/2) lambda_n g_{n+1}. The coarse spheres at dt = 0.02 (4 steps in
// contact): with the energy guard off the run ends 4.9 % above its initial energy (bound: above
// 1 %, so a fix of the defect shows here); with the guard (on by default) the release steps are cut
// until the gain is within its tolerance 1e-4 (measured 3.5e-5 after 2 cuts).
TEST(MassRedistribution, CoarseSpheresGainAtReleaseIsCaughtByTheEnergyGuard)
{
  for (const bool guarded : {false, true})
  {
    const MeshRun run = run_mesh_case(
        "prm/spheres_rho0.001.prm",
        paper_coarse_spheres({"Contact/dynamics=mass-redistribution",
                              "Time integration/time step=0.02",
                              "Time integration/end time=2.16",
                              guarded ? "Guards/energy=true" : "Guards/energy=false"}));
    const auto energy   = run.history().column("total_energy");
    const auto cuts     = run.history().column("step_cuts");
    double largest_gain = 0.;
    for (const double e : energy)
      largest_gain = std::max(largest_gain, e / energy.front() - 1.);
    const double total_cuts = std::accumulate(cuts.begin(), cuts.end(), 0.);
    std::cout << "  coarse spheres, mass redistribution, energy guard " << guarded
              << ": largest gain " << largest_gain << ", step cuts " << total_cuts << "\n";
    if (guarded)
    {
      EXPECT_LE(largest_gain, 1e-4);
      EXPECT_GT(total_cuts, 0.);
    }
    else
    {
      EXPECT_GT(largest_gain, 0.01);
    }
  }
}
} // namespace dyncontact::testing
