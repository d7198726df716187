#include <dyncontact/reference/hertz_impact.h>
#include <dyncontact/reference/impact_measures.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using dyncontact::ElasticSphere;
using dyncontact::HertzImpact;
using dyncontact::ImpactMeasures;
using dyncontact::measure_impact;

namespace
{
/**
 * The exact Hertz impact of the paper's spheres (R = 8, E = 5e3, nu = 0.3) of density rho at the
 * relative speed 2, first touch at 2 + touch_offset * dt, sampled with step dt from begin to end.
 */
struct SampledHertzImpact
{
  double rho;
  double dt;
  double begin;
  double end;
  double touch_offset;
};

HertzImpact hertz_impact(const SampledHertzImpact& c)
{
  const ElasticSphere sphere{8.0, 5e3, 0.3, c.rho};
  return HertzImpact::two_spheres(sphere, sphere, 2.0, 2.0 + c.touch_offset * c.dt);
}

std::vector<double> sample_times(const SampledHertzImpact& c)
{
  const long n_samples = std::lround((c.end - c.begin) / c.dt) + 1;
  std::vector<double> times;
  for (long n = 0; n < n_samples; ++n)
    times.push_back(c.begin + n * c.dt);
  return times;
}

/**
 * The step in units of the time scale T = d_max / v of the impact, h = dt / T. In these units
 * (x = d / d_max, s = t / T) Hertz's ODE reads x'' = -(5/4) x^{3/2}, so every error bound below is
 * a number times a power of h. The contact lasts 2.943 T, i.e. 2.943 / h steps.
 */
double scaled_step(const SampledHertzImpact& c)
{
  const HertzImpact hertz = hertz_impact(c);
  return c.dt * hertz.relative_approach_speed() / hertz.maximum_approach();
}

/// The two sampled cases of the paper's section 6.4 (about 33 and 26 steps per contact), each with
/// first touch on a sample, halfway between samples and 0.3 of a step after one.
std::vector<SampledHertzImpact> sampled_cases()
{
  std::vector<SampledHertzImpact> cases;
  for (const double offset : {0.0, 0.5, 0.3})
  {
    cases.push_back({0.001, 0.0025, 1.9, 2.2, offset});
    cases.push_back({1.0, 0.05, 1.5, 4.0, offset});
  }
  return cases;
}

std::string describe(const SampledHertzImpact& c)
{
  std::ostringstream text;
  text << "rho = " << c.rho << ", dt = " << c.dt << ", touch offset " << c.touch_offset << " dt";
  return text.str();
}

/// The RMS of @p force over the centres of the 5-point windows that lie in the contact interval.
double rms_over_window_centres(const std::vector<double>& force)
{
  std::size_t first = force.size();
  std::size_t last  = 0;
  for (std::size_t n = 0; n < force.size(); ++n)
    if (force[n] > 0.0)
    {
      first = std::min(first, n);
      last  = n;
    }
  double sum_of_squares = 0.0;
  std::size_t count     = 0;
  for (std::size_t n = first + 2; n + 2 <= last; ++n, ++count)
    sum_of_squares += force[n] * force[n];
  return std::sqrt(sum_of_squares / static_cast<double>(count));
}
} // namespace

