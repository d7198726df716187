#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/join_over_ranks.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>

#include <algorithm>
#include <limits>
#include <map>

namespace dyncontact
{
template <int dim>
NodeIndex<dim>::NodeIndex(const DoFHandler<dim>& dof_handler, const Mapping<dim>& mapping)
    : communicator(dof_handler.get_triangulation().get_communicator()),
      locally_owned_dofs(dof_handler.locally_owned_dofs())
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  Assert(fe.n_components() == dim, ExcMessage("NodeIndex expects a dim-component vector field."));
  const std::vector<Point<dim>>& unit_points = fe.get_unit_support_points();

  // Key a node by the DoF of its first component; collect the other components' DoFs into it.
  std::map<types::global_dof_index, Node<dim>> nodes_by_first_dof;
  std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (cell->is_artificial())
      continue;
    cell->get_dof_indices(local_dofs);
    // Local DoFs of one support point are adjacent per base node: group them by the base index.
    std::map<unsigned int, std::array<types::global_dof_index, dim>> dofs_of_base_node;
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
    {
      const auto [component, base_index]       = fe.system_to_component_index(i);
      dofs_of_base_node[base_index][component] = local_dofs[i];
    }
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
    {
      const auto [component, base_index] = fe.system_to_component_index(i);
      if (component != 0 || nodes_by_first_dof.count(local_dofs[i]) > 0)
        continue;
      Node<dim> node;
      node.body     = cell->material_id();
      node.position = mapping.transform_unit_to_real_cell(cell, unit_points[i]);
      node.dofs     = dofs_of_base_node[base_index];
      nodes_by_first_dof.emplace(local_dofs[i], node);
    }
  }
  for (const auto& entry : nodes_by_first_dof)
    local_nodes.push_back(entry.second);
  std::sort(local_nodes.begin(), local_nodes.end(), precedes<dim>);
  for (unsigned int i = 0; i < local_nodes.size(); ++i)
    by_first_dof.emplace_back(local_nodes[i].dofs[0], i);
  std::sort(by_first_dof.begin(), by_first_dof.end());
}

template <int dim>
const Node<dim>& NodeIndex<dim>::node_of_first_dof(const types::global_dof_index first_dof) const
{
  const auto found =
      std::lower_bound(by_first_dof.begin(), by_first_dof.end(), std::make_pair(first_dof, 0u));
  Assert(found != by_first_dof.end() && found->first == first_dof,
         ExcMessage("DoF " + std::to_string(first_dof) + " is no node's first DoF on this rank"));
  return local_nodes[found->second];
}

template <int dim>
std::vector<Node<dim>> NodeIndex<dim>::gather_on_root() const
{
  std::vector<Node<dim>> owned;
  for (const Node<dim>& node : local_nodes)
    if (locally_owned_dofs.is_element(node.dofs[0]))
      owned.push_back(node);
  std::vector<Node<dim>> all = join_on_root(communicator, owned);
  std::sort(all.begin(), all.end(), precedes<dim>);
  return all;
}

template <int dim>
Node<dim> NodeIndex<dim>::closest_node(const types::material_id body, const Point<dim>& point) const
{
  const Node<dim>* closest = nullptr;
  double distance          = std::numeric_limits<double>::max();
  for (const auto& node : local_nodes)
    if (node.body == body && node.position.distance(point) < distance)
    {
      distance = node.position.distance(point);
      closest  = &node;
    }
  // The lowest rank of those at the smallest distance sends its node.
  struct
  {
    double distance;
    int rank;
  } mine{distance, static_cast<int>(Utilities::MPI::this_mpi_process(communicator))}, nearest;
  MPI_Allreduce(&mine, &nearest, 1, MPI_DOUBLE_INT, MPI_MINLOC, communicator);
  AssertThrow(nearest.distance < std::numeric_limits<double>::max(),
              ExcMessage("No node of body " + std::to_string(body) + "."));
  return Utilities::MPI::broadcast(
      communicator, closest != nullptr ? *closest : Node<dim>{}, nearest.rank);
}

DYNCONTACT_INSTANTIATE_CLASS(NodeIndex)
} // namespace dyncontact
