#pragma once

#include <dyncontact/contact/contact_constraints.h>

#include <deal.II/lac/vector.h>

namespace dyncontact
{
/** What Contact/penalty factor = auto needs to know of a run besides its contact pairs. */
struct PenaltySizingInput
{
  const Vector<double>& lumped_mass; ///< per DoF (n_dofs), kg (or the model's mass unit)
  double time_step;                  ///< s
  double body_omega_dt;              ///< the bodies' highest mode times the time step
};

/**
 * The stiffest penalty spring against the time step: the largest dt sqrt(k / m_r) over the
 * candidate pairs, k a pair's penalty stiffness and m_r the reduced lumped mass of its nodes,
 * 1 / m_r = 1 / m_slave + sum_i w_i^2 / m_i (the slave node's own mass against a rigid wall). Zero
 * for Lagrange multipliers. Pairs with a massless node (mass redistribution) are left out: their
 * spring has no mode of its own. `lumped_mass` has one entry per DoF.
 */
template <int dim>
double penalty_spring_omega_dt(const ContactConstraints<dim>& contact,
                               const Vector<double>& lumped_mass,
                               double time_step);

/**
 * Contact/penalty factor = auto (doc/method.md, implementation notes): in a wave problem (the
 * bodies' highest mode resolved, is_resolved(body_omega_dt)) a penalty spring stiffer than
 * omega dt = 1 is the one mode the step cannot follow and the contact node chatters (bars 6.2 at
 * factor 100: omega dt = 20, force peak 3.2 against the exact 0.5, 117 contact episodes); every
 * pair's stiffness is scaled so that the stiffest spring has omega dt = 1 (period error 8 %, peak
 * 0.513, one episode). In the quasi-static regime (the spheres) the stiff factor is kept: both are
 * unresolved and the penalty keeps the penetration small. Returns the factor applied to every
 * pair's stiffness (1 if none).
 */
template <int dim>
double size_automatic_penalty(ContactConstraints<dim>& contact, const PenaltySizingInput& input);
} // namespace dyncontact
