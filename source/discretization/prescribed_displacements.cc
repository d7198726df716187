#include <dyncontact/base/dimensions.h>
#include <dyncontact/discretization/prescribed_displacements.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace dyncontact
{
template <int dim>
IndexSet held_dofs(const DoFHandler<dim>& dof_handler, const FixedBoundary& boundary)
{
  ComponentMask mask(dim, false);
  for (const unsigned int component : boundary.components)
    mask.set(component, true);
  return DoFTools::extract_boundary_dofs(dof_handler, mask, {boundary.boundary});
}

template <int dim>
PrescribedDisplacements<dim>::PrescribedDisplacements(
    const DoFHandler<dim>& dof_handler,
    const NodeIndex<dim>& nodes,
    const std::vector<FixedBoundary>& boundaries,
    const std::vector<types::global_dof_index>& zero_dofs)
    : communicator(dof_handler.get_communicator()), boundaries(boundaries)
{
  const IndexSet& owned = dof_handler.locally_owned_dofs();
  std::set<types::global_dof_index> taken(zero_dofs.begin(), zero_dofs.end());
  for (const FixedBoundary& boundary : boundaries)
    if (boundary.displacement.expression.empty())
    {
      const IndexSet dofs = held_dofs(dof_handler, boundary);
      taken.insert(dofs.begin(), dofs.end());
    }
  // The first boundary (lowest index) whose g(X, 0) is not zero on any rank.
  unsigned int nonzero_start = std::numeric_limits<unsigned int>::max();
  for (unsigned int b = 0; b < boundaries.size(); ++b)
  {
    functions.push_back(nullptr);
    if (boundaries[b].displacement.expression.empty())
      continue;
    functions.back()        = boundaries[b].displacement.template create<dim>(dim);
    const IndexSet dofs     = held_dofs(dof_handler, boundaries[b]);
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
  throw_on_every_rank(
      nonzero_start,
      [this](const unsigned int b)
      {
        return this->boundaries[b].section + "/Displacement/Function expression = '" +
               this->boundaries[b].displacement.expression +
               "' is not 0 at t = 0 on the boundary: the bodies start undeformed, so it must be 0 "
               "at t = 0 (e.g. d * (1 - cos(pi * t / T)) / 2, a ramp from rest).";
      });
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
template <class Message>
void PrescribedDisplacements<dim>::throw_on_every_rank(const unsigned int flagged,
                                                       const Message& message) const
{
  const unsigned int first = Utilities::MPI::min(flagged, communicator);
  if (first != std::numeric_limits<unsigned int>::max())
    throw InputError(message(first));
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
#define DYNCONTACT_INSTANTIATE_HELD_DOFS(dim)                                                      \
  template IndexSet held_dofs<dim>(const DoFHandler<dim>&, const FixedBoundary&);
DYNCONTACT_FOR_EACH_DIMENSION(DYNCONTACT_INSTANTIATE_HELD_DOFS)
} // namespace dyncontact
