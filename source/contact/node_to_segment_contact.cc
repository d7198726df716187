#include <dyncontact/contact/face_patch.h>
#include <dyncontact/contact/node_to_segment_contact.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace dyncontact
{
namespace
{
/// |n_s - sum_i N_i n_i| (at most 2) below which a slave node does not face the master surface.
constexpr double least_averaged_normal = 1e-8;

/// The parameter distance from a master node or from a side the face shares with another face
/// within which a pair's normal turns from the face's normal to the averaged one
/// (project_onto_faces()).
constexpr double edge_zone = 0.01;

/** The distance of x in [0, 1] from the nearest of 0, 1/2 and 1 (a Q2 face's nodes along x). */
double node_distance(const double x)
{
  return std::min({x, std::abs(x - 0.5), 1. - x});
}

/**
 * The parameter distance of xi from the face's nodes and from its sides that `shared` marks (the
 * order of FaceSides), whichever is nearer: in 2D the nodes alone (a face's ends are nodes); in
 * 3D the 3 x 3 grid of nodes (maximum norm) and the shared sides.
 */
double node_or_kink_distance(const double xi, const std::array<bool, 2>& /*ends: nodes*/)
{
  return node_distance(xi);
}
double node_or_kink_distance(const Point<2>& xi, const std::array<bool, 4>& shared)
{
  return std::min({std::max(node_distance(xi[0]), node_distance(xi[1])),
                   shared[0] ? xi[0] : 1.,
                   shared[1] ? 1. - xi[0] : 1.,
                   shared[2] ? xi[1] : 1.,
                   shared[3] ? 1. - xi[1] : 1.});
}

/**
 * Per face of `surface`, which of its sides (FaceSides' order) it shares with another face: the
 * sides whose corner nodes (one node in 2D, two in 3D) another face has as a side too.
 */
template <int dim>
std::vector<FaceSides<dim>> shared_face_sides(const ContactSurface<dim>& surface)
{
  // The corner nodes of each side, in FacePatch's node order (QuadraticQuad: FE_Q<2>(2)'s unit
  // support points, corners 0 (0, 0), 1 (1, 0), 2 (0, 1), 3 (1, 1)).
  const std::vector<std::vector<unsigned int>> side_corners =
      dim == 2 ? std::vector<std::vector<unsigned int>>{{0}, {1}}
               : std::vector<std::vector<unsigned int>>{{0, 2}, {1, 3}, {0, 1}, {2, 3}};
  const auto key = [&](const std::vector<unsigned int>& face, const unsigned int side)
  {
    std::vector<unsigned int> nodes;
    for (const unsigned int corner : side_corners[side])
      nodes.push_back(face[corner]);
    std::sort(nodes.begin(), nodes.end());
    return nodes;
  };
  std::map<std::vector<unsigned int>, unsigned int> count;
  for (const auto& face : surface.face_nodes())
    for (unsigned int side = 0; side < side_corners.size(); ++side)
      ++count[key(face, side)];
  std::vector<FaceSides<dim>> shared(surface.face_nodes().size());
  for (unsigned int f = 0; f < shared.size(); ++f)
    for (unsigned int side = 0; side < side_corners.size(); ++side)
      shared[f][side] = count[key(surface.face_nodes()[f], side)] > 1;
  return shared;
}

/** Where move_master_point() put a pair's master point. */
template <int dim>
struct MasterPoint
{
  Tensor<1, dim> averaged; ///< nbar = n_s - sum_i N_i n_i, the ray's direction (not normalized)
  unsigned int face;       ///< the face the point is on
  typename FacePatch<dim>::Parameter xi; ///< the point's parameter on it
};

/**
 * Moves `pair`'s master point onto `faces` of `master_surface`, its nodes at `master_positions`:
 * to where the ray from the slave node (at `slave_point`) along nbar(face, xi) = n_s - sum_i
 * N_i(xi) n_i meets a face (the nearest such point), else to the closest point of the faces; sets
 * the pair's masters (the face's nodes) and weights (N_i at the point) and returns nbar, the face
 * and the point's parameter. `master_normals`: the master surface's nodal normals n_i there
 * (update_pairs(): the averaged normal of the two surfaces, n_s the slave node's normal), or null
 * for a ray along n_s alone (update_master_points(): n_s the pair's ray direction, kept).
 */
template <int dim>
MasterPoint<dim> move_master_point(const ContactSurface<dim>& master_surface,
                                   const std::vector<unsigned int>& faces,
                                   const std::vector<Point<dim>>& master_positions,
                                   const Point<dim>& slave_point,
                                   const Tensor<1, dim>& n_s,
                                   const std::vector<Tensor<1, dim>>* master_normals,
                                   ContactPair<dim>& pair)
{
  using Patch           = FacePatch<dim>;
  const auto normals_of = [&](const unsigned int face)
  {
    std::array<Tensor<1, dim>, Patch::n_nodes> normals; // zero: the ray along n_s alone
    if (master_normals != nullptr)
      for (unsigned int i = 0; i < Patch::n_nodes; ++i)
        normals[i] = (*master_normals)[master_surface.face_nodes()[face][i]];
    return normals;
  };
  unsigned int chosen_face = faces.front();
  typename Patch::Parameter chosen_xi{};
  double chosen_distance = std::numeric_limits<double>::max();
  bool on_ray            = false;
  for (const unsigned int face : faces)
  {
    const auto curve      = face_patch<dim>(master_surface.face_nodes()[face], master_positions);
    const auto closest    = curve.closest_point(slave_point);
    const auto ray_xi     = curve.ray_point(slave_point, n_s, normals_of(face), closest.xi);
    const auto xi         = ray_xi ? *ray_xi : closest.xi;
    const double distance = curve.point(xi).distance(slave_point);
    // A point on the ray beats any closest point; among equals, the nearest.
    if ((ray_xi && !on_ray) || (bool(ray_xi) == on_ray && distance < chosen_distance))
    {
      chosen_face     = face;
      chosen_xi       = xi;
      chosen_distance = distance;
      on_ray          = bool(ray_xi);
    }
  }
  const auto weights  = Patch::shape_values(chosen_xi);
  const auto normals  = normals_of(chosen_face);
  Tensor<1, dim> nbar = n_s;
  pair.masters.clear();
  for (unsigned int i = 0; i < Patch::n_nodes; ++i)
  {
    pair.masters.push_back(
        {master_surface.nodes()[master_surface.face_nodes()[chosen_face][i]], weights[i]});
    nbar -= weights[i] * normals[i];
  }
  return {nbar, chosen_face, chosen_xi};
}

/**
 * The unit normal of a pair whose master point is at `xi` on a face with normal `face` (any
 * length, either sign) and shared sides `shared`: the face's unit normal on the side of
 * `ray_direction` (the unit averaged normal), turned to `ray_direction` within `edge_zone` of a
 * master node or of a shared side, continuously: w = (1 - d / edge_zone)^2 of the ray direction,
 * d = node_or_kink_distance().
 */
template <int dim>
Tensor<1, dim> pair_normal(const Tensor<1, dim>& face,
                           const typename FacePatch<dim>::Parameter& xi,
                           const FaceSides<dim>& shared,
                           const Tensor<1, dim>& ray_direction)
{
  const double zone = std::max(0., 1. - node_or_kink_distance(xi, shared) / edge_zone);
  const Tensor<1, dim> normal =
      (1. - zone * zone) * (face * ray_direction >= 0. ? 1. : -1.) * face / face.norm() +
      zone * zone * ray_direction;
  return normal / normal.norm();
}

/**
 * Sets `pair`'s masters, weights and normal from `faces` of `master_surface`, its nodes at
 * `master_positions`, with the slave node at `slave_point`, its normal `slave_normal` and the
 * master surface's nodal normals `master_normals` there: the master point is where the ray from the
 * slave node along the averaged normal meets a face (the nearest such point), else the closest
 * point of the faces. The pair's ray direction is the unit averaged normal, along which the
 * master point follows the slave within the step (update_master_points()); its normal is the
 * face's unit normal at the point, turned to the averaged normal's side: the gap along the ray
 * then does not change to first order as the master point slides over the face, so a sliding
 * pair's force does no work at a closed gap (doc/method.md section 4.1). Within `edge_zone` of a
 * master node or of a side the face shares with another face (a kink of the C0 surface, where the
 * face normal jumps) the normal turns to the averaged one, continuously: a slave node on a kink
 * is not pushed by one face's normal or the other's from step to step, and one on a master node
 * (matching meshes) has node-to-node contact's normal. Throws SolverFailure if the averaged
 * normal vanishes (the ray has no direction) or is tangent to the face.
 */
template <int dim>
void project_onto_faces(const ContactSurface<dim>& master_surface,
                        const std::vector<unsigned int>& faces,
                        const std::vector<Point<dim>>& master_positions,
                        const Point<dim>& slave_point,
                        const Tensor<1, dim>& slave_normal,
                        const std::vector<Tensor<1, dim>>& master_normals,
                        const std::vector<FaceSides<dim>>& shared_sides,
                        ContactPair<dim>& pair)
{
  const auto [averaged, face_index, xi] = move_master_point(
      master_surface, faces, master_positions, slave_point, slave_normal, &master_normals, pair);
  const Tensor<1, dim> face =
      face_patch<dim>(master_surface.face_nodes()[face_index], master_positions).normal(xi);
  const double facing = averaged * face;
  if (!(averaged.norm() >= least_averaged_normal) || // also for NaN
      !(std::abs(facing) >= least_averaged_normal * averaged.norm() * face.norm()))
  {
    std::ostringstream where;
    where << pair.slave.position;
    throw SolverFailure("node-to-segment contact: the slave node at " + where.str() +
                        " (reference position) does not face the master surface (its outward "
                        "normal equals the master surface's there).");
  }
  pair.ray_direction = averaged / averaged.norm();
  pair.normal        = pair_normal(face, xi, shared_sides[face_index], pair.ray_direction);
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
    AssertThrow(face.size() == FacePatch<dim>::n_nodes,
                ExcMessage("node-to-segment contact needs Q2 faces (three nodes a face in 2D, nine "
                           "in 3D)"));
  shared_sides                 = shared_face_sides(this->master_surface);
  const auto undeformed_slave  = this->slave_surface.reference_positions();
  const auto undeformed_master = this->master_surface.reference_positions();
  const auto slave_areas       = this->slave_surface.lumped_areas(undeformed_slave);
  const auto slave_normals     = this->slave_surface.normals(undeformed_slave);
  const auto master_normals    = this->master_surface.normals(undeformed_master);

  for (unsigned int i = 0; i < slave_nodes.size(); ++i)
  {
    std::vector<unsigned int> faces;
    for (unsigned int face = 0; face < master_faces.size(); ++face)
      if (face_patch<dim>(master_faces[face], undeformed_master)
              .closest_point(slave_nodes[i].position)
              .distance <= search_radius)
        faces.push_back(face);
    if (faces.empty())
      continue;
    ContactPair<dim> pair;
    pair.slave             = slave_nodes[i];
    pair.penalty_stiffness = penalty_stiffness_per_area * slave_areas[i];
    try
    {
      project_onto_faces(this->master_surface,
                         faces,
                         undeformed_master,
                         pair.slave.position,
                         slave_normals[i],
                         master_normals,
                         shared_sides,
                         pair);
    }
    catch (const SolverFailure& failure) // at the reference configuration: the input's fault
    {
      throw InputError(failure.what());
    }
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
                     ": node-to-segment contact has no candidate pairs (the radius is the bodies' "
                     "initial gap plus a quarter of the smaller one's height): check that the pair "
                     "names the two facing surfaces.");
}

template <int dim>
void NodeToSegmentContact<dim>::update_pairs(const BorderDisplacement<dim>& displacement,
                                             std::vector<ContactPair<dim>>& pairs) const
{
  const auto master_positions = master_surface.current_positions(displacement);
  const auto slave_normals  = slave_surface.normals(slave_surface.current_positions(displacement));
  const auto master_normals = master_surface.normals(master_positions);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    project_onto_faces(master_surface,
                       candidate_faces_of_pair[k],
                       master_positions,
                       displacement.current_position(pairs[k].slave),
                       slave_normals[slave_node_of_pair[k]],
                       master_normals,
                       shared_sides,
                       pairs[k]);
}

template <int dim>
void NodeToSegmentContact<dim>::update_master_points(const BorderDisplacement<dim>& displacement,
                                                     std::vector<ContactPair<dim>>& pairs,
                                                     const bool move_normals) const
{
  update_master_points(displacement, pairs, move_normals, std::vector<bool>(pairs.size(), true));
}

template <int dim>
void NodeToSegmentContact<dim>::update_master_points(const BorderDisplacement<dim>& displacement,
                                                     std::vector<ContactPair<dim>>& pairs,
                                                     const bool move_normals,
                                                     const std::vector<bool>& selected) const
{
  AssertDimension(selected.size(), pairs.size());
  const auto master_positions = master_surface.current_positions(displacement);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    if (selected[k])
    {
      const auto [averaged, face, xi] =
          move_master_point<dim>(master_surface,
                                 candidate_faces_of_pair[k],
                                 master_positions,
                                 displacement.current_position(pairs[k].slave),
                                 pairs[k].ray_direction,
                                 nullptr,
                                 pairs[k]);
      if (move_normals)
        pairs[k].normal = pair_normal(
            face_patch<dim>(master_surface.face_nodes()[face], master_positions).normal(xi),
            xi,
            shared_sides[face],
            pairs[k].ray_direction);
    }
}

template <int dim>
std::vector<Node<dim>> NodeToSegmentContact<dim>::coupled_nodes(const unsigned int k) const
{
  std::vector<Node<dim>> nodes = {candidate_pairs[k].slave};
  for (const unsigned int face : candidate_faces_of_pair[k])
    for (const unsigned int node : master_surface.face_nodes()[face])
      nodes.push_back(master_surface.nodes()[node]);
  return nodes;
}

template <int dim>
std::vector<double>
NodeToSegmentContact<dim>::contact_pressures(const BorderDisplacement<dim>& displacement,
                                             const std::vector<double>& multipliers) const
{
  AssertDimension(multipliers.size(), candidate_pairs.size());
  return slave_surface.consistent_pressures(
      slave_surface.current_positions(displacement), slave_node_of_pair, multipliers);
}

template <int dim>
std::vector<Node<dim>> NodeToSegmentContact<dim>::surface_nodes() const
{
  return nodes_of_both(slave_surface, master_surface);
}

// 2D and 3D, the exception to base/dimensions.h: its face patch (FacePatch) is a 3-node line or a
// 9-node quadrilateral.
template class NodeToSegmentContact<2>;
template class NodeToSegmentContact<3>;
} // namespace dyncontact
