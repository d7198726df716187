#include <dyncontact/reference/exact_bar_solution.h>

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

using dyncontact::ExactBar;
using dyncontact::ExactBarSolution;

namespace
{
// The solution is exact: every value below is the sum of a few products of piecewise-constant
// states, so agreement is expected to round-off, 1e-12 (relative to values of order 1-10).
constexpr double tolerance = 1e-12;

/// A bar of length 10 with rho = A = 1 (the paper's unit data) and Young's modulus E.
ExactBar unit_bar(const double left_end, const double initial_velocity, const double E = 1.0)
{
  return {left_end, 10.0, E, 1.0, 1.0, initial_velocity};
}

/// Total kinetic plus strain energy of all bars at time t.
double total_energy(const ExactBarSolution& solution, const double t)
{
  double energy = 0.0;
  for (unsigned int bar = 0; bar < solution.n_bars(); ++bar)
    energy += solution.kinetic_energy(bar, t) + solution.strain_energy(bar, t);
  return energy;
}

/// Total momentum of all bars at time t plus the impulse the wall (if any) has taken up to t.
double momentum_with_wall_impulse(const ExactBarSolution& solution, const double t)
{
  double momentum = 0.0;
  for (unsigned int bar = 0; bar < solution.n_bars(); ++bar)
    momentum += solution.momentum(bar, t);
  for (unsigned int i = 0; i < solution.n_interfaces(); ++i)
    if (solution.right_bar(i) < 0)
      momentum += solution.contact_impulse(i, t);
  return momentum;
}

/// Expect that constructing the solution from the given data throws std::invalid_argument whose
/// message contains expected_text.
void expect_invalid_argument(const std::vector<ExactBar>& bars,
                             const std::optional<double> wall,
                             const double end_time,
                             const std::string& expected_text)
{
  try
  {
    ExactBarSolution(bars, wall, end_time);
    ADD_FAILURE() << "no exception for input that should mention '" << expected_text << "'";
  }
  catch (const std::invalid_argument& error)
  {
    EXPECT_NE(std::string(error.what()).find(expected_text), std::string::npos) << error.what();
  }
}
} // namespace

TEST(ExactBarSolution, BarOnRigidWall)
{
  // Paper case 6.1: a bar hitting a wall at v0 = 1 has contact force z v0 = 1 for 2 L / c = 20,
  // its tip rests during contact, then the bar leaves rigidly at -1. Tolerance: round-off.
  const ExactBarSolution solution({unit_bar(-10.0, 1.0)}, 0.0, 40.0);
  ASSERT_EQ(solution.n_interfaces(), 1u);
  EXPECT_EQ(solution.left_bar(0), 0);
  EXPECT_EQ(solution.right_bar(0), -1);
  for (const double t : {0.0, 5.0, 10.0, 19.9})
  {
    EXPECT_NEAR(solution.contact_force(0, t), 1.0, tolerance) << "t = " << t;
    EXPECT_NEAR(solution.velocity(0, 0.0, t), 0.0, tolerance) << "t = " << t;
    EXPECT_TRUE(solution.in_contact(0, t)) << "t = " << t;
  }
  for (const double t : {20.0, 25.0, 40.0})
  {
    EXPECT_EQ(solution.contact_force(0, t), 0.0) << "t = " << t;
    EXPECT_NEAR(solution.velocity(0, 0.0, t), -1.0, tolerance) << "t = " << t;
    EXPECT_FALSE(solution.in_contact(0, t)) << "t = " << t;
  }
  const auto intervals = solution.contact_intervals(0);
  ASSERT_EQ(intervals.size(), 1u);
  EXPECT_NEAR(intervals[0].first, 0.0, tolerance);
  EXPECT_NEAR(intervals[0].second, 20.0, tolerance);

  // At t = 5 the compression front is at X = -5: behind it the bar is at rest, touching the wall.
  for (const double X : {-10.0, -7.0, -5.1})
  {
    EXPECT_NEAR(solution.velocity(0, X, 5.0), 1.0, tolerance) << "X = " << X;
    EXPECT_NEAR(solution.displacement(0, X, 5.0), 5.0, tolerance) << "X = " << X;
    EXPECT_NEAR(solution.axial_force(0, X, 5.0), 0.0, tolerance) << "X = " << X;
  }
  for (const double X : {-5.0, -4.9, -2.0, 0.0})
  {
    EXPECT_NEAR(solution.velocity(0, X, 5.0), 0.0, tolerance) << "X = " << X;
    EXPECT_NEAR(solution.displacement(0, X, 5.0), -X, tolerance) << "X = " << X;
    EXPECT_NEAR(solution.axial_force(0, X, 5.0), -1.0, tolerance) << "X = " << X;
  }

  // After release: rigid motion at -1, stress free; the tip left the wall at t = 20.
  for (const double X : {-10.0, -6.3, -0.2, 0.0})
  {
    EXPECT_NEAR(solution.velocity(0, X, 30.0), -1.0, tolerance) << "X = " << X;
    EXPECT_NEAR(solution.axial_force(0, X, 30.0), 0.0, tolerance) << "X = " << X;
  }
  EXPECT_NEAR(solution.displacement(0, 0.0, 30.0), -10.0, tolerance);
}

