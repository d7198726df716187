// Issue 14's acceptance C for the default scheme: the paper's rate correction on Chung & Hulbert's
// generalized-alpha integrator, rho_inf = 0.8 (the defaults of Contact/dynamics and Time
// integration/integrator and spectral radius; doc/schemes.md, "The default"). The shipped prm
// files name the paper's Newmark, so the runs name the defaults back: they are what a prm file
// without those entries gets.
#include <dyncontact/base/parameters.h>

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "case_run.h"

namespace dyncontact::testing
{
namespace
{
/** The default scheme, named over a shipped prm file. */
const std::vector<std::string> default_scheme{"Contact/dynamics=taylor-papadopoulos",
                                              "Time integration/integrator=generalized-alpha",
                                              "Time integration/spectral radius=0.8",
                                              "Time integration/beta=0.25",
                                              "Time integration/gamma=0.5"};

std::vector<std::string> with_default_scheme(std::vector<std::string> overrides)
{
  overrides.insert(overrides.begin(), default_scheme.begin(), default_scheme.end());
  return overrides;
}
} // namespace

// The overrides above are the declared defaults: the shipped 6.2 file without its integrator and
// contact-dynamics lines gets this scheme.
TEST(DefaultScheme, IsThePapersSchemeOnGeneralizedAlpha)
{
  std::ifstream shipped(std::string(DYNCONTACT_SOURCE_DIR) + "/prm/bars_identical.prm");
  const std::string file = std::filesystem::temp_directory_path() / "dyncontact_default_scheme.prm";
  {
    std::ofstream stripped(file);
    for (std::string line; std::getline(shipped, line);)
      if (line.find("set integrator") == std::string::npos &&
          line.find("set dynamics") == std::string::npos &&
          line.find("set beta") == std::string::npos)
        stripped << line << "\n";
  }
  const RunParameters parameters = ParameterReader(file, {}).parameters();
  std::filesystem::remove(file);
  EXPECT_EQ(parameters.contact.dynamics, ContactDynamicsKind::taylor_papadopoulos);
  EXPECT_EQ(parameters.time.integrator, IntegratorFamily::generalized_alpha);
  EXPECT_EQ(parameters.time.spectral_radius, 0.8);
}

// The stiff striker (6.2 with bar 1 at E = 1e4, dt = 0.1: Courant 100 in the striker): exact one
// contact episode on [0, 20) with the force decaying from 0.990 to 0.137. On the trapezoidal rule
// the paper's scheme opens and closes the contact 67 times; on generalized-alpha, which damps the
// striker's element modes (omega dt about 100) by 0.8 per step, it keeps one episode, and every
// window mean of the force over one time unit is within 0.1 of exact (the bound; measured
// 0.089, in the last window, where the discrete release comes early as with every scheme here).
TEST(DefaultScheme, StiffStrikerKeepsOneContactEpisodeWithTheExactForce)
{
  const BarRun run   = run_bar_case("prm/bars_identical.prm",
                                  with_default_scheme({"Geometry/Bar 1/Young's modulus=1e4"}));
  const double worst = max_window_mean_force_error(run, 20);
  std::cout << "  stiff striker, default scheme: " << contact_episodes(run.history())
            << " contact episode(s), worst window-mean force error " << worst << "\n";
  EXPECT_EQ(contact_episodes(run.history()), 1u);
  EXPECT_LE(worst, 0.1);
}

// The coarse spheres at dt = 0.02 (4 steps in contact), where the trapezoidal rule gains up to
// 4.9 % at release and needs the energy guard's cuts: the default scheme never exceeds the initial
// energy (1e-9: the Newton tolerance's share), takes every step as it comes (no cut), and ends
// the contact (measured: largest change 4.3e-11, final -9.7 %, the integrator's dissipation at
// 4 steps per contact).
TEST(DefaultScheme, CoarseSpheresNeverGainEnergyAndNeedNoStepCut)
{
  const MeshRun run =
      run_mesh_case("prm/spheres_rho0.001.prm",
                    paper_coarse_spheres(with_default_scheme(
                        {"Time integration/time step=0.02", "Time integration/end time=2.16"})));
  const auto energy   = run.history().column("total_energy");
  const auto cuts     = run.history().column("step_cuts");
  double largest_gain = -1.;
  for (const double e : energy)
    largest_gain = std::max(largest_gain, e / energy.front() - 1.);
  std::cout << "  coarse spheres at dt = 0.02, default scheme: largest energy change "
            << largest_gain << ", final " << energy.back() / energy.front() - 1. << "\n";
  EXPECT_LE(largest_gain, 1e-9);
  EXPECT_EQ(*std::max_element(cuts.begin(), cuts.end()), 0.);
  EXPECT_EQ(run.history().value(run.history().n_rows() - 1, "active_constraints"), 0.);
}
} // namespace dyncontact::testing
