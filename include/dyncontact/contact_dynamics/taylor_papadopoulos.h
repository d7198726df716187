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
 * Assumes exactly closed active pairs (Lagrange multipliers; with a penalty a pair stays
 * penetrated and the correction glues it, an input error).
 */
template <int dim>
class TaylorPapadopoulos : public ContactDynamics<dim>
{
public:
  void correct_rates(const RateMap& rates,
                     const ContactConstraints<dim>& contact,
                     const Vector<double>& lumped_mass,
                     const StepStates& step,
                     Vector<double>& v_new,
                     Vector<double>& a_new) const override;
};
} // namespace dyncontact
