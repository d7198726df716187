#pragma once

#include <dyncontact/base/global.h>

#include <cstdint>

namespace dyncontact
{
/**
 * Step control by cutting: the run advances on the nominal grid t_n = n dt (n = 1..n_steps), and a
 * step that fails (Newton, an inverted element, a tripped guard) is retried with half the size,
 * down to dt / 2^max_cuts. After two accepted sub-steps at one size, the size doubles again as
 * soon as the position allows it to end on the grid of the doubled size, so every nominal time
 * t_n is still reached exactly and a cut costs only the sub-steps it needs.
 *
 * Positions are counted in integer units of dt / 2^max_cuts, so times are exact multiples and
 * never accumulate round-off. It does not solve, check or record anything.
 */
class StepController
{
public:
  /** `nominal_step` dt > 0, `n_steps` >= 1 nominal steps, `max_cuts` <= 30 halvings. */
  StepController(double nominal_step, unsigned int n_steps, unsigned int max_cuts);

  /** Whether the last nominal time has been reached. */
  bool finished() const { return nominal_index > n_steps; }

  /** Size of the next (sub)step [time]. */
  double step_size() const;

  /** Time at the start and at the end of the next (sub)step [time]. */
  double start_time() const;
  double end_time() const;

  /** The nominal step in progress, 1..n_steps (the next step ends inside or at its end). */
  unsigned int nominal_step() const { return nominal_index; }

  /**
   * The next step was accepted: advances the position; returns true if it reached a nominal time
   * t_n. The size regrows (doubles) after two accepted sub-steps at a level when aligned.
   */
  bool accept();

  /** The next step failed: halves its size. Returns false (and changes nothing) at the minimum. */
  bool cut();
  /** Whether the next step is above the smallest size, dt / 2^max_cuts (cut() would succeed). */
  bool can_cut() const { return level < max_cuts; }

  /** Writes or reads the position (checkpoints); the nominal grid comes from the constructor. */
  template <class Archive>
  void serialize(Archive& archive, const unsigned int)
  {
    archive& nominal_index& position& level& accepted_at_level;
  }

private:
  /** Units of dt / 2^max_cuts in a step at the current level. */
  std::uint64_t units_per_step() const { return std::uint64_t(1) << (max_cuts - level); }

  const double nominal_step_size;
  const unsigned int n_steps;
  const unsigned int max_cuts;
  const std::uint64_t units_per_nominal_step;
  unsigned int nominal_index     = 1;
  std::uint64_t position         = 0; ///< within the nominal step in progress, in units
  unsigned int level             = 0;
  unsigned int accepted_at_level = 0;
};
} // namespace dyncontact
