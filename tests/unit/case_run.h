#pragma once
// Test support: runs shipped prm files in-process (bars paired with their exact solution).

#include <dyncontact/reference/exact_bar_solution.h>
#include <dyncontact/simulation/parameter_reader.h>
#include <dyncontact/simulation/simulation.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dyncontact::testing
{
/** Path of a file in the source tree, e.g. "prm/bar_rigid_wall.prm". */
std::string source_path(const std::string& relative_path);

/** A finished bar run and the exact solution of the same problem. */
struct BarRun
{
  RunParameters parameters;
  std::unique_ptr<Simulation<1>> simulation;
  std::unique_ptr<ExactBarSolution> exact;
  /** The text of exact_summary.csv, by name (see MeshRun::files). */
  std::map<std::string, std::string> files;

  const History& history() const { return simulation->history(); }
  double time_step() const { return parameters.time.time_step; }
  /** Reference x of the tip (monitor node) of body b (0-based). */
  double tip_position(unsigned int body) const
  {
    return simulation->monitor_nodes()[body].position[0];
  }
  /** Exact total contact force (all interfaces) at t, right-continuous. */
  double exact_contact_force(double t) const;
};

/** A finished run of a mesh problem: 2D (axisymmetric or plane strain) or 3D. */
template <int dim>
struct CaseRun
{
  RunParameters parameters;
  std::unique_ptr<Simulation<dim>> simulation;
  /**
   * The text of every profile_t<T>.csv, contact_pressure_t<T>.csv and *_summary.csv the run
   * wrote, by name.
   */
  std::map<std::string, std::string> files;

  const History& history() const { return simulation->history(); }
};

/** A finished run of a 2D mesh problem. */
using MeshRun = CaseRun<2>;
/** A finished run of a 3D mesh problem (Problem/geometry = 3d mesh). */
using SolidRun = CaseRun<3>;

/**
 * Runs `prm_file` (relative to the source tree) with the overrides applied after the file, in a
 * fresh temporary directory (removed afterwards) without VTU or exact.csv: the tests read the
 * in-memory history and evaluate references directly.
 */
BarRun run_bar_case(const std::string& prm_file, const std::vector<std::string>& overrides = {});

/**
 * The same for an axisymmetric mesh problem; the profiles it writes (Output/profile times) and
 * its summary are kept in memory, see MeshRun::files.
 */
MeshRun run_mesh_case(const std::string& prm_file, const std::vector<std::string>& overrides = {});

/** `more` after `overrides`. */
std::vector<std::string> with(std::vector<std::string> overrides,
                              const std::vector<std::string>& more);

/** The same for a 3D mesh problem. */
SolidRun run_solid_case(const std::string& prm_file,
                        const std::vector<std::string>& overrides = {});

/**
 * The overrides that put prm/spheres_rho0.001.prm (graded mesh, node-to-segment, modified Newton)
 * on the paper's structured coarse mesh, as the tests were written for: meshes/two_spheres.geo
 * Refinement 0 (432 cells, pole edge 0.26) with `geo_prefix` before its parameters (e.g.
 * "CentreZ: -10, "), node-to-node pairs and full Newton; then `more`.
 */
std::vector<std::string> paper_coarse_spheres(const std::vector<std::string>& more = {},
                                              const std::string& geo_prefix        = "");

/**
 * History rows strictly inside the exact contact interval (first interface), minus the samples
 * taken exactly at a jump of the exact tip velocities or contact force. At such an instant the
 * exact solution is a step seen from one side (right-continuous) while the discrete solution is
 * in transit, so neither side's value is a meaningful reference; there is one such sample per jump.
 */
std::vector<unsigned int> contact_samples(const BarRun& run);

/**
 * The largest difference between two runs' histories (same rows) over the columns of the bodies
 * as a whole (contact force, energies, momenta), relative to the column's largest magnitude in
 * `reference`.
 */
double largest_relative_difference(const History& history, const History& reference);

/** One row of contact_pressure_t<T>.csv: the slave node's current x (r), y and z (0 in 2D), its
 * nodal force (multiplier) and contact pressure, active or not. */
struct PressureRow
{
  double x, y, z, multiplier, pressure;
  bool active;
};

/** The rows of the text of a contact_pressure_t<T>.csv file (columns x, y, (z,) gap, multiplier,
 * pressure, active). */
std::vector<PressureRow> pressure_rows(const std::string& text);

/** The number of contact episodes: rows with active pairs that follow a row without. */
unsigned int contact_episodes(const History& history);

/**
 * The largest |mean of contact_force - mean of the exact force| over the windows (w, w + 1] of
 * one time unit, w = 0, ..., windows - 1 (issue 14's measure of a force against its exact
 * history: a chattering force can average right, a biased one cannot). Every window must hold a
 * row (a test failure otherwise).
 */
double max_window_mean_force_error(const BarRun& run, unsigned int windows);

/** max |contact_force - value| over the rows with start < t < end. */
double max_force_deviation(const History& history, double value, double start, double end);
} // namespace dyncontact::testing
