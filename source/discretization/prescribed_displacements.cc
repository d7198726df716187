#include <dyncontact/base/dimensions.h>
#include <dyncontact/discretization/prescribed_displacements.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace dyncontact
{
template <int dim>
PrescribedDisplacements<dim>::PrescribedDisplacements(const DoFHandler<dim>& dof_handler,
                                                      const NodeIndex<dim>& nodes,
                                                      const std::vector<FixedBoundary>& boundaries)
{
  const IndexSet& owned = dof_handler.locally_owned_dofs();
  std::set<types::global_dof_index> taken;
  for (const FixedBoundary& boundary : boundaries)
  {
    ComponentMask mask(dim, false);
    for (const unsigned int component : boundary.components)
      mask.set(component, true);
    const IndexSet dofs = DoFTools::extract_boundary_dofs(dof_handler, mask, {boundary.boundary});
    if (boundary.displacement.expression.empty())
    {
      taken.insert(dofs.begin(), dofs.end());
      continue;
    }
    functions.push_back(boundary.displacement.template create<dim>(dim));
    double extent           = 0.;
    const std::size_t first = entries.size();
    for (const Node<dim>& node : nodes.nodes())
      for (const unsigned int d : boundary.components)
        if (dofs.is_element(node.dofs[d]) && taken.insert(node.dofs[d]).second &&
            owned.is_element(node.dofs[d]))
        {
          entries.push_back(
              {node.dofs[d], d, node.position, static_cast<unsigned int>(functions.size() - 1)});
          extent = std::max(extent, node.position.norm());
        }
    for (std::size_t k = first; k < entries.size(); ++k)
      if (std::abs(value(entries[k], 0.)) > 1e-12 * extent)
        throw InputError(boundary.section + "/Displacement/Function expression = '" +
                         boundary.displacement.expression + "' is " +
                         format_number(value(entries[k], 0.)) + " in component " +
                         "xyz"[entries[k].component] +
                         " at t = 0: the bodies start undeformed, so it must be 0 at t = 0 "
                         "(e.g. d * t / T, or d * (1 - cos(pi * t / T)) / 2 for a smooth start).");
  }
}

template <int dim>
double PrescribedDisplacements<dim>::value(const Entry& entry, const double t) const
{
  Functions::ParsedFunction<dim>& g = *functions[entry.function];
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
    const double before = value(entry, t - h), now = value(entry, t), after = value(entry, t + h);
    v[entry.dof] = (after - before) / (2. * h);
    a[entry.dof] = (after - 2. * now + before) / (h * h);
  }
}

DYNCONTACT_INSTANTIATE_CLASS(PrescribedDisplacements)
} // namespace dyncontact
