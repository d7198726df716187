#pragma once

#include <dyncontact/base/name_table.h>

namespace dyncontact
{
/**
 * The treatment of the contact nodes' rates by the time integration (Contact/dynamics): what the
 * paper's modified Newmark is one of (sections 4 and 5). A new treatment adds its enumerator and
 * its name here, its class in its own file, and its case in create_contact_dynamics().
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
} // namespace dyncontact
