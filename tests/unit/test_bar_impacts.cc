// Acceptance tests of the paper's bar impacts (Taylor & Papadopoulos 1993, sections 6.1-6.3): the
// shipped prm files are run in-process and compared with the exact wave solution
// (ExactBarSolution, tested on its own in test_exact_bar_solution.cc) and with the paper's
// closed-form first-step values, eqs. (17)-(18).
#include <cmath>
#include <gtest/gtest.h>

#include "bar_run.h"

namespace dyncontact::testing
{
namespace
{
const std::string rigid_wall = "prm/bar_rigid_wall.prm";
const std::string identical  = "prm/bars_identical.prm";
const std::string dissimilar = "prm/bars_dissimilar.prm";

/** Largest |FE - exact| of body b's tip velocity over the given rows. */
double max_tip_velocity_error(const BarRun& run,
                              const unsigned int body,
                              const std::vector<unsigned int>& rows)
{
  const auto v_tip = run.history().column("v_tip_" + std::to_string(body + 1));
  const auto times = run.history().column("time");
  double error     = 0.;
  for (const unsigned int row : rows)
    error = std::max(
        error,
        std::abs(v_tip[row] - run.exact->velocity(body, run.tip_position(body), times[row])));
  return error;
}

/** Largest |a_tip| of body b over the rows (the exact tip acceleration is zero between jumps). */
double max_tip_acceleration(const BarRun& run,
                            const unsigned int body,
                            const std::vector<unsigned int>& rows)
{
  const auto a_tip = run.history().column("a_tip_" + std::to_string(body + 1));
  double value     = 0.;
  for (const unsigned int row : rows)
    value = std::max(value, std::abs(a_tip[row]));
  return value;
}

double contact_force_rms_error(const BarRun& run, const std::vector<unsigned int>& rows)
{
  const auto force = run.history().column("contact_force");
  const auto times = run.history().column("time");
  double sum       = 0.;
  for (const unsigned int row : rows)
    sum += std::pow(force[row] - run.exact_contact_force(times[row]), 2);
  return std::sqrt(sum / rows.size());
}

/** Time of the last step with an active contact pair. */
double last_active_time(const BarRun& run)
{
  const auto active = run.history().column("active_constraints");
  const auto times  = run.history().column("time");
  double last       = -1.;
  for (unsigned int row = 0; row < times.size(); ++row)
    if (active[row] > 0.)
      last = times[row];
  return last;
}

/** Checks B and C of the acceptance list for one paper case. */
void check_paper_case(const std::string& prm_file,
                      const double velocity_bound,
                      const double acceleration_bound)
{
  const BarRun run   = run_bar_case(prm_file);
  const auto samples = contact_samples(run);
  ASSERT_GT(samples.size(), 100u) << "the contact interval must be resolved by many steps";

  for (unsigned int b = 0; b < run.exact->n_bars(); ++b)
  {
    const double velocity_error = max_tip_velocity_error(run, b, samples);
    std::cout << "  " << prm_file << " body " << b + 1 << ": max tip velocity error "
              << velocity_error << ", max |tip acceleration| "
              << max_tip_acceleration(run, b, samples) << "\n";
    EXPECT_LE(velocity_error, velocity_bound);
    if (acceleration_bound > 0.)
    {
      EXPECT_LE(max_tip_acceleration(run, b, samples), acceleration_bound);
    }

    const double t_end          = run.history().column("time").back();
    const double final_momentum = run.history().column("momentum_" + std::to_string(b + 1)).back();
    const double exact_momentum = run.exact->momentum(b, t_end);
    std::cout << "  " << prm_file << " body " << b + 1 << ": final momentum " << final_momentum
              << " (exact " << exact_momentum << ")\n";
    // C: 0.05 of the exact momentum (unit order here) is the acceptance bound.
    EXPECT_NEAR(final_momentum, exact_momentum, 0.05);
  }

  // C: the force is recovered from the contact nodes' equations of motion; RMS over the contact
  // interval of the exact force of unit order, bound 0.01 from the acceptance list.
  const double force_error = contact_force_rms_error(run, samples);
  std::cout << "  " << prm_file << ": contact force RMS error " << force_error << " over "
            << samples.size() << " samples\n";
  EXPECT_LE(force_error, 0.01);

  // C: the exact contact ends at a time step (Courant number 1); the discrete release may lag it
  // by at most one step (1e-9 relative slack for the round-off of t = n dt).
  const double exact_end = run.exact->contact_intervals(0).front().second;
  std::cout << "  " << prm_file << ": last active step t = " << last_active_time(run)
            << ", exact end of contact " << exact_end << "\n";
  EXPECT_LE(std::abs(last_active_time(run) - exact_end), run.time_step() * (1. + 1e-9));
}
} // namespace

// A: classical Newmark at the first contact step of 6.1, eqs. (17)-(18): with only the
// displacement constrained, v_tip = 1 - gamma/beta and a_tip = -dt v0 / (beta dt^2). These are
// exact consequences of the Newmark formulas, so only round-off separates them (1e-9 relative).
TEST(BarImpacts, ClassicalNewmarkFirstContactStepMatchesEquations17And18)
{
  for (const auto& [beta, expected_velocity, expected_acceleration] :
       std::vector<std::tuple<std::string, double, double>>{{"0.001", -499., -1e4},
                                                            {"0.25", -1., -40.}})
  {
    const BarRun run          = run_bar_case(rigid_wall,
                                    {"Time integration/scheme=classical",
                                              "Time integration/beta=" + beta,
                                              "Time integration/end time=0.1"});
    const double velocity     = run.history().value(1, "v_tip_1");
    const double acceleration = run.history().value(1, "a_tip_1");
    std::cout << "  beta = " << beta << ": v_tip = " << velocity << ", a_tip = " << acceleration
              << "\n";
    EXPECT_NEAR(velocity, expected_velocity, 1e-9 * std::abs(expected_velocity));
    EXPECT_NEAR(acceleration, expected_acceleration, 1e-9 * std::abs(expected_acceleration));
  }
}

// B, C for 6.1. At Courant number 1 the modified scheme puts the tip exactly at the wall's
// velocity and acceleration (zero) while in contact: 1e-7 and 1e-6 are round-off-level bounds
// from the acceptance list.
TEST(BarImpacts, RigidWallModifiedNewmarkMatchesExactSolution)
{
  check_paper_case(rigid_wall, 1e-7, 1e-6);
}

// B, C for 6.2. By symmetry the interface of identical bars moves at the centre-of-mass velocity
// 0.5 with zero acceleration; the bounds 1e-7, 1e-6 leave room only for round-off and the
// nearly (not exactly) explicit beta = 0.001.
TEST(BarImpacts, IdenticalBarsModifiedNewmarkMatchesExactSolution)
{
  check_paper_case(identical, 1e-7, 1e-6);
}

// B, C for 6.3. Dissimilar lumped masses at the interface make the discrete solution ring after
// each wave arrival (the paper's "local oscillations"); 0.05 on a velocity of order 1 is the
// acceptance bound. The tip acceleration rings too and is not asserted here.
TEST(BarImpacts, DissimilarBarsModifiedNewmarkMatchesExactSolution)
{
  check_paper_case(dissimilar, 0.05, 0.);
}

// D: lumped masses, equal and opposite contact forces and the mass-weighted rate correction
// conserve the total momentum exactly; 1e-10 relative allows the Newton/direct-solver round-off
// accumulated over a few hundred steps.
TEST(BarImpacts, TwoBarMomentumIsConservedAtEveryStepByBothSchemes)
{
  for (const std::string& prm_file : {identical, dissimilar})
    for (const std::string scheme : {"classical", "modified"})
    {
      const BarRun run = run_bar_case(prm_file, {"Time integration/scheme=" + scheme});
      const auto p1 = run.history().column("momentum_1"), p2 = run.history().column("momentum_2");
      double drift = 0.;
      for (unsigned int row = 0; row < p1.size(); ++row)
        drift = std::max(drift,
                         std::abs(p1[row] + p2[row] - (p1[0] + p2[0])) / std::abs(p1[0] + p2[0]));
      std::cout << "  " << prm_file << ", " << scheme << ": max relative momentum drift " << drift
                << "\n";
      EXPECT_LE(drift, 1e-10);
    }
}

// E: gamma = 1/2 Newmark conserves 1/2 vMv + 1/2 uKu + (beta - 1/4) dt^2/2 aMa exactly for a
// linear system on which the constraint forces do no work (free flight, persistent contact), so
// 1e-8 relative is round-off; the modified scheme's correction at the impact step removes
// 1/2 m_red [[v0]]^2 (a wall has infinite mass), also an identity up to round-off.
TEST(BarImpacts, AlgorithmicEnergyIsConservedAndImpactRemovesReducedMassEnergy)
{
  struct Case
  {
    std::string prm_file;
    std::vector<std::string> overrides;
    double reduced_mass; // of the two contact nodes: lumped masses rho A h / 2
    double impact_speed;
  };
  const double dissimilar_bar_1 = 0.05, dissimilar_bar_2 = 0.5 * 10. / 70.;
  const std::vector<Case> cases = {
      {rigid_wall, {}, 0.05, 1.},
      {identical, {}, 0.025, 1.},
      {dissimilar,
       {},
       dissimilar_bar_1 * dissimilar_bar_2 / (dissimilar_bar_1 + dissimilar_bar_2),
       1.},
      // initial gap 0.5: 5 steps of free flight before contact starts at t = 0.5
      {identical, {"Geometry/Bar 2/left end=0.5"}, 0.025, 1.}};
  for (const auto& test_case : cases)
  {
    const BarRun run    = run_bar_case(test_case.prm_file, test_case.overrides);
    const auto energy   = run.history().column("algorithmic_energy");
    const auto active   = run.history().column("active_constraints");
    unsigned int impact = 0;
    while (active[impact] == 0.)
      ++impact;
    double drift = 0.;
    for (unsigned int row = 1; row < energy.size(); ++row)
      if ((active[row] == 0. && row < impact) || (active[row] > 0. && active[row - 1] > 0.))
        drift = std::max(drift, std::abs(energy[row] - energy[row - 1]) / energy[0]);
    const double removed  = energy[impact - 1] - energy[impact];
    const double expected = 0.5 * test_case.reduced_mass * std::pow(test_case.impact_speed, 2);
    std::cout << "  " << test_case.prm_file << (test_case.overrides.empty() ? "" : " with gap")
              << ": impact at step " << impact << ", energy removed " << removed << " (expected "
              << expected << "), max relative step change " << drift << "\n";
    EXPECT_LE(drift, 1e-8);
    EXPECT_NEAR(removed, expected, 1e-8 * expected);
  }
}

// F: profile at t = 5 of 6.1 (modified, beta = 0.001): the front is at mid-bar. Bounds from the
// acceptance list: u within 0.01 everywhere; v within 0.03 except at the node the front sits on,
// whose exact value is a jump.
TEST(BarImpacts, RigidWallProfileAtTimeFiveMatchesExactSolution)
{
  const BarRun run = run_bar_case(rigid_wall, {"Time integration/end time=5"});
  const double t   = run.history().column("time").back();
  ASSERT_NEAR(t, 5., 1e-12);
  double u_error = 0., v_error = 0.;
  for (const auto& node : run.simulation->all_nodes())
  {
    const double X = node.position[0];
    u_error        = std::max(u_error,
                       std::abs(run.simulation->current_displacement()[node.dofs[0]] -
                                run.exact->displacement(0, X, t)));
    if (std::abs(X - (-5.)) > 1e-9)
      v_error = std::max(v_error,
                         std::abs(run.simulation->current_velocity()[node.dofs[0]] -
                                  run.exact->velocity(0, X, t)));
  }
  std::cout << "  t = 5 profile: max u error " << u_error << ", max v error off the front "
            << v_error << "\n";
  EXPECT_LE(u_error, 0.01);
  EXPECT_LE(v_error, 0.03);
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
namespace
{
/** RMS over the exact contact interval of the penalty force minus the multiplier force. */
double penalty_force_difference(const std::vector<std::string>& overrides,
                                const std::string& penalty_factor)
{
  const BarRun multiplier = run_bar_case(identical, overrides);
  auto penalty_overrides  = overrides;
  penalty_overrides.insert(
      penalty_overrides.end(),
      {"Contact/formulation=penalty", "Contact/penalty factor=" + penalty_factor});
  const BarRun penalty    = run_bar_case(identical, penalty_overrides);
  const auto rows         = contact_samples(multiplier);
  const auto f_multiplier = multiplier.history().column("contact_force");
  const auto f_penalty    = penalty.history().column("contact_force");
  double sum              = 0.;
  for (const unsigned int row : rows)
    sum += std::pow(f_penalty[row] - f_multiplier[row], 2);
  return std::sqrt(sum / rows.size());
}
} // namespace

// H: the penalty force eps <-g> converges to the multiplier force as eps grows, with an error of
// order 1/eps. At the paper's beta = 0.001 the error must fall monotonically over three decades
// and by at least 10x in all; at beta = 1/4 (no nearly-explicit dispersion mixed in) each decade
// must gain at least a factor 8 (first order with a 20% margin).
TEST(BarImpacts, PenaltyForceApproachesMultiplierForceAsPenaltyGrows)
{
  for (const auto& [overrides, per_decade_gain, total_gain] :
       std::vector<std::tuple<std::vector<std::string>, double, double>>{
           {{}, 1., 10.}, {{"Time integration/beta=0.25"}, 8., 512.}})
  {
    std::vector<double> errors;
    for (const std::string factor : {"10", "100", "1000", "10000"})
    {
      errors.push_back(penalty_force_difference(overrides, factor));
      std::cout << "  " << (overrides.empty() ? "beta = 0.001" : "beta = 0.25")
                << ", penalty factor " << factor
                << ": RMS(F_penalty - F_multiplier) = " << errors.back() << "\n";
    }
    for (unsigned int i = 1; i < errors.size(); ++i)
      EXPECT_LT(errors[i] * per_decade_gain, errors[i - 1]);
    EXPECT_LT(errors.back() * total_gain, errors.front());
  }
}
} // namespace dyncontact::testing
