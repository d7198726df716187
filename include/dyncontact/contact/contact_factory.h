#pragma once

#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact/contact_description.h>
#include <dyncontact/contact/contact_parameters.h>
#include <dyncontact/contact/node_to_node_contact.h>
#include <dyncontact/contact/penalty_sizing.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/dofs/dof_handler.h>

#include <memory>
#include <optional>

namespace dyncontact
{
/** The contact of a run: the surface geometry (if any) and the constraint set on its pairs. */
template <int dim>
struct Contact
{
  std::unique_ptr<ContactGeometry<dim>> surfaces; ///< null: fixed-normal pairs only
  std::unique_ptr<ContactConstraints<dim>> constraints;
  /// the penalty factor in force: Contact/penalty factor, times the automatic scale if any
  double penalty_factor;
  /// whether Contact/penalty factor = auto lowered the springs to omega dt = 1
  bool penalty_lowered_to_resolve_springs;
};

/**
 * Builds the contact a model described: NodeToNodeContact for a surface pair (or the fixed pairs
 * as given; a model uses one or the other) and the constraint set with `parameters.formulation`;
 * penalty stiffness = Contact/penalty factor x the described stiffness scale, then, for
 * Contact/penalty factor = auto with the penalty formulation, sized by size_automatic_penalty()
 * from `sizing` (required in that case). `surfaces` of the result refers to `dof_handler`,
 * `kinematics` and `nodes`, which must outlive it. Throws InputError for surfaces that do not
 * match or overlap at t = 0 (naming the description's source).
 */
template <int dim>
Contact<dim> create_contact(const ContactDescription<dim>& description,
                            const DoFHandler<dim>& dof_handler,
                            const Kinematics<dim>& kinematics,
                            const NodeIndex<dim>& nodes,
                            const ContactParameters& parameters,
                            const std::optional<PenaltySizingInput>& sizing = std::nullopt);
} // namespace dyncontact
