#pragma once

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * What a checkpoint (checkpoint.bin) must share with the run that resumes it, so that the resumed
 * run continues the interrupted one's problem instead of mixing two:
 *  - the number of MPI ranks: the DoF numbering of the distributed triangulation follows the
 *    partition into ranks, so the saved vectors are only meaningful on as many ranks;
 *  - every parameter entry that defines the problem (RunParameters::problem_entries: materials,
 *    densities, loads, mesh file and its parameters, contact pairs and settings, integrator and
 *    its parameters, time step, Newton, guards; all but Output and Time integration/end time);
 *  - the discretization: dimension, DoFs, candidate pairs, bodies and a checksum of the node
 *    positions (a mesh file changed under the same name).
 */
struct ProblemFingerprint
{
  unsigned int n_ranks = 1;
  /** "Section/entry" and value, in declaration order. */
  std::vector<std::pair<std::string, std::string>> entries;
  std::string discretization;

  template <class Archive>
  void serialize(Archive& archive, const unsigned int)
  {
    archive& n_ranks& entries& discretization;
  }

  /**
   * Empty if a run with this fingerprint may continue `checkpoint`, else one sentence naming the
   * first difference: the rank counts, the entry (with both values) or the discretization.
   */
  std::string difference_from(const ProblemFingerprint& checkpoint) const;
};

/**
 * A checksum of `values` (e.g. the node coordinates in node order) as 16 hexadecimal digits:
 * 64-bit FNV-1a over their bytes, so any change of any value changes it.
 */
std::string checksum(const std::vector<double>& values);
} // namespace dyncontact
