#include <dyncontact/time_integration/step_state.h>

namespace dyncontact
{
void StepState::reinit(const types::global_dof_index n_dofs)
{
  for (Vector<double>* vector :
       {&displacement, &velocity, &acceleration, &internal_force, &external_force})
    vector->reinit(n_dofs);
}
} // namespace dyncontact