// Measures the exact Hertz history and compares with the closed forms. Error bounds, derived in the
// scaled units of scaled_step() (h = dt / T; h = 0.0898 for rho = 0.001 and 0.1133 for rho = 1):
// - Peak. Near the peak F / F_max = 1 - A s^2 + B s^4 with A = 15/16, B = 75/256 (from x'' =
//   -(5/4) x^{3/2}: x'''' = 75/32 at the peak). The parabola through three samples at s0 - h, s0,
//   s0 + h (|s0| <= h/2) reproduces the quadratic part; the quartic leaves the remainder s^4 - p(s)
//   = w(s) (s + 3 s0), w = (s - s0)((s - s0)^2 - h^2), so at the true peak p(0) - 1 = -3 B s0^2
//   (h^2
//   - s0^2), at most (9/16) B h^4 = 0.165 h^4; the vertex lies higher than p(0) only by
//   p'(0)^2 / (4 A) = O(h^6). Tolerance 0.2 h^4 relative (1.3e-5 and 3.3e-5). The vertex lies
//   p'(0) / (2 A) = B s0 (h^2 - 4 s0^2) / A <= 0.1925 (B / A) h^3 = 0.060 h^3 from the peak;
//   tolerance 0.07 h^3 T.
// - Contact ends. x = s - s^{7/2} / 7 + O(s^6) from touch, so F^{2/3}, proportional to x, through
//   samples at a and a + h (0 <= a <= h) extrapolates to s* = c (a^{7/2} - a D) / (1 - c D) with c
//   = 1/7, D = ((a + h)^{7/2} - a^{7/2}) / h: early (s* < 0) by at most (2^{7/2} - 1) h^{7/2} / 7 /
//   (1 - c D) < 1.5 h^{7/2} (T units), and the same at separation by symmetry. So the duration is
//   too long by at most 3 h^{7/2} T = 1.02 h^{7/2} t_c (t_c = 2.943 T); tolerance 1.05 h^{7/2} t_c
//   (2.3e-4 and 5.1e-4 relative).
// - Impulse (2 m* v = 1.6 F_max T). F vanishes like s^{3/2} at both ends with F' = 0 there, so the
//   regular Euler-Maclaurin terms vanish and the trapezoidal error is the generalized one (Navot)
//   of the two s^{3/2} ends: zeta(-3/2, theta) h^{5/2} F_max T each, theta = a / h the grid phase.
//   max over theta of |zeta(-3/2, theta)| = 0.03154 (mpmath), so the relative error is at most
//   2 * 0.03154 / 1.6 h^{5/2} = 0.0394 h^{5/2}; tolerance 0.045 h^{5/2} (1.1e-4 and 1.9e-4); the
//   next singular term, of order h^{15/2}, is negligible.
// - Ringing. P_n = 4th difference / 16 is h^4 F'''' / 16 + ... for a smooth F: 0.44 h^4 F_max at
//   the peak (F'''' = 24 B F_max / T^4). It is largest for the first (last) window of the contact,
//   where F ~ F_max s^{3/2}: with samples at a + j h, j = 0..4, |Delta^4 s^{3/2}| decreases in a
//   and is 0.187 h^{3/2} at a = 0, so |P_n| <= 0.0117 h^{3/2} F_max and the RMS is below 0.012
//   h^{3/2} (3.2e-4 and 4.6e-4).
TEST(ImpactMeasures, ExactHertzHistoryReproducesClosedForms)
{
  std::cout << std::scientific << std::setprecision(3);
  for (const SampledHertzImpact& c : sampled_cases())
  {
    SCOPED_TRACE(describe(c));
    const HertzImpact hertz         = hertz_impact(c);
    const std::vector<double> times = sample_times(c);
    const ImpactMeasures measures   = measure_impact(times, hertz.contact_force_history(times));
    const double h                  = scaled_step(c);
    const double time_scale         = hertz.maximum_approach() / hertz.relative_approach_speed();
    const double t0                 = hertz.first_touch_time();
    const double t_c                = hertz.contact_duration();

    const double peak_error = measures.peak_force / hertz.maximum_force() - 1.0;
    EXPECT_LE(std::abs(peak_error), 0.2 * std::pow(h, 4));
    EXPECT_NEAR(measures.peak_time, t0 + 0.5 * t_c, 0.07 * std::pow(h, 3) * time_scale);

    const double end_bound = 1.5 * std::pow(h, 3.5) * time_scale;
    EXPECT_LE(measures.contact_start, t0);
    EXPECT_GE(measures.contact_start, t0 - end_bound);
    EXPECT_GE(measures.contact_end, t0 + t_c);
    EXPECT_LE(measures.contact_end, t0 + t_c + end_bound);
    const double duration_error = measures.duration / t_c - 1.0;
    EXPECT_GE(duration_error, 0.0);
    EXPECT_LE(duration_error, 1.05 * std::pow(h, 3.5));

    const double impulse_error = measures.impulse / hertz.impulse() - 1.0;
    EXPECT_LE(std::abs(impulse_error), 0.045 * std::pow(h, 2.5));

    EXPECT_LE(measures.ringing, 0.012 * std::pow(h, 1.5));

    std::cout << describe(c) << " (h = " << h << ", " << measures.contact_samples
              << " samples in contact): relative errors peak " << peak_error << ", duration "
              << duration_error << ", impulse " << impulse_error << "; ringing " << measures.ringing
              << "\n";
  }
}

