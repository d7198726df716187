#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/simulation/run_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * Reads a parameter file, applies `Section/entry=value` overrides, checks every value and keeps
 * the ParameterHandler so that the run can record what it used. Every problem becomes an
 * InputError naming the file, the entry and the allowed range. It does not create any output.
 */
class ParameterReader
{
public:
  /**
   * Parses `filename` and then the overrides in order (each "Section/Subsection/entry=value").
   * Throws InputError on an unreadable file, an unknown entry, a value out of range, or
   * inconsistent geometry.
   */
  ParameterReader(const std::string& filename, const std::vector<std::string>& overrides);

  const RunParameters& parameters() const { return run_parameters; }

  /**
   * Writes `original.prm` (the input as given, followed by the overrides as comments) and
   * `parameters.prm` (every entry with the value in effect) into `directory`.
   */
  void write_records(const std::string& directory) const;

  /**
   * Prints a parameter file for problems of `kind` ("bars" or "mesh"): every entry such a problem
   * takes, with its documentation, default and allowed values. It runs as printed: bars, one bar
   * at rest; mesh, two spheres at rest in the shipped meshes/two_spheres.geo (named by its
   * absolute path in the source tree) with one contact pair.
   */
  static void print_template(std::ostream& out, const std::string& kind);

private:
  /**
   * Resolves the deprecated Time integration/scheme into Contact/dynamics (with a warning) and
   * checks across subsections (contact dynamics vs formulation).
   */
  void resolve_and_check();
  /** Fills RunParameters::problem_entries from the parsed entries. */
  void record_problem_entries();

  std::string input_filename;
  std::string input_text;
  std::vector<std::string> overrides;
  ParameterHandler prm;
  RunParameters run_parameters;
};
} // namespace dyncontact
