#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact/contact_pair.h>
#include <dyncontact/contact/contact_surface.h>
#include <dyncontact/contact/node_to_segment_contact.h>
#include <dyncontact/discretization/kinematics.h>

#include <map>
#include <vector>

namespace dyncontact
{
/**
 * Mortar contact on Q2 faces (2D: plane strain or the axisymmetric meridian plane) with dual
 * Lagrange multipliers (Wohlmuth 2000; Popp, Gee & Wall, IJNME 79, 2009, for the quadratic
 * case): the non-penetration condition of each slave node j is imposed on the weighted gap
 *   g_j = n_j . (sum_m M_jm x_m - D_j x_j),  M_jm = integral over the slave surface of
 *   psi_j N_m(proj), D_j = integral of N_j,
 * the integrals taken over the deformed slave surface with the kinematics' measure factor (2 pi r
 * in axisymmetry), psi_j the dual shape functions, biorthogonal to the slave face's N_k
 * (integral of psi_j N_k = delta_jk D_j on every face, so the slave side of the weighted gap is
 * D_j x_j exactly), N_m(proj) the master face's shape functions at the point the ray from the
 * slave point along the interpolated slave normal meets. A pair is then a slave node against the
 * master nodes with the weights w_m = M_jm / sum_m M_jm, which sum to one (its forces balance):
 * a ContactPair as node-to-segment's, whose master point is the psi_j-weighted mean of the master
 * surface over the slave node's faces instead of one projected point. The multiplier stays the
 * nodal force.
 *
 * Why: node-to-segment's point projection passes the patch test only on matching Q2 meshes;
 * between non-matching ones the master nodes' forces N_m(xi_j) lambda_j are not those of a
 * smooth traction, and Hertz's line contact of a cylinder on a block came out with a pressure
 * alternating by 10-21 % of p0 between vertex and mid-side nodes. The mortar weights transmit a
 * constant pressure exactly (the patch test, on any non-matching meshes).
 *
 * Integration (segment-based): each slave face is split at the parameters where the rays through
 * the master faces' end points leave it; on every piece a 6-point Gauss rule, the master face hit
 * nearest to the slave point chosen where several are (a curved master surface seen from both
 * sides). Exact for straight faces; on curved faces to the rule's accuracy.
 *
 * Pairs, candidates, normals, penalty stiffnesses and the touching tolerance are node-to-segment
 * contact's (NodeToSegmentContact, built inside), whose projection remains where the mortar row is
 * not defined: a slave node whose dual area D_j is below 1/10 of its lumped area (the vertex on
 * the axis of an axisymmetric model, whose D_j vanishes), whose faces have less than half of D_j
 * over the master surface (the master surface ends under them; above half, the weights are
 * normalized by the covered part), or whose integrals are not finite (a collapsed face). A mortar
 * pair's slave position is the node's own (not node-to-segment's, which may have been moved onto
 * its projected point), moved along the normal by the mortar reference gap if that is within the
 * touching tolerance. Within a time step the pair's normal is held at u_n as in node-to-segment
 * contact; the weights follow the first Newton iterates (update_master_points()), their change
 * with u left out of the rows.
 *
 * Only 2D meshes of Q2 elements.
 */
template <int dim>
class MortarContact : public ContactGeometry<dim>
{
public:
  /**
   * The pairs of NodeToSegmentContact(slave_surface, master_surface, penalty_stiffness_per_area,
   * search_radius, touching_tolerance) with mortar weights at the reference configuration, the
   * surfaces' measure from `kinematics` (which must outlive this). Throws what that constructor
   * throws, and InputError, naming both bodies, for a pair whose mortar reference gap is below
   * -`touching_tolerance` (overlap).
   */
  MortarContact(const ContactSurface<dim>& slave_surface,
                const ContactSurface<dim>& master_surface,
                const Kinematics<dim>& kinematics,
                double penalty_stiffness_per_area,
                double search_radius,
                double touching_tolerance);

  /** The candidate pairs with their reference masters, weights and normals. */
  const std::vector<ContactPair<dim>>& pairs() const override { return candidate_pairs; }

  /**
   * Node-to-segment contact's normals at `displacement`, and the mortar masters and weights there
   * where defined (else the projected point's). Throws SolverFailure as node-to-segment contact.
   */
  void update_pairs(const BorderDisplacement<dim>& displacement,
                    std::vector<ContactPair<dim>>& pairs) const override;

