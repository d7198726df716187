#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace dyncontact
{
/** What a run writes and where. Subsection `Output`. */
struct OutputParameters
{
  std::string directory;
  std::vector<double> profile_times;
  unsigned int vtu_interval;
  std::vector<double> vtu_times;
  /// with VTU output on, also a frame at every step (cut steps included) with active pairs
  bool vtu_during_contact;
  /// write checkpoint.bin every this many nominal steps (0: only when interrupted)
  unsigned int checkpoint_interval;
  bool write_exact_solution;

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm);
};
} // namespace dyncontact
