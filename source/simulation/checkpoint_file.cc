#include <dyncontact/base/global.h>
#include <dyncontact/simulation/checkpoint_file.h>

#include <filesystem>
#include <fstream>

namespace dyncontact::checkpoint_file
{
void write(const std::string& directory,
           const ProblemFingerprint& fingerprint,
           const std::function<void(boost::archive::binary_oarchive&)>& write_state)
{
  const std::string file = directory + "/checkpoint.bin";
  {
    std::ofstream stream(file + ".tmp", std::ios::binary);
    boost::archive::binary_oarchive archive(stream);
    archive << fingerprint;
    write_state(archive);
    if (!stream)
      throw SolverFailure("cannot write the checkpoint " + file + ".tmp");
  }
  // Atomic: a run killed while writing leaves the previous checkpoint intact.
  std::filesystem::rename(file + ".tmp", file);
}

void read(const std::string& directory,
          const ProblemFingerprint& fingerprint,
          const std::function<void(boost::archive::binary_iarchive&)>& read_state)
{
  const std::string file = directory + "/checkpoint.bin";
  std::ifstream stream(file, std::ios::binary);
  if (!stream)
    throw InputError("--resume " + directory + ": there is no checkpoint " + file +
                     " (a run writes one when interrupted or every Output/checkpoint interval "
                     "steps).");
  try
  {
    boost::archive::binary_iarchive archive(stream);
    ProblemFingerprint written;
    archive >> written;
    const std::string difference = fingerprint.difference_from(written);
    if (!difference.empty())
      throw InputError("--resume " + directory +
                       ": the checkpoint belongs to another problem: " + difference + ".");
    read_state(archive);
  }
  catch (const boost::archive::archive_exception& error)
  {
    throw InputError("--resume " + directory + ": " + file + " is not a readable checkpoint (" +
                     error.what() + ").");
  }
}
} // namespace dyncontact::checkpoint_file
