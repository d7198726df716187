// Acceptance tests of Contact/dynamics = velocity-update (Laursen & Love 2002) on the paper's
// identical bars (6.2) with the trapezoidal rule: exact solution one contact on [0, 20) with the
// force Z v / 2 = 0.5, after which bar 1 is at rest and bar 2 moves at the impact speed 1.
#include <cmath>
#include <gtest/gtest.h>

#include "case_run.h"

namespace dyncontact::testing
{
// The defining property: at every step with an active pair, the relative normal velocity of the
// contact nodes is zero after the step (bound 1e-12: round-off of velocities of order 1; measured
// 1.1e-16), where classical trapezoidal Newmark leaves a jump of the impact speed 1 and chatters
// (123 episodes on 6.1). Consequences checked against the exact solution: one contact episode; the
// force within 0.01 of 0.5 after the first time unit (measured 8.2e-3, the dissipation at the two
// contact nodes); no energy gain at any step (1e-12 of E0: the Newton tolerance's share) and the
// impact's loss, the two contact nodes' kinetic energy m v^2 / 4 with m = dx / 2 = 0.05 per node,
// i.e. 0.0125 / 5 = 0.25 % of E0 (measured 0.2500 %, bound 1e-6 relative).
TEST(VelocityUpdate, IdenticalBarsHaveNoNormalVelocityJumpInContact)
{
  const BarRun run = run_bar_case(
      "prm/bars_identical.prm", {"Contact/dynamics=velocity-update", "Time integration/beta=0.25"});
  const History& history = run.history();
  double largest_jump = 0., largest_gain = -1.;
  const double e0 = history.value(0, "total_energy");
  for (unsigned int row = 0; row < history.n_rows(); ++row)
  {
    if (history.value(row, "active_constraints") > 0.)
      largest_jump = std::max(largest_jump, history.value(row, "velocity_jump"));
    largest_gain = std::max(largest_gain, history.value(row, "total_energy") / e0 - 1.);
  }
  const double final_change = history.value(history.n_rows() - 1, "total_energy") / e0 - 1.;
  const double deviation    = max_force_deviation(history, 0.5, 1., 19.);
  std::cout << "  6.2 trapezoidal, velocity update: largest jump " << largest_jump
            << ", max |F - 0.5| on (1, 19) = " << deviation << ", energy change " << final_change
            << "\n";
  EXPECT_LE(largest_jump, 1e-12);
  EXPECT_EQ(contact_episodes(history), 1u);
  EXPECT_LE(deviation, 0.01);
  EXPECT_LE(largest_gain, 1e-12);
  EXPECT_NEAR(final_change, -0.0025, 0.0025 * 1e-6);
}
} // namespace dyncontact::testing
