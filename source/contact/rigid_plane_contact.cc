#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact/rigid_plane_contact.h>

#include <sstream>

namespace dyncontact
{
template <int dim>
RigidPlaneContact<dim>::RigidPlaneContact(ContactSurface<dim> surface,
                                          const Point<dim>& point,
                                          const Tensor<1, dim>& normal,
                                          const double penalty_stiffness_per_area,
                                          const double touching_tolerance)
    : surface(std::move(surface))
{
  const auto undeformed = this->surface.reference_positions();
  const auto normals    = this->surface.normals(undeformed);
  const auto areas      = this->surface.lumped_areas(undeformed);
  const auto& nodes     = this->surface.nodes();
  for (unsigned int i = 0; i < nodes.size(); ++i)
  {
    if (normals[i] * normal >= 0.)
      continue;
    ContactPair<dim> pair;
    pair.slave             = nodes[i];
    pair.wall_point        = point;
    pair.normal            = -normal;
    pair.penalty_stiffness = penalty_stiffness_per_area * areas[i];
    if (pair.reference_gap() < -touching_tolerance)
    {
      std::ostringstream plane;
      plane << "the plane through (" << point << ") with normal (" << normal
            << "), which must point toward the body";
      throw InputError(std::string(overlap_at_start(pair, touching_tolerance).what()) + " Is " +
                       plane.str() + "?");
    }
    candidate_pairs.push_back(pair);
    surface_node_of_pair.push_back(i);
  }
  if (candidate_pairs.empty())
    throw InputError("no node of the surface of body " + std::to_string(nodes.front().body + 1) +
                     " faces the rigid plane (every outward normal points away from it).");
}

template <int dim>
std::vector<Node<dim>> RigidPlaneContact<dim>::coupled_nodes(const unsigned int k) const
{
  std::vector<Node<dim>> nodes;
  candidate_pairs[k].for_each_node([&nodes](const Node<dim>& node, double)
                                   { nodes.push_back(node); });
  return nodes;
}

template <int dim>
std::vector<double>
RigidPlaneContact<dim>::contact_pressures(const BorderDisplacement<dim>& displacement,
                                          const std::vector<double>& multipliers) const
{
  return surface.consistent_pressures(
      surface.current_positions(displacement), surface_node_of_pair, multipliers);
}

DYNCONTACT_INSTANTIATE_CLASS(RigidPlaneContact)
} // namespace dyncontact
