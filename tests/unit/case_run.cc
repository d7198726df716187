#include "case_run.h"

#include <dyncontact/base/output_directory.h>
#include <dyncontact/models/bar_model.h>
#include <dyncontact/simulation/mesh_model_factory.h>

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numeric>
#include <sstream>
#include <unistd.h>

namespace dyncontact::testing
{
std::string source_path(const std::string& relative_path)
{
  return std::string(DYNCONTACT_SOURCE_DIR) + "/" + relative_path;
}

double BarRun::exact_contact_force(const double t) const
{
  double force = 0.;
  for (unsigned int i = 0; i < exact->n_interfaces(); ++i)
    force += exact->contact_force(i, t);
  return force;
}

namespace
{
/** Reads the prm with the overrides, redirected to a fresh temporary output directory. */
RunParameters test_parameters(const std::string& prm_file,
                              const std::vector<std::string>& overrides)
{
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::ostringstream directory;
  directory << std::filesystem::temp_directory_path().string() << "/dyncontact-tests/"
            << (test ? std::string(test->test_suite_name()) + "." + test->name() : "run") << "-"
            << ::getpid() << "-"
            << std::hash<std::string>()(
                   prm_file + std::accumulate(overrides.begin(), overrides.end(), std::string()));
  std::vector<std::string> all_overrides = overrides;
  all_overrides.insert(all_overrides.end(),
                       {"Output/directory=" + directory.str(),
                        "Output/vtu interval=0",
                        "Output/write exact solution=false"});
  const RunParameters parameters =
      ParameterReader(source_path(prm_file), all_overrides).parameters();
  prepare_output_directory(parameters.output.directory);
  return parameters;
}

/**
 * Runs the simulation quietly and removes its output directory, after reading the profiles and
 * summaries it wrote (profile_t<T>.csv, contact_pressure_t<T>.csv, *_summary.csv) into `files`.
 */
template <int dim>
std::unique_ptr<Simulation<dim>> run_quietly(const RunParameters& parameters,
                                             std::unique_ptr<ProblemModel<dim>> model,
                                             std::map<std::string, std::string>& files)
{
  std::ostringstream log;
  auto simulation = std::make_unique<Simulation<dim>>(parameters, std::move(model), log);
  simulation->run();
  for (const auto& entry : std::filesystem::directory_iterator(parameters.output.directory))
  {
    const std::string name = entry.path().filename().string();
    if (name.rfind("profile_t", 0) == 0 || name.rfind("contact_pressure_t", 0) == 0 ||
        name.find("_summary.csv") != std::string::npos)
    {
      std::ostringstream text;
      text << std::ifstream(entry.path()).rdbuf();
      files[name] = text.str();
    }
  }
  std::filesystem::remove_all(parameters.output.directory);
  return simulation;
}
} // namespace

BarRun run_bar_case(const std::string& prm_file, const std::vector<std::string>& overrides)
{
  BarRun run;
  run.parameters = test_parameters(prm_file, overrides);
  const BarModel model(run.parameters.geometry);
  run.simulation = run_quietly<1>(run.parameters, std::make_unique<BarModel>(model), run.files);
  run.exact      = std::make_unique<ExactBarSolution>(
      model.exact_solution(run.parameters.time.end_time + run.parameters.time.time_step));
  return run;
}

std::vector<std::string> paper_coarse_spheres(const std::vector<std::string>& more,
                                              const std::string& geo_prefix)
{
  std::vector<std::string> overrides = {"Mesh/file=" + source_path("meshes/two_spheres.geo"),
                                        "Mesh/geo parameters=" + geo_prefix +
                                            "Refinement: 0, PoleGrading: 10, CoreOffset: 0.3",
                                        "Contact/discretization=node-to-node",
                                        "Newton/method=full"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return overrides;
}

MeshRun run_mesh_case(const std::string& prm_file, const std::vector<std::string>& overrides)
{
  MeshRun run;
  run.parameters = test_parameters(prm_file, overrides);
  run.simulation = run_quietly<2>(run.parameters, create_mesh_model(run.parameters), run.files);
  return run;
}

std::vector<std::string> with(std::vector<std::string> overrides,
                              const std::vector<std::string>& more)
{
  overrides.insert(overrides.end(), more.begin(), more.end());
  return overrides;
}

SolidRun run_solid_case(const std::string& prm_file, const std::vector<std::string>& overrides)
{
  SolidRun run;
  run.parameters = test_parameters(prm_file, overrides);
  run.simulation =
      run_quietly<3>(run.parameters, create_solid_mesh_model(run.parameters), run.files);
  return run;
}

std::vector<unsigned int> contact_samples(const BarRun& run)
{
  const auto intervals   = run.exact->contact_intervals(0);
  const double start     = intervals.front().first;
  const double end       = intervals.front().second;
  const double left_side = 1e-6 * run.time_step();
  const auto times       = run.history().column("time");

  std::vector<unsigned int> samples;
  for (unsigned int row = 0; row < times.size(); ++row)
  {
    const double t = times[row];
    if (!(t > start + left_side && t < end - left_side))
      continue;
    bool at_jump =
        std::abs(run.exact_contact_force(t) - run.exact_contact_force(t - left_side)) > 1e-12;
    for (unsigned int b = 0; b < run.exact->n_bars(); ++b)
      at_jump =
          at_jump || std::abs(run.exact->velocity(b, run.tip_position(b), t) -
                              run.exact->velocity(b, run.tip_position(b), t - left_side)) > 1e-12;
    if (!at_jump)
      samples.push_back(row);
  }
  return samples;
}

double max_window_mean_force_error(const BarRun& run, const unsigned int windows)
{
  const auto force = run.history().column("contact_force");
  const auto times = run.history().column("time");
  double worst     = 0.;
  for (unsigned int window = 0; window < windows; ++window)
  {
    double computed = 0., exact = 0.;
    unsigned int samples = 0;
    for (unsigned int row = 0; row < times.size(); ++row)
      if (times[row] > window && times[row] <= window + 1)
      {
        computed += force[row];
        exact += run.exact_contact_force(times[row]);
        ++samples;
      }
    EXPECT_GT(samples, 0u) << "no row in the window (" << window << ", " << window + 1 << "]";
    if (samples > 0)
      worst = std::max(worst, std::abs(computed - exact) / samples);
  }
  return worst;
}

double max_force_deviation(const History& history,
                           const double value,
                           const double start,
                           const double end)
{
  const auto force = history.column("contact_force");
  const auto times = history.column("time");
  double deviation = 0.;
  for (unsigned int row = 0; row < times.size(); ++row)
    if (times[row] > start && times[row] < end)
      deviation = std::max(deviation, std::abs(force[row] - value));
  return deviation;
}

double largest_relative_difference(const History& history, const History& reference)
{
  EXPECT_EQ(history.n_rows(), reference.n_rows());
  double largest = 0.;
  for (const std::string name : {"contact_force",
                                 "kinetic_energy",
                                 "strain_energy",
                                 "total_energy",
                                 "momentum_1",
                                 "momentum_2"})
  {
    const auto values = history.column(name), expected = reference.column(name);
    double scale = 0., difference = 0.;
    for (unsigned int row = 0; row < std::min(values.size(), expected.size()); ++row)
    {
      scale      = std::max(scale, std::abs(expected[row]));
      difference = std::max(difference, std::abs(values[row] - expected[row]));
    }
    largest = std::max(largest, difference / scale);
  }
  return largest;
}

std::vector<PressureRow> pressure_rows(const std::string& text)
{
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);
  const bool solid = line == "x,y,z,gap,multiplier,pressure,active";
  EXPECT_TRUE(solid || line == "x,y,gap,multiplier,pressure,active") << line;
  const std::size_t n_fields = solid ? 7 : 6;
  std::vector<PressureRow> rows;
  while (std::getline(lines, line))
  {
    std::vector<double> fields;
    std::istringstream values(line);
    for (std::string value; std::getline(values, value, ',');)
      fields.push_back(std::stod(value));
    EXPECT_EQ(fields.size(), n_fields) << line;
    if (fields.size() != n_fields)
      continue;
    const double* const tail = fields.data() + n_fields - 4; // gap, multiplier, pressure, active
    rows.push_back({fields[0], fields[1], solid ? fields[2] : 0., tail[1], tail[2], tail[3] == 1.});
  }
  return rows;
}

unsigned int contact_episodes(const History& history)
{
  const auto active     = history.column("active_constraints");
  unsigned int episodes = 0;
  for (unsigned int row = 1; row < active.size(); ++row)
    episodes += active[row] > 0. && active[row - 1] == 0.;
  return episodes;
}
} // namespace dyncontact::testing
