// The default contact dynamics, chosen over the whole kind (issue 25, item 7; doc/schemes.md,
// "The default"): mass redistribution on Newmark with gamma = 0.502, beta = 0.251001 (the
// defaults of Contact/dynamics and Time integration/integrator, beta and gamma), with its contact
// events resolved to Guards/contact event tolerance = 1e-4. The shipped prm files name the paper's
// Newmark, so the runs name the defaults back: they are what a prm file without those entries gets
// (an empty beta or gamma is the default).
#include <dyncontact/simulation/parameter_reader.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <utility>
#include <vector>

#include "case_run.h"

namespace dyncontact::testing
{
namespace
{
/** The default scheme, named over a shipped prm file. */
const std::vector<std::string> default_scheme{"Contact/dynamics=mass-redistribution",
                                              "Time integration/integrator=newmark",
                                              "Time integration/beta=",
                                              "Time integration/gamma="};

std::vector<std::string> with_default_scheme(std::vector<std::string> overrides)
{
  overrides.insert(overrides.begin(), default_scheme.begin(), default_scheme.end());
  return overrides;
}
} // namespace

// The overrides above are the declared defaults: the shipped 6.2 file without its integrator,
// contact-dynamics, beta and gamma lines gets this scheme. Its beta is (gamma + 1/2)^2 / 4, the
// unconditionally stable member with the most high-frequency damping for its gamma, written out
// (to 1 ulp of the product).
TEST(DefaultScheme, IsMassRedistributionOnSlightlyDissipativeNewmark)
{
  std::ifstream shipped(std::string(DYNCONTACT_SOURCE_DIR) + "/prm/bars_identical.prm");
  const std::string file = std::filesystem::temp_directory_path() / "dyncontact_default_scheme.prm";
  {
    std::ofstream stripped(file);
    for (std::string line; std::getline(shipped, line);)
      if (line.find("set integrator") == std::string::npos &&
          line.find("set dynamics") == std::string::npos &&
          line.find("set beta") == std::string::npos && line.find("set gamma") == std::string::npos)
        stripped << line << "\n";
  }
  const RunParameters parameters = ParameterReader(file, {}).parameters();
  std::filesystem::remove(file);
  EXPECT_EQ(parameters.contact.dynamics, ContactDynamicsKind::mass_redistribution);
  EXPECT_EQ(parameters.time.integrator, IntegratorFamily::newmark);
  EXPECT_EQ(parameters.time.gamma, 0.502);
  EXPECT_EQ(parameters.time.beta, 0.251001);
  EXPECT_NEAR(parameters.time.beta, (0.502 + 0.5) * (0.502 + 0.5) / 4., 1e-16);
  EXPECT_EQ(parameters.guards.contact_event_tolerance, 1e-4);
}

// Newmark's coefficients when not both given: gamma alone takes beta = (gamma + 1/2)^2 / 4, beta
// alone takes gamma = 1/2 (the paper's beta = 0.001 lines), and the treatments built on the
// trapezoidal rule take 1/4 and 1/2 when neither is given.
TEST(DefaultScheme, NewmarkCoefficientsLeftEmpty)
{
  const auto read = [](const std::vector<std::string>& overrides)
  {
    std::vector<std::string> all{"Time integration/beta=", "Time integration/gamma="};
    all.insert(all.end(), overrides.begin(), overrides.end());
    return ParameterReader(std::string(DYNCONTACT_SOURCE_DIR) + "/prm/bars_identical.prm", all)
        .parameters()
        .time;
  };
  const TimeIntegrationParameters gamma_only = read({"Time integration/gamma=0.6"});
  EXPECT_EQ(gamma_only.gamma, 0.6);
  EXPECT_NEAR(gamma_only.beta, 0.3025, 1e-16);
  const TimeIntegrationParameters beta_only = read({"Time integration/beta=0.001"});
  EXPECT_EQ(beta_only.beta, 0.001);
  EXPECT_EQ(beta_only.gamma, 0.5);
  for (const char* dynamics : {"contact-stabilized", "persistency", "velocity-update"})
  {
    const TimeIntegrationParameters trapezoidal =
        read({std::string("Contact/dynamics=") + dynamics});
    EXPECT_EQ(trapezoidal.beta, 0.25) << dynamics;
    EXPECT_EQ(trapezoidal.gamma, 0.5) << dynamics;
  }
  const TimeIntegrationParameters paper = read({"Contact/dynamics=taylor-papadopoulos"});
  EXPECT_EQ(paper.gamma, 0.502);
}

// The record of a run (parameters.prm) names the coefficients it used, not the empty entries: read
// back, it gives the same beta and gamma (exactly, written to 17 digits), also for a treatment that
// takes the trapezoidal rule and for gamma given alone.
TEST(DefaultScheme, RecordNamesTheNewmarkCoefficientsUsed)
{
  const std::string prm_file = std::string(DYNCONTACT_SOURCE_DIR) + "/prm/bars_identical.prm";
  for (const std::vector<std::string>& overrides :
       {std::vector<std::string>{"Time integration/beta=", "Time integration/gamma="},
        {"Time integration/beta=", "Time integration/gamma=", "Contact/dynamics=velocity-update"},
        {"Time integration/beta=", "Time integration/gamma=0.6"}})
  {
    const ParameterReader reader(prm_file, overrides);
    const std::filesystem::path directory =
        std::filesystem::temp_directory_path() / "dyncontact_default_scheme_record";
    std::filesystem::create_directories(directory);
    reader.write_records(directory.string());
    std::ifstream record(directory / "parameters.prm");
    std::string beta_line, gamma_line;
    for (std::string line; std::getline(record, line);)
    {
      if (line.find("set beta") != std::string::npos)
        beta_line = line;
      if (line.find("set gamma") != std::string::npos)
        gamma_line = line;
    }
    const TimeIntegrationParameters used = reader.parameters().time;
    const TimeIntegrationParameters reread =
        ParameterReader((directory / "parameters.prm").string(), {}).parameters().time;
    std::filesystem::remove_all(directory);
    EXPECT_NE(beta_line.find_first_of("0123456789"), std::string::npos) << beta_line;
    EXPECT_NE(gamma_line.find_first_of("0123456789"), std::string::npos) << gamma_line;
    EXPECT_EQ(reread.beta, used.beta) << beta_line;
    EXPECT_EQ(reread.gamma, used.gamma) << gamma_line;
  }
}

// The stiff striker (6.2 with bar 1 at E = ratio^2: impedance ratio 100 and 1e4) at dt = 0.1 and
// 0.01 (Courant up to 1e3 in the striker): exact one contact episode on [0, 20) with the force
// decaying from 0.990 to 0.137. The bounds: one episode, every window mean of the force
// over one time unit within 0.1 of exact, the peak at most 1.5x the exact 0.990 (measured by
// bench/schemes_sweep.py: window errors 0.070-0.091, peaks 1.32-1.35x; the old default made 3
// episodes at dt = 0.01 with a peak of 4.5x).
TEST(DefaultScheme, StiffStrikerKeepsOneContactEpisodeAtEveryStep)
{
  for (const char* modulus : {"1e4", "1e8"})
    for (const char* dt : {"0.1", "0.01"})
    {
      const BarRun run = run_bar_case(
          "prm/bars_identical.prm",
          with_default_scheme({std::string("Geometry/Bar 1/Young's modulus=") + modulus,
                               std::string("Time integration/time step=") + dt}));
      const double worst = max_window_mean_force_error(run, 20);
      const auto force   = run.history().column("contact_force");
      const double peak  = *std::max_element(force.begin(), force.end());
      std::cout << "  stiff striker E = " << modulus << ", dt = " << dt
                << ", default scheme: " << contact_episodes(run.history())
                << " contact episode(s), worst window-mean "
                << "force error " << worst << ", peak " << peak << "\n";
      EXPECT_EQ(contact_episodes(run.history()), 1u) << modulus << " " << dt;
      EXPECT_LE(worst, 0.1) << modulus << " " << dt;
      EXPECT_LE(peak, 1.5 * 0.990) << modulus << " " << dt;
    }
}

// The coarse spheres at dt = 0.02 (4 steps in contact): the trapezoidal rule alone gains 4.9 % at
// the release and the old default lost 10 % (its closing and its dissipation); the default never
// exceeds the initial energy (1e-9: the Newton tolerance's share; measured 4.3e-11), loses at most
// 2 % (the bound; measured -0.11 %) and ends the contact.
TEST(DefaultScheme, CoarseSpheresKeepTheirEnergy)
{
  const MeshRun run =
      run_mesh_case("prm/spheres_rho0.001.prm",
                    paper_coarse_spheres(with_default_scheme(
                        {"Time integration/time step=0.02", "Time integration/end time=2.19"})));
  const auto energy   = run.history().column("total_energy");
  double largest_gain = -1.;
  for (const double e : energy)
    largest_gain = std::max(largest_gain, e / energy.front() - 1.);
  const double final_change = energy.back() / energy.front() - 1.;
  std::cout << "  coarse spheres at dt = 0.02, default scheme: largest energy change "
            << largest_gain << ", final " << final_change << "\n";
  EXPECT_LE(largest_gain, 1e-9);
  EXPECT_GE(final_change, -0.02);
  EXPECT_EQ(run.history().value(run.history().n_rows() - 1, "active_constraints"), 0.);
}

namespace
{
/** The largest (E - E0) / E0 of a history's total energy. */
double largest_energy_gain(const History& history)
{
  const auto energy = history.column("total_energy");
  double largest    = -1.;
  for (const double e : energy)
    largest = std::max(largest, e / energy.front() - 1.);
  return largest;
}
} // namespace

// The kind behind the coarse spheres: every shipped bar problem and the penalty bars of case 06,
// the coarse spheres at the paper's dt = 0.0025 and the three spheres, on the default scheme.
// None may gain energy without external work (bound 1e-9: the Newton tolerance's share, as
// above). On the trapezoidal rule (gamma = 1/2) the same runs gain 6.5e-5 (6.1), 3.3e-5 (6.2),
// 1.3e-6 (6.3), 9.7e-5 (Signorini), 9.6e-5 (6.2 with penalty factor 100), 5.6e-6 (coarse spheres)
// and 5.1e-5 (three spheres): the works of contact events each within Guards/contact event
// tolerance = 1e-4, and on the neo-Hookean spheres the rule's own second-order error (measured in
// doc/schemes.md, "Its limits"). The spheres' losses on the default stay below 1 % (measured 0.075
// % and 0.094 %).
TEST(DefaultScheme, NoImpactOfTheKindGainsEnergy)
{
  const std::vector<std::pair<std::string, std::vector<std::string>>> bars{
      {"prm/bar_rigid_wall.prm", {}},
      {"prm/bars_identical.prm", {}},
      {"prm/bars_dissimilar.prm", {}},
      {"prm/signorini_bar.prm", {}},
      {"prm/bars_identical.prm", {"Contact/formulation=penalty", "Contact/penalty factor=100"}}};
  for (const auto& [prm, overrides] : bars)
  {
    const BarRun run = run_bar_case(prm, with_default_scheme(overrides));
    std::cout << "  " << prm << (overrides.empty() ? "" : " with a penalty")
              << ", default scheme: largest energy gain " << largest_energy_gain(run.history())
              << "\n";
    EXPECT_LE(largest_energy_gain(run.history()), 1e-9) << prm;
  }
  const MeshRun coarse =
      run_mesh_case("prm/spheres_rho0.001.prm",
                    paper_coarse_spheres(with_default_scheme(
                        {"Time integration/time step=0.0025", "Time integration/end time=2.19"})));
  const MeshRun three = run_mesh_case("prm/three_spheres.prm", with_default_scheme({}));
  for (const auto& [name, run] : {std::pair<const char*, const MeshRun*>{"coarse spheres", &coarse},
                                  {"three spheres", &three}})
  {
    const auto energy = run->history().column("total_energy");
    std::cout << "  " << name << ", default scheme: largest energy gain "
              << largest_energy_gain(run->history()) << ", final "
              << energy.back() / energy.front() - 1. << "\n";
    EXPECT_LE(largest_energy_gain(run->history()), 1e-9) << name;
    EXPECT_GE(energy.back() / energy.front() - 1., -0.01) << name;
  }
}
} // namespace dyncontact::testing
