#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact/contact_factory.h>
#include <dyncontact/contact/contact_geometry_set.h>
#include <dyncontact/contact/mortar_contact.h>
#include <dyncontact/contact/node_to_segment_contact.h>
#include <dyncontact/contact/rigid_plane_contact.h>

namespace dyncontact
{
const NameTable<ContactDiscretization>& contact_discretization_names()
{
  static const NameTable<ContactDiscretization> names{
      {"node-to-node", ContactDiscretization::node_to_node},
      {"node-to-segment", ContactDiscretization::node_to_segment},
      {"mortar", ContactDiscretization::mortar}};
  return names;
}

namespace
{
template <int dim>
std::unique_ptr<ContactGeometry<dim>>
surface_contact(const typename ContactDescription<dim>::SurfacePair& surfaces,
                const DoFHandler<dim>& dof_handler,
                const Kinematics<dim>& kinematics,
                const NodeIndex<dim>& nodes,
                const ContactParameters& parameters)
{
  ContactSurface<dim> surface_a(dof_handler, kinematics, nodes, surfaces.surface_a);
  ContactSurface<dim> surface_b(dof_handler, kinematics, nodes, surfaces.surface_b);
  const double penalty_per_area =
      parameters.penalty_factor * surfaces.stiffness_modulus / surfaces.stiffness_length;
  switch (parameters.discretization)
  {
  case ContactDiscretization::node_to_node:
    return std::make_unique<NodeToNodeContact<dim>>(std::move(surface_a),
                                                    std::move(surface_b),
                                                    penalty_per_area,
                                                    surfaces.matching_tolerance,
                                                    surfaces.touching_tolerance);
  case ContactDiscretization::node_to_segment:
    if constexpr (dim == 1)
      throw InputError("Contact/discretization = node-to-segment is for meshes, not bars.");
    else
      return std::make_unique<NodeToSegmentContact<dim>>(std::move(surface_a),
                                                         std::move(surface_b),
                                                         penalty_per_area,
                                                         surfaces.search_radius,
                                                         surfaces.touching_tolerance);
  case ContactDiscretization::mortar:
    if constexpr (dim != 2)
      throw InputError("Contact/discretization = mortar is implemented for 2D (axisymmetric and "
                       "plane strain) meshes only.");
    else
      return std::make_unique<MortarContact<dim>>(surface_a,
                                                  surface_b,
                                                  kinematics,
                                                  penalty_per_area,
                                                  surfaces.search_radius,
                                                  surfaces.touching_tolerance);
  }
  AssertThrow(false, ExcInternalError()); // every ContactDiscretization is a case above
  return nullptr;
}

/**
 * The geometry of every described surface and plane pair: one, or a ContactGeometrySet; and into
 * `friction_coefficients` the friction coefficient of each of its candidate pairs (the described
 * pair's own, else Contact/friction coefficient).
 */
template <int dim>
std::unique_ptr<ContactGeometry<dim>> surface_geometry(const ContactDescription<dim>& description,
                                                       const DoFHandler<dim>& dof_handler,
                                                       const Kinematics<dim>& kinematics,
                                                       const NodeIndex<dim>& nodes,
                                                       const ContactParameters& parameters,
                                                       std::vector<double>& friction_coefficients)
{
  std::vector<std::unique_ptr<ContactGeometry<dim>>> members;
  // The set's pairs are its members' in order (ContactGeometrySet).
  const auto add_coefficients = [&](const std::optional<double>& own)
  {
    friction_coefficients.insert(friction_coefficients.end(),
                                 members.back()->pairs().size(),
                                 own.value_or(parameters.friction_coefficient));
  };
  for (const auto& surfaces : description.surface_pairs)
    try
    {
      members.push_back(surface_contact(surfaces, dof_handler, kinematics, nodes, parameters));
      add_coefficients(surfaces.friction_coefficient);
    }
    catch (const InputError& error)
    {
      throw InputError(surfaces.source + ": " + error.what());
    }
  for (const auto& plane : description.plane_pairs)
    try
    {
      members.push_back(std::make_unique<RigidPlaneContact<dim>>(
          ContactSurface<dim>(dof_handler, kinematics, nodes, plane.surface),
          plane.point,
          plane.normal,
          parameters.penalty_factor * plane.stiffness_modulus / plane.stiffness_length,
          plane.touching_tolerance));
      add_coefficients(plane.friction_coefficient);
    }
    catch (const InputError& error)
    {
      throw InputError(plane.source + ": " + error.what());
    }
  if (members.size() == 1)
    return std::move(members.front());
  return std::make_unique<ContactGeometrySet<dim>>(std::move(members));
}

template <int dim>
Contact<dim> build_contact(const ContactDescription<dim>& description,
                           const DoFHandler<dim>& dof_handler,
                           const Kinematics<dim>& kinematics,
                           const NodeIndex<dim>& nodes,
                           const ContactParameters& parameters)
{
  Contact<dim> contact;
  if (!description.surface_pairs.empty() || !description.plane_pairs.empty())
  {
    Assert(description.fixed_pairs.empty(), ExcMessage("surface contact or fixed pairs, not both"));
    std::vector<double> friction_coefficients;
    contact.surfaces = surface_geometry(
        description, dof_handler, kinematics, nodes, parameters, friction_coefficients);
    contact.constraints = std::make_unique<ContactConstraints<dim>>(
        *contact.surfaces, parameters.formulation, std::move(friction_coefficients));
    return contact;
  }
  if (parameters.friction_coefficient > 0.)
    throw InputError(
        "Contact/friction coefficient = " + format_number(parameters.friction_coefficient) +
        " is not allowed for bars: a bar has no tangential direction (friction is "
        "for meshes); set it to 0.");
  std::vector<ContactPair<dim>> pairs;
  for (const auto& described : description.fixed_pairs)
  {
    ContactPair<dim> pair;
    pair.slave = described.node_a;
    if (described.node_b)
      pair.masters = {{*described.node_b, 1.}};
    pair.wall_point        = described.wall_point;
    pair.normal            = described.normal;
    pair.penalty_stiffness = parameters.penalty_factor * described.stiffness_scale;
    pairs.push_back(pair);
  }
  contact.constraints = std::make_unique<ContactConstraints<dim>>(pairs, parameters.formulation);
  return contact;
}
} // namespace

template <int dim>
Contact<dim> create_contact(const ContactDescription<dim>& description,
                            const DoFHandler<dim>& dof_handler,
                            const Kinematics<dim>& kinematics,
                            const NodeIndex<dim>& nodes,
                            const ContactParameters& parameters,
                            const std::optional<PenaltySizingInput>& sizing)
{
  Contact<dim> contact   = build_contact(description, dof_handler, kinematics, nodes, parameters);
  contact.penalty_factor = parameters.penalty_factor;
  contact.penalty_lowered_to_resolve_springs = false;
  if (parameters.formulation == ContactFormulation::penalty && parameters.automatic_penalty)
  {
    AssertThrow(sizing.has_value(),
                ExcMessage("Contact/penalty factor = auto needs the lumped mass and time step"));
    const double scale = size_automatic_penalty(*contact.constraints, *sizing);
    contact.penalty_factor *= scale;
    contact.penalty_lowered_to_resolve_springs = scale < 1.;
  }
  return contact;
}

#define DYNCONTACT_INSTANTIATE(dim)                                                                \
  template Contact<dim> create_contact(const ContactDescription<dim>&,                             \
                                       const DoFHandler<dim>&,                                     \
                                       const Kinematics<dim>&,                                     \
                                       const NodeIndex<dim>&,                                      \
                                       const ContactParameters&,                                   \
                                       const std::optional<PenaltySizingInput>&);
DYNCONTACT_FOR_EACH_DIMENSION(DYNCONTACT_INSTANTIATE)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
