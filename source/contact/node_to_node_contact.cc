#include <dyncontact/base/dimensions.h>
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

/** The area-weighted mean of a surface's unit nodal `normals` (`areas`: lumped nodal areas). */
template <int dim>
Tensor<1, dim> mean_normal(const std::vector<Tensor<1, dim>>& normals,
                           const std::vector<double>& areas)
{
  Tensor<1, dim> sum;
  double area = 0.;
  for (unsigned int i = 0; i < normals.size(); ++i)
  {
    sum += areas[i] * normals[i];
    area += areas[i];
  }
  return sum / area;
}

/// |mean normal| of a flat surface: its unit normals are parallel to within about 0.1 degree.
constexpr double flat_mean_normal = 1. - 1e-6;
/// |mean n_A - mean n_B| below which the mean normals give no direction (the surfaces do not face
/// each other on average, e.g. two closed surfaces).
constexpr double least_facing = 0.5;

/**
 * The unit direction e from surface A toward surface B along which the surfaces approach, which
 * decides which nodes face each other (`nodes_a`, `nodes_b`: the surfaces' nodes; `mean_normal_a`,
 * `mean_normal_b`: their mean_normal()). The direction between the centroids of the two node sets,
 * except where it is not one: for two flat surfaces (both mean normals of length at least
 * flat_mean_normal: rod ends, a flat punch, block on block), whose centroids may coincide (faces
 * touching) or be offset along the faces (a punch off the centre of the face below), and for
 * surfaces whose centroids coincide to `touching_tolerance` [length]. Those take the mean normals'
 * difference, n_A - n_B normalized. Throws InputError if that difference is shorter than
 * least_facing (NaN included), i.e. the surfaces do not face each other: e is always a finite
 * unit vector.
 */
template <int dim>
Tensor<1, dim> approach_direction(const std::vector<Node<dim>>& nodes_a,
                                  const std::vector<Node<dim>>& nodes_b,
                                  const Tensor<1, dim>& mean_normal_a,
                                  const Tensor<1, dim>& mean_normal_b,
                                  const double touching_tolerance)
{
  const Tensor<1, dim> centres = centroid(nodes_b) - centroid(nodes_a);
  const Tensor<1, dim> facing  = mean_normal_a - mean_normal_b;
  const bool flat =
      mean_normal_a.norm() >= flat_mean_normal && mean_normal_b.norm() >= flat_mean_normal;
  if (!flat && centres.norm() > touching_tolerance)
    return centres / centres.norm();
  if (facing.norm() >= least_facing) // also false for NaN
    return facing / facing.norm();
  const std::string body_a = "body " + std::to_string(nodes_a.front().body + 1);
  const std::string body_b = "body " + std::to_string(nodes_b.front().body + 1);
  throw InputError("the contact surfaces of " + body_a + " and " + body_b +
                   (flat ? " are flat but do not face each other (their outward normals point the "
                           "same way)"
                         : " have a common centroid (to " + format_number(touching_tolerance) +
                               ") and do not face each other on average (mean outward normals " +
                               "differ by " + format_number(facing.norm()) + " < " +
                               format_number(least_facing) + ")") +
                   ": node-to-node contact finds no direction along which they approach.");
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
  const auto undeformed_a               = this->surface_a.reference_positions();
  const auto undeformed_b               = this->surface_b.reference_positions();
  const auto normals_a                  = this->surface_a.normals(undeformed_a);
  const auto normals_b                  = this->surface_b.normals(undeformed_b);
  const auto areas_a                    = this->surface_a.lumped_areas(undeformed_a);
  const auto areas_b                    = this->surface_b.lumped_areas(undeformed_b);
  const Tensor<1, dim> approach         = approach_direction(nodes_a,
                                                     nodes_b,
                                                     mean_normal(normals_a, areas_a),
                                                     mean_normal(normals_b, areas_b),
                                                     touching_tolerance);
  const auto across_offset              = [&approach](const Tensor<1, dim>& offset)
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
  const std::string body_a = "body " + std::to_string(nodes_a.front().body + 1);
  const std::string body_b = "body " + std::to_string(nodes_b.front().body + 1);
  if (candidate_pairs.empty() && unmatched == 0)
    throw InputError("no surface node of " + body_a + " faces " + body_b +
                     " (outward normal within 60 degrees of the approach direction): node-to-node "
                     "contact has no candidate pairs.");
  const auto reference_normals = current_normals(undeformed_a, undeformed_b);
  for (unsigned int k = 0; k < candidate_pairs.size(); ++k)
    candidate_pairs[k].normal = reference_normals[k];
  if (unmatched == 0)
    for (const ContactPair<dim>& pair : candidate_pairs)
      if (pair.reference_gap() < -touching_tolerance)
        throw overlap_at_start(pair, touching_tolerance);
  if (unmatched > 0)
    throw InputError(std::to_string(unmatched) + " of the " +
                     std::to_string(unmatched + candidate_pairs.size()) + " surface nodes of " +
                     body_a + " that face " + body_b + " have no node of " + body_b +
                     " across from them (first at " + first_unmatched.str() +
                     "): node-to-node contact needs matching (e.g. mirrored) meshes of the facing "
                     "surfaces; for meshes that do not match, set Contact/discretization = "
                     "mortar (or node-to-segment).");
}

template <int dim>
std::vector<Tensor<1, dim>>
NodeToNodeContact<dim>::current_normals(const std::vector<Point<dim>>& positions_a,
                                        const std::vector<Point<dim>>& positions_b) const
{
  const auto normals_a = surface_a.normals(positions_a);
  const auto normals_b = surface_b.normals(positions_b);
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
NodeToNodeContact<dim>::contact_pressures(const BorderDisplacement<dim>& displacement,
                                          const std::vector<double>& multipliers) const
{
  AssertDimension(multipliers.size(), candidate_pairs.size());
  std::vector<unsigned int> nodes_a_of_pairs;
  for (const auto& nodes_of_pair : surface_nodes_of_pair)
    nodes_a_of_pairs.push_back(nodes_of_pair.first);
  return surface_a.consistent_pressures(
      surface_a.current_positions(displacement), nodes_a_of_pairs, multipliers);
}

template <int dim>
void NodeToNodeContact<dim>::update_pairs(const BorderDisplacement<dim>& displacement,
                                          std::vector<ContactPair<dim>>& pairs) const
{
  const auto normals = current_normals(surface_a.current_positions(displacement),
                                       surface_b.current_positions(displacement));
  for (unsigned int k = 0; k < pairs.size(); ++k)
    pairs[k].normal = normals[k];
}

template <int dim>
std::vector<Node<dim>> NodeToNodeContact<dim>::coupled_nodes(const unsigned int k) const
{
  std::vector<Node<dim>> nodes;
  candidate_pairs[k].for_each_node([&nodes](const Node<dim>& node, double)
                                   { nodes.push_back(node); });
  return nodes;
}

template <int dim>
std::vector<Node<dim>> NodeToNodeContact<dim>::surface_nodes() const
{
  return nodes_of_both(surface_a, surface_b);
}

DYNCONTACT_INSTANTIATE_CLASS(NodeToNodeContact)
} // namespace dyncontact
