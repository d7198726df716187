#pragma once

#include <dyncontact/simulation/problem_fingerprint.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <functional>
#include <string>

namespace dyncontact
{
/**
 * The file `directory`/checkpoint.bin: a boost binary archive holding the ProblemFingerprint of
 * the run that wrote it, then that run's state, which each owner writes and reads itself
 * (`write_state`, `read_state`).
 */
namespace checkpoint_file
{
/**
 * Writes the file atomically (to checkpoint.bin.tmp, then renamed: a run killed while writing
 * leaves the previous checkpoint intact). Throws SolverFailure if it cannot be written.
 */
void write(const std::string& directory,
           const ProblemFingerprint& fingerprint,
           const std::function<void(boost::archive::binary_oarchive&)>& write_state);

/**
 * Opens the file, checks its fingerprint against `fingerprint` and hands the archive, positioned
 * at the state, to `read_state`. Throws InputError naming `--resume directory` if the file is
 * missing, unreadable or of another problem (the first difference: ranks, an entry with both
 * values, or the discretization).
 */
void read(const std::string& directory,
          const ProblemFingerprint& fingerprint,
          const std::function<void(boost::archive::binary_iarchive&)>& read_state);
} // namespace checkpoint_file
} // namespace dyncontact
