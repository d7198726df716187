#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact/contact_pair.h>
#include <dyncontact/contact/contact_surface.h>
#include <dyncontact/contact/face_patch.h>

#include <vector>

namespace dyncontact
{
/**
 * Node-to-segment contact on Q2 faces (2D: 3-node lines of the meridian or plane-strain plane;
 * 3D: node-to-surface on 9-node quadrilaterals, the face patch FacePatch<dim>, whose parameter xi
 * is then (xi, eta) and whose faces have nine nodes where the text below says three): every slave
 * node of body A is projected onto the curved master faces of body B (Wriggers, Computational
 * Contact Mechanics, 2nd ed., ch. 4; Laursen, Computational Contact and Impact Mechanics, ch. 5),
 * so that the meshes of the two surfaces need not match.
 *
 * Candidates (reference configuration, fixed for the run): a slave node is a candidate pair if
 * some master face lies within `search_radius` [length] of it (the distance from the node to its
 * closest point on the curved face, QuadraticFace::closest_point()); its candidate faces are all
 * master faces within that distance. The search radius is thus how far a run can follow a slave
 * node along the master surface (sliding plus approach) before it leaves its candidate faces;
 * the sparsity pattern (coupled_nodes()) is built from them once.
 *
 * Pair at a displacement u (update_pairs(), and the reference pairs at u = 0): on each candidate
 * face in its current configuration, x(xi) = sum_i N_i(xi) (X_i + u_i), the master point is where
 * the ray from the slave node's current position x_s along the averaged normal
 * nbar(xi) = n_s - sum_i N_i(xi) n_i^B meets the face, (x(xi) - x_s) x nbar(xi) = 0 (Newton's
 * method from the closest point; n_s the slave surface's and n_i^B the master surface's current
 * outward nodal normals, ContactSurface::normals()); of the faces with such a point the nearest
 * is kept, and if no face has one the closest point of the faces (clamped to a face end) is used.
 * masters = the face's three nodes with weights N_i(xi), and the normal n = nbar / |nbar| (from A
 * toward B), continuous where a slave node crosses a vertex. This is NodeToNodeContact's pairing
 * and normal on matching meshes: for mirrored surfaces the ray along (n_A - n_B) from a slave node
 * meets its mirror node (xi at that node, weight 1 up to round-off), also while the pair is open,
 * so both discretizations give the same active sets (the ctest
 * cli.node_to_segment_matches_node_to_node_on_matching_meshes). The ray is that of the last
 * converged configuration within a time step. The master point follows the Newton iterates
 * (update_master_points(): along the held ray, the normal turning with the face), so that the
 * step's constraint and contact forces are those of its own configuration: held at u_n too, a
 * sliding slave node's gap jumped at every re-projection, and an antisymmetric sliding mode of two
 * flat rod ends grew from round-off (doc/method.md, section 4.1). The rows n N_i leave out the
 * change of xi and n with u (Newton converges linearly while a slave node slides).
 *
 * Penalty stiffness of a pair: `penalty_stiffness_per_area` [force/length^3] times the slave
 * node's lumped reference area (ContactSurface::lumped_areas(), 2 pi r weighted in axisymmetry).
 * The contact pressure is recovered on the slave surface (ContactSurface::consistent_pressures()).
 *
 * Only Q2 elements (three support points per face in 2D, nine in 3D); no self contact, no search
 * beyond the reference candidate faces.
 */
template <int dim>
class NodeToSegmentContact : public ContactGeometry<dim>
{
public:
  /**
   * Pairs the nodes of `slave_surface` (body A) with the faces of `master_surface` (body B) as
   * described above. The bodies may touch at t = 0 but not overlap: a pair whose slave node lies
   * within `touching_tolerance` [length] of its closest point starts closed, its slave position
   * (in the pair only) being moved onto that point so that its reference gap is exactly zero;
   * every later gap of the pair carries that offset, at most the tolerance. Non-matching
   * discretizations of the same curved surface differ by the O(h^3) error of quadratic
   * interpolation, which the tolerance must cover for touching bodies to start closed. A pair
   * whose reference gap is below -`touching_tolerance` means overlap: InputError naming both
   * bodies, where and how much. Also InputError if no slave node lies within `search_radius` of
   * the master surface (no candidate pair), or if a candidate's averaged normal vanishes (its
   * outward normal equals the master surface's: no normal, never a NaN one); AssertThrow if a face
   * does not have three nodes (not Q2).
   */
  NodeToSegmentContact(ContactSurface<dim> slave_surface,
                       ContactSurface<dim> master_surface,
                       double penalty_stiffness_per_area,
                       double search_radius,
                       double touching_tolerance);

