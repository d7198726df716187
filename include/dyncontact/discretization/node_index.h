#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
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

  /** Sends a node between ranks (Utilities::MPI's gather and broadcast). */
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& body;
    archive& position;
    for (types::global_dof_index& dof : dofs)
      archive& dof;
  }
};

/** The order of NodeIndex: by body, then by position (lexicographic in the coordinates). */
template <int dim>
bool precedes(const Node<dim>& a, const Node<dim>& b)
{
  if (a.body != b.body)
    return a.body < b.body;
  for (unsigned int d = 0; d < dim; ++d)
    if (a.position[d] != b.position[d])
      return a.position[d] < b.position[d];
  return false;
}

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
 * The nodes of this rank's cells, locally owned and ghost (vertices, and for Q2 also mid-side and
 * centre nodes), found through the element's support points as in step-42, so that it works for
 * any Lagrange degree; on a shared triangulation (the bars) every node of the mesh. Nodes are
 * ordered by body, then by position (precedes()). A node's position is computed on the first of its
 * cells met, so on a distributed mesh two ranks may differ in its last bits. The queries over the
 * whole mesh (gather_on_root(), closest_node()) are collective. It owns no solution data.
 */
template <int dim>
class NodeIndex
{
public:
  NodeIndex(const DoFHandler<dim>& dof_handler, const Mapping<dim>& mapping);

  /** This rank's nodes (see the class), ordered by precedes(). */
  const std::vector<Node<dim>>& nodes() const { return local_nodes; }

  /** The node of nodes() whose first component has DoF `first_dof`; asserts that there is one. */
  const Node<dim>& node_of_first_dof(types::global_dof_index first_dof) const;

  /**
   * Every node of the mesh, ordered by precedes(), on rank 0; empty on the other ranks. Each node
   * comes from the rank that owns its first DoF. Collective.
   */
  std::vector<Node<dim>> gather_on_root() const;

  /**
   * The node of `body` nearest to `point` (reference configuration) over all ranks; of nodes at
   * the same distance the first in precedes() order on the lowest rank. Collective; throws if
   * `body` has no node.
   */
  Node<dim> closest_node(types::material_id body, const Point<dim>& point) const;

private:
  MPI_Comm communicator;
  IndexSet locally_owned_dofs;
  std::vector<Node<dim>> local_nodes;
  /** (first DoF, index in local_nodes), sorted by DoF. */
  std::vector<std::pair<types::global_dof_index, unsigned int>> by_first_dof;
};
} // namespace dyncontact
