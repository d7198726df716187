// The Signorini bar (prm/signorini_bar.prm): a bar clamped at its left end bouncing on a rigid
// obstacle, against its exact solution (ExactBarSolution with a clamped end, tested on its own in
// test_exact_bar_solution.cc): contact on [0.1, 1.0) of every period of 3.1, 10 periods.
#include <gtest/gtest.h>

#include "case_run.h"

namespace dyncontact::testing
{
namespace
{
const std::string signorini = "prm/signorini_bar.prm";
} // namespace

// The schemes that fix the contact dynamics keep one contact episode per period: 10 exact, at most
// 12 allowed (the 8th impact, reached by a wave front the mesh has smeared over a few elements,
// opens for a step once with taylor-papadopoulos and contact-stabilized, twice with
// mass-redistribution), while classical Newmark chatters (339 episodes, with 576
// energy-guard step cuts). The first contact starts within one step of the exact t = 0.1 and ends
// within two of the exact 1.0 (the release is reached by the reflected wave, whose front is spread
// over a few elements). The clamp's reaction is an external impulse: the run's momentum guard
// would stop a run that did not account for it.
TEST(SignoriniBar, FixedSchemesKeepOneContactPerPeriod)
{
  for (const std::string dynamics :
       {"taylor-papadopoulos", "mass-redistribution", "contact-stabilized"})
  {
    const BarRun run     = run_bar_case(signorini, {"Contact/dynamics=" + dynamics});
    const auto active    = run.history().column("active_constraints");
    const auto times     = run.history().column("time");
    const auto energy    = run.history().column("total_energy");
    double first_contact = -1., first_release = -1.;
    for (unsigned int row = 1; row < times.size() && first_release < 0.; ++row)
    {
      if (active[row] > 0. && first_contact < 0.)
        first_contact = times[row];
      if (active[row] == 0. && first_contact > 0.)
        first_release = times[row];
    }
    const auto intervals = run.exact->contact_intervals(0);
    std::cout << "  " << dynamics << ": " << contact_episodes(run.history())
              << " contact episodes (exact " << intervals.size() << "), first contact ["
              << first_contact << ", " << first_release << "), energy after 10 periods "
              << energy.back() / energy.front() - 1. << " relative\n";
    EXPECT_EQ(intervals.size(), 10u);
    EXPECT_LE(contact_episodes(run.history()), 12u) << dynamics;
    EXPECT_LE(std::abs(first_contact - intervals.front().first), run.time_step() * (1. + 1e-9))
        << dynamics;
    EXPECT_LE(std::abs(first_release - intervals.front().second),
              2. * run.time_step() * (1. + 1e-9))
        << dynamics;
  }
  const BarRun classical = run_bar_case(signorini, {"Contact/dynamics=none"});
  EXPECT_GT(contact_episodes(classical.history()), 100u);
}
} // namespace dyncontact::testing
