#pragma once

#include <dyncontact/contact_dynamics/contact_dynamics.h>

namespace dyncontact
{
/**
 * The common part of the treatments whose step carries the contact impulse of t_{n+1} alone,
 * dt gamma G^T lambda_{n+1} (ContactStabilizedNewmark, Persistency, VelocityUpdate): the old
 * contact force is left out of the explicit part of the step. At the DoFs where the contact force
 * of t_n acts, the step uses the free acceleration a^free_n = M^-1 (W_n - Q(u_n)) instead of a_n,
 * in the predictor u~ = u_n + dt v_n + dt^2 (1/2 - beta) a^free_n (plus predictor_shift()) and in
 * the velocity update v_{n+1} = v_n + dt (1 - gamma) a^free_n + dt gamma a_{n+1}.
 *
 * With the trapezoidal rule (beta = 1/4, gamma = 1/2) the step is then the midpoint rule with one
 * contact force per step, G^T lambda_{n+1/2} = gamma G^T lambda_{n+1}: the form of the energy
 * arguments of Laursen & Chawla (IJNME 40 (1997) 863-886) and Deuflhard, Krause & Ertel (IJNME 73
 * (2008) 1274-1290). For linear elasticity and a gap linear over the step (the pairs are held
 * over a step), the step's energy change is then the contact force's work
 * gamma lambda_{n+1} (g_{n+1} - g_n) alone: zero at a pair that stays closed or opens
 * (lambda = 0), negative at a pair that closes. The classical trapezoidal rule instead adds the
 * old force's share (1 - gamma) lambda_n (g_{n+1} - g_n), a gain at every release. The treatments
 * need that rule (ParameterReader: exit 2 otherwise). Away from contact (no contact force at t_n,
 * no predictor shift) the step is classical Newmark, bit for bit.
 */
template <int dim>
class ImplicitContactImpulse : public ContactDynamics<dim>
{
public:
  using typename ContactDynamics<dim>::StepStart;

  /**
   * False: the pair normals are held over a step, as the energy argument above needs (a pair
   * turned within the step measures g_n along a normal the face of u_n is not normal to;
   * ContactDynamics::turns_normals()). Persistency turns them.
   */
  bool turns_normals() const override { return false; }

  /** The free acceleration at the DoFs where the contact force of t_n acts, see above. */
  void adjust_predictor(const RateMap& rates,
                        const ContactConstraints<dim>& contact,
                        const Vector<double>& lumped_mass,
                        const StepStart& start,
                        Vector<double>& old_acceleration,
                        Vector<double>& predictor) const final;

  /**
   * gamma: the step's contact impulse is dt gamma G^T lambda_{n+1}, so the force of an impact
   * that lasts several steps is gamma lambda (measured on the paper's 6.1: lambda = 1.0 for the
   * exact force 0.5).
   */
  double contact_force_factor(const RateMap& rates) const final { return rates.gamma; }

protected:
  /**
   * A shift added to the predictor (a border vector, zero at fixed DoFs), computed
   * from the state at t_n; an empty vector (the default) shifts nothing.
   */
  virtual Vector<double> predictor_shift(const RateMap& rates,
                                         const ContactConstraints<dim>& contact,
                                         const Vector<double>& lumped_mass,
                                         const StepStart& start) const;
};
} // namespace dyncontact
