#include <dyncontact/simulation/run_progress.h>

#include <algorithm>
#include <iomanip>

namespace dyncontact
{
namespace
{
/// Wall-clock seconds between two progress lines (active-set changes are reported at once).
constexpr double progress_interval = 3.;

double seconds(const std::chrono::steady_clock::duration duration)
{
  return std::chrono::duration<double>(duration).count();
}
} // namespace

RunProgress::RunProgress(const ConditionalOStream& log,
                         const unsigned int n_steps,
                         const double time_step)
    : log(log), n_steps(n_steps), time_step(time_step)
{
}

void RunProgress::start(const double time)
{
  wall_start     = Clock::now();
  last_report    = wall_start;
  steps_this_run = 0;
  start_fraction = time / (n_steps * time_step);
}

void RunProgress::begin_step()
{
  step_start = Clock::now();
}

void RunProgress::count_cut(const double start_time)
{
  ++total_cuts;
  if (cut_places.size() < 10)
    cut_places.push_back(format_number(start_time));
}

void RunProgress::count_step(const unsigned int linear_solves)
{
  ++steps_taken;
  ++steps_this_run;
  total_solves += linear_solves;
}

void RunProgress::end_step(const bool in_contact)
{
  step_wall[in_contact] += seconds(Clock::now() - step_start);
  ++step_count[in_contact];
}

void RunProgress::count_pairs_across_ranks(const unsigned int n_pairs)
{
  most_pairs_across_ranks = std::max(most_pairs_across_ranks, n_pairs);
}

void RunProgress::report(const unsigned int nominal_step,
                         const double time,
                         const bool finished,
                         const bool active_set_changed,
                         const unsigned int n_active,
                         const double energy)
{
  const auto now = Clock::now();
  if (!shown ||
      !(active_set_changed || seconds(now - last_report) >= progress_interval || finished))
    return;
  last_report                = now;
  const double elapsed       = seconds(now - wall_start);
  const double done          = time / (n_steps * time_step);
  const double done_this_run = std::max(done - start_fraction, 1e-9);
  log << "  step " << std::setw(6) << nominal_step << "/" << n_steps << "  t = " << std::setw(10)
      << time << "  " << std::fixed << std::setprecision(1) << std::setw(5) << 100. * done << "%  "
      << std::setw(7) << steps_this_run / std::max(elapsed, 1e-9) << " steps/s  ETA "
      << std::setw(6) << elapsed * (1. - done) / done_this_run << " s  " << std::setprecision(2)
      << static_cast<double>(total_solves) / steps_taken << " solves/step" << std::defaultfloat
      << std::setprecision(6) << "  active pairs " << n_active << "  energy " << energy << "\n";
}

void RunProgress::report_totals(const unsigned int factorizations,
                                const unsigned int low_rank_updates,
                                const std::string& solver_statistics,
                                const std::map<std::string, double>& phases,
                                const Utilities::MPI::MinMaxAvg& peak_memory,
                                const std::string& directory) const
{
  log << "dyncontact: done, " << n_steps << " steps (" << steps_taken << " taken, " << total_cuts
      << " step cuts";
  for (unsigned int c = 0; c < cut_places.size(); ++c)
    log << (c == 0 ? " at t = " : ", ") << cut_places[c];
  if (total_cuts > cut_places.size())
    log << ", ...";
  log << "), " << total_solves << " linear solves (" << factorizations << " factorizations, "
      << low_rank_updates << " low-rank updates), wall time " << seconds(Clock::now() - wall_start)
      << " s (";
  for (auto phase = phases.begin(); phase != phases.end(); ++phase)
    log << (phase == phases.begin() ? "" : ", ") << phase->first << " " << phase->second << " s";
  log << "). Results in " << directory << "\n";
  log << "dyncontact: cost per step";
  for (const bool in_contact : {false, true})
    log << (in_contact ? ", " : " ")
        << 1e3 * step_wall[in_contact] / std::max(step_count[in_contact], 1u) << " ms "
        << (in_contact ? "with" : "without") << " active pairs (" << step_count[in_contact]
        << " steps)";
  log << "\ndyncontact: peak memory per rank " << std::fixed << std::setprecision(1)
      << peak_memory.max << " MiB (largest, rank " << peak_memory.max_index << "), "
      << peak_memory.min << " MiB (smallest), " << peak_memory.avg << " MiB (mean)"
      << std::defaultfloat << std::setprecision(6) << "\n";
  if (const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD); n_ranks > 1)
    log << "dyncontact: at most " << most_pairs_across_ranks << " active contact pairs in one step "
        << "had their slave node on one of the " << n_ranks
        << " ranks and their whole master face on others\n";
  if (!solver_statistics.empty())
    log << "dyncontact: " << solver_statistics << "\n";
}
} // namespace dyncontact
