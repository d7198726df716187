#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{
/** n . f at `node` of a nodal vector field `field` (indexed by the node's DoFs). */
template <int dim>
double
normal_component(const Node<dim>& node, const Tensor<1, dim>& normal, const Vector<double>& field)
{
  double component = 0.;
  for (unsigned int d = 0; d < dim; ++d)
    component += normal[d] * field[node.dofs[d]];
  return component;
}

/**
 * A node of the master (mortar) side of a pair with its weight: the master surface's shape
 * function at the slave node's projection (node-to-segment), or 1 for the one facing node
 * (node-to-node). A pair's weights sum to 1.
 */
template <int dim>
struct MasterNode
{
  Node<dim> node;
  double weight;
};

/**
 * One candidate contact constraint: a slave (non-mortar) node of body A against a point of body
 * B, given by master nodes and their weights (node-to-node: one node of weight 1; node-to-segment:
 * the nodes of the master face with its shape functions at the projection), or against a fixed
 * rigid wall (no master nodes). The gap is g = n . (x_B - x_A) with x_B = sum_i w_i x_i, current
 * positions x = X + u and the unit normal n from A toward B: fixed for the bars and the wall,
 * updated to the current configuration by the contact geometry for pairs between curved surfaces.
 * Compression is a positive multiplier.
 *
 * Every linear form of the pair (gap, constraint row, contact force, rate jump) is
 * sum_j c_j n . f_j over its nodes with the coefficients c_j = -1 for the slave node and w_i for
 * the master nodes (for_each_node()); sum_j c_j = 0 (for a pair between bodies), so the pair's
 * forces balance and a rigid translation leaves its gap unchanged.
 *
 * Its nodes' DoFs index the vectors it is evaluated at: the volume vectors where a contact
 * geometry builds it, the border vectors (ContactBorder) in the contact layer, which holds its
 * pairs on the border (ContactConstraints::candidate_pairs()).
 */
template <int dim>
struct ContactPair
{
  Node<dim> slave;
  std::vector<MasterNode<dim>> masters; ///< empty: a rigid wall through `wall_point`
  Point<dim> wall_point;
  Tensor<1, dim> normal;
  double penalty_stiffness; ///< used by the penalty formulation only
  /**
   * Node-to-segment pairs only: the unit averaged normal of the two surfaces at the projection
   * (NodeToSegmentContact), along which the master point follows the slave node within a step;
   * `normal` is the master face's normal there.
   */
  Tensor<1, dim> ray_direction;

  bool against_wall() const { return masters.empty(); }

  /** Calls f(node, c) for the slave node (c = -1) and then each master node (c = its weight). */
  template <typename Function>
  void for_each_node(const Function& f) const
  {
    f(slave, -1.);
    for (const MasterNode<dim>& master : masters)
      f(master.node, master.weight);
  }

  /** [[f]] = n . (f_B - f_A) of a nodal vector field; a wall is at rest (f_B = 0). */
  double normal_jump(const Vector<double>& field) const
  {
    return master_side(field, 0.) - normal_component(slave, normal, field);
  }

  /**
   * [[f]] . d = sum_j c_j d . f_j over the pair's nodes: the master point's field minus the slave
   * node's along `direction` (a wall at rest).
   */
  double jump_along(const Tensor<1, dim>& direction, const Vector<double>& field) const
  {
    double jump = 0.;
    for_each_node([&](const Node<dim>& node, const double coefficient)
                  { jump += coefficient * normal_component(node, direction, field); });
    return jump;
  }

  /** The gap g = reference_gap() + [[u]] at the displacement `u` (indexed by the nodes' DoFs). */
  double gap(const Vector<double>& u) const
  {
    // Reference gap plus relative displacement, never absolute positions: translating a problem
    // must not cost digits.
    return master_side(u, reference_gap()) - normal_component(slave, normal, u);
  }

  /**
   * 1 / m_r = sum_j c_j^2 / m_j over the pair's nodes (`lumped_mass` per DoF): the inverse of the
   * mass the pair's normal constraint moves, 1 / m_slave + sum_i w_i^2 / m_i (node-to-node: the
   * reduced mass of the two nodes; a wall: the slave node's own).
   */
  double inverse_effective_mass(const Vector<double>& lumped_mass) const
  {
    double inverse_mass = 0.;
    for_each_node([&](const Node<dim>& node, const double coefficient)
                  { inverse_mass += coefficient * coefficient / lumped_mass[node.dofs[0]]; });
    return inverse_mass;
  }

  /** n . (X_B - X_A), or n . (wall point - X_A): the gap at zero displacement. */
  double reference_gap() const
  {
    Point<dim> point_b = wall_point;
    if (!against_wall())
    {
      point_b = Point<dim>();
      for (const MasterNode<dim>& master : masters)
        point_b += master.weight * master.node.position;
    }
    return normal * (point_b - slave.position);
  }

private:
  /** start + n . f_B, f_B = sum_i w_i f_i (the wall: start). */
  double master_side(const Vector<double>& field, double start) const
  {
    for (const MasterNode<dim>& master : masters)
      start += master.weight * normal_component(master.node, normal, field);
    return start;
  }
};

} // namespace dyncontact
