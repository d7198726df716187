#pragma once
// Test support: the classical Runge-Kutta method for the impact ODE d'' = acceleration(d), for
// references computed independently of the code.

#include <vector>

namespace dyncontact::testing
{
/// Approach d and approach rate d' of an impact ODE at one instant.
struct OdeState
{
  double d;
  double rate;
};

/**
 * The solution of d'' = acceleration(d), d(0) = 0, d'(0) = @p speed by the classical fourth-order
 * Runge-Kutta method (Nystrom form for a second-order equation without d') with @p n_steps steps
 * of size @p h: the states at t = 0, h, 2h, ...
 */
template <typename Acceleration>
std::vector<OdeState> runge_kutta_history(const Acceleration& acceleration,
                                          const double speed,
                                          const double h,
                                          const unsigned int n_steps)
{
  std::vector<OdeState> states = {{0.0, speed}};
  for (unsigned int step = 0; step < n_steps; ++step)
  {
    const OdeState& s = states.back();
    const double k1   = acceleration(s.d);
    const double k2   = acceleration(s.d + 0.5 * h * s.rate);
    const double k3   = acceleration(s.d + 0.5 * h * s.rate + 0.25 * h * h * k1);
    const double k4   = acceleration(s.d + h * s.rate + 0.5 * h * h * k2);
    states.push_back({s.d + h * s.rate + h * h / 6.0 * (k1 + k2 + k3),
                      s.rate + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)});
  }
  return states;
}
} // namespace dyncontact::testing
