#include <dyncontact/base/version.h>
#include <dyncontact/simulation/interruption.h>
#include <dyncontact/simulation/run_record.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
namespace
{
/** Now in UTC as ISO 8601, e.g. 2026-12-01T22:40:07Z. */
std::string now_utc()
{
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::ostringstream text;
  text << std::put_time(&utc, "%Y-%m-%dT%H:%M:%SZ");
  return text.str();
}

/** `text` as a JSON string literal. */
std::string quoted(const std::string& text)
{
  std::string json = "\"";
  for (const char c : text)
    switch (c)
    {
    case '"':
      json += "\\\"";
      break;
    case '\\':
      json += "\\\\";
      break;
    case '\n':
      json += "\\n";
      break;
    case '\t':
      json += "\\t";
      break;
    default:
      if (static_cast<unsigned char>(c) < 0x20)
      {
        char escaped[8];
        std::snprintf(escaped, sizeof(escaped), "\\u%04x", c);
        json += escaped;
      }
      else
        json += c;
    }
  return json + "\"";
}
} // namespace

RunOutcome RunOutcome::of(const std::exception_ptr& exception)
{
  try
  {
    std::rethrow_exception(exception);
  }
  catch (const InputError& error)
  {
    return {2, "input error", error.what(), 0};
  }
  catch (const RunInterrupted& interruption)
  {
    return {128 + interruption.signal(), "interrupted", interruption.what(), interruption.signal()};
  }
  catch (const SolverFailure& error)
  {
    return {3, "solve failed", error.what(), 0};
  }
  catch (const ExceptionBase& error)
  {
    std::ostringstream message;
    error.print_info(message);
    return {4, "internal error", message.str(), 0};
  }
  catch (const std::exception& error)
  {
    return {4, "internal error", error.what(), 0};
  }
  catch (...)
  {
    return {4, "internal error", "an unknown exception", 0};
  }
}

RunRecord::RunRecord(std::string directory,
                     std::vector<std::string> command_line,
                     const std::string& parameter_file,
                     const unsigned int n_ranks)
    : directory(std::move(directory)), command_line(std::move(command_line)),
      working_directory(std::filesystem::current_path().string()),
      parameter_file(std::filesystem::absolute(parameter_file).lexically_normal().string()),
      n_ranks(n_ranks), started(now_utc()), start_time(std::chrono::steady_clock::now())
{
  if (!write())
    throw InputError("Output/directory = '" + this->directory + "': cannot write run.json.");
}

void RunRecord::set_wall_times(std::map<std::string, double> times)
{
  wall_times = std::move(times);
}

void RunRecord::set_summary_status(std::string status)
{
  summary_status = std::move(status);
}

void RunRecord::finish(const RunOutcome& run_outcome)
{
  finished = now_utc();
  wall_times["total"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  outcome     = run_outcome;
  has_outcome = true;
  write();
}

bool RunRecord::write() const
{
  std::ofstream file(directory + "/run.json");
  file << "{\n  \"program\": \"dyncontact\",\n  \"version\": " << quoted(version())
       << ",\n  \"commit\": " << quoted(commit()) << ",\n  \"started\": " << quoted(started)
       << ",\n  \"finished\": " << (has_outcome ? quoted(finished) : "null")
       << ",\n  \"command_line\": [";
  for (unsigned int i = 0; i < command_line.size(); ++i)
    file << (i > 0 ? ", " : "") << quoted(command_line[i]);
  file << "],\n  \"working_directory\": " << quoted(working_directory)
       << ",\n  \"parameter_file\": " << quoted(parameter_file) << ",\n  \"mpi_ranks\": " << n_ranks
       << ",\n  \"wall_time_seconds\": {";
  bool first = true;
  for (const auto& [phase, seconds] : wall_times)
  {
    file << (first ? "" : ",") << "\n    " << quoted(phase) << ": " << std::setprecision(6)
         << seconds;
    first = false;
  }
  file << (wall_times.empty() ? "" : "\n  ")
       << "},\n  \"outcome\": " << quoted(has_outcome ? outcome.kind : "running")
       << ",\n  \"message\": " << quoted(has_outcome ? outcome.message : "")
       << ",\n  \"exit_code\": " << (has_outcome ? std::to_string(outcome.exit_code) : "null")
       << ",\n  \"summaries\": " << (summary_status.empty() ? "null" : quoted(summary_status))
       << "\n}\n";
  return static_cast<bool>(file);
}
} // namespace dyncontact
