#pragma once

#include <dyncontact/contact_dynamics/contact_dynamics.h>

namespace dyncontact
{
/**
 * Contact/dynamics = contact-stabilized: the contact-stabilized Newmark method of Deuflhard,
 * Krause & Ertel, IJNME 73 (2008) 1274-1290 (also Krause & Walloth, Appl. Numer. Math. 62 (2012)
 * 1393-1410). The old contact force is left out of the explicit part of the step: the predictor's
 * position part u_n + dt v_n is projected onto the admissible set in the mass norm,
 *
 *   u^pred = argmin { |w - (u_n + dt v_n)|_M : g_k(w) >= 0 for every candidate pair k },
 *
 * and the step uses the free acceleration a^free_n = M^-1 (W_n - Q(u_n)) instead of a_n, in the
 * predictor u~ = u^pred + dt^2 (1/2 - beta) a^free_n and in the velocity update
 * v_{n+1} = v_n + dt (1 - gamma) a^free_n + dt gamma a_{n+1}. With the trapezoidal rule
 * (beta = 1/4, gamma = 1/2) this is the paper's scheme, v_{n+1} = v_n + 2/dt (u_{n+1} - u^pred),
 * which is energy dissipative at contact (Deuflhard, Krause & Ertel, Theorem 4.2, linear
 * elasticity) and free of the oscillations of the contact force and velocity of classical
 * Newmark. The parameters allow only that rule (ParameterReader: exit 2 otherwise): with the
 * paper's beta = 0.001 the construction gained 3300 times the initial energy on 6.1, hidden from
 * the energy guard by the algorithmic energy's negative a.Ma weight. Away from contact
 * (no pair closing in the predictor, no contact force at t_n) it is classical Newmark, bit for bit.
 *
 * The projection: the pairs whose gap at u_n + dt v_n is negative are closed together by nodal
 * shifts M^-1 B^T mu with mu >= 0 (PairMassSystem, the mass-weighted closure of each pair, which
 * conserves momentum); a pair whose mu comes out negative is dropped and one that the shifts make
 * penetrate is added, until neither happens (at most one round per candidate pair). The free
 * acceleration replaces a_n at the DoFs that carry a contact force at t_n.
 *
 * Assumptions: positive masses at the pairs' nodes (not combined with mass redistribution);
 * Lagrange multipliers or penalty (the projection closes the predicted gaps either way); the
 * rates of the contact nodes are not corrected afterwards (correct_rates() keeps its default).
 */
template <int dim>
class ContactStabilizedNewmark : public ContactDynamics<dim>
{
public:
  using typename ContactDynamics<dim>::StepStart;

  void adjust_predictor(const RateMap& rates,
                        const ContactConstraints<dim>& contact,
                        const Vector<double>& lumped_mass,
                        const StepStart& start,
                        Vector<double>& old_acceleration,
                        Vector<double>& predictor) const override;

  /**
   * gamma: the step's contact impulse is dt gamma G^T lambda_{n+1} (the old force's share
   * dt (1 - gamma) G^T lambda_n is left out), so the force of an impact that lasts several steps
   * is gamma lambda (measured on the paper's 6.1: lambda = 1.0 for the exact force 0.5).
   */
  double contact_force_factor(const RateMap& rates) const override { return rates.gamma; }
};
} // namespace dyncontact
