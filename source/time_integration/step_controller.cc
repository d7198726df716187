#include <dyncontact/time_integration/step_controller.h>

namespace dyncontact
{
StepController::StepController(const double nominal_step,
                               const unsigned int n_steps,
                               const unsigned int max_cuts)
    : nominal_step_size(nominal_step), n_steps(n_steps), max_cuts(max_cuts),
      units_per_nominal_step(std::uint64_t(1) << max_cuts)
{
  Assert(nominal_step > 0., ExcMessage("The time step must be positive."));
  Assert(max_cuts <= 30, ExcMessage("At most 30 cuts are supported."));
}

double StepController::step_size() const
{
  return nominal_step_size * static_cast<double>(units_per_step()) / units_per_nominal_step;
}

double StepController::start_time() const
{
  // (n - 1) dt + position dt / 2^max_cuts, with exact integer positions.
  return nominal_step_size *
         ((nominal_index - 1) + static_cast<double>(position) / units_per_nominal_step);
}

double StepController::end_time() const
{
  const std::uint64_t end = position + units_per_step();
  return end == units_per_nominal_step
             ? nominal_step_size * nominal_index
             : nominal_step_size *
                   ((nominal_index - 1) + static_cast<double>(end) / units_per_nominal_step);
}

bool StepController::accept()
{
  position += units_per_step();
  ++accepted_at_level;
  if (level > 0 && accepted_at_level >= 2 && position % (2 * units_per_step()) == 0)
  {
    --level;
    accepted_at_level = 0;
  }
  if (position < units_per_nominal_step)
    return false;
  position = 0;
  ++nominal_index;
  return true;
}

bool StepController::cut()
{
  if (!can_cut())
    return false;
  ++level;
  accepted_at_level = 0;
  return true;
}
} // namespace dyncontact
