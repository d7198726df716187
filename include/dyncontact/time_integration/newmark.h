#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/parameters.h>
#include <dyncontact/time_integration/rate_map.h>

#include <deal.II/lac/vector.h>

namespace dyncontact
{
/**
 * The Newmark (beta, gamma) family, eqs. (11)-(12) of the paper, written displacement-first: the
 * predictor u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n, then a_{n+1} = (u_{n+1} - u~)/(beta dt^2)
 * and v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}), each formula from RateMap, which is
 * also all that a contact-dynamics treatment gets of it (rate_map()). It also knows the
 * algorithmic energy weight and the stability limit; assembly and solves are not here.
 */
class Newmark
{
public:
  /** Needs beta > 0, which TimeIntegrationParameters ensures. */
  explicit Newmark(const TimeIntegrationParameters& parameters);

  double beta() const { return beta_value; }
  double gamma() const { return gamma_value; }
  double time_step() const { return dt; }

  /**
   * The largest omega dt of a mode for which the scheme is stable: 1 / sqrt(gamma/2 - beta) when
   * 2 beta < gamma (Hughes, The Finite Element Method, 2000, sec. 9.1), else infinity
   * (unconditionally stable).
   */
  double stability_limit() const;

  /** The per-component relations of the current step size, for contact-dynamics treatments. */
  RateMap rate_map() const { return {dt, beta_value, gamma_value}; }

  /** Sets the step size of the next steps (step control cuts and regrows it), dt > 0. */
  void set_time_step(double time_step);

  /** 1 / (beta dt^2): multiplies M (u_{n+1} - u~) in the equation of motion. */
  double inertia_factor() const { return rate_map().da_du(); }

  /** The predictor u~ from the state at t_n. */
  void predict(const Vector<double>& u_n,
               const Vector<double>& v_n,
               const Vector<double>& a_n,
               Vector<double>& predictor) const;

  /**
   * a_{n+1} = increment / (beta dt^2) and v_{n+1} from the converged increment u_{n+1} - u~
   * (classical update, every DoF). Working with the increment avoids the cancellation of
   * u_{n+1} - u~, which the large factor 1/(beta dt^2) would turn into momentum drift.
   */
  void update_rates(const Vector<double>& increment,
                    const Vector<double>& v_n,
                    const Vector<double>& a_n,
                    Vector<double>& v_new,
                    Vector<double>& a_new) const;

  /**
   * 1/2 v.Mv + W(u) + (beta - gamma/2) dt^2/2 a.Ma, the energy of Hughes' energy method (The
   * Finite Element Method, 2000, section 9.3.3): conserved exactly by gamma = 1/2 Newmark for a
   * linear free system (the plain energy is not when beta != 1/4), and non-increasing for
   * gamma > 1/2 with beta >= gamma/2, the dissipation being (gamma - 1/2) times positive terms.
   */
  double
  algorithmic_energy(double kinetic_energy, double strain_energy, double acceleration_energy) const;

private:
  double beta_value;
  double gamma_value;
  double dt;
};
} // namespace dyncontact
