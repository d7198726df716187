#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/postprocess/field_output.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{
/**
 * What the contact layer's state shows, for the step measures, the history, the acceptance of a
 * step and the field output: the contact force recovered from the nodes' balances, the normal rate
 * jumps across the active pairs, the penetration, the contact radius, the event work of a step,
 * the nodal contact traction and the pressure samples of the contact surfaces. Reads the
 * ContactConstraints' pairs, active set, pair forces and gaps (which must outlive it); nothing
 * here feeds the solve. Vectors passed in and out are volume vectors over the displacement DoFs
 * (the state's and the traction: each rank its owned DoFs; the lumped mass whole); each query
 * gathers what it reads onto the contact border (ContactBorder), so every query that takes a
 * DistributedVector is collective.
 */
template <int dim>
class ContactFields
{
public:
  explicit ContactFields(const ContactConstraints<dim>& contact);

  /**
   * Total interface force, compression positive, recovered from the equations of motion of the
   * body-A nodes of the active pairs: the sum of -n . (M a + Q(u) - W) at those nodes
   * (`net_internal_force` = Q(u) - W) [force]. It equals the sum of the multipliers for the
   * classical scheme and differs at an impact step of the modified one, whose corrected
   * accelerations carry the interface force.
   */
  double recovered_contact_force(const Vector<double>& lumped_mass,
                                 const DistributedVector& acceleration,
                                 const DistributedVector& net_internal_force) const;

  /**
   * The interface force of the active pairs between bodies (wall pairs left out) recovered from
   * the nodes' balances (M a + Q - W) along `direction` (a unit vector, e.g. the impact
   * direction) on each side [force]: `on_a` from the slave nodes of body A (compression
   * positive), `on_b` from the master nodes of body B (the force A exerts on B), each node once
   * however many pairs hold it. Equal up to round-off, also after the modified scheme's
   * correction, which conserves momentum; their difference measures the force balance.
   */
  struct SideForces
  {
    double on_a;
    double on_b;
  };
  SideForces recovered_side_forces(const Vector<double>& lumped_mass,
                                   const DistributedVector& acceleration,
                                   const DistributedVector& net_internal_force,
                                   const Tensor<1, dim>& direction) const;

  /** Sum of ContactConstraints::pair_force() over the pairs [force]. */
  double total_pair_force() const;

  /**
   * The work of the contact events of a step [force x length], from the state `old` at u_n
   * (`old_displacement`) to the current one at u_{n+1} (`new_displacement`): (1/2) sum over the
   * pairs that closed (active now, not in `old`) of pair_force() times the gap g_k(u_n), plus
   * (1/2) sum over the pairs that opened (active in `old`, not now) of their old force
   * force_per_multiplier lambda_k,n times the gap g_k(u_{n+1}) (positive parts). With massless
   * contact nodes (mass redistribution) on the trapezoidal rule these are exactly the energy the
   * step loses at the closings and gains at the releases, for linear elasticity and gaps: the
   * step's energy change is (1/2) sum_k (lambda_k,n + lambda_k,n+1)(g_k,n+1 - g_k,n)
   * (doc/schemes.md, "Mass redistribution with resolved contact events").
   */
  double event_work(const DistributedVector& old_displacement,
                    const DistributedVector& new_displacement,
                    const typename ContactConstraints<dim>::State& old) const;

  /** The largest penetration max(0, -g) over all candidate pairs at `displacement` [length]. */
  double max_penetration(const DistributedVector& displacement) const;

  /**
   * The largest |[[f]]| = |n . (f_B - f_A)| over the active pairs of a nodal field (velocity:
   * length/time, acceleration: length/time^2); zero if none is active. The paper's modified
   * Newmark (Taylor & Papadopoulos 1993, eqs. 22-23) makes it zero for velocity and acceleration.
   */
  double max_active_normal_jump(const DistributedVector& field) const;

  /**
   * The largest |[[f]] . t| over the stuck pairs' tangents t (ContactConstraints::
   * stick_directions()) of a nodal field; zero if no pair sticks. The modified Newmark extended to
   * stick (TaylorPapadopoulos with friction) makes it zero for velocity and acceleration.
   */
  double max_stick_jump(const DistributedVector& field) const;

  /**
   * The largest distance of the current position of node A from the axis of the last coordinate
   * (r in axisymmetry, where it is the contact radius) over the active pairs; zero if none is
   * active. Meaningless in 1D, where it is zero.
   */
  double contact_radius(const DistributedVector& displacement) const;

  /**
   * The nodal traction -p n on body A and p n on body B of every pair, p = `pressures` (one per
   * candidate pair) [force/area], on the owned DoFs of `layout` (a volume vector over the
   * displacement DoFs).
   */
  DistributedVector traction(const std::vector<double>& pressures,
                             const DistributedVector& layout) const;

  /** Per candidate pair: its slave node, gap, multiplier, `pressures[k]` and active flag. */
  std::vector<typename FieldOutput<dim>::PressureSample>
  pressure_samples(const std::vector<double>& pressures,
                   const DistributedVector& displacement) const;

private:
  const ContactConstraints<dim>& contact;
};
} // namespace dyncontact
