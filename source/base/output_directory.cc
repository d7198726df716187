#include <dyncontact/base/output_directory.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <unistd.h>

namespace dyncontact
{
void prepare_output_directory(const std::string& directory)
{
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory))
    throw InputError("Output/directory = '" + directory + "' cannot be created" +
                     (error ? " (" + error.message() + ")" : std::string()) +
                     "; give a writable directory.");
  const std::string probe = directory + "/.dyncontact-write-test";
  {
    std::ofstream file(probe);
    if (!(file << "ok"))
      throw InputError("Output/directory = '" + directory +
                       "' is not writable; give a writable directory.");
  }
  std::filesystem::remove(probe, error);
}

void check_output_directory(const std::string& directory)
{
  // The directory itself if it exists, else the nearest ancestor that does (where it would be
  // created); a relative name without an existing ancestor lives in the working directory.
  std::filesystem::path existing = std::filesystem::absolute(directory).lexically_normal();
  std::error_code error;
  while (!std::filesystem::exists(existing, error) && existing.has_relative_path())
    existing = existing.parent_path();
  const bool is_directory = std::filesystem::is_directory(existing, error);
  if (!is_directory || access(existing.c_str(), W_OK | X_OK) != 0)
    throw InputError("Output/directory = '" + directory + "' cannot be " +
                     (existing == std::filesystem::absolute(directory).lexically_normal()
                          ? std::string("written")
                          : "created in '" + existing.string() + "'") +
                     (is_directory ? ": permission denied" : ": not a directory") +
                     "; give a writable directory.");
}

bool is_result_file(const std::string& file_name)
{
  // Times are written with C++'s default format (e.g. 5, 0.05, 2.0275, 1e-05).
  static const std::regex result_name(
      "(history|exact|exact_summary|hertz|hertz_parameters|finite_sphere|"
      "finite_sphere_parameters|impact_summary|cells)\\.csv|"
      "(profile|contact_pressure)_t[-+.0-9eE]+\\.csv|"
      "(solution|contact_surface)(_[0-9]+\\.([0-9]+\\.vtu|pvtu)|\\.pvd)|"
      "(original|parameters)\\.prm|run\\.json|checkpoint\\.bin(\\.tmp)?");
  return std::regex_match(file_name, result_name);
}

unsigned int remove_previous_results(const std::string& directory)
{
  unsigned int n_removed = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
    if (entry.is_regular_file(error) && is_result_file(entry.path().filename().string()))
    {
      if (!std::filesystem::remove(entry.path(), error))
        throw InputError("Output/directory = '" + directory + "': cannot remove " +
                         entry.path().filename().string() + " of an earlier run (" +
                         error.message() + "); give a directory this run can own.");
      ++n_removed;
    }
  if (error)
    throw InputError("Output/directory = '" + directory + "' cannot be read (" + error.message() +
                     "); give a writable directory.");
  return n_removed;
}
} // namespace dyncontact
