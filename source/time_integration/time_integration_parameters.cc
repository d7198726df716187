#include <dyncontact/base/parameter_entries.h>
#include <dyncontact/time_integration/generalized_alpha.h>
#include <dyncontact/time_integration/time_integration_parameters.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace dyncontact
{
void TimeIntegrationParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Time integration");
  prm.declare_entry("scheme",
                    "",
                    Patterns::Anything(),
                    "Deprecated: use Contact/dynamics. classical = Contact/dynamics none, "
                    "modified = taylor-papadopoulos; given, it sets Contact/dynamics and the run "
                    "prints a warning. Empty: not given.");
  prm.declare_entry(
      "integrator",
      "newmark",
      Patterns::Selection(integrator_family_names().selection()),
      "The time integrator, a member of the generalized-alpha family. newmark: Newmark with the "
      "beta and gamma below; the default, gamma = 0.502 and beta = 0.251001, damps the highest "
      "frequencies slightly (rho_inf = 0.996) and, with the default Contact/dynamics = "
      "mass-redistribution, keeps one contact episode on a stiff striker and never gains energy "
      "in an impact at any time step, where the trapezoidal rule (beta = 1/4, gamma = 1/2, the "
      "paper's) gains up to the contact event tolerance (doc/schemes.md, \"The default\"). hht "
      "(Hilber, Hughes & Taylor 1977), bossak (Wood, Bossak & Zienkiewicz 1980) and "
      "generalized-alpha (Chung & Hulbert 1993): second order and unconditionally stable, damping "
      "the highest frequencies by the spectral radius below; they set beta and gamma themselves "
      "(leave those entries empty, or at 0.25 and 0.5).");
  prm.declare_entry("spectral radius",
                    "0.8",
                    Patterns::Double(0., 1.),
                    "rho_inf [-] of hht (in [0.5, 1]), bossak and generalized-alpha (in [0, 1]): "
                    "the amplification of the highest frequencies per step; 1 dissipates nothing, "
                    "0 annihilates them in one step (generalized-alpha). Unused by newmark.");
  prm.declare_entry("beta",
                    "",
                    Patterns::List(Patterns::Double(), 0, 1),
                    "Newmark beta [-], 0 < beta <= 0.5. Unconditionally stable when "
                    "2 beta >= gamma; beta = 0.25 with gamma = 0.5 is the trapezoidal rule. beta = "
                    "0 (explicit central difference) is rejected: u_{n+1} would not depend on the "
                    "contact force, so no constraint could act on it. Empty: (gamma + 1/2)^2 / 4, "
                    "the stable member with the most high-frequency damping for that gamma "
                    "(0.251001 with both entries empty; 0.25 with a Contact/dynamics built on the "
                    "trapezoidal rule: contact-stabilized, persistency, velocity-update).");
  prm.declare_entry("gamma",
                    "",
                    Patterns::List(Patterns::Double(0.5, 1.), 0, 1),
                    "Newmark gamma [-], 0.5 <= gamma <= 1. Second order only for gamma = 0.5; "
                    "gamma > 0.5 adds numerical dissipation. Empty: 0.5 if beta is given, else "
                    "0.502 (0.5 with a Contact/dynamics built on the trapezoidal rule).");
  prm.declare_entry("time step",
                    "0.1",
                    Patterns::Double(),
                    "Time step dt [time], > 0. The Courant number c dt / h is printed at start.");
  prm.declare_entry("end time", "30", Patterns::Double(), "End of the run [time], > 0.");
  prm.declare_entry("maximum step cuts",
                    "10",
                    Patterns::Integer(),
                    "Step control [-], 0..20: a step that fails (Newton does not converge, an "
                    "element inverts, or a guard of subsection Guards trips) is retried with half "
                    "the size, at most this many times, i.e. down to time step / 2^cuts; the size "
                    "grows back after two accepted sub-steps. If the smallest step still fails the "
                    "run stops (exit 3) keeping its output. 0 = never cut.");
  prm.leave_subsection();
}

void TimeIntegrationParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Time integration");
  deprecated_scheme          = prm.get("scheme"); // resolved, or rejected, by resolve_and_check()
  const auto optional_double = [&prm](const std::string& entry) -> std::optional<double>
  {
    const std::string text = prm.get(entry);
    if (text.empty())
      return std::nullopt;
    return prm.get_double(entry);
  };
  given_beta  = optional_double("beta");
  given_gamma = optional_double("gamma");
  if (given_beta == 0.)
    throw InputError("Time integration/beta = 0 is not supported: with beta = 0 the displacement "
                     "u_{n+1} is explicit and the contact constraint cannot act on it. Use "
                     "0 < beta <= 0.5 (the paper's nearly explicit choice is 0.001).");
  if (given_beta && !(*given_beta > 0. && *given_beta <= 0.5))
    throw InputError("Time integration/beta = " + prm.get("beta") +
                     " is not allowed: it must be in (0, 0.5].");
  time_step = get_positive(prm, "time step", "Time integration");
  integrator =
      integrator_family_names().parse(prm.get("integrator"), "Time integration/integrator");
  spectral_radius = prm.get_double("spectral radius");
  // Newmark's coefficients left empty are resolved in ParameterReader::resolve_and_check(): their
  // defaults depend on Contact/dynamics.
  if (integrator != IntegratorFamily::newmark)
  {
    const std::string member = "Time integration/integrator = " + prm.get("integrator");
    // A file written for the trapezoidal rule (beta = 1/4, gamma = 1/2, as the shipped ones) runs
    // on any member; other values given would be ignored, so they are refused.
    if (given_beta.value_or(0.25) != 0.25 || given_gamma.value_or(0.5) != 0.5)
      throw InputError(member +
                       " sets beta and gamma from the spectral radius; leave Time "
                       "integration/beta and gamma empty (their defaults), out, or at the "
                       "trapezoidal rule's 0.25 and 0.5 (given beta = '" +
                       prm.get("beta") + "', gamma = '" + prm.get("gamma") + "').");
    const double lowest = GeneralizedAlpha::lowest_spectral_radius(integrator);
    if (spectral_radius < lowest)
      throw InputError("Time integration/spectral radius = " + format_number(spectral_radius) +
                       " is not allowed with " + member + ": it must be in [" +
                       format_number(lowest) + ", 1].");
    const GeneralizedAlpha member_coefficients(integrator, spectral_radius, time_step);
    beta  = member_coefficients.beta();
    gamma = member_coefficients.gamma();
  }
  end_time = get_positive(prm, "end time", "Time integration");
  if (end_time / time_step > 1e8)
    throw InputError("Time integration/end time = " + prm.get("end time") +
                     " with time step = " + prm.get("time step") +
                     " asks for more than 1e8 steps; at most 1e8 are allowed.");
  max_step_cuts =
      static_cast<unsigned int>(get_in_range(prm, "maximum step cuts", "Time integration", 0, 20));
  prm.leave_subsection();
}

void TimeIntegrationParameters::resolve_newmark_coefficients(const bool trapezoidal_rule_required)
{
  if (integrator != IntegratorFamily::newmark)
    return;
  if (trapezoidal_rule_required && !given_beta && !given_gamma)
  {
    beta  = 0.25;
    gamma = 0.5;
    return;
  }
  if (!given_beta && !given_gamma)
  {
    beta  = default_newmark_beta;
    gamma = default_newmark_gamma;
    return;
  }
  gamma = given_gamma.value_or(0.5);
  beta  = given_beta.value_or((gamma + 0.5) * (gamma + 0.5) / 4.);
}

unsigned int TimeIntegrationParameters::n_steps() const
{
  // At least one: an end time below 1e-9 of the time step is not a run of zero steps.
  return std::max(1u, static_cast<unsigned int>(std::ceil(end_time / time_step - 1e-9)));
}
} // namespace dyncontact
