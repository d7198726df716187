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

// The energy identity of mass redistribution on the trapezoidal rule (doc/schemes.md, "Mass
// redistribution with resolved contact events"): for linear elasticity and a linear gap every
// step changes the energy by exactly (1/2)(lambda_n + lambda_n+1)(g_n+1 - g_n), zero while the pair
// stays closed, -(1/2) lambda_n+1 g_n at the closing, +(1/2) lambda_n g_n+1 at the release. The
// paper's 6.2 bars on the trapezoidal rule with a gap of 0.05 (closing at t = 0.05, inside the
// first step), events not resolved (tolerance 1): every step against the identity, the gap from
// the contact ends' displacements. Bound 1e-12 of E0 = 5, round-off (measured 7.1e-15; the
// closing step loses 5.5e-3, the release gains 3.1e-4).
TEST(MassRedistribution, TrapezoidalEnergyChangesByTheEventWorkAlone)
{
  const BarRun run       = run_bar_case(identical,
                                  {"Contact/dynamics=mass-redistribution",
                                         "Time integration/beta=0.25",
                                         "Geometry/Bar 2/left end=0.05",
                                         "Guards/contact event tolerance=1",
                                         "Guards/energy=false"});
  const History& history = run.history();
  const auto gap         = [&](const unsigned int row)
  { return 0.05 + history.value(row, "u_tip_2") - history.value(row, "u_tip_1"); };
  double largest = 0., closing = 0., opening = 0.;
  for (unsigned int row = 1; row < history.n_rows(); ++row)
  {
    const double lambda_old = history.value(row - 1, "contact_multiplier");
    const double lambda_new = history.value(row, "contact_multiplier");
    const double change =
        history.value(row, "total_energy") - history.value(row - 1, "total_energy");
    const double event_work = 0.5 * (lambda_old + lambda_new) * (gap(row) - gap(row - 1));
    largest                 = std::max(largest, std::abs(change - event_work));
    if (lambda_old == 0. && lambda_new > 0.)
      closing += change;
    if (lambda_old > 0. && lambda_new == 0.)
      opening += change;
  }
  const double energy = history.value(0, "total_energy");
  std::cout << "  6.2 with a gap, mass redistribution, trapezoidal: largest step energy change "
            << "minus the event work " << largest << ", closing " << closing << ", opening "
            << opening << " (E0 = " << energy << ")\n";
  EXPECT_LE(largest, 1e-12 * energy);
  EXPECT_LT(closing, -1e-3 * energy); // the events are there: the test sees them
  EXPECT_GT(opening, 1e-6 * energy);
}

// Mass redistribution on the trapezoidal rule changes the energy only at contact events, by
// (1/2) sum_k (lambda_k,n + lambda_k,n+1)(g_k,n+1 - g_k,n): a loss at a closing, a gain at a
// release (doc/schemes.md, "Mass redistribution with resolved contact events"). With the contact
// event control off (tolerance 1) and the energy guard off, the coarse spheres (4 steps in contact
// at dt = 0.02) end 4.9 % above their initial energy; at dt = 0.03 they lose 22.7 % at the closing
// (and end 0.46 % above it after the release). Bounds: a gain above 1 % and a loss above 10 %, so
// that the defect shows. With the control both runs end within 6e-5 of the initial energy and
// never exceed it by more than 4.3e-11 (measured). With the control (on by
// default, Guards/contact event tolerance = 1e-4) the events are resolved by halving the step and
// the energy ends within 0.1 % of its start (the bounds on the loss are 2 % and 5 %). What
// is left is the nonlinear (neo-Hookean) trapezoidal rule's own fluctuation in persistent contact,
// up to 7e-6 either way even with the events resolved to 1e-8 (measured): it is bounded here by the
// energy guard's tolerance, 1e-4.
TEST(MassRedistribution, CoarseSpheresResolveTheirContactEvents)
{
  for (const double dt : {0.02, 0.03})
    for (const bool control : {false, true})
    {
      const MeshRun run = run_mesh_case(
          "prm/spheres_rho0.001.prm",
          paper_coarse_spheres(
              {"Contact/dynamics=mass-redistribution",
               "Time integration/time step=" + std::to_string(dt),
               "Time integration/end time=2.19",
               control ? "Guards/contact event tolerance=1e-4" : "Guards/contact event tolerance=1",
               control ? "Guards/energy=true" : "Guards/energy=false"}));
      const auto energy   = run.history().column("total_energy");
      double largest_gain = 0., largest_loss = 0.;
      for (const double e : energy)
      {
        largest_gain = std::max(largest_gain, e / energy.front() - 1.);
        largest_loss = std::min(largest_loss, e / energy.front() - 1.);
      }
      const double final_change = energy.back() / energy.front() - 1.;
      std::cout << "  coarse spheres, mass redistribution, dt = " << dt << ", event control "
                << control << ": largest gain " << largest_gain << ", largest loss " << largest_loss
                << ", final change " << final_change << "\n";
      if (control)
      {
        EXPECT_LE(largest_gain, 1e-4) << dt;
        EXPECT_LE(std::abs(final_change), 1e-3) << dt;
      }
      else if (dt == 0.02)
        EXPECT_GT(largest_gain, 0.01);
      else
        EXPECT_LT(largest_loss, -0.1);
    }
}
} // namespace dyncontact::testing
