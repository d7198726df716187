#pragma once

#include <dyncontact/contact_dynamics/contact_dynamics.h>

namespace dyncontact
{
/**
 * Contact/dynamics = taylor-papadopoulos: the modified Newmark of Taylor & Papadopoulos (1993),
 * eqs. (21)-(22) and the recovery formulas after them, extended to pairs whose master side is a
 * weighted set of nodes (node-to-segment; doc/method.md section 4.1). On all active pairs at once
 * the rates of their nodes are shifted along the pairs' normals, with weights equal to the lumped
 * nodal masses (a wall has infinite weight and stays at rest), so that every pair's normal
 * velocity and acceleration jumps vanish: the multipliers solve S lambda = r with
 * S = B M^-1 B^T (size: the number of active pairs; diagonal for node-to-node pairs, where the
 * corrected normal rates of both nodes are the mass-weighted means of the classical ones). Linear
 * momentum is conserved (each pair's coefficients sum to zero). All other nodes keep the classical
 * rates; a node-to-node pair's tangential rates are kept up to round-off.
 *
 * With Coulomb friction a stuck pair moves with its master point: the same correction makes its
 * relative rates continuous along its tangents as well (rows of S along each tangent of
 * ContactConstraints::stick_directions(), eqs. (21)-(22) with [[u_n - u_{n+1}]] . t in the place
 * of g_n - g_{n+1}); a sliding pair's normal parts only. At zero friction no pair is stuck and the
 * scheme is the one above, bit for bit.
 *
 * Assumes exactly closed active pairs (Lagrange multipliers; with a penalty a pair stays
 * penetrated and the correction glues it, an input error).
 */
template <int dim>
class TaylorPapadopoulos : public ContactDynamics<dim>
{
public:
  /**
   * With friction a stuck pair's whole relative velocity and acceleration are made continuous,
   * a sliding pair's normal parts only (doc/method.md section 7).
   */
  bool carries_friction() const override { return true; }

  void correct_rates(const RateMap& rates,
                     const ContactConstraints<dim>& contact,
                     const Vector<double>& lumped_mass,
                     const StepStates& step,
                     Vector<double>& v_new,
                     Vector<double>& a_new) const override;
};
} // namespace dyncontact
