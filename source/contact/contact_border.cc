#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/sum_over_ranks.h>
#include <dyncontact/contact/contact_border.h>

#include <algorithm>
#include <stdexcept>

namespace dyncontact
{
namespace
{
template <int dim>
bool by_first_dof(const Node<dim>& a, const Node<dim>& b)
{
  return a.dofs[0] < b.dofs[0];
}
} // namespace

template <int dim>
ContactBorder<dim>::ContactBorder(const std::vector<Node<dim>>& nodes) : volume_nodes(nodes)
{
  std::stable_sort(volume_nodes.begin(), volume_nodes.end(), by_first_dof<dim>);
  volume_nodes.erase(std::unique(volume_nodes.begin(),
                                 volume_nodes.end(),
                                 [](const Node<dim>& a, const Node<dim>& b)
                                 { return a.dofs[0] == b.dofs[0]; }),
                     volume_nodes.end());
  border_nodes = volume_nodes;
  for (unsigned int i = 0; i < border_nodes.size(); ++i)
    for (unsigned int d = 0; d < dim; ++d)
      border_nodes[i].dofs[d] = dim * i + d;
}

template <int dim>
unsigned int ContactBorder<dim>::index(const Node<dim>& node) const
{
  const auto found =
      std::lower_bound(volume_nodes.begin(), volume_nodes.end(), node, by_first_dof<dim>);
  if (found == volume_nodes.end() || found->dofs[0] != node.dofs[0])
    throw std::out_of_range("ContactBorder: the node with DoF " + std::to_string(node.dofs[0]) +
                            " is not a contact node");
  return found - volume_nodes.begin();
}

template <int dim>
Vector<double> ContactBorder<dim>::gather(const Vector<double>& volume) const
{
  Vector<double> border(n_dofs());
  for (unsigned int i = 0; i < border.size(); ++i)
    border[i] = volume[volume_dof(i)];
  return border;
}

template <int dim>
Vector<double> ContactBorder<dim>::gather(const DistributedVector& volume) const
{
  return gather_all({&volume})[0];
}

template <int dim>
std::vector<Vector<double>>
ContactBorder<dim>::gather_all(const std::vector<const DistributedVector*>& volumes) const
{
  if (volumes.empty())
    return {};
  // Each entry from its owner, zero elsewhere; the sum over the ranks adds only zeros to it.
  Vector<double> all(volumes.size() * n_dofs());
  for (unsigned int v = 0; v < volumes.size(); ++v)
    for (unsigned int i = 0; i < n_dofs(); ++i)
      if (volumes[v]->in_local_range(volume_dof(i)))
        all[v * n_dofs() + i] = (*volumes[v])(volume_dof(i));
  sum_over_ranks(all, volumes.front()->get_mpi_communicator());
  std::vector<Vector<double>> borders(volumes.size(), Vector<double>(n_dofs()));
  for (unsigned int v = 0; v < volumes.size(); ++v)
    std::copy_n(all.begin() + v * n_dofs(), n_dofs(), borders[v].begin());
  return borders;
}

template <int dim>
std::vector<bool> ContactBorder<dim>::gather(const std::vector<bool>& volume) const
{
  std::vector<bool> border(n_dofs());
  for (unsigned int i = 0; i < border.size(); ++i)
    border[i] = volume[volume_dof(i)];
  return border;
}

template <int dim>
void ContactBorder<dim>::scatter_add(const Vector<double>& border, Vector<double>& volume) const
{
  AssertDimension(border.size(), n_dofs());
  for (unsigned int i = 0; i < border.size(); ++i)
    volume[volume_dof(i)] += border[i];
}

template <int dim>
void ContactBorder<dim>::scatter_add(const Vector<double>& border, DistributedVector& volume) const
{
  AssertDimension(border.size(), n_dofs());
  for (unsigned int i = 0; i < border.size(); ++i)
    if (volume.in_local_range(volume_dof(i)))
      volume(volume_dof(i)) += border[i];
}

template <int dim>
void ContactBorder<dim>::scatter(const Vector<double>& border, DistributedVector& volume) const
{
  AssertDimension(border.size(), n_dofs());
  for (unsigned int i = 0; i < border.size(); ++i)
    if (volume.in_local_range(volume_dof(i)))
      volume(volume_dof(i)) = border[i];
}

DYNCONTACT_INSTANTIATE_CLASS(ContactBorder)
} // namespace dyncontact
