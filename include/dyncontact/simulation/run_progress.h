#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * What a run tells about its progress: the counts of steps taken, step cuts (and the times of the
 * first ten) and linear solves, kept across a resume (serialize()); the progress line with its
 * ETA, at most every few seconds and whenever the active set changed; and the final lines (the
 * counts, the wall time per timed phase, the cost per step with and without active pairs). Wall
 * times are this run's. Writes to the log it is given; computes nothing else.
 */
class RunProgress
{
public:
  /** A run of `n_steps` steps of `time_step` [time]; `log` must outlive it. */
  RunProgress(const ConditionalOStream& log, unsigned int n_steps, double time_step);

  /** Whether report() prints the progress line (default true; `--quiet` switches it off). */
  void set_shown(const bool show) { shown = show; }

  /** Starts this run's wall clock at `time` [time] (0, or a resumed run's). */
  void start(double time);
  /** Starts the wall clock of one step (for end_step()). */
  void begin_step();
  /** A step cut; `start_time` [time] is the start of the step that was cut. */
  void count_cut(double start_time);
  /** A step accepted after `linear_solves` solves (of every attempt). */
  void count_step(unsigned int linear_solves);
  /**
   * Ends the step's wall clock, begun at begin_step(); `in_contact`: pairs were active at its
   * start or end.
   */
  void end_step(bool in_contact);
  /**
   * The active pairs of the step that couple two ranks' data (pairs_across_ranks()); the most in
   * one step is reported by report_totals().
   */
  void count_pairs_across_ranks(unsigned int n_pairs);

  /**
   * The progress line after nominal step `nominal_step` at `time`, if due (`active_set_changed`,
   * `finished` or the interval since the last line): the share done, steps per second, ETA,
   * solves per step, `n_active` pairs and the algorithmic `energy`.
   */
  void report(unsigned int nominal_step,
              double time,
              bool finished,
              bool active_set_changed,
              unsigned int n_active,
              double energy);

  /**
   * The run's last lines: steps, cuts, solves (`factorizations`, `low_rank_updates`), the wall
   * time and its `phases` [s], the `directory` of the results, the cost per step and the peak
   * resident memory of the ranks, `peak_memory` [MiB] (largest with its rank, smallest, mean);
   * on several ranks the most active pairs of one step that coupled two ranks' data
   * (count_pairs_across_ranks()); then `solver_statistics` (the direct solver's own figures of its
   * last factorization) if not empty.
   */
  void report_totals(unsigned int factorizations,
                     unsigned int low_rank_updates,
                     const std::string& solver_statistics,
                     const std::map<std::string, double>& phases,
                     const Utilities::MPI::MinMaxAvg& peak_memory,
                     const std::string& directory) const;

  /** The counts (checkpoint). */
  template <class Archive>
  void serialize(Archive& archive, const unsigned int)
  {
    archive& total_solves;
    archive& total_cuts;
    archive& steps_taken;
    archive& cut_places;
  }

private:
  using Clock = std::chrono::steady_clock;
  const ConditionalOStream& log;
  const unsigned int n_steps;
  const double time_step;
  bool shown                = true;
  unsigned int total_solves = 0, total_cuts = 0, steps_taken = 0;
  std::vector<std::string> cut_places; ///< times of the first cuts
  Clock::time_point wall_start, last_report, step_start;
  unsigned int steps_this_run = 0;
  double start_fraction       = 0.; ///< of the run, done before this one started (resume)
  /** Wall time [s] and number of this run's steps without ([0]) and with ([1]) active pairs. */
  double step_wall[2]                  = {0., 0.};
  unsigned int step_count[2]           = {0, 0};
  unsigned int most_pairs_across_ranks = 0; ///< in one of this run's steps
};
} // namespace dyncontact
