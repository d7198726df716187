#include <dyncontact/time_integration/step_state.h>

namespace dyncontact
{
void StepState::reinit(const std::shared_ptr<const Utilities::MPI::Partitioner>& owned_dofs)
{
  for (DistributedVector* vector :
       {&displacement, &velocity, &acceleration, &internal_force, &external_force})
    vector->reinit(owned_dofs);
}

StepState::Whole StepState::gather_on_root() const
{
  return {dyncontact::gather_on_root(displacement),
          dyncontact::gather_on_root(velocity),
          dyncontact::gather_on_root(acceleration),
          dyncontact::gather_on_root(internal_force),
          dyncontact::gather_on_root(external_force)};
}

void StepState::assign(const Whole& whole)
{
  copy_owned_entries(whole.displacement, displacement);
  copy_owned_entries(whole.velocity, velocity);
  copy_owned_entries(whole.acceleration, acceleration);
  copy_owned_entries(whole.internal_force, internal_force);
  copy_owned_entries(whole.external_force, external_force);
}
} // namespace dyncontact
