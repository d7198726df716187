#pragma once

namespace dyncontact
{
/// omega dt up to which the trapezoidal rule is said to resolve a mode (its period error is about
/// 1/3 at omega dt = 2; a mesh at Courant number 1 has its highest mode there).
constexpr double resolved_omega_dt = 2.;

/// Whether the trapezoidal rule follows a mode of this omega dt (dimensionless), with a relative
/// slack of 1e-9 so that a mesh at Courant number 1 exactly counts as resolved.
inline bool is_resolved(const double omega_dt)
{
  return omega_dt <= resolved_omega_dt * (1. + 1e-9);
}
} // namespace dyncontact
