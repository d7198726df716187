#pragma once

#include <dyncontact/base/name_table.h>

namespace dyncontact
{
/**
 * How the contact between two deformable surfaces is discretized (Contact/discretization): the
 * member of the ContactGeometry family create_contact() builds. A new one adds its enumerator and
 * name here, its class in its own file and its case in create_contact().
 */
enum class ContactDiscretization
{
  node_to_node,    ///< matching meshes: each slave node against the facing master node
  node_to_segment, ///< any meshes: each slave node against its projection on a master face
  mortar           ///< any meshes: each slave node's dual-weighted gap over the master surface
};

/** The names of Contact/discretization (defined beside create_contact()). */
const NameTable<ContactDiscretization>& contact_discretization_names();
} // namespace dyncontact
