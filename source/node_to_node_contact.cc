#include <dyncontact/node_to_node_contact.h>

#include <limits>
#include <sstream>

namespace dyncontact
{
namespace
{
template <int dim>
Point<dim> centroid(const std::vector<Node<dim>>& nodes)
{
  Point<dim> sum;
  for (const auto& node : nodes)
    sum += node.position;
  return sum / static_cast<double>(nodes.size());
}
} // namespace

template <int dim>
NodeToNodeContact<dim>::NodeToNodeContact(ContactSurface<dim> surface_a,
                                          ContactSurface<dim> surface_b,
                                          const double penalty_stiffness_per_area,
                                          const double matching_tolerance)
    : surface_a(std::move(surface_a)), surface_b(std::move(surface_b))
{
  const std::vector<Node<dim>>& nodes_a = this->surface_a.nodes();
  const std::vector<Node<dim>>& nodes_b = this->surface_b.nodes();
  Tensor<1, dim> approach               = centroid(nodes_b) - centroid(nodes_a);
  approach /= approach.norm();
  const auto geometry_a    = this->surface_a.reference_geometry();
  const auto geometry_b    = this->surface_b.reference_geometry();
  const auto across_offset = [&approach](const Tensor<1, dim>& offset)
  { return (offset - (offset * approach) * approach).norm(); };

  unsigned int unmatched = 0;
  std::ostringstream first_unmatched;
  for (unsigned int i = 0; i < nodes_a.size(); ++i)
  {
    if (geometry_a.normals[i] * approach < 0.5)
      continue;
    unsigned int partner = nodes_b.size();
    double offset        = std::numeric_limits<double>::max();
    for (unsigned int j = 0; j < nodes_b.size(); ++j)
      if (geometry_b.normals[j] * approach <= -0.5 &&
          across_offset(nodes_b[j].position - nodes_a[i].position) < offset)
      {
        partner = j;
        offset  = across_offset(nodes_b[j].position - nodes_a[i].position);
      }
    if (offset > matching_tolerance)
    {
      if (unmatched++ == 0)
        first_unmatched << nodes_a[i].position;
      continue;
    }
    ContactPair<dim> pair;
    pair.node_a = nodes_a[i];
    pair.node_b = nodes_b[partner];
    pair.normal = geometry_a.normals[i] - geometry_b.normals[partner];
    pair.normal /= pair.normal.norm();
    pair.penalty_stiffness =
        penalty_stiffness_per_area * 0.5 * (geometry_a.areas[i] + geometry_b.areas[partner]);
    candidate_pairs.push_back(pair);
    surface_nodes_of_pair.emplace_back(i, partner);
  }
  if (unmatched > 0)
    throw InputError(std::to_string(unmatched) + " of the " +
                     std::to_string(unmatched + candidate_pairs.size()) +
                     " surface nodes of body " + std::to_string(nodes_a.front().body + 1) +
                     " that face body " + std::to_string(nodes_b.front().body + 1) +
                     " have no node of body " + std::to_string(nodes_b.front().body + 1) +
                     " across from them (first at " + first_unmatched.str() +
                     "): node-to-node contact needs matching (e.g. mirrored) meshes of the facing "
                     "surfaces.");
}

template <int dim>
typename NodeToNodeContact<dim>::PairGeometry
NodeToNodeContact<dim>::current_geometry(const Vector<double>& displacement) const
{
  const auto geometry_a = surface_a.current_geometry(displacement);
  const auto geometry_b = surface_b.current_geometry(displacement);
  PairGeometry geometry;
  for (const auto& [index_a, index_b] : surface_nodes_of_pair)
  {
    Tensor<1, dim> normal = geometry_a.normals[index_a] - geometry_b.normals[index_b];
    geometry.normals.push_back(normal / normal.norm());
    geometry.areas.push_back(0.5 * (geometry_a.areas[index_a] + geometry_b.areas[index_b]));
  }
  return geometry;
}

template <int dim>
std::vector<double>
NodeToNodeContact<dim>::contact_pressures(const Vector<double>& displacement,
                                          const std::vector<double>& multipliers) const
{
  AssertDimension(multipliers.size(), candidate_pairs.size());
  Eigen::VectorXd nodal_forces = Eigen::VectorXd::Zero(surface_a.nodes().size());
  for (unsigned int k = 0; k < candidate_pairs.size(); ++k)
    nodal_forces(surface_nodes_of_pair[k].first) = multipliers[k];
  const Eigen::VectorXd pressure = surface_a.mass_matrix(displacement).ldlt().solve(nodal_forces);
  std::vector<double> pressures(candidate_pairs.size());
  for (unsigned int k = 0; k < candidate_pairs.size(); ++k)
    pressures[k] = pressure(surface_nodes_of_pair[k].first);
  return pressures;
}

template class NodeToNodeContact<1>;
template class NodeToNodeContact<2>;
template class NodeToNodeContact<3>;
} // namespace dyncontact
