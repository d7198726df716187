#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_border.h>
#include <dyncontact/contact/contact_pair.h>

#include <sstream>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * The geometry of contact between two deformable surfaces: which candidate pairs exist, where each
 * slave node's contact point on the master surface is and along which normal, and the contact
 * pressure a set of nodal multipliers represents. The family: NodeToNodeContact (matching
 * meshes, one facing node per slave node) and node-to-segment contact (the slave node projected
 * onto a master face). ContactConstraints enforces the pairs; it calls update_pairs() once per
 * converged configuration, so that within a time step the rays (node-to-node: the normals) are
 * those of u_n, and update_master_points() at every Newton iterate, so that a master point that
 * is not a material point (node-to-segment) and its face's normal are those of the configuration
 * the step ends in (doc/method.md, section 4.1).
 *
 * The number of pairs and each pair's slave node never change; the master nodes, weights and
 * normal may (update_pairs()), within the nodes coupled_nodes() declares, from which the contact
 * border and the sparsity pattern of the saddle-point system are built once. Its pairs' nodes
 * carry the volume (DoFHandler) numbering. It reads the configuration from the displacement of
 * the contact nodes only (BorderDisplacement over a border that holds surface_nodes()), never
 * from a volume vector.
 */
template <int dim>
class ContactGeometry
{
public:
  virtual ~ContactGeometry() = default;

  /** The candidate pairs in the reference configuration (penalty stiffness included). */
  virtual const std::vector<ContactPair<dim>>& pairs() const = 0;

  /**
   * Moves every pair of `pairs` (as given by pairs(), same order) to the configuration
   * `displacement` (of a border holding surface_nodes()): its normal and, where the
   * geometry allows it, its master nodes and weights. Slave nodes, wall points and penalty
   * stiffnesses are left as they are.
   */
  virtual void update_pairs(const BorderDisplacement<dim>& displacement,
                            std::vector<ContactPair<dim>>& pairs) const = 0;

  /**
   * Moves the master point (master nodes and weights) of every pair of `pairs` (as given by
   * pairs(), same order) to the configuration `displacement`: the point of the master surface on
   * the pair's ray through the slave node, held over the step. With `move_normals` the pair's
   * normal turns to the master face's there too (node-to-segment); else it is kept. Called at
   * every Newton iterate of a step. This default leaves the pairs as they are: right where the
   * master point is a material point (node-to-node: the facing node) or fixed (a rigid plane).
   */
  virtual void update_master_points(const BorderDisplacement<dim>& /*displacement*/,
                                    std::vector<ContactPair<dim>>& /*pairs*/,
                                    bool /*move_normals*/) const
  {
  }

  /** Whether update_master_points() with `move_normals` may turn a pair's normal. */
  virtual bool moves_normals() const { return false; }

  /**
   * Every node the constraint row of pair `k` may couple to over the run (the slave node and
   * every master node update_pairs() may choose; repeats allowed), in the volume numbering: the
   * pair's part of the contact border (ContactBorder).
   */
  virtual std::vector<Node<dim>> coupled_nodes(unsigned int k) const = 0;

  /**
   * Every node whose position the geometry reads (the nodes of its surfaces; repeats allowed), in
   * the volume numbering: with the coupled nodes, the contact border.
   */
  virtual std::vector<Node<dim>> surface_nodes() const = 0;

  /**
   * The contact pressure [force/area] at every pair's slave node, consistent with the nodal
   * forces `multipliers` (one per pair, zero for inactive pairs) at `displacement`: exactly 0 for
   * an open pair.
   */
  virtual std::vector<double> contact_pressures(const BorderDisplacement<dim>& displacement,
                                                const std::vector<double>& multipliers) const = 0;
};

/**
 * The InputError a contact geometry's constructor throws for a pair whose reference gap is below
 * -`touching_tolerance` [length] (the bodies overlap at t = 0): it names both bodies (1-based), or
 * the rigid plane, where the slave node is and how deep it lies inside the other side.
 */
template <int dim>
InputError overlap_at_start(const ContactPair<dim>& pair, const double touching_tolerance)
{
  std::ostringstream where;
  where << pair.slave.position;
  const std::string body_a = "body " + std::to_string(pair.slave.body + 1);
  const std::string other  = pair.against_wall()
                                 ? std::string("the rigid plane")
                                 : "body " + std::to_string(pair.masters[0].node.body + 1);
  return InputError(body_a + " and " + other + " overlap at t = 0: the node " + where.str() +
                    " of " + body_a + " lies " + format_number(-pair.reference_gap()) +
                    (pair.against_wall() ? " behind " : " inside ") + other +
                    " (bodies may touch, to " + format_number(touching_tolerance) +
                    ", but not overlap).");
}
} // namespace dyncontact
