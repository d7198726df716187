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
} // namespace dyncontact::testing
