#include <dyncontact/base/dimensions.h>
#include <dyncontact/discretization/prescribed_displacements.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace dyncontact
{
template <int dim>
PrescribedDisplacements<dim>::PrescribedDisplacements(
    const DoFHandler<dim>& dof_handler,
    const NodeIndex<dim>& nodes,
    const std::vector<FixedBoundary>& boundaries,
    const std::vector<IndexSet>& held,
    const std::vector<types::global_dof_index>& zero_dofs)
    : communicator(dof_handler.get_communicator())
{
  AssertDimension(held.size(), boundaries.size());
  const IndexSet& owned = dof_handler.locally_owned_dofs();
  std::set<types::global_dof_index> taken(zero_dofs.begin(), zero_dofs.end());
  for (unsigned int b = 0; b < boundaries.size(); ++b)
    if (boundaries[b].displacement.expression.empty())
      taken.insert(held[b].begin(), held[b].end());
  // The first boundary (lowest index) whose g(X, 0) is not zero on any rank.
  unsigned int nonzero_start = std::numeric_limits<unsigned int>::max();
  for (unsigned int b = 0; b < boundaries.size(); ++b)
  {
    functions.push_back(nullptr);
    if (boundaries[b].displacement.expression.empty())
      continue;
    functions.back()        = boundaries[b].displacement.template create<dim>(dim);
    const IndexSet& dofs    = held[b];
    const std::size_t first = entries.size();
    double extent           = 0.;
    for (const Node<dim>& node : nodes.nodes())
      for (const unsigned int d : boundaries[b].components)
        if (dofs.is_element(node.dofs[d]) && taken.insert(node.dofs[d]).second &&
            owned.is_element(node.dofs[d]))
        {
          entries.push_back({node.dofs[d], d, node.position, b});
          extent = std::max(extent, node.position.norm());
        }
    extent = Utilities::MPI::max(extent, communicator);
    for (std::size_t k = first; k < entries.size(); ++k)
      if (std::abs(value(entries[k], 0.)) > 1e-12 * extent)
        nonzero_start = std::min(nonzero_start, b);
  }
  const unsigned int first = Utilities::MPI::min(nonzero_start, communicator);
  if (first != std::numeric_limits<unsigned int>::max())
    throw InputError(boundaries[first].section + "/Displacement/Function expression = '" +
                     boundaries[first].displacement.expression +
                     "' is not 0 at t = 0 on the boundary: the bodies start undeformed, so it must "
                     "be 0 at t = 0 (e.g. d * (1 - cos(pi * t / T)) / 2, a ramp from rest).");
}

template <int dim>
std::vector<bool> PrescribedDisplacements<dim>::flags(const types::global_dof_index n_dofs) const
{
  std::vector<types::global_dof_index> own;
  for (const Entry& entry : entries)
    own.push_back(entry.dof);
  std::vector<bool> prescribed(n_dofs, false);
  for (const auto& part : Utilities::MPI::all_gather(communicator, own))
    for (const auto dof : part)
      prescribed[dof] = true;
  return prescribed;
}

template <int dim>
double PrescribedDisplacements<dim>::value(const Entry& entry, const double t) const
{
  Functions::ParsedFunction<dim>& g = *functions[entry.boundary];
  g.set_time(t);
  return g.value(entry.position, entry.component);
}

template <int dim>
void PrescribedDisplacements<dim>::set_displacement(const double t, DistributedVector& u) const
{
  for (const Entry& entry : entries)
    u[entry.dof] = value(entry, t);
}

template <int dim>
void PrescribedDisplacements<dim>::set_rates(const double t,
                                             const double h,
                                             DistributedVector& v,
                                             DistributedVector& a) const
{
  for (const Entry& entry : entries)
  {
    const double g0 = value(entry, t), g1 = value(entry, t + h), g2 = value(entry, t + 2. * h);
    v[entry.dof] = (-3. * g0 + 4. * g1 - g2) / (2. * h);
    a[entry.dof] = (g0 - 2. * g1 + g2) / (h * h);
  }
}

DYNCONTACT_INSTANTIATE_CLASS(PrescribedDisplacements)
} // namespace dyncontact
