#include <dyncontact/contact/node_to_node_contact.h>

#include <algorithm>
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
                                          const double matching_tolerance,
                                          const double touching_tolerance)
    : surface_a(std::move(surface_a)), surface_b(std::move(surface_b))
{
  const std::vector<Node<dim>>& nodes_a = this->surface_a.nodes();
  const std::vector<Node<dim>>& nodes_b = this->surface_b.nodes();
  Tensor<1, dim> approach               = centroid(nodes_b) - centroid(nodes_a);
  approach /= approach.norm();
  const Vector<double> undeformed(this->surface_a.n_dofs());
  const auto normals_a     = this->surface_a.normals(undeformed);
  const auto normals_b     = this->surface_b.normals(undeformed);
  const auto areas_a       = this->surface_a.lumped_areas(undeformed);
  const auto areas_b       = this->surface_b.lumped_areas(undeformed);
  const auto across_offset = [&approach](const Tensor<1, dim>& offset)
  { return (offset - (offset * approach) * approach).norm(); };

  unsigned int unmatched = 0;
  std::ostringstream first_unmatched;
  for (unsigned int i = 0; i < nodes_a.size(); ++i)
  {
    if (normals_a[i] * approach < 0.5)
      continue;
    unsigned int partner = nodes_b.size();
    double offset        = std::numeric_limits<double>::max();
    for (unsigned int j = 0; j < nodes_b.size(); ++j)
      if (normals_b[j] * approach <= -0.5 &&
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
    pair.slave   = nodes_a[i];
    pair.masters = {{nodes_b[partner], 1.}};
    if (nodes_b[partner].position.distance(nodes_a[i].position) <= touching_tolerance)
      pair.masters[0].node.position = nodes_a[i].position;
    pair.penalty_stiffness = penalty_stiffness_per_area * 0.5 * (areas_a[i] + areas_b[partner]);
    candidate_pairs.push_back(pair);
    surface_nodes_of_pair.emplace_back(i, partner);
  }
  const auto reference_normals = current_normals(undeformed);
  for (unsigned int k = 0; k < candidate_pairs.size(); ++k)
    candidate_pairs[k].normal = reference_normals[k];
  if (unmatched == 0)
    for (const ContactPair<dim>& pair : candidate_pairs)
      if (pair.reference_gap() < -touching_tolerance)
        throw overlap_at_start(pair, touching_tolerance);
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
std::vector<Tensor<1, dim>>
NodeToNodeContact<dim>::current_normals(const Vector<double>& displacement) const
{
  const auto normals_a = surface_a.normals(displacement);
  const auto normals_b = surface_b.normals(displacement);
  std::vector<Tensor<1, dim>> pair_normals;
  for (const auto& [index_a, index_b] : surface_nodes_of_pair)
  {
    const Tensor<1, dim> normal = normals_a[index_a] - normals_b[index_b];
    pair_normals.push_back(normal / normal.norm());
  }
  return pair_normals;
}

template <int dim>
std::vector<double>
NodeToNodeContact<dim>::contact_pressures(const Vector<double>& displacement,
                                          const std::vector<double>& multipliers) const
{
  AssertDimension(multipliers.size(), candidate_pairs.size());
  std::vector<unsigned int> nodes_a_of_pairs;
  for (const auto& nodes_of_pair : surface_nodes_of_pair)
    nodes_a_of_pairs.push_back(nodes_of_pair.first);
  return surface_a.consistent_pressures(displacement, nodes_a_of_pairs, multipliers);
}

template <int dim>
void NodeToNodeContact<dim>::update_pairs(const Vector<double>& displacement,
                                          std::vector<ContactPair<dim>>& pairs) const
{
  const auto normals = current_normals(displacement);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    pairs[k].normal = normals[k];
}

template <int dim>
std::vector<types::global_dof_index>
NodeToNodeContact<dim>::coupled_dofs(const unsigned int k) const
{
  return candidate_pairs[k].dofs();
}

template class NodeToNodeContact<1>;
template class NodeToNodeContact<2>;
template class NodeToNodeContact<3>;
} // namespace dyncontact