TEST(ExactBarSolution, IdenticalBars)
{
  // Paper case 6.2, bars given right one first: equal impedances share the velocity, interface
  // velocity 0.5 and force z v0 / 2 = 0.5 for 20; then the striker rests and the other bar moves
  // at 1, both stress free. Tolerance: round-off.
  const ExactBarSolution solution({unit_bar(0.0, 0.0), unit_bar(-10.0, 1.0)}, {}, 40.0);
  ASSERT_EQ(solution.n_interfaces(), 1u);
  EXPECT_EQ(solution.left_bar(0), 1);
  EXPECT_EQ(solution.right_bar(0), 0);
  for (const double t : {0.0, 3.0, 10.0, 19.9})
  {
    EXPECT_NEAR(solution.contact_force(0, t), 0.5, tolerance) << "t = " << t;
    EXPECT_NEAR(solution.velocity(1, 0.0, t), 0.5, tolerance) << "t = " << t;
    EXPECT_NEAR(solution.velocity(0, 0.0, t), 0.5, tolerance) << "t = " << t;
  }
  for (const double t : {20.0, 30.0, 40.0})
  {
    EXPECT_EQ(solution.contact_force(0, t), 0.0) << "t = " << t;
    for (const double x : {0.0, 2.5, 7.0, 10.0})
    {
      EXPECT_NEAR(solution.velocity(1, x - 10.0, t), 0.0, tolerance) << "t = " << t;
      EXPECT_NEAR(solution.velocity(0, x, t), 1.0, tolerance) << "t = " << t;
      EXPECT_NEAR(solution.axial_force(1, x - 10.0, t), 0.0, tolerance) << "t = " << t;
      EXPECT_NEAR(solution.axial_force(0, x, t), 0.0, tolerance) << "t = " << t;
    }
  }
  const auto intervals = solution.contact_intervals(0);
  ASSERT_EQ(intervals.size(), 1u);
  EXPECT_NEAR(intervals[0].first, 0.0, tolerance);
  EXPECT_NEAR(intervals[0].second, 20.0, tolerance);
}

TEST(ExactBarSolution, DissimilarBars)
{
  // Paper case 6.3 (c1 = 0.7, z1 = 0.7; c2 = z2 = 1): force z1 z2 / (z1 + z2) = 7/17 until the
  // reflection in bar 2 returns at 20, then 21/289 until the one in bar 1 returns at 2 L / c1 =
  // 200/7, where the bars separate. Tolerance: round-off.
  const ExactBarSolution solution({unit_bar(-10.0, 1.0, 0.49), unit_bar(0.0, 0.0)}, {}, 40.0);
  for (const double t : {0.0, 10.0, 19.9})
    EXPECT_NEAR(solution.contact_force(0, t), 7.0 / 17.0, tolerance) << "t = " << t;
  for (const double t : {20.0, 25.0, 28.5})
    EXPECT_NEAR(solution.contact_force(0, t), 21.0 / 289.0, tolerance) << "t = " << t;
  for (const double t : {200.0 / 7.0, 30.0, 40.0})
    EXPECT_EQ(solution.contact_force(0, t), 0.0) << "t = " << t;
  const auto intervals = solution.contact_intervals(0);
  ASSERT_EQ(intervals.size(), 1u);
  EXPECT_NEAR(intervals[0].first, 0.0, tolerance);
  EXPECT_NEAR(intervals[0].second, 200.0 / 7.0, tolerance);
}

