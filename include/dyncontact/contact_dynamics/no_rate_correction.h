#pragma once

#include <dyncontact/contact_dynamics/contact_dynamics.h>

namespace dyncontact
{
/**
 * Contact/dynamics = none: classical Newmark, the contact constrains the displacements only and
 * the rates of the contact nodes keep the classical update, with its velocity and acceleration
 * jumps across active pairs (the defect the paper describes, section 4).
 */
template <int dim>
class NoRateCorrection : public ContactDynamics<dim>
{
public:
  /** The classical scheme with friction: the tangential forces are the constraint's, no more. */
  bool carries_friction() const override { return true; }
  // Every other hook keeps its default: the classical scheme.
};
} // namespace dyncontact
