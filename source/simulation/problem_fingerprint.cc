#include <dyncontact/simulation/problem_fingerprint.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <map>
#include <sstream>

namespace dyncontact
{
std::string ProblemFingerprint::difference_from(const ProblemFingerprint& checkpoint) const
{
  if (n_ranks != checkpoint.n_ranks)
    return "the checkpoint was written by a run on " + std::to_string(checkpoint.n_ranks) +
           " MPI rank(s), this one has " + std::to_string(n_ranks) +
           " (the saved state is numbered by the ranks' partition of the mesh): resume with "
           "mpirun -np " +
           std::to_string(checkpoint.n_ranks);
  const std::map<std::string, std::string> saved(checkpoint.entries.begin(),
                                                 checkpoint.entries.end());
  for (const auto& [entry, value] : entries)
  {
    const auto found = saved.find(entry);
    if (found == saved.end())
      return entry + " = " + value + " is set here, but the checkpoint's problem has no such entry";
    if (found->second != value)
      return entry + " = " + value + " here, but " + found->second +
             " in the checkpoint's run (resume with --set \"" + entry + "=" + found->second +
             "\", or start a new run)";
  }
  for (const auto& [entry, value] : checkpoint.entries)
    if (std::none_of(entries.begin(),
                     entries.end(),
                     [&entry](const auto& here) { return here.first == entry; }))
      return "the checkpoint's run has " + entry + " = " + value + ", which this problem lacks";
  if (discretization != checkpoint.discretization)
    return "the discretization differs (checkpoint: " + checkpoint.discretization +
           "; here: " + discretization + "): the mesh file changed";
  return "";
}

std::string checksum(const std::vector<double>& values)
{
  std::uint64_t hash = 14695981039346656037ull;
  for (const double value : values)
  {
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &value, sizeof(double));
    for (const unsigned char byte : bytes)
    {
      hash ^= byte;
      hash *= 1099511628211ull;
    }
  }
  std::ostringstream text;
  text << std::hex << std::setw(16) << std::setfill('0') << hash;
  return text.str();
}
} // namespace dyncontact