TEST(ExactBarSolution, InitialGap)
{
  // Case 6.2 with a gap of 0.5: the striker closes it at v0 = 1 at t = 0.5, then everything is
  // case 6.2 shifted by 0.5 in time. Tolerance: round-off.
  const ExactBarSolution solution({unit_bar(-10.0, 1.0), unit_bar(0.5, 0.0)}, {}, 40.0);
  EXPECT_EQ(solution.contact_force(0, 0.4), 0.0);
  EXPECT_NEAR(solution.contact_force(0, 10.0), 0.5, tolerance);
  EXPECT_NEAR(solution.displacement(1, 0.5, 10.0), 0.5 * 9.5, tolerance);
  const auto intervals = solution.contact_intervals(0);
  ASSERT_EQ(intervals.size(), 1u);
  EXPECT_NEAR(intervals[0].first, 0.5, tolerance);
  EXPECT_NEAR(intervals[0].second, 20.5, tolerance);
}

TEST(ExactBarSolution, ChainWithWallSatisfiesContactConditions)
{
  // Three dissimilar bars with gaps and a wall: closures, a release and a renewed contact between
  // bars 1 and 2 (when written, a fine lumped-mass simulation matched these contact periods within
  // 0.03 in time). At many times the gaps are non-negative, forces compressive, and in contact the
  // ends share velocity and force. Tolerance: round-off, scaled by the largest positions (30).
  const std::vector<ExactBar> bars = {{-30.0, 8.0, 2.0, 1.0, 1.5, 1.3},
                                      {-21.5, 5.0, 1.0, 2.0, 1.0, -0.2},
                                      {-15.0, 12.0, 0.7, 1.2, 0.8, 0.4}};
  const ExactBarSolution solution(bars, 0.0, 40.0);
  ASSERT_EQ(solution.n_interfaces(), 3u);
  EXPECT_EQ(solution.contact_intervals(0).size(), 1u);
  EXPECT_EQ(solution.contact_intervals(1).size(), 2u);
  EXPECT_EQ(solution.contact_intervals(2).size(), 1u);

  const auto right_end = [&](const unsigned int bar)
  { return bars[bar].left_end + bars[bar].length; };
  for (double t = 0.0; t <= 40.0; t += 0.0731)
    for (unsigned int i = 0; i < 3; ++i)
    {
      const unsigned int left = solution.left_bar(i);
      const int right         = solution.right_bar(i);
      const double left_position =
          right_end(left) + solution.displacement(left, right_end(left), t);
      const double right_position =
          right < 0 ? 0.0
                    : bars[right].left_end + solution.displacement(right, bars[right].left_end, t);
      const double left_force = -solution.axial_force(left, right_end(left), t);
      if (solution.in_contact(i, t))
      {
        EXPECT_NEAR(right_position - left_position, 0.0, 30 * tolerance) << "t = " << t;
        EXPECT_GE(solution.contact_force(i, t), 0.0) << "t = " << t;
        EXPECT_NEAR(left_force, solution.contact_force(i, t), 10 * tolerance) << "t = " << t;
        const double right_velocity =
            right < 0 ? 0.0 : solution.velocity(right, bars[right].left_end, t);
        EXPECT_NEAR(solution.velocity(left, right_end(left), t), right_velocity, 10 * tolerance)
            << "t = " << t;
      }
      else
      {
        EXPECT_GE(right_position - left_position, -30 * tolerance) << "t = " << t;
        EXPECT_EQ(solution.contact_force(i, t), 0.0) << "t = " << t;
        EXPECT_NEAR(left_force, 0.0, 10 * tolerance) << "t = " << t;
      }
    }
}

