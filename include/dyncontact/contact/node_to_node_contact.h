#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact/contact_pair.h>
#include <dyncontact/contact/contact_surface.h>

#include <deal.II/base/tensor.h>

#include <vector>

namespace dyncontact
{
/**
 * Node-to-node contact between two bodies whose facing surfaces have matching nodes, such as the
 * mirror-image meshes of the paper's two spheres: the candidate pairs and, for a displacement,
 * their current normals and contact pressures.
 *
 * Pairing (reference configuration): with e the approach direction, a unit vector from surface A
 * toward surface B, every node of surface A whose outward normal n_A satisfies n_A . e >= 1/2 (it
 * faces B, within 60 degrees) is paired with the node of surface B that faces A (n_B . e <= -1/2)
 * and lies across from it: the one nearest in the directions orthogonal to e. The two must
 * coincide in those directions to `matching_tolerance`; otherwise the meshes do not match and the
 * constructor throws InputError. Both vertex and mid-side nodes of Q2 faces take part. e is the
 * direction from the centroid of surface A's nodes to that of surface B's (curved surfaces such as
 * the paper's spheres), or, for two flat surfaces (parallel normals: rod ends, a flat punch, block
 * on block) and for surfaces whose centroids coincide (flat faces touching at t = 0), the
 * difference of their area-weighted mean outward normals, normalized: a centroid direction would
 * be 0/0 for coincident faces and along the faces for a punch off the centre.
 *
 * Current normal of a pair: n = (n_A - n_B) / |n_A - n_B| with the current outward nodal normals of
 * ContactSurface; it points from A toward B and is the common normal of the two surfaces where they
 * touch (n_B = -n_A there). The 60-degree limit keeps |n_A - n_B| >= 1. Within a time step the
 * normals stay those of the last converged configuration u_n (ContactConstraints::update_geometry()
 * is called once per accepted step), so that the gap is linear in u and Newton's tangent is exact.
 * Following the normal inside Newton without linearizing it left out the term lambda dn/du of the
 * contact force, proportional to the multiplier, not to the separation: on dissimilar spheres
 * (E1/E2 >= 10) that quasi-Newton stalled at a residual 10^3 times the tolerance whenever the
 * active set shrank. A closed pair of matching nodes is separated only tangentially, so the lag
 * changes its gap at second order in the rotation of n over one step. Contact area of a pair: the
 * mean of its two nodes' lumped areas (ContactSurface::lumped_areas(), 2 pi r weighted in
 * axisymmetry); it scales the penalty stiffness. The contact pressure comes from a consistent
 * recovery instead (contact_pressures()).
 *
 * It is not a general contact search: no sliding beyond the matched partner, no segment
 * projection, no self contact.
 */
template <int dim>
class NodeToNodeContact : public ContactGeometry<dim>
{
public:
  /**
   * Pairs the facing nodes of `surface_a` (body A) and `surface_b` (body B). A pair's penalty
   * stiffness is `penalty_stiffness_per_area` times its reference contact area.
   *
   * The bodies may touch at t = 0 but not overlap. Two paired nodes closer than
   * `touching_tolerance` are the same point: the pair's node B is given node A's position, so
   * that its reference gap is exactly zero, whatever the normal, and the pair starts closed. A
   * pair whose reference gap is below -`touching_tolerance` means that the bodies overlap: the
   * constructor throws InputError, with the overlap and where it is. Also InputError if the
   * surfaces give no approach direction (flat surfaces whose normals point the same way; surfaces
   * with a common centroid whose mean normals do not face each other) or no node of surface A
   * faces surface B (no candidate pair): never a contact without pairs or with a NaN normal.
   */
  NodeToNodeContact(ContactSurface<dim> surface_a,
                    ContactSurface<dim> surface_b,
                    double penalty_stiffness_per_area,
                    double matching_tolerance,
                    double touching_tolerance);

  /** The candidate pairs, with their reference normals. */
  const std::vector<ContactPair<dim>>& pairs() const override { return candidate_pairs; }

  /**
   * Sets each pair's normal to current_normals() at `displacement`; the partners never change.
   */
  void update_pairs(const BorderDisplacement<dim>& displacement,
                    std::vector<ContactPair<dim>>& pairs) const override;

  /** The pair's two nodes. */
  std::vector<Node<dim>> coupled_nodes(unsigned int k) const override;

  /** The nodes of both surfaces. */
  std::vector<Node<dim>> surface_nodes() const override;

  /**
   * The current normal of every pair, in the order of pairs(), with the nodes of surface A at
   * `positions_a` and those of B at `positions_b` (ContactSurface::current_positions()).
   */
  std::vector<Tensor<1, dim>> current_normals(const std::vector<Point<dim>>& positions_a,
                                              const std::vector<Point<dim>>& positions_b) const;

  /**
   * The contact pressure at every pair's node of surface A, consistent with the nodal forces
   * `multipliers` (one per pair, zero for inactive pairs): ContactSurface::consistent_pressures()
   * of surface A at `displacement`. Open pairs (zero multiplier) carry exactly 0.
   */
  std::vector<double> contact_pressures(const BorderDisplacement<dim>& displacement,
                                        const std::vector<double>& multipliers) const override;

private:
  ContactSurface<dim> surface_a, surface_b;
  /** Per pair: index of the slave node in surface_a.nodes() and of its master node in
   * surface_b.nodes(). */
  std::vector<std::pair<unsigned int, unsigned int>> surface_nodes_of_pair;
  std::vector<ContactPair<dim>> candidate_pairs;
};
} // namespace dyncontact
