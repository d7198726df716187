#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/lac/vector.h>

namespace dyncontact
{
/**
 * The state of the time integration at one time t_n, each a vector over the displacement DoFs
 * (length n_dofs): the displacement u_n [length], velocity v_n [length/time] and acceleration a_n
 * [length/time^2] of Newmark's scheme (Taylor & Papadopoulos 1993, eqs. 9-10), the internal force
 * Q(u_n) and the external force W(t_n) [force]. What a failed step returns to, and what a
 * checkpoint keeps of the integration.
 */
struct StepState
{
  Vector<double> displacement, velocity, acceleration, internal_force, external_force;

  /** Every vector set to zero with `n_dofs` entries. */
  void reinit(types::global_dof_index n_dofs);

  /** Writes or reads the five vectors, in the order above (boost serialization). */
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& displacement;
    archive& velocity;
    archive& acceleration;
    archive& internal_force;
    archive& external_force;
  }
};
} // namespace dyncontact
