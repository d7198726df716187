#include <dyncontact/contact/node_to_segment_contact.h>
#include <dyncontact/contact/quadratic_face.h>

#include <algorithm>
#include <limits>

namespace dyncontact
{
namespace
{
/** Face `face` of `surface` at `displacement`. */
template <int dim>
QuadraticFace<dim> current_face(const ContactSurface<dim>& surface,
                                const unsigned int face,
                                const Vector<double>& displacement)
{
  QuadraticFace<dim> curve;
  for (unsigned int i = 0; i < 3; ++i)
    curve.points[i] =
        current_position(surface.nodes()[surface.face_nodes()[face][i]], displacement);
  return curve;
}

/**
 * Sets `pair`'s masters, weights and normal from the nearest of `faces` of `master_surface` at
 * `displacement`, with the master surface's nodal normals `master_normals` there.
 */
template <int dim>
void project_onto_faces(const ContactSurface<dim>& master_surface,
                        const std::vector<unsigned int>& faces,
                        const Vector<double>& displacement,
                        const std::vector<Tensor<1, dim>>& master_normals,
                        ContactPair<dim>& pair)
{
  const Point<dim> slave_point = current_position(pair.slave, displacement);
  unsigned int nearest_face    = faces.front();
  auto nearest =
      current_face(master_surface, nearest_face, displacement).closest_point(slave_point);
  for (const unsigned int face : faces)
  {
    const auto projection =
        current_face(master_surface, face, displacement).closest_point(slave_point);
    if (projection.distance < nearest.distance)
    {
      nearest_face = face;
      nearest      = projection;
    }
  }
  const auto weights = QuadraticFace<dim>::shape_values(nearest.xi);
  Tensor<1, dim> normal;
  pair.masters.clear();
  for (unsigned int i = 0; i < 3; ++i)
  {
    const unsigned int node = master_surface.face_nodes()[nearest_face][i];
    pair.masters.push_back({master_surface.nodes()[node], weights[i]});
    normal -= weights[i] * master_normals[node];
  }
  pair.normal = normal / normal.norm();
}
} // namespace

template <int dim>
NodeToSegmentContact<dim>::NodeToSegmentContact(ContactSurface<dim> slave_surface,
                                                ContactSurface<dim> master_surface,
                                                const double penalty_stiffness_per_area,
                                                const double search_radius,
                                                const double touching_tolerance)
    : slave_surface(std::move(slave_surface)), master_surface(std::move(master_surface))
{
  const std::vector<Node<dim>>& slave_nodes = this->slave_surface.nodes();
  const auto& master_faces                  = this->master_surface.face_nodes();
  for (const auto& face : master_faces)
    AssertThrow(face.size() == 3,
                ExcMessage("node-to-segment contact needs Q2 faces in 2D (three nodes a face)"));
  const Vector<double> undeformed(this->slave_surface.n_dofs());
  const auto slave_areas    = this->slave_surface.lumped_areas(undeformed);
  const auto master_normals = this->master_surface.normals(undeformed);

  for (unsigned int i = 0; i < slave_nodes.size(); ++i)
  {
    std::vector<unsigned int> faces;
    for (unsigned int face = 0; face < master_faces.size(); ++face)
      if (current_face(this->master_surface, face, undeformed)
              .closest_point(slave_nodes[i].position)
              .distance <= search_radius)
        faces.push_back(face);
    if (faces.empty())
      continue;
    ContactPair<dim> pair;
    pair.slave             = slave_nodes[i];
    pair.penalty_stiffness = penalty_stiffness_per_area * slave_areas[i];
    project_onto_faces(this->master_surface, faces, undeformed, master_normals, pair);
    Point<dim> closest_point;
    for (const MasterNode<dim>& master : pair.masters)
      closest_point += master.weight * master.node.position;
    if (closest_point.distance(pair.slave.position) <= touching_tolerance)
      pair.slave.position = closest_point;
    if (pair.reference_gap() < -touching_tolerance)
      throw overlap_at_start(pair, touching_tolerance);
    candidate_pairs.push_back(pair);
    slave_node_of_pair.push_back(i);
    candidate_faces_of_pair.push_back(faces);
  }
  if (candidate_pairs.empty())
    throw InputError("no surface node of body " + std::to_string(slave_nodes.front().body + 1) +
                     " lies within the search radius " + format_number(search_radius) +
                     " of the surface of body " +
                     std::to_string(this->master_surface.nodes().front().body + 1) +
                     ": node-to-segment contact has no candidate pairs (a larger search radius "
                     "covers the approach the run needs).");
}

template <int dim>
void NodeToSegmentContact<dim>::update_pairs(const Vector<double>& displacement,
                                             std::vector<ContactPair<dim>>& pairs) const
{
  const auto master_normals = master_surface.normals(displacement);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    project_onto_faces(
        master_surface, candidate_faces_of_pair[k], displacement, master_normals, pairs[k]);
}

template <int dim>
std::vector<types::global_dof_index>
NodeToSegmentContact<dim>::coupled_dofs(const unsigned int k) const
{
  std::vector<types::global_dof_index> dofs(candidate_pairs[k].slave.dofs.begin(),
                                            candidate_pairs[k].slave.dofs.end());
  for (const unsigned int face : candidate_faces_of_pair[k])
    for (const unsigned int node : master_surface.face_nodes()[face])
    {
      const auto& node_dofs = master_surface.nodes()[node].dofs;
      dofs.insert(dofs.end(), node_dofs.begin(), node_dofs.end());
    }
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

template <int dim>
std::vector<double>
NodeToSegmentContact<dim>::contact_pressures(const Vector<double>& displacement,
                                             const std::vector<double>& multipliers) const
{
  AssertDimension(multipliers.size(), candidate_pairs.size());
  return slave_surface.consistent_pressures(displacement, slave_node_of_pair, multipliers);
}

template class NodeToSegmentContact<2>;
} // namespace dyncontact