// Multiplies the positive samples of the exact Hertz histories by 1 + e (-1)^n, e = 0.05: a
// period-2 oscillation of relative amplitude e. Then P_n = e (-1)^n B_n + P_n(clean), with B_n =
// (F_{n-2} + 4 F_{n-1} + 6 F_n + 4 F_{n+1} + F_{n+2}) / 16 = F_n + dt^2 F'' / 2 + ... and |F''|
// <= 1.875 F_max / T^2 (at the peak; less at the centres of the end windows), so by the triangle
// inequality for RMS norms ringing * peak_force differs from e RMS(F_n) (over the window centres)
// by at most e 0.94 h^2 F_max + 0.012 h^{3/2} F_max (the clean bound of the test above). That is 2
// % and 3 % of the ringing for rho = 0.001 and 1; the tolerance takes this bound with h^2 instead
// of 0.94 h^2. The oscillation also makes the ringing more than 10 times (in fact 500 to 1400
// times) that of the clean history. (A 5-point moving average would give 0.8 e for a constant
// amplitude, but its smooth-force floor dt^2 F'' of 1-1.5 % of F_max would make it only 2-3 times
// the clean value here; see measure_impact().)
TEST(ImpactMeasures, PeriodTwoOscillationGivesItsAmplitude)
{
  const double e = 0.05;
  std::cout << std::scientific << std::setprecision(3);
  for (const SampledHertzImpact& c : sampled_cases())
  {
    SCOPED_TRACE(describe(c));
    const HertzImpact hertz           = hertz_impact(c);
    const std::vector<double> times   = sample_times(c);
    const std::vector<double> clean   = hertz.contact_force_history(times);
    std::vector<double> ringing_force = clean;
    for (std::size_t n = 0; n < ringing_force.size(); ++n)
      ringing_force[n] *= 1.0 + (n % 2 == 0 ? e : -e);

    const ImpactMeasures clean_measures = measure_impact(times, clean);
    const ImpactMeasures measures       = measure_impact(times, ringing_force);
    const double h                      = scaled_step(c);
    const double expected               = e * rms_over_window_centres(clean) / measures.peak_force;
    const double tolerance =
        (e * h * h + 0.012 * std::pow(h, 1.5)) * hertz.maximum_force() / measures.peak_force;
    EXPECT_NEAR(measures.ringing, expected, tolerance);
    EXPECT_GT(measures.ringing, 10.0 * clean_measures.ringing);
    EXPECT_EQ(measures.contact_samples, clean_measures.contact_samples);

    std::cout << describe(c) << ": ringing " << measures.ringing << ", expected " << expected
              << " (relative difference " << measures.ringing / expected - 1.0 << "), clean "
              << clean_measures.ringing << "\n";
  }
}

// Zeros inside the contact (classical Newmark may release and close the contact within an impact)
// keep one contact interval: the ends, which depend only on the first two and last two positive
// samples, do not move, contact_samples counts the positive samples only and the impulse loses
// exactly the removed samples (trapezoidal weight dt; round-off tolerance).
TEST(ImpactMeasures, ChatterZerosStayInsideOneContact)
{
  const SampledHertzImpact c      = {0.001, 0.0025, 1.9, 2.2, 0.3};
  const HertzImpact hertz         = hertz_impact(c);
  const std::vector<double> times = sample_times(c);
  const std::vector<double> clean = hertz.contact_force_history(times);
  std::size_t first               = 0;
  while (!(clean[first] > 0.0))
    ++first;
  std::vector<double> chattering          = clean;
  const std::vector<std::size_t> released = {first + 3, first + 4, first + 20};
  double removed_force                    = 0.0;
  for (const std::size_t n : released)
  {
    removed_force += chattering[n];
    chattering[n] = 0.0;
  }

  const ImpactMeasures clean_measures = measure_impact(times, clean);
  const ImpactMeasures measures       = measure_impact(times, chattering);
  EXPECT_EQ(measures.contact_samples, clean_measures.contact_samples - released.size());
  EXPECT_EQ(measures.contact_start, clean_measures.contact_start);
  EXPECT_EQ(measures.contact_end, clean_measures.contact_end);
  EXPECT_NEAR(measures.impulse, clean_measures.impulse - c.dt * removed_force, 1e-12);
  EXPECT_GT(measures.ringing, 0.0);

  // Two positive samples three zeros apart are still one contact, from the sample before the first
  // to the sample after the last (F^{2/3} does not increase into the contact, so no extrapolation).
  // The one 5-point window, 8, 0, 0, 0, 8, has the period-2 component (8 + 8) / 16 = 1, so the
  // ringing is 1 / 8 (the parabola through 0, 8, 0 peaks at the sample, 8).
  const std::vector<double> short_times = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
  const ImpactMeasures split =
      measure_impact(short_times, {0.0, 8.0, 0.0, 0.0, 0.0, 8.0, 0.0, 0.0});
  EXPECT_EQ(split.contact_samples, 2u);
  EXPECT_DOUBLE_EQ(split.contact_start, 0.0);
  EXPECT_DOUBLE_EQ(split.contact_end, 0.6);
  EXPECT_DOUBLE_EQ(split.duration, 0.6);
  EXPECT_DOUBLE_EQ(split.impulse, 1.6);
  EXPECT_DOUBLE_EQ(split.peak_force, 8.0);
  EXPECT_DOUBLE_EQ(split.ringing, 1.0 / 8.0);
}

