#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/vector.h>

#include <memory>

namespace dyncontact
{
/**
 * The state of the time integration at one time t_n, each a vector over the displacement DoFs
 * distributed like the DoFs (each rank its owned DoFs): the displacement u_n [length], velocity
 * v_n [length/time] and acceleration a_n [length/time^2] of Newmark's scheme (Taylor &
 * Papadopoulos 1993, eqs. 9-10), the internal force Q(u_n) and the external force W(t_n) [force].
 * What a failed step returns to, and what a checkpoint keeps of the integration (as Whole).
 */
struct StepState
{
  DistributedVector displacement, velocity, acceleration, internal_force, external_force;

  /** Every vector set to zero, with the layout of `owned_dofs`. */
  void reinit(const std::shared_ptr<const Utilities::MPI::Partitioner>& owned_dofs);

  /** The five vectors whole (n_dofs entries each), as a checkpoint writes them. */
  struct Whole
  {
    Vector<double> displacement, velocity, acceleration, internal_force, external_force;

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

  /** The state whole on rank 0 (what it writes to a checkpoint), empty elsewhere. Collective. */
  Whole gather_on_root() const;

  /** Sets each vector's owned entries from `whole` (the vectors must have their layout). */
  void assign(const Whole& whole);
};
} // namespace dyncontact
