#pragma once

#include <dyncontact/base/global.h>

#include <chrono>
#include <exception>
#include <map>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * How a run ended, as the executable reports it: the exit code, a word for the kind ("completed",
 * "input error" = exit 2, "solve failed" = 3, "interrupted" = 128 + signal, "internal error" = 4)
 * and the message.
 */
struct RunOutcome
{
  int exit_code;
  std::string kind;
  std::string message;
  int signal; ///< the signal of an interrupted run, 0 otherwise

  /** The outcome of a run that threw `exception` (InputError, SolverFailure, RunInterrupted, a
   *  deal.II or standard exception). */
  static RunOutcome of(const std::exception_ptr& exception);
};

/**
 * `run.json` in a run's output directory: what made the results and how the run went, for a
 * reader who finds the directory later. It holds the program, version and git commit, the start
 * and end (UTC, ISO 8601), the command line, the working directory and the absolute parameter file,
 * the number of MPI ranks, the wall time of each phase [s], the outcome, its message and the exit
 * code. It is written when the run starts (outcome "running", exit code null, so a killed run
 * shows as such) and rewritten when it ends. Written by the caller's rank only (rank 0).
 */
class RunRecord
{
public:
  /** Records the start now and writes `directory`/run.json; throws InputError if it cannot. */
  RunRecord(std::string directory,
            std::vector<std::string> command_line,
            const std::string& parameter_file,
            unsigned int n_ranks);

  /** The wall time [s] of each timed phase; finish() adds the whole run's as "total". */
  void set_wall_times(std::map<std::string, double> wall_times);

  /**
   * The status of the run's summaries (Simulation::summary_status(): "complete" or
   * "incomplete: <why>"), written as "summaries"; null while empty.
   */
  void set_summary_status(std::string status);

  /** Records the end now with `outcome` and rewrites run.json (silently keeps the old one if the
   *  file cannot be written: the outcome is also on the terminal). */
  void finish(const RunOutcome& outcome);

private:
  /** Writes run.json; false if it could not be written. */
  bool write() const;

  std::string directory;
  std::vector<std::string> command_line;
  std::string working_directory;
  std::string parameter_file;
  unsigned int n_ranks;
  std::string started;
  std::chrono::steady_clock::time_point start_time;
  std::string finished;
  std::map<std::string, double> wall_times;
  std::string summary_status;
  bool has_outcome = false;
  RunOutcome outcome{};
};
} // namespace dyncontact
