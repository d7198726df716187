// The output matrix (issue 25, build 2): every quantity a user reads from a run, checked against
// an independent reference on every integrator and every contact-dynamics treatment that runs on
// it, on one bar case (the paper's 6.2, exact wave solution) and one sphere case (the paper's
// coarse spheres, Hertz). A new integrator or treatment is covered by adding a row to schemes().
//
// Before this test every pressure test ran Newmark: on the dissipative integrators the per-pair
// forces, the pressures and the penalty spring were 1/(1 - alpha_f) too large (1.8 at the default
// rho_inf = 0.8) while the total force was right.
#include <dyncontact/reference/hertz_impact.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "case_run.h"

namespace dyncontact::testing
{
namespace
{
/** One row of the matrix: an integrator with a contact-dynamics treatment. */
struct Scheme
{
  std::string integrator;
  std::string dynamics;

  /** The overrides that select it over a shipped prm (which names Newmark's beta and gamma). */
  std::vector<std::string> overrides() const
  {
    return {"Time integration/integrator=" + integrator,
            "Time integration/beta=0.25",
            "Time integration/gamma=0.5",
            "Contact/dynamics=" + dynamics};
  }
  /** Whether the treatment carries the contact impulse of t_{n+1} alone (force gamma lambda). */
  bool one_force_per_step() const
  {
    return dynamics == "contact-stabilized" || dynamics == "persistency" ||
           dynamics == "velocity-update";
  }
};

/**
 * Every integrator with every treatment it accepts: the three with one contact force per step
 * need the trapezoidal rule (ParameterReader refuses them elsewhere).
 */
std::vector<Scheme> schemes()
{
  std::vector<Scheme> rows;
  for (const std::string integrator : {"newmark", "hht", "bossak", "generalized-alpha"})
    for (const std::string dynamics : {"none",
                                       "taylor-papadopoulos",
                                       "mass-redistribution",
                                       "contact-stabilized",
                                       "persistency",
                                       "velocity-update"})
    {
      const Scheme scheme{integrator, dynamics};
      if (integrator == "newmark" || !scheme.one_force_per_step())
        rows.push_back(scheme);
    }
  return rows;
}

/** How GoogleTest prints a row in a failure message. */
void PrintTo(const Scheme& scheme, std::ostream* out)
{
  *out << scheme.dynamics << " on " << scheme.integrator;
}

std::string scheme_name(const ::testing::TestParamInfo<Scheme>& info)
{
  std::string name = info.param.integrator + "_" + info.param.dynamics;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

/** The value in column `column` (0: the name) of the row named `quantity` of a summary CSV. */
double summary_value(const std::string& csv, const std::string& quantity, unsigned int column)
{
  std::istringstream lines(csv);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(quantity + ",", 0) == 0)
    {
      std::istringstream fields(line);
      std::string field;
      for (unsigned int c = 0; c <= column; ++c)
        std::getline(fields, field, ',');
      return std::stod(field);
    }
  ADD_FAILURE() << "no row " << quantity;
  return std::nan("");
}

/** Index of the row with the largest contact force. */
unsigned int peak_row(const History& history)
{
  const std::vector<double> force = history.column("contact_force");
  return std::max_element(force.begin(), force.end()) - force.begin();
}

class OutputMatrix : public ::testing::TestWithParam<Scheme>
{
};

// 6.2 (two identical bars, E = rho = A = 1, L = 10, 100 elements, v = 1, touching), dt = 0.1
// (Courant 1) on the scheme's integrator with beta = 1/4 where it is Newmark. Exact: force
// rho c A v / 2 = 0.5 on [0, 20), bar 1 at rest and bar 2 at v = 1 after, energy 5.
// - total force: every 1-unit window mean on [1, 19] within 0.1 of 0.5 (issue 14's bound of a
//   force against its exact history; the schemes measure 0.001 to 0.07 here), except for the
//   classical scheme (none) on the undamped or lightly damped integrators, whose force chatters
//   at the contact nodes: the defect of the paper's eqs. 17-18 that the treatments exist for
//   (measured 0.17 on Newmark, 0.21 on HHT, 0.27 on Bossak; generalized-alpha damps it to pass);
// - the pairs' force (contact_multiplier, the multipliers as forces) equals the recovered total
//   force in the steady interior (t in [1, 19]): both are the force of the step's balance, to
//   the Newton tolerance (1e-10 relative; bound 1e-6);
// - no penetration with Lagrange multipliers beyond the gap tolerance (1e-10 of a cell: 1e-11);
// - impulse = momentum change for each bar (the guard's 1e-6 of the momentum scale 10) and
//   exact_summary.csv's impulse equals the momentum bar 1 lost (same 1e-6 relative);
// - the final momenta within 2 % of the exact (0, 10) (measured: at most 1.5 %, the discrete
//   release of every scheme leaves a little vibration) and the energy never above its start by
//   more than the guard tolerance 1e-4.
TEST_P(OutputMatrix, IdenticalBarsAgainstTheExactWaves)
{
  const Scheme& scheme               = GetParam();
  std::vector<std::string> overrides = scheme.overrides();
  overrides.push_back("Time integration/end time=25");
  const BarRun run          = run_bar_case("prm/bars_identical.prm", overrides);
  const History& history    = run.history();
  const unsigned int last   = history.n_rows() - 1;
  const double momentum_0   = history.value(0, "momentum_1");
  const double momentum_1   = history.value(last, "momentum_1");
  const double momentum_2   = history.value(last, "momentum_2");
  const double start_energy = history.value(0, "total_energy");

  if (scheme.dynamics != "none" || scheme.integrator == "generalized-alpha")
  {
    EXPECT_LT(max_window_mean_force_error(run, 19), 0.1);
  }
  for (unsigned int row = 0; row < history.n_rows(); ++row)
  {
    const double t = history.value(row, "time");
    if (t >= 1. && t <= 19.)
    {
      EXPECT_NEAR(
          history.value(row, "contact_multiplier"), history.value(row, "contact_force"), 1e-6)
          << "t = " << t;
    }
    EXPECT_LT(history.value(row, "max_penetration"), 1e-11) << "t = " << t;
    EXPECT_LT(history.value(row, "total_energy"), start_energy * (1. + 1e-4)) << "t = " << t;
  }
  EXPECT_NEAR(history.value(last, "impulse_1"), momentum_1 - momentum_0, 1e-6 * 10.);
  EXPECT_NEAR(history.value(last, "impulse_2"), momentum_2, 1e-6 * 10.);
  ASSERT_EQ(run.files.count("exact_summary.csv"), 1u);
  EXPECT_NEAR(summary_value(run.files.at("exact_summary.csv"), "impulse", 1),
              momentum_0 - momentum_1,
              1e-6 * 10.);
  EXPECT_NEAR(momentum_1, 0., 0.02 * 10.);
  EXPECT_NEAR(momentum_2, 10., 0.02 * 10.);
}

// The coarse identical spheres of the paper (R = 8, E = 5e3, nu = 0.3, rho = 0.001, neo-Hookean,
// node-to-node, dt = 0.0025), 0.05 apart so that the whole impact (about 33 steps) lies in
// t < 0.14. Hertz for the run's own peak force F: p0 = 3 F / (2 pi a^2), a = (3 F R* / (4
// E*))^(1/3).
// - the peak force within 6 % of Hertz's 96.28 (the coarse mesh is stiffer than Hertz's
//   half-space: +4.5 % on Newmark, +3.9 % on generalized-alpha; the finite-sphere law, which
//   knows the finite radius, is 98.9);
// - at the peak row: the pairs' force sum (contact_multiplier) equals the total force within
//   1 % (the pairs' force and the recovered force are one force; the modified scheme's corrected
//   accelerations move the recovered one by much less), and centre_pressure within 2 % of Hertz's
//   p0(F) (issue 25, acceptance A; the consistent recovery on this mesh gives -0.2 % on Newmark;
//   persistency within 15 %: its pairs predicted to close are held at their gap of t_n, so the
//   contact acts across up to one step's approach, 0.005, a sixth of the indentation, and its
//   pressure is not Hertz's: -12 % at the centre, measured),
//   and the outermost active node (contact_radius) within one surface node spacing (0.15) of
//   a(F) (the pairs are nodes: 0.405 against a = 0.479 on Newmark);
// - no penetration beyond the gap tolerance (1e-10 of a cell, 1.5e-11);
// - impulse = momentum change for each sphere, and impact_summary.csv's impulse equals the
//   momentum sphere 1 lost, to the guard's 1e-6 of the momentum scale 4.3;
// - energy never above its start by more than the guard tolerance, and not below 0.9 of it (the
//   dissipative integrators lose up to 1 % here, 2 steps of a 33-step impact).
TEST_P(OutputMatrix, CoarseSpheresAgainstHertz)
{
  const Scheme& scheme               = GetParam();
  std::vector<std::string> overrides = scheme.overrides();
  overrides.push_back("Time integration/end time=0.14");
  const MeshRun run      = run_mesh_case("prm/spheres_rho0.001.prm",
                                    paper_coarse_spheres(overrides, "CentreDistance: 16.05, "));
  const History& history = run.history();
  const ElasticSphere sphere{8., 5e3, 0.3, 0.001};
  const HertzImpact hertz = HertzImpact::two_spheres(sphere, sphere, 2., 0.025);
  const unsigned int peak = peak_row(history);
  const double force      = history.value(peak, "contact_force");
  const double radius =
      std::cbrt(3. * force * hertz.effective_radius() / (4. * hertz.effective_modulus()));
  const double centre_p0    = 3. * force / (2. * numbers::PI * radius * radius);
  const unsigned int last   = history.n_rows() - 1;
  const double momentum_0   = history.value(0, "momentum_1");
  const double start_energy = history.value(0, "total_energy");

  EXPECT_NEAR(force / hertz.maximum_force(), 1., 0.06);
  EXPECT_NEAR(history.value(peak, "contact_multiplier") / force, 1., 0.01);
  EXPECT_NEAR(history.value(peak, "centre_pressure") / centre_p0,
              1.,
              scheme.dynamics == "persistency" ? 0.15 : 0.02);
  EXPECT_NEAR(history.value(peak, "contact_radius"), radius, 0.15);
  double lowest_energy = start_energy;
  for (unsigned int row = 0; row < history.n_rows(); ++row)
  {
    EXPECT_LT(history.value(row, "max_penetration"), 1.5e-11) << "row " << row;
    EXPECT_LT(history.value(row, "total_energy"), start_energy * (1. + 1e-4)) << "row " << row;
    lowest_energy = std::min(lowest_energy, history.value(row, "total_energy"));
  }
  EXPECT_GT(lowest_energy, 0.9 * start_energy);
  const double scale = 1e-6 * 2. * std::abs(momentum_0);
  EXPECT_NEAR(
      history.value(last, "impulse_1"), history.value(last, "momentum_1") - momentum_0, scale);
  EXPECT_NEAR(history.value(last, "impulse_2"),
              history.value(last, "momentum_2") - history.value(0, "momentum_2"),
              scale);
  ASSERT_EQ(run.files.count("impact_summary.csv"), 1u);
  EXPECT_NEAR(summary_value(run.files.at("impact_summary.csv"), "impulse", 1),
              momentum_0 - history.value(last, "momentum_1"),
              scale);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegratorAndTreatment,
                         OutputMatrix,
                         ::testing::ValuesIn(schemes()),
                         scheme_name);

// Item 8 of issue 25: impact_summary.csv from every accepted row. The coarse spheres on Newmark
// 1/4 at dt = 0.03 (3 steps in contact) gain energy at release and the guard cuts steps; from the
// nominal rows alone the summary's impulse was 4.2936 against a momentum change of 4.0874. It is
// now the impulse the run accumulated, equal to the momentum sphere 1 lost to the momentum
// guard's 1e-6 of the momentum scale.
TEST(ImpactSummary, CountsTheSubStepsOfCutSteps)
{
  const MeshRun run = run_mesh_case(
      "prm/spheres_rho0.001.prm",
      paper_coarse_spheres({"Time integration/time step=0.03", "Time integration/end time=0.21"},
                           "CentreDistance: 16.05, "));
  const History& history         = run.history();
  const std::vector<double> cuts = history.column("step_cuts");
  ASSERT_GT(*std::max_element(cuts.begin(), cuts.end()), 0.) << "the run must cut steps";
  const unsigned int last = history.n_rows() - 1;
  const double lost       = history.value(0, "momentum_1") - history.value(last, "momentum_1");
  ASSERT_EQ(run.files.count("impact_summary.csv"), 1u);
  EXPECT_NEAR(summary_value(run.files.at("impact_summary.csv"), "impulse", 1),
              lost,
              1e-6 * 2. * history.value(0, "momentum_1"));
}

/**
 * The schemes that take a penalty (the rate corrections assume exactly closed pairs), but
 * contact-stabilized: with a penalty it fails the first step of 6.2 on the energy guard (gain
 * 1.0e-4 at every penalty factor tried, 0.1 to auto), before this changes as after them
 * (doc/validation.md, known limitations).
 */
std::vector<Scheme> penalty_schemes()
{
  std::vector<Scheme> rows;
  for (const Scheme& scheme : schemes())
    if (scheme.dynamics == "none" || scheme.dynamics == "mass-redistribution")
      rows.push_back(scheme);
  return rows;
}

class PenaltyMatrix : public ::testing::TestWithParam<Scheme>
{
};

// The penalty spring on 6.2 with factor 0.25 (k = 0.25 E A / h = 2.5, omega dt = 1 at dt = 0.1):
// the pair's force is eps <-g>, so at every row with an active pair the penetration equals the
// pairs' force over k to round-off (bound 1e-9 relative), and the recovered total force over k
// within 1 % (issue 25, acceptance A; they differ by the Newton residual). Before, the dissipative
// integrators gave 1 / (1 - alpha_f) times the penetration: a spring soft by that factor.
TEST_P(PenaltyMatrix, PenetrationIsTheForceOverTheSpringStiffness)
{
  std::vector<std::string> overrides = GetParam().overrides();
  overrides.insert(overrides.end(),
                   {"Contact/formulation=penalty",
                    "Contact/penalty factor=0.25",
                    "Time integration/end time=20"});
  const BarRun run       = run_bar_case("prm/bars_identical.prm", overrides);
  const History& history = run.history();
  const double stiffness = 0.25 * 1. * 1. / 0.1;
  unsigned int checked   = 0;
  for (unsigned int row = 1; row < history.n_rows(); ++row)
  {
    if (history.value(row, "active_constraints") == 0.)
      continue;
    const double penetration = history.value(row, "max_penetration");
    const double t           = history.value(row, "time");
    EXPECT_NEAR(
        history.value(row, "contact_multiplier") / stiffness, penetration, 1e-9 * penetration)
        << "t = " << t;
    if (t >= 1. && t <= 19.)
    {
      EXPECT_NEAR(history.value(row, "contact_force") / stiffness, penetration, 0.01 * penetration)
          << "t = " << t;
      ++checked;
    }
  }
  EXPECT_GT(checked, 150u);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegratorAndTreatment,
                         PenaltyMatrix,
                         ::testing::ValuesIn(penalty_schemes()),
                         scheme_name);
} // namespace
} // namespace dyncontact::testing