  /** The candidate pairs with their reference masters, weights and normals. */
  const std::vector<ContactPair<dim>>& pairs() const override { return candidate_pairs; }

  /**
   * Sets each pair's masters, weights and normal by projecting its slave node onto its candidate
   * faces at `displacement`. Throws SolverFailure
   * if a pair's averaged normal vanishes there (a step that deformed the surfaces that far).
   */
  void update_pairs(const BorderDisplacement<dim>& displacement,
                    std::vector<ContactPair<dim>>& pairs) const override;

  /**
   * Moves each pair's master point to where its ray (through the slave node along the unit
   * averaged normal of u_n, ContactPair::ray_direction) meets its candidate faces at
   * `displacement` (the nearest such point; else the closest point of the faces): within a time
   * step the gap n . (x(xi) - x_s) is then measured to the master face, not to a material point
   * of it. With `move_normals` the normal n turns to the face's normal there (as
   * update_pairs() sets it): a normal held at u_n does the work lambda (n_n . x_,xi) dxi per
   * step on a sliding pair while the face turns, which summed to an O(dt) energy error that
   * rose and fell with the force (+3.9e-4 of the energy in the coarse oblique impact, dt =
   * 0.0025; +2.1e-4 at dt / 2).
   */
  void update_master_points(const BorderDisplacement<dim>& displacement,
                            std::vector<ContactPair<dim>>& pairs,
                            bool move_normals) const override;
  bool moves_normals() const override { return true; }

  /** update_master_points() of the pairs k with `selected[k]` (one flag per pair) only. */
  void update_master_points(const BorderDisplacement<dim>& displacement,
                            std::vector<ContactPair<dim>>& pairs,
                            bool move_normals,
                            const std::vector<bool>& selected) const;

  /** The slave node and every node of the pair's candidate faces. */
  std::vector<Node<dim>> coupled_nodes(unsigned int k) const override;

  /** The nodes of both surfaces. */
  std::vector<Node<dim>> surface_nodes() const override;

  /** ContactSurface::consistent_pressures() of the slave surface at the pairs' slave nodes. */
  std::vector<double> contact_pressures(const BorderDisplacement<dim>& displacement,
                                        const std::vector<double>& multipliers) const override;

  /** The slave surface (body A's). */
  const ContactSurface<dim>& slave() const { return slave_surface; }

  /** The master surface (body B's). */
  const ContactSurface<dim>& master() const { return master_surface; }

  /** The index in the slave surface's nodes() of pair `k`'s slave node. */
  unsigned int slave_node(const unsigned int k) const { return slave_node_of_pair[k]; }

  /** Pair `k`'s candidate faces: indices into the master surface's face_nodes(). */
  const std::vector<unsigned int>& candidate_faces(const unsigned int k) const
  {
    return candidate_faces_of_pair[k];
  }

private:
  ContactSurface<dim> slave_surface, master_surface;
  /** Per pair: index of its slave node in slave_surface.nodes(). */
  std::vector<unsigned int> slave_node_of_pair;
  /** Per pair: its candidate faces, indices into master_surface.face_nodes(). */
  std::vector<std::vector<unsigned int>> candidate_faces_of_pair;
  /// per master face, the sides it shares with another master face (project_onto_faces())
  std::vector<FaceSides<dim>> shared_sides;
  std::vector<ContactPair<dim>> candidate_pairs;
};
} // namespace dyncontact
