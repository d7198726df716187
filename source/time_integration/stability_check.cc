#include <dyncontact/base/global.h>
#include <dyncontact/time_integration/stability_check.h>

#include <cmath>
#include <string>

namespace dyncontact
{
namespace
{
/**
 * A largest admissible time step as printed in a message: 6 significant digits rounded down, so
 * that the printed step itself passes the check that suggested it (rounded to nearest, 0.100201
 * for the limit 0.1002006 was refused).
 */
std::string format_largest_step(const double step)
{
  const double scale = std::pow(10., 5 - std::floor(std::log10(step)));
  return format_number(std::floor(step * scale) / scale);
}

/// Relative slack of the stability checks: the round-off of omega dt recomputed from a step that
/// was printed at the limit, nothing more.
constexpr double round_off_slack = 1e-12;
} // namespace

void check_stability(const GeneralizedAlpha& integrator,
                     const double body_omega_dt,
                     const double spring_omega_dt,
                     const bool penalty_lowered)
{
  // Every mode must stay below the limit: above, the run blows up, and the algorithmic energy,
  // whose weight beta - gamma/2 of a.Ma is then negative, does not show it (measured: 6.1 at
  // dt = 0.3, energy 5 -> 2.7e64 with the guards passing). 6.1 with a spring of omega dt = 1 on a
  // mesh at 2 (bound 2.24, limit 2.004) went from energy 5 to 6e51. Such an input is rejected
  // before the first step.
  const double limit = integrator.stability_limit();
  const auto reject = [&](const std::string& what, const double omega_dt, const std::string& remedy)
  {
    throw InputError(
        "Time integration/time step = " + format_number(integrator.time_step()) + ": " + what +
        " has omega dt = " + format_number(omega_dt) + ", above the stability limit " +
        format_number(limit) + " of Newmark with beta = " + format_number(integrator.beta()) +
        ", gamma = " + format_number(integrator.gamma()) +
        "; use a time step <= " + format_largest_step(integrator.time_step() * limit / omega_dt) +
        ", or 2 beta >= gamma" + remedy + ".");
  };
  // The automatic penalty keeps its springs at omega dt = 1; a softer spring would buy stability
  // with a penetration growing as 1 / (omega dt)^2, so such a time step is refused instead.
  if (penalty_lowered &&
      body_omega_dt * body_omega_dt + 1. > limit * limit * (1. + 2. * round_off_slack))
    throw InputError(
        "Contact/penalty factor = auto: with Time integration/beta = " +
        format_number(integrator.beta()) +
        " < gamma/2 the mesh's highest mode (omega dt = " + format_number(body_omega_dt) +
        ") leaves a penalty spring of omega dt = 1 no room below the stability limit " +
        format_number(limit) + "; use a time step <= " +
        format_largest_step(integrator.time_step() * std::sqrt(limit * limit - 1.) /
                            body_omega_dt) +
        ", beta >= gamma/2, or Lagrange multipliers.");
  if (body_omega_dt > limit * (1. + round_off_slack))
    reject("the mesh's highest mode", body_omega_dt, "");
  const double coupled_omega_dt = std::hypot(body_omega_dt, spring_omega_dt);
  if (spring_omega_dt > 0. && coupled_omega_dt > limit * (1. + round_off_slack))
    reject("the mesh with the penalty spring (Contact/penalty factor)",
           coupled_omega_dt,
           " or a smaller penalty factor");
}
} // namespace dyncontact