TEST(ExactBarSolution, ConservesMomentumAndEnergy)
{
  // Elastic bars and frictionless contact conserve energy; momentum changes only by the impulse
  // of the wall. The exact fields must show this to round-off (1e-12 relative) at many times
  // that are not aligned with the events, in every case above.
  struct Case
  {
    std::string name;
    std::vector<ExactBar> bars;
    std::optional<double> wall;
  };
  const std::vector<Case> cases = {
      {"6.1 wall", {unit_bar(-10.0, 1.0)}, 0.0},
      {"6.2 identical", {unit_bar(-10.0, 1.0), unit_bar(0.0, 0.0)}, {}},
      {"6.3 dissimilar", {unit_bar(-10.0, 1.0, 0.49), unit_bar(0.0, 0.0)}, {}},
      {"initial gap", {unit_bar(-10.0, 1.0), unit_bar(0.5, 0.0)}, {}},
      {"chain with wall",
       {{-30.0, 8.0, 2.0, 1.0, 1.5, 1.3},
        {-21.5, 5.0, 1.0, 2.0, 1.0, -0.2},
        {-15.0, 12.0, 0.7, 1.2, 0.8, 0.4}},
       0.0}};
  for (const Case& c : cases)
  {
    const ExactBarSolution solution(c.bars, c.wall, 40.0);
    const double initial_momentum = momentum_with_wall_impulse(solution, 0.0);
    const double initial_energy   = total_energy(solution, 0.0);
    double momentum_scale         = 0.0;
    for (const ExactBar& bar : c.bars)
      momentum_scale += std::abs(bar.density * bar.area * bar.length * bar.initial_velocity);
    for (double t = 0.0; t <= 40.0; t += 0.0173)
    {
      EXPECT_NEAR(
          momentum_with_wall_impulse(solution, t), initial_momentum, tolerance * momentum_scale)
          << c.name << ", t = " << t;
      EXPECT_NEAR(total_energy(solution, t), initial_energy, tolerance * initial_energy)
          << c.name << ", t = " << t;
    }
  }
}

// A bar clamped at its left end, moving at v0 = 1 (c = 1, L = 10, no obstacle): the classical
// solution (d'Alembert, the clamped-free bar) stops the bar from the clamp outward in one travel
// time L/c, reverses it in the next, and after 4 L/c the bar is back in its initial state, while
// the clamp stays at rest and the energy 1/2 rho A L v0^2 = 5 stays constant. At t = L/c the bar is
// at rest and stretched by the stopping wave: N = z v0 = 1 (tension) everywhere.
TEST(ExactBarSolution, ClampedBarReturnsToItsInitialStateEveryFourTravelTimes)
{
  const ExactBarSolution solution({unit_bar(0.0, 1.0)}, std::nullopt, 50.0, true);
  for (const double t : {0.5, 7.0, 23.0, 41.5})
  {
    EXPECT_NEAR(solution.velocity(0, 0.0, t), 0.0, tolerance) << t;
    EXPECT_NEAR(total_energy(solution, t), 5.0, tolerance) << t;
  }
  for (const double X : {2.5, 5.0, 9.0})
  {
    EXPECT_NEAR(solution.velocity(0, X, 10.0), 0.0, tolerance) << X;
    EXPECT_NEAR(solution.axial_force(0, X, 10.0), 1.0, tolerance) << X;
    EXPECT_NEAR(solution.velocity(0, X, 20.0), -1.0, tolerance) << X;
    EXPECT_NEAR(solution.axial_force(0, X, 20.0), 0.0, tolerance) << X;
    EXPECT_NEAR(solution.velocity(0, X, 40.0), 1.0, tolerance) << X;
    EXPECT_NEAR(solution.axial_force(0, X, 40.0), 0.0, tolerance) << X;
    EXPECT_NEAR(solution.displacement(0, X, 40.0), 0.0, tolerance) << X;
  }
}

TEST(ExactBarSolution, RejectsBadInput)
{
  // Invalid data must be refused with a message naming the culprit; no tolerance involved.
  expect_invalid_argument(
      {unit_bar(-10.0, 1.0), {0.0, -1.0, 1.0, 1.0, 1.0, 0.0}}, {}, 1.0, "bar 1: length");
  expect_invalid_argument({{0.0, 1.0, 1.0, 0.0, 1.0, 0.0}}, {}, 1.0, "bar 0: density");
  expect_invalid_argument(
      {unit_bar(-10.0, 1.0), unit_bar(-1.0, 0.0)}, {}, 1.0, "bar 0 overlaps bar 1");
  expect_invalid_argument({unit_bar(-10.0, 1.0)}, -1.0, 1.0, "bar 0 reaches beyond the wall");
  expect_invalid_argument(
      {unit_bar(-10.0, 1.0)}, {}, -1.0, "end_time"); // 0 is allowed: the reference at t = 0

  const ExactBarSolution solution({unit_bar(-10.0, 1.0)}, {}, 1.0);
  EXPECT_THROW(solution.velocity(0, -5.0, 1.5), std::out_of_range);
  EXPECT_THROW(solution.velocity(1, -5.0, 0.5), std::out_of_range);
  EXPECT_THROW(solution.velocity(0, 1.0, 0.5), std::out_of_range);
}
