#pragma once

#include <dyncontact/contact_dynamics/implicit_contact_impulse.h>

namespace dyncontact
{
/**
 * Contact/dynamics = contact-stabilized: the contact-stabilized Newmark method of Deuflhard,
 * Krause & Ertel, IJNME 73 (2008) 1274-1290 (also Krause & Walloth, Appl. Numer. Math. 62 (2012)
 * 1393-1410). The old contact force is left out of the explicit part of the step
 * (ImplicitContactImpulse) and the predictor's position part u_n + dt v_n is projected onto the
 * admissible set in the mass norm,
 *
 *   u^pred = argmin { |w - (u_n + dt v_n)|_M : g_k(w) >= 0 for every candidate pair k },
 *
 * so that u~ = u^pred + dt^2 (1/2 - beta) a^free_n. With the trapezoidal rule (beta = 1/4,
 * gamma = 1/2) this is the paper's scheme, v_{n+1} = v_n + 2/dt (u_{n+1} - u^pred), which is
 * energy dissipative at contact (Deuflhard, Krause & Ertel, Theorem 4.2, linear elasticity) and
 * free of the oscillations of the contact force and velocity of classical Newmark. The
 * parameters allow only that rule (ParameterReader: exit 2 otherwise): with the paper's
 * beta = 0.001 the construction gained 3300 times the initial energy on 6.1, hidden from the
 * energy guard by the algorithmic energy's negative a.Ma weight.
 *
 * The projection: the pairs whose gap at u_n + dt v_n is negative are closed together by nodal
 * shifts M^-1 B^T mu with mu >= 0 (PairMassSystem, the mass-weighted closure of each pair, which
 * conserves momentum); a pair whose mu comes out negative is dropped and one that the shifts make
 * penetrate is added, until neither happens (at most one round per candidate pair).
 *
 * Assumptions: positive masses at the pairs' nodes (not combined with mass redistribution);
 * Lagrange multipliers or penalty (the projection closes the predicted gaps either way); the
 * rates of the contact nodes are not corrected afterwards (correct_rates() keeps its default).
 */
template <int dim>
class ContactStabilizedNewmark : public ImplicitContactImpulse<dim>
{
protected:
  using typename ImplicitContactImpulse<dim>::StepStart;

  /** The projection's shift u^pred - (u_n + dt v_n). */
  Vector<double> predictor_shift(const RateMap& rates,
                                 const ContactConstraints<dim>& contact,
                                 const Vector<double>& lumped_mass,
                                 const StepStart& start) const override;
};
} // namespace dyncontact
