#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>
#include <dyncontact/time_integration/integrator_family.h>
#include <dyncontact/time_integration/rate_map.h>
#include <dyncontact/time_integration/time_integration_parameters.h>

#include <deal.II/lac/vector.h>

#include <string>

namespace dyncontact
{
/**
 * The generalized-alpha family of one-step integrators for M a + Q(u) = W(t) (Chung & Hulbert,
 * J. Appl. Mech. 60 (1993) 371-375), with Newmark, HHT-alpha and WBZ-alpha (Bossak) as members.
 *
 * Sign convention (Chung & Hulbert's): x_{n+1-alpha} = (1 - alpha) x_{n+1} + alpha x_n, and the
 * equation of motion is balanced at the intermediate times,
 *   M a_{n+1-alpha_m} + (1 - alpha_f) Q(u_{n+1}) + alpha_f Q(u_n) = W(t_{n+1-alpha_f}),
 * a nonlinear Q being averaged, not evaluated at u_{n+1-alpha_f} (the common choice, e.g. Erlicher,
 * Bonaventura & Bursi, Comput. Mech. 28 (2002) 83-104). u, v, a are related over the step by
 * Newmark's formulas with this member's (beta, gamma) (paper eqs. 11-12, RateMap). Hilber, Hughes
 * & Taylor (Earthq. Eng. Struct. Dyn. 5 (1977) 283-292) write M a_{n+1} + (1 + alpha) K u_{n+1} -
 * alpha K u_n = F(t_{n+1+alpha}) with alpha in [-1/3, 0]: their alpha is -alpha_f here.
 *
 * The members and their coefficients, from the spectral radius rho_inf at infinite frequency:
 *  - newmark: alpha_m = alpha_f = 0, explicit (beta, gamma) (the paper uses beta = 0.001);
 *  - hht: alpha_m = 0, alpha_f = (1 - rho)/(1 + rho), rho in [1/2, 1] (alpha_f <= 1/3),
 *    gamma = 1/2 + alpha_f, beta = (1 + alpha_f)^2 / 4;
 *  - bossak (Wood, Bossak & Zienkiewicz, IJNME 15 (1980) 1562-1566): alpha_f = 0,
 *    alpha_m = (rho - 1)/(rho + 1), rho in [0, 1], gamma = 1/2 - alpha_m,
 *    beta = (1 - alpha_m)^2 / 4;
 *  - generalized_alpha: alpha_m = (2 rho - 1)/(rho + 1), alpha_f = rho/(rho + 1), rho in [0, 1],
 *    gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2 / 4 (Chung & Hulbert's
 *    choice: second order, unconditionally stable, high-frequency dissipation set by rho).
 *
 * One step, displacement-first: the predictor u~ (predict()), then Newton on
 *   c M (u_{n+1} - u~) + Q(u_{n+1}) - W_eff = 0,
 * the balance divided by (1 - alpha_f), with c = inertia_factor() and W_eff = effective_force(),
 * then the rates from the converged increment u_{n+1} - u~ (update_rates()). Every member is
 * selectable per run (Time integration/integrator, spectral radius). With contact the step
 * equation gains -G^T lambda, so a multiplier is the contact force of the balance at
 * t_{n+1-alpha_f} divided by (1 - alpha_f). Assembly, solves and contact are not here; a
 * contact-dynamics treatment sees the integrator only through rate_map().
 */
class GeneralizedAlpha
{
public:
  using Family = IntegratorFamily;

  /**
   * The run's integrator (Time integration/integrator): newmark with the parameters' beta > 0
   * (checked when read) and gamma, or a dissipative member by the parameters' spectral radius;
   * step size dt.
   */
  explicit GeneralizedAlpha(const TimeIntegrationParameters& parameters);

  /**
   * A dissipative member (hht, bossak, generalized_alpha) from the spectral radius at infinite
   * frequency and the step size dt > 0 [time]. Throws (deal.II ExcMessage) for newmark, which
   * takes (beta, gamma) instead, and for rho_inf outside the member's range listed above.
   */
  GeneralizedAlpha(Family family, double spectral_radius, double time_step);

  /** The smallest rho_inf of a dissipative member: 1/2 for hht (alpha_f <= 1/3), else 0. */
  static double lowest_spectral_radius(Family family);

  Family family() const { return family_value; }

  /**
   * One line for logs: "Newmark (beta = 0.25, gamma = 0.5)" or, for a dissipative member, its
   * name, rho_inf, alpha_m, alpha_f, beta and gamma, the numbers with `precision` digits.
   */
  std::string description(int precision = 6) const;
  double alpha_m() const { return alpha_m_value; }
  double alpha_f() const { return alpha_f_value; }
  double beta() const { return beta_value; }
  double gamma() const { return gamma_value; }
  double time_step() const { return dt; }

