#include <dyncontact/base/dimensions.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/fe/fe.h>

#include <algorithm>
#include <limits>
#include <map>

namespace dyncontact
{
template <int dim>
NodeIndex<dim>::NodeIndex(const DoFHandler<dim>& dof_handler, const Mapping<dim>& mapping)
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  Assert(fe.n_components() == dim, ExcMessage("NodeIndex expects a dim-component vector field."));
  const std::vector<Point<dim>>& unit_points = fe.get_unit_support_points();

  // Key a node by the DoF of its first component; collect the other components' DoFs into it.
  std::map<types::global_dof_index, Node<dim>> nodes_by_first_dof;
  std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
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
    all_nodes.push_back(entry.second);
  std::sort(all_nodes.begin(),
            all_nodes.end(),
            [](const Node<dim>& a, const Node<dim>& b)
            {
              if (a.body != b.body)
                return a.body < b.body;
              for (unsigned int d = 0; d < dim; ++d)
                if (a.position[d] != b.position[d])
                  return a.position[d] < b.position[d];
              return false;
            });
}

template <int dim>
const Node<dim>& NodeIndex<dim>::closest_node(const types::material_id body,
                                              const Point<dim>& point) const
{
  const Node<dim>* closest = nullptr;
  double distance          = std::numeric_limits<double>::max();
  for (const auto& node : all_nodes)
    if (node.body == body && node.position.distance(point) < distance)
    {
      distance = node.position.distance(point);
      closest  = &node;
    }
  AssertThrow(closest != nullptr, ExcMessage("No node of body " + std::to_string(body) + "."));
  return *closest;
}

DYNCONTACT_INSTANTIATE_CLASS(NodeIndex)
} // namespace dyncontact
