#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <optional>

namespace dyncontact
{
/** n . f at `node` of a nodal vector field `field` (whole vector over all displacement DoFs). */
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
 * One candidate contact constraint: a node of body A against a node of body B (node-to-node) or
 * against a fixed rigid wall. The gap is g = n . (x_B - x_A) with current positions x = X + u and
 * the unit normal n from A toward B: fixed for the bars and the wall, updated to the current
 * configuration by NodeToNodeContact for pairs between curved surfaces. Compression is a positive
 * multiplier.
 */
template <int dim>
struct ContactPair
{
  Node<dim> node_a;
  std::optional<Node<dim>> node_b; ///< empty: a rigid wall through `wall_point`
  Point<dim> wall_point;
  Tensor<1, dim> normal;
  double penalty_stiffness; ///< used by the penalty formulation only

  bool against_wall() const { return !node_b.has_value(); }

  /** [[f]] = n . (f_B - f_A) of a nodal vector field; a wall is at rest (f_B = 0). */
  double normal_jump(const Vector<double>& field) const
  {
    const double side_b = against_wall() ? 0. : normal_component(*node_b, normal, field);
    return side_b - normal_component(node_a, normal, field);
  }

  /** n . (X_B - X_A), or n . (wall point - X_A): the gap at zero displacement. */
  double reference_gap() const
  {
    return normal * ((against_wall() ? wall_point : node_b->position) - node_a.position);
  }
};

} // namespace dyncontact