// The documented fallbacks of the contact ends and of the peak, on hand-computed histories.
TEST(ImpactMeasures, FallsBackToSampleTimes)
{
  const std::vector<double> times = {1.0, 1.5, 2.0, 2.5, 3.0};

  // One positive sample: the ends are the neighbouring sample times; the parabola through 0, 4, 0
  // peaks at the sample; no 5-point window fits into the contact, so no ringing.
  const ImpactMeasures single = measure_impact(times, {0.0, 0.0, 4.0, 0.0, 0.0});
  EXPECT_EQ(single.contact_samples, 1u);
  EXPECT_DOUBLE_EQ(single.contact_start, 1.5);
  EXPECT_DOUBLE_EQ(single.contact_end, 2.5);
  EXPECT_DOUBLE_EQ(single.peak_force, 4.0);
  EXPECT_DOUBLE_EQ(single.peak_time, 2.0);
  EXPECT_DOUBLE_EQ(single.impulse, 2.0);
  EXPECT_DOUBLE_EQ(single.ringing, 0.0);

  // F^{2/3} = 1, 4 through samples 1 and 2 reaches zero 1/3 step before sample 1 (F = 1, 8); the
  // end: F^{2/3} = 4, 1 at samples 2 and 3 (F = 8, 1) extrapolates 1/3 step beyond sample 3. The
  // parabola through 1, 8, 1 has its vertex at the sample.
  const ImpactMeasures triangle = measure_impact(times, {0.0, 1.0, 8.0, 1.0, 0.0});
  EXPECT_NEAR(triangle.contact_start, 1.5 - 0.5 / 3.0, 1e-14);
  EXPECT_NEAR(triangle.contact_end, 2.5 + 0.5 / 3.0, 1e-14);
  EXPECT_NEAR(triangle.duration, 1.0 + 1.0 / 3.0, 1e-14);
  EXPECT_DOUBLE_EQ(triangle.peak_force, 8.0);

  // Parabola through 0, 4, 2 (b = 1, c = -3): vertex 1/6 step after the sample, value 4 + 1/12.
  // The start extrapolates F^{2/3} = 4^{2/3}, 2^{2/3} decreasing into the contact: no zero, so the
  // previous sample time; the end extrapolates 2^{2/3} from 4^{2/3} to 2.5 + 0.5 / (2^{2/3} - 1) =
  // 3.35, beyond the next sample, and is clamped to it.
  const ImpactMeasures skewed = measure_impact(times, {0.0, 0.0, 4.0, 2.0, 0.0});
  EXPECT_DOUBLE_EQ(skewed.peak_force, 4.0 + 1.0 / 12.0);
  EXPECT_DOUBLE_EQ(skewed.peak_time, 2.0 + 0.5 / 6.0);
  EXPECT_DOUBLE_EQ(skewed.contact_start, 1.5);
  EXPECT_DOUBLE_EQ(skewed.contact_end, 3.0);

  // A history that begins and ends in contact: its first and last sample times; the largest sample
  // is the first, without a left neighbour, so the raw maximum.
  const ImpactMeasures truncated = measure_impact(times, {5.0, 4.0, 3.0, 2.0, 1.0});
  EXPECT_DOUBLE_EQ(truncated.contact_start, 1.0);
  EXPECT_DOUBLE_EQ(truncated.contact_end, 3.0);
  EXPECT_DOUBLE_EQ(truncated.peak_force, 5.0);
  EXPECT_DOUBLE_EQ(truncated.peak_time, 1.0);
  EXPECT_EQ(truncated.contact_samples, 5u);
  // A linear history has no period-2 component.
  EXPECT_NEAR(truncated.ringing, 0.0, 1e-15);
}

