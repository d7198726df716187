#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <cmath>
#include <vector>

namespace dyncontact
{
/** One node of the vector-valued finite element field: its body, position and DoF per component. */
template <int dim>
struct Node
{
  types::material_id body;
  Point<dim> position;
  std::array<types::global_dof_index, dim> dofs;
};

/** Current position X + u of `node` for the displacement vector `displacement`. */
template <int dim>
Point<dim> current_position(const Node<dim>& node, const Vector<double>& displacement)
{
  Point<dim> position = node.position;
  for (unsigned int d = 0; d < dim; ++d)
    position[d] += displacement[node.dofs[d]];
  return position;
}

/**
 * Distance of `point` from the axis of the last coordinate (the components before it): r in an
 * axisymmetric model (x = r, y = z), zero in 1D.
 */
template <int dim>
double distance_from_axis(const Point<dim>& point)
{
  double distance_squared = 0.;
  for (unsigned int d = 0; d + 1 < dim; ++d)
    distance_squared += point[d] * point[d];
  return std::sqrt(distance_squared);
}

/**
 * Every node of the mesh (vertices, and for Q2 also mid-side and centre nodes), found through the
 * element's support points as in step-42, so that it works for any Lagrange degree. Nodes are
 * ordered by body, then by position. It does not own any solution data.
 */
template <int dim>
class NodeIndex
{
public:
  NodeIndex(const DoFHandler<dim>& dof_handler, const Mapping<dim>& mapping);

  const std::vector<Node<dim>>& nodes() const { return all_nodes; }

  /** The node of `body` nearest to `point` (reference configuration). */
  const Node<dim>& closest_node(types::material_id body, const Point<dim>& point) const;

private:
  std::vector<Node<dim>> all_nodes;
};
} // namespace dyncontact
