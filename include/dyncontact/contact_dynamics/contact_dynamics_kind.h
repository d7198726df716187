#pragma once

#include <dyncontact/base/name_table.h>

#include <string>

namespace dyncontact
{
/**
 * The treatment of the contact nodes' rates by the time integration (Contact/dynamics): what the
 * paper's modified Newmark is one of (sections 4 and 5). A new treatment adds its enumerator here,
 * its class in its own file, and its name, traits and case beside create_contact_dynamics().
 */
enum class ContactDynamicsKind
{
  none,                ///< classical: contact constrains displacements only
  taylor_papadopoulos, ///< also [[v]].n = 0 and [[a]].n = 0 on active pairs, paper eqs. (19)-(24)
  mass_redistribution, ///< no mass on the contact nodes (Khenous, Laborde & Renard 2008)
  contact_stabilized,  ///< predictor projected, old contact force dropped (Deuflhard et al. 2008)
  persistency,         ///< gap-rate condition on persisting pairs (Laursen & Chawla 1997)
  velocity_update      ///< [[v]].n = 0 by a velocity jump after each step (Laursen & Love 2002)
};

/** The names of Contact/dynamics (defined beside create_contact_dynamics()). */
const NameTable<ContactDynamicsKind>& contact_dynamics_names();

/**
 * What a treatment declares about itself for the parameter file: its documentation and what it
 * needs of the integrator and of the contact formulation. ParameterReader refuses a run that
 * lacks what its treatment needs, with the treatment's reason.
 */
struct ContactDynamicsTraits
{
  /// its sentences in the documentation of Contact/dynamics
  std::string help;
  /// why it needs Newmark with beta = 1/4 and gamma = 1/2 (the trapezoidal rule); empty: it does
  /// not, and takes the default Newmark coefficients when none are given
  std::string trapezoidal_rule_reason;
  /// why it cannot run with Contact/formulation = penalty; empty: it can
  std::string penalty_refusal;
};

/** The traits of `kind` (defined beside create_contact_dynamics()). */
const ContactDynamicsTraits& contact_dynamics_traits(ContactDynamicsKind kind);

/**
 * The documentation of Contact/dynamics: every treatment's name and help, `default_kind` marked,
 * then which treatments need the trapezoidal rule and which need Lagrange multipliers.
 */
std::string contact_dynamics_documentation(ContactDynamicsKind default_kind);
} // namespace dyncontact
