#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <optional>

namespace dyncontact
{
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

  /** n . (X_B - X_A), or n . (wall point - X_A): the gap at zero displacement. */
  double reference_gap() const
  {
    return normal * ((against_wall() ? wall_point : node_b->position) - node_a.position);
  }
};

} // namespace dyncontact
