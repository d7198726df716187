#pragma once

#include <dyncontact/contact_dynamics/implicit_contact_impulse.h>

namespace dyncontact
{
/**
 * Contact/dynamics = velocity-update: the velocity update of Laursen & Love, IJNME 53 (2002)
 * 245-274, which restores geometric admissibility to the conserving framework of Laursen & Chawla
 * (1997). The step enforces impenetrability, g_{n+1} >= 0, with one contact force per step
 * (ImplicitContactImpulse: with the trapezoidal rule, the midpoint rule with the force
 * gamma G^T lambda_{n+1}); after it, the velocities of the nodes of the active pairs take a
 * discrete jump M^-1 B^T mu that makes every active pair's relative normal velocity zero,
 *
 *   [[v_{n+1}]].n = 0   (B M^-1 B^T mu = [[v^Newmark_{n+1}]].n, PairMassSystem),
 *
 * the persistency condition lambda dg/dt = 0 in rate form: an impact is perfectly inelastic in
 * the normal direction at the contact nodes (the defining property, unit test VelocityUpdate.*).
 * The jump is the mass-norm projection of the velocities onto [[v]].n = 0, so it conserves
 * momentum and can only remove kinetic energy, (1/2) mu^T (B M^-1 B^T) mu; with the impact step's
 * work -gamma lambda g_n <= 0 that is the scheme's whole dissipation, and it never gains energy at
 * a release (where lambda = 0) or in persistent contact (where the jump vanishes once the pair
 * moves together).
 *
 * Unlike TaylorPapadopoulos, the accelerations keep the integrator's values (Laursen & Love
 * correct the velocity only), and the contact force is not averaged with the old one.
 *
 * Assumptions: Lagrange multipliers (with a penalty a pair stays penetrated and the update glues
 * it: exit 2); the trapezoidal rule (exit 2 otherwise); positive masses at the pairs' nodes.
 */
template <int dim>
class VelocityUpdate : public ImplicitContactImpulse<dim>
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