  /**
   * With `move_normals`, the mortar masters and weights at `displacement`, each mortar pair's
   * normal kept; without, the mortar pairs as they are (their weights, like node-to-segment's
   * normals, move over a step's first Newton updates only: the rows leave out the weights' change
   * with u, and with friction an update past that point could not lower the residual further, so
   * that Newton stalled at 40 times its tolerance on the Cattaneo cylinders). A contact-dynamics
   * treatment that holds the normals over the step (ContactDynamics::turns_normals() false:
   * contact-stabilized, velocity-update) never passes `move_normals`, and holds the weights of
   * u_n too: its energy argument holds the constraint gradient. Pairs without mortar rows (at the
   * last update that moved the weights) as NodeToSegmentContact::update_master_points(). The
   * pairs must be those the last update_pairs() set (one ContactConstraints per geometry).
   */
  void update_master_points(const BorderDisplacement<dim>& displacement,
                            std::vector<ContactPair<dim>>& pairs,
                            bool move_normals) const override;
  /** True: the pairs without mortar rows are node-to-segment pairs. */
  bool moves_normals() const override { return true; }

  /**
   * The slave node, the nodes of its own candidate faces and those of the candidate faces of
   * every slave node sharing a face with it.
   */
  std::vector<Node<dim>> coupled_nodes(unsigned int k) const override;

  /** The nodes of both surfaces. */
  std::vector<Node<dim>> surface_nodes() const override;

  /**
   * The mortar method's own traction at the pairs whose mortar row is defined at `displacement`:
   * the coefficient
   * z_j = lambda_j / D_j of slave node j's dual shape function psi_j in the multiplier field
   * sum_j z_j psi_j, whose work on N_j is lambda_j (int psi_j N_k = delta_jk D_j). Local to the
   * node, so that a sliding node's shear traction is mu times its pressure (Coulomb's law holds
   * nodally) and a stuck neighbour does not pull it off: the consistent recovery of
   * ContactSurface::consistent_pressures() couples each node to the nodes of its faces, and put
   * the Cattaneo cylinders' shear 2-5 % of mu p0 off mu times their own pressure next to the stick
   * zone. The pairs without mortar rows (the axis vertex of an axisymmetric surface, whose D_j is
   * zero): that consistent recovery.
   */
  std::vector<double> contact_pressures(const BorderDisplacement<dim>& displacement,
                                        const std::vector<double>& multipliers) const override;

private:
  /** One slave node's integrals: D_j, the covered part of it, and M_jm by master node m. */
  struct MortarRow
  {
    double dual_area    = 0.;
    double covered_area = 0.;
    std::map<unsigned int, double> master_integrals;

    /**
     * Whether the row defines the pair (class documentation): D_j at least 1/10 of the node's
     * lumped area `lumped_area`, at least half of it covered, every integral finite.
     */
    bool defined(double lumped_area) const;
  };

  NodeToSegmentContact<dim> point_projection;
  const Kinematics<dim>& kinematics;
  /** Per slave face: the master faces it is integrated against (its nodes' candidate faces). */
  std::vector<std::vector<unsigned int>> master_faces_of_slave_face;
  std::vector<ContactPair<dim>> candidate_pairs;
  /**
   * Per pair, whether its mortar row was defined at the last configuration the weights were set
   * at (update_pairs(), or update_master_points() with `move_normals`).
   */
  mutable std::vector<bool> mortar_pairs;

  /** The surfaces, node-to-segment contact's (one copy). */
  const ContactSurface<dim>& slave_surface() const { return point_projection.slave(); }
  const ContactSurface<dim>& master_surface() const { return point_projection.master(); }

  /** Every slave node's row, the surfaces' nodes at the given positions. */
  std::vector<MortarRow> mortar_rows(const std::vector<Point<dim>>& slave_positions,
                                     const std::vector<Point<dim>>& master_positions) const;

  /** Adds slave face `face`'s integrals to `rows`. */
  void integrate_face(unsigned int face,
                      const std::vector<Point<dim>>& slave_positions,
                      const std::vector<Tensor<1, dim>>& slave_normals,
                      const std::vector<Point<dim>>& master_positions,
                      std::vector<MortarRow>& rows) const;

  /**
   * Sets the mortar masters and weights of every pair of `pairs` where its row is defined; returns
   * per pair whether it was.
   */
  std::vector<bool> apply_mortar_weights(const std::vector<Point<dim>>& slave_positions,
                                         const std::vector<Point<dim>>& master_positions,
                                         std::vector<ContactPair<dim>>& pairs) const;
};
} // namespace dyncontact
