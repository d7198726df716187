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
 * penetrate in the step) take the reference g_n (ContactDynamics::reference_gaps()); every other
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
  using typename ImplicitContactImpulse<dim>::StepStart;

  /** g_k(u_n) where g_k(predictor) < 0, else 0 [length], per candidate pair. */
  std::vector<double> reference_gaps(const ContactConstraints<dim>& contact,
                                     const StepStart& start,
                                     const Vector<double>& predictor) const override;
};
} // namespace dyncontact
