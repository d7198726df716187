#pragma once
// Test support: composite Simpson quadrature, for references computed independently of the code.

namespace dyncontact::testing
{
/// Composite Simpson rule for the integral of f over [0, upper] with n_intervals (even) intervals.
template <typename Function>
double simpson(const double upper, const unsigned int n_intervals, const Function& f)
{
  const double h = upper / n_intervals;
  double sum     = f(0.0) + f(upper);
  for (unsigned int i = 1; i < n_intervals; ++i)
    sum += (i % 2 == 1 ? 4.0 : 2.0) * f(i * h);
  return sum * h / 3.0;
}

/// The integrals of a contact force history over the two halves of a contact [t0, t0 + t_c],
/// by Simpson's rule with n_intervals in the variable sigma, t = t0 + t_c sigma^2 / 2 from the
/// start (first) and t = t0 + t_c - t_c sigma^2 / 2 from the end (second): the substitution
/// removes the square-root behaviour of the force at both ends of an impact.
struct HalfImpulses
{
  double first;
  double second;
};
template <typename Force>
HalfImpulses
half_impulses(const Force& force, const double t0, const double t_c, const unsigned int n_intervals)
{
  const auto from = [&](const bool start)
  {
    return simpson(1.0,
                   n_intervals,
                   [&](const double sigma)
                   {
                     const double offset = 0.5 * t_c * sigma * sigma;
                     return force(start ? t0 + offset : t0 + t_c - offset) * t_c * sigma;
                   });
  };
  return {from(true), from(false)};
}
} // namespace dyncontact::testing
