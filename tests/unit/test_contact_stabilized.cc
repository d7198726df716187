// Acceptance tests of Contact/dynamics = contact-stabilized (Deuflhard, Krause & Ertel 2008) on
// problems with exact references: the paper's identical bars of 6.2 (exact force Z v / 2 = 0.5 on
// [0, 20)) and the coarse spheres at a time step 8 times the paper's, where the other schemes gain
// energy at release.
#include <cmath>
#include <gtest/gtest.h>

#include "case_run.h"

namespace dyncontact::testing
{
// The defining property (Deuflhard, Krause & Ertel 2008, Theorem 4.2): the trapezoidal
// contact-stabilized step never gains energy at contact. The coarse spheres at dt = 0.02 (4 steps
// in contact): classical Newmark, the paper's scheme and mass redistribution all gain 4.9 % at the
// release and need the energy guard's step cuts; this scheme takes every step as it comes (no
// cut) and its total energy never exceeds the initial one (1e-9 relative: the Newton tolerance's
// share of the energy), losing 7.7 % in the impact (the contact nodes' relative motion, which
// vanishes under refinement: 0.23 % on the default mesh at the paper's dt).
TEST(ContactStabilized, CoarseTimeStepsNeverGainEnergyAndNeedNoStepCut)
{
  const MeshRun run   = run_mesh_case("prm/spheres_rho0.001.prm",
                                    paper_coarse_spheres({"Contact/dynamics=contact-stabilized",
                                                            "Time integration/time step=0.02",
                                                            "Time integration/end time=2.16"}));
  const auto energy   = run.history().column("total_energy");
  const auto cuts     = run.history().column("step_cuts");
  double largest_gain = -1.;
  for (const double e : energy)
    largest_gain = std::max(largest_gain, e / energy.front() - 1.);
  std::cout << "  spheres at dt = 0.02, contact-stabilized: largest energy change " << largest_gain
            << ", final " << energy.back() / energy.front() - 1. << "\n";
  EXPECT_LE(largest_gain, 1e-9);
  EXPECT_EQ(*std::max_element(cuts.begin(), cuts.end()), 0.);
  EXPECT_EQ(run.history().value(run.history().n_rows() - 1, "active_constraints"), 0.);
}

// No contact-force oscillation on 6.2 with the trapezoidal rule, where classical Newmark opens and
// closes the contact 123 times with forces up to 3.9: one contact episode, and after the first
// time unit the force (gamma lambda, ContactStabilizedNewmark::contact_force_factor()) within 0.01
// of the exact 0.5 (measured 8.2e-3: the scheme's dissipation at the two contact nodes).
TEST(ContactStabilized, IdenticalBarsContactForceDoesNotOscillate)
{
  const BarRun run =
      run_bar_case("prm/bars_identical.prm",
                   {"Contact/dynamics=contact-stabilized", "Time integration/beta=0.25"});
  const double deviation = max_force_deviation(run.history(), 0.5, 1., 19.);
  std::cout << "  6.2, contact-stabilized: max |F - 0.5| on (1, 19) = " << deviation << "\n";
  EXPECT_EQ(contact_episodes(run.history()), 1u);
  EXPECT_LE(deviation, 0.01);
}
} // namespace dyncontact::testing
