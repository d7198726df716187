#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{
/**
 * The Newmark relations between displacement, velocity and acceleration over one step of size dt,
 * paper eqs. (11)-(12), per component: the predictor u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n,
 * a_{n+1} = (u_{n+1} - u~) / (beta dt^2) and v_{n+1} = v_n + dt (1 - gamma) a_n + dt gamma
 * a_{n+1}. This is all a contact-dynamics treatment gets of the integrator; GeneralizedAlpha's
 * vector updates are these very functions applied to every DoF, so each formula exists once. They
 * hold for every member of that family (its alpha_m, alpha_f enter only the balance). The sums are
 * evaluated left to right, as deal.II's Vector::add(a, V, b, W) does.
 */
struct RateMap
{
  double time_step; ///< dt [time], > 0
  double beta;      ///< Newmark beta [-], > 0
  double gamma;     ///< Newmark gamma [-]

  /** d a_{n+1} / d u_{n+1} = 1 / (beta dt^2) [1/time^2]. */
  double da_du() const { return 1. / (beta * time_step * time_step); }

  /** u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n [length]. */
  double predicted_displacement(const double u_n, const double v_n, const double a_n) const
  {
    return u_n + time_step * v_n + time_step * time_step * (0.5 - beta) * a_n;
  }

  /** v_n + dt (1 - gamma) a_n [length/time]: v_{n+1} without its a_{n+1} part. */
  double predicted_velocity(const double v_n, const double a_n) const
  {
    return v_n + time_step * (1. - gamma) * a_n;
  }

  /** a_{n+1} from the increment u_{n+1} - u~ [length] over the predictor. */
  double acceleration(const double increment) const { return increment * da_du(); }

  /** v_{n+1} = v_n + dt (1 - gamma) a_n + dt gamma a_{n+1} [length/time]. */
  double velocity(const double v_n, const double a_n, const double a_new) const
  {
    return predicted_velocity(v_n, a_n) + time_step * gamma * a_new;
  }
};

/**
 * The states of one completed step, t_n -> t_{n+1}, before the rates at t_{n+1} are corrected:
 * what a contact-dynamics treatment reads, over the DoFs it works on (the contact border's in a
 * run, ContactDynamics).
 */
struct StepStates
{
  const Vector<double>& old_displacement;
  const Vector<double>& old_velocity;
  const Vector<double>& old_acceleration;
  const Vector<double>& new_displacement;
  const Vector<double>& increment; ///< u_{n+1} - u~, the converged displacement minus the predictor
  const std::vector<bool>& is_fixed; ///< per DoF: fixed (e.g. u_r = 0 on an axis), rates stay 0
};
} // namespace dyncontact
