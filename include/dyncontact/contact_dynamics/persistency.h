#pragma once

#include <dyncontact/contact_dynamics/implicit_contact_impulse.h>

namespace dyncontact
{
/**
 * Contact/dynamics = persistency: the energy-conserving contact enforcement of Laursen & Chawla,
 * IJNME 40 (1997) 863-886, in the Lagrange-multiplier limit that Armero & Petőcz, CMAME 158
 * (1998) 269-300, analyse: a pair that persists in contact over a step is held by the discrete
 * persistency (gap-rate) condition
 *
 *   lambda_{n+1} >= 0,   g_{n+1} - g_n >= 0,   lambda_{n+1} (g_{n+1} - g_n) = 0,
 *
 * instead of the impenetrability condition g_{n+1} >= 0, and the step carries one contact force
 * (ImplicitContactImpulse: with the trapezoidal rule, the midpoint rule with the force
 * gamma G^T lambda_{n+1}). The contact force then does no work in any step: for linear elasticity
 * and the pairs held over a step (gaps linear in u), the energy is conserved through impact,
 * persistent contact and release to the Newton tolerance (the defining property; unit test
 * Persistency.*).
 *
 * Which pairs persist: those whose gap at the step's predictor is negative (they would close or
 * penetrate in the step) hold g_n (ContactDynamics::persistent_pairs()), measured by the step's
 * own pair (ContactConstraints::hold_gaps(): a node-to-segment pair's normal turns within the
 * step, and g_n measured by u_n's pair instead made the energy swing by 4.3e-4 of it on the
 * coarse oblique spheres, against 6.5e-7 with the step's pair); every other
 * pair keeps g_{n+1} >= 0. The price of conservation is geometric, as Laursen & Love (2002) point
 * out: a pair predicted to close is held at its gap of t_n, so contact acts across a gap of at
 * most one step's approach, |[[v]].n| dt, and a pair that closes without being predicted to
 * (impenetrability, work -gamma lambda g_n <= 0) dissipates instead. Penetration stays at the
 * Newton tolerance.
 *
 * Assumptions: Lagrange multipliers (a penalty on the gap rate dissipates: exit 2; Armero &
 * Petőcz's conserving penalty force is not implemented); the trapezoidal rule (exit 2 otherwise);
 * positive masses at the pairs' nodes. The rates are the integrator's (correct_rates() keeps its
 * default).
 */
template <int dim>
class Persistency : public ImplicitContactImpulse<dim>
{
public:
  /**
   * True: its constraint is g_{n+1} - g_n itself, both measured by the step's pair, so its work
   * is exact with turned normals too (ContactDynamics::turns_normals()).
   */
  bool turns_normals() const override { return true; }

  /** Per candidate pair, whether g_k(predictor) < 0. */
  std::vector<bool> persistent_pairs(const ContactConstraints<dim>& contact,
                                     const Vector<double>& predictor) const override;
};
} // namespace dyncontact