// Each input error throws std::invalid_argument; a history without contact gives zeros. Unequal
// steps (the sub-steps of a cut step) and the times 1e6 + n * 0.001 are accepted.
TEST(ImpactMeasures, RejectsInvalidInputAndMeasuresNoContactAsZero)
{
  const std::vector<double> times = {0.0, 0.1, 0.2, 0.3};
  const std::vector<double> force = {0.0, 1.0, 1.0, 0.0};
  const double nan                = std::numeric_limits<double>::quiet_NaN();
  const double infinity           = std::numeric_limits<double>::infinity();

  EXPECT_NO_THROW(measure_impact(times, force));
  EXPECT_THROW(measure_impact(times, {0.0, 1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(measure_impact({0.0, 0.1}, {0.0, 1.0}), std::invalid_argument);
  EXPECT_NO_THROW(measure_impact({0.0, 0.1, 0.2, 0.31}, force)); // unequal steps are allowed
  EXPECT_THROW(measure_impact({0.3, 0.2, 0.1, 0.0}, force), std::invalid_argument);
  EXPECT_THROW(measure_impact({0.0, 0.1, 0.1, 0.3}, force), std::invalid_argument);
  EXPECT_THROW(measure_impact({0.0, 0.0, 0.0, 0.0}, force), std::invalid_argument);
  EXPECT_THROW(measure_impact({0.0, nan, 0.2, 0.3}, force), std::invalid_argument);
  EXPECT_THROW(measure_impact(times, {0.0, infinity, 1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(measure_impact(times, {0.0, 1.0, nan, 0.0}), std::invalid_argument);

  std::vector<double> late_times;
  for (int n = 0; n < 4; ++n)
    late_times.push_back(1e6 + n * 0.001);
  EXPECT_NO_THROW(measure_impact(late_times, force));

  for (const std::vector<double>& no_contact :
       {std::vector<double>{0.0, 0.0, 0.0, 0.0}, std::vector<double>{0.0, -1.0, -2.0, 0.0}})
  {
    const ImpactMeasures measures = measure_impact(times, no_contact);
    EXPECT_EQ(measures.peak_force, 0.0);
    EXPECT_EQ(measures.peak_time, 0.0);
    EXPECT_EQ(measures.contact_start, 0.0);
    EXPECT_EQ(measures.contact_end, 0.0);
    EXPECT_EQ(measures.duration, 0.0);
    EXPECT_EQ(measures.impulse, 0.0);
    EXPECT_EQ(measures.ringing, 0.0);
    EXPECT_EQ(measures.contact_samples, 0u);
  }
}

// A history whose step control cut steps records the sub-steps: the exact Hertz history of the
// paper's spheres (rho = 0.001, dt = 0.0025), with the steps within 3 dt of the peak cut into
// halves and those within 2 dt of the first touch into quarters. Measured on all samples it must
// agree with the uniform history to within what the finer samples change: the impulse within
// 1e-3 of Hertz's 2 m* v (the uniform history's trapezoidal error is below 2e-4, see above, and
// finer samples only lower it); the peak force within 1e-4 of Hertz's (the parabola through
// unequal steps is third order, dt^3 |F'''| / 24 ~ 2e-5 relative) and its time within 0.05 dt
// (0.060 h^3 T above, with h = 0.09); the ends within one uniform step of the uniform history's;
// the ringing of the windows of four equal steps below 1e-3 (0.012 h^{3/2} = 3.2e-4 above).
TEST(ImpactMeasures, CutStepsAreMeasuredWithTheirOwnSizes)
{
  const SampledHertzImpact c       = {0.001, 0.0025, 1.9, 2.2, 0.3};
  const HertzImpact hertz          = hertz_impact(c);
  const std::vector<double> coarse = sample_times(c);
  const double peak_time           = 2.0 + 0.3 * c.dt + 0.5 * hertz.contact_duration();
  std::vector<double> times;
  for (std::size_t n = 0; n + 1 < coarse.size(); ++n)
  {
    const bool near_peak  = std::abs(coarse[n] - peak_time) < 3.0 * c.dt;
    const bool near_touch = std::abs(coarse[n] - 2.0) < 2.0 * c.dt;
    const int parts       = near_touch ? 4 : near_peak ? 2 : 1;
    for (int k = 0; k < parts; ++k)
      times.push_back(coarse[n] + k * (coarse[n + 1] - coarse[n]) / parts);
  }
  times.push_back(coarse.back());
  ASSERT_GT(times.size(), coarse.size() + 10);

  const ImpactMeasures uniform = measure_impact(coarse, hertz.contact_force_history(coarse));
  const ImpactMeasures cut     = measure_impact(times, hertz.contact_force_history(times));
  EXPECT_NEAR(cut.impulse / hertz.impulse(), 1.0, 1e-3);
  EXPECT_NEAR(cut.peak_force / hertz.maximum_force(), 1.0, 1e-4);
  EXPECT_NEAR(cut.peak_time, peak_time, 0.05 * c.dt);
  EXPECT_NEAR(cut.contact_start, uniform.contact_start, c.dt);
  EXPECT_NEAR(cut.contact_end, uniform.contact_end, c.dt);
  EXPECT_LT(cut.ringing, 1e-3);
}
