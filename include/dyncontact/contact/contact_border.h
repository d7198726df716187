#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{
/**
 * The contact border: every node a contact pair may couple and every node whose position the
 * contact geometry reads (its surfaces' nodes, ContactGeometry::surface_nodes()): the contact
 * nodes, numbered 0 .. n_nodes() - 1 in the order of their first DoF in the volume (the
 * DoFHandler's numbering), and the vectors over them. A border vector holds dim entries per contact
 * node, entry dim i + d for component d of node i (the border DoFs); a volume vector is a vector
 * over the displacement DoFs, whole on every rank or distributed (each rank its owned DoFs). The
 * contact layer (pairs, constraints, rate treatments, contact fields) works on border vectors only:
 * gather() copies the contact nodes' entries of a volume vector (u, v, a, masses, fixed flags) into
 * one, scatter_add() adds a border vector (the contact forces G^T lambda) into a volume vector,
 * scatter() writes one back (corrected rates). The copies are exact, so a computation on border
 * vectors gives the same bits as on the volume.
 *
 * The border's own nodes (node()) carry the border DoFs in Node::dofs, with the position and body
 * of the volume node (volume_node()) they stand for.
 */
template <int dim>
class ContactBorder
{
public:
  /** An empty border (no contact nodes). */
  ContactBorder() = default;

  /**
   * The border of the volume nodes `nodes` (repeats allowed: each node once, identified by its
   * first DoF; the first of its copies in `nodes` gives its position).
   */
  explicit ContactBorder(const std::vector<Node<dim>>& nodes);

  /** The number of contact nodes. */
  unsigned int n_nodes() const { return volume_nodes.size(); }

  /** The size of a border vector: dim n_nodes(). */
  unsigned int n_dofs() const { return dim * volume_nodes.size(); }

  /** Contact node `i` (< n_nodes()) with its border DoFs dim i + d. */
  const Node<dim>& node(const unsigned int i) const { return border_nodes[i]; }

  /** The volume node contact node `i` stands for (its DoFs in the volume numbering). */
  const Node<dim>& volume_node(const unsigned int i) const { return volume_nodes[i]; }

  /** The volume DoF of border DoF `border_dof` (< n_dofs()). */
  types::global_dof_index volume_dof(const unsigned int border_dof) const
  {
    return volume_nodes[border_dof / dim].dofs[border_dof % dim];
  }

  /**
   * The index (< n_nodes()) of the contact node that stands for the volume node `node`. Throws
   * std::out_of_range if `node` is not a contact node.
   */
  unsigned int index(const Node<dim>& node) const;

  /** The contact nodes' entries of the volume vector `volume` (a border vector). */
  Vector<double> gather(const Vector<double>& volume) const;

  /**
   * The contact nodes' entries of the distributed volume vector `volume` (a border vector, the
   * same on every rank): each rank contributes the entries it owns. Collective.
   */
  Vector<double> gather(const DistributedVector& volume) const;

  /**
   * gather() of each of the distributed volume vectors `volumes` (same layout), in their order,
   * in one sum over the ranks instead of one per vector. Collective.
   */
  std::vector<Vector<double>>
  gather_all(const std::vector<const DistributedVector*>& volumes) const;

  /** The contact nodes' entries of the per-DoF flags `volume` (one per border DoF). */
  std::vector<bool> gather(const std::vector<bool>& volume) const;

  /** Adds the border vector `border` into the contact nodes' entries of `volume`. */
  void scatter_add(const Vector<double>& border, Vector<double>& volume) const;

  /**
   * Adds the border vector `border` (the same on every rank) into the entries of the contact
   * nodes that this rank owns in the distributed `volume`.
   */
  void scatter_add(const Vector<double>& border, DistributedVector& volume) const;

  /**
   * Writes the border vector `border` (the same on every rank) into the entries of the contact
   * nodes that this rank owns in the distributed `volume`.
   */
  void scatter(const Vector<double>& border, DistributedVector& volume) const;

private:
  std::vector<Node<dim>> volume_nodes; ///< sorted by first DoF
  std::vector<Node<dim>> border_nodes; ///< the same nodes with border DoFs
};

/**
 * A displacement of the contact nodes: a border vector (`values`, dim entries per contact node)
 * with the border it lives on, both referenced. What the contact geometry reads instead of a
 * volume vector, so that it needs no more than the contact nodes on any rank.
 */
template <int dim>
struct BorderDisplacement
{
  const ContactBorder<dim>& border;
  const Vector<double>& values;

  /**
   * X + u of the volume node `node` (volume numbering, X its own position): u from the contact
   * node that stands for it. Throws std::out_of_range if it is not a contact node.
   */
  Point<dim> current_position(const Node<dim>& node) const
  {
    AssertDimension(values.size(), border.n_dofs());
    Node<dim> on_border = node; // its own position, the border's DoFs
    on_border.dofs      = border.node(border.index(node)).dofs;
    return dyncontact::current_position(on_border, values);
  }
};
} // namespace dyncontact
