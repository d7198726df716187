#pragma once

#include <dyncontact/contact_dynamics/contact_dynamics.h>

namespace dyncontact
{
/**
 * Contact/dynamics = taylor-papadopoulos: the modified Newmark of Taylor & Papadopoulos (1993),
 * eqs. (21)-(22) and the recovery formulas after them. On every active pair the normal components
 * of v_{n+1} and a_{n+1} of its two nodes are corrected so that their jumps vanish, with weights
 * equal to the lumped nodal masses (a wall has infinite weight and stays at rest): the corrected
 * normal rates of both nodes are the mass-weighted means of the classical ones, so linear momentum
 * is conserved. Tangential components and all other nodes keep the classical values.
 *
 * Assumes exactly closed active pairs (Lagrange multipliers; with a penalty a pair stays
 * penetrated and the correction glues it, an input error) and node-to-node pairs.
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
