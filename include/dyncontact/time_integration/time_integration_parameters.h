#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/time_integration/integrator_family.h>

#include <deal.II/base/parameter_handler.h>

#include <optional>
#include <string>

namespace dyncontact
{
/** Newmark parameters and the time window of a run. Subsection `Time integration`. */
struct TimeIntegrationParameters
{
  /// the deprecated Time integration/scheme (classical | modified), "" if not given; it sets
  /// Contact/dynamics (ParameterReader resolves it)
  std::string deprecated_scheme;
  /// the member of the generalized-alpha family (Time integration/integrator)
  IntegratorFamily integrator;
  /// rho_inf of a dissipative member (Time integration/spectral radius); unused by newmark
  double spectral_radius;
  /// Newmark beta and gamma: for newmark as given, an entry left empty taking its default (see
  /// resolve_newmark_coefficients()); else the member's, set from rho_inf when read
  double beta;
  double gamma;
  /// Time integration/beta and gamma as given; empty when the entry is left empty
  std::optional<double> given_beta;
  std::optional<double> given_gamma;

  /**
   * gamma of newmark when neither beta nor gamma is given: 0.502, with beta = (gamma + 1/2)^2 / 4
   * = 0.251001, the unconditionally stable member that damps the highest frequencies most for its
   * gamma (rho_inf = (3/2 - gamma) / (gamma + 1/2) = 0.996), first order with the error constant
   * gamma - 1/2. Chosen over the whole kind of issue 25, item 7: with the default Contact/dynamics
   * = mass-redistribution no impact of the sweep gains energy at any step from gamma = 0.501 on,
   * where the trapezoidal rule gains up to 1e-4 of it; 0.502 doubles that smallest damping
   * (doc/schemes.md, "The default").
   */
  static constexpr double default_newmark_gamma = 0.502;
  /// beta of newmark when neither is given: (default_newmark_gamma + 1/2)^2 / 4, written out so
  /// that the record names it in its 6 digits
  static constexpr double default_newmark_beta = 0.251001;
  double time_step;
  double end_time;
  /// a failing step is halved at most this many times (minimum step dt / 2^max_step_cuts)
  unsigned int max_step_cuts;

  /**
   * Number of steps: end time / time step, rounded up (the last step may end past end time), at
   * least 1.
   */
  unsigned int n_steps() const;

  /**
   * Newmark's beta and gamma when not both given: gamma left empty is 1/2 if beta is given, else
   * default_newmark_gamma; beta left empty is (gamma + 1/2)^2 / 4. With
   * `trapezoidal_rule_required` (a contact treatment built on the trapezoidal rule) and neither
   * given, they are 1/4 and 1/2. Does nothing for the other members.
   */
  void resolve_newmark_coefficients(bool trapezoidal_rule_required);

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm);
};
} // namespace dyncontact