  /**
   * The largest omega dt of a mode for which the scheme is stable: 1 / sqrt(gamma/2 - beta) when
   * 2 beta < gamma (Hughes, The Finite Element Method, 2000, sec. 9.1), else infinity
   * (unconditionally stable, which every dissipative member is: 2 beta - gamma = (alpha_f -
   * alpha_m)^2 / 2 >= 0).
   */
  double stability_limit() const;

  /**
   * The per-component relations of the current step size, for contact-dynamics treatments. They
   * hold for every member between u, v, a at t_n and t_{n+1}; for alpha_m or alpha_f != 0 its
   * da_du() = 1/(beta dt^2) is d a_{n+1} / d u_{n+1}, not the mass factor inertia_factor().
   */
  RateMap rate_map() const { return {dt, beta_value, gamma_value}; }

  /** Sets the step size of the next steps (step control cuts and regrows it), dt > 0. */
  void set_time_step(double time_step);

  /**
   * c = (1 - alpha_m) / ((1 - alpha_f) beta dt^2) [1/time^2]: multiplies M (u_{n+1} - u~) in the
   * step equation; 1 / (beta dt^2), bit for bit, for newmark.
   */
  double inertia_factor() const;

  /** t_{n+1-alpha_f} = t_{n+1} - alpha_f dt [time], where W is evaluated. */
  double load_time(double new_time) const { return new_time - alpha_f_value * dt; }

  /**
   * The predictor u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n, every owned DoF (the vectors all
   * have the layout of u_n; `predictor` is given it).
   */
  void predict(const DistributedVector& u_n,
               const DistributedVector& v_n,
               const DistributedVector& a_n,
               DistributedVector& predictor) const;

  /**
   * W_eff = (W(t_{n+1-alpha_f}) - alpha_m M a_n - alpha_f Q(u_n)) / (1 - alpha_f) [force], every
   * owned DoF: the right-hand side of the step equation. `external_force` is W at load_time(),
   * `old_inertia_force` M a_n, `old_internal_force` Q(u_n), all of one layout; W for newmark.
   */
  void effective_force(const DistributedVector& external_force,
                       const DistributedVector& old_inertia_force,
                       const DistributedVector& old_internal_force,
                       DistributedVector& effective) const;

  /**
   * a_{n+1} = increment / (beta dt^2) and v_{n+1} from the converged increment u_{n+1} - u~
   * (every owned DoF, every member; the outputs are given the layout of `increment`). Working
   * with the increment avoids the cancellation of u_{n+1} - u~, which the large factor
   * 1/(beta dt^2) would turn into momentum drift.
   */
  void update_rates(const DistributedVector& increment,
                    const DistributedVector& v_n,
                    const DistributedVector& a_n,
                    DistributedVector& v_new,
                    DistributedVector& a_new) const;

  /**
   * The algorithmic energy [energy] of a state, from kinetic_energy = 1/2 v.Mv, strain_energy,
   * acceleration_energy = 1/2 a.Ma and residual_energy = 1/2 r.K^{-1} r with r = M a + K u - W,
   * the equation of motion's residual at that state:
   *   E = 1/2 v.Mv + W(u) + (beta - gamma/2) dt^2/2 a.Ma + (1/2 - alpha_f)/(alpha_f - alpha_m) 1/2
   *   r.K^{-1} r.
   * For newmark (r = 0 after every step; the last term is left out when alpha_f = alpha_m) this is
   * the energy of Hughes' energy method (The Finite Element Method, 2000, sec. 9.3.3): conserved
   * exactly by gamma = 1/2 for a linear free system (the plain energy is not when beta != 1/4),
   * non-increasing for gamma > 1/2 with beta >= gamma/2. For a linear free system (Q = K u, W = 0)
   * and alpha_m < alpha_f <= 1/2, the same energy method with a_n = a^_n + M^{-1} r_n, where
   * M a^_n = -K u_n and (1 - alpha_m) r_{n+1} + alpha_m r_n = -(alpha_f - alpha_m) M (a^_{n+1} -
   * a^_n) (r as in the acceleration-like variable of Arnold & Bruls, Multibody Syst. Dyn. 18 (2007)
   * 185-202), gives
   *   E_{n+1} - E_n = -(beta - gamma/2)(gamma - 1/2) dt^2 |a_{n+1} - a_n|_M^2
   *                   - (1/2 - alpha_f)(1/2 - alpha_m)/(alpha_f - alpha_m) |r_{n+1} -
   * r_n|_{K^-1}^2, so E is non-increasing for every dissipative member (derived here; the unit test
   * checks it).
   */
  double algorithmic_energy(double kinetic_energy,
                            double strain_energy,
                            double acceleration_energy,
                            double residual_energy = 0.) const;

private:
  Family family_value;
  double rho_inf = 1.; ///< the spectral radius of a dissipative member
  double alpha_m_value;
  double alpha_f_value;
  double beta_value;
  double gamma_value;
  double dt;
};
} // namespace dyncontact
