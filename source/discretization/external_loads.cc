#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/sum_over_ranks.h>
#include <dyncontact/discretization/external_loads.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace dyncontact
{
template <int dim>
ExternalLoads<dim>::ExternalLoads(const DoFHandler<dim>& dof_handler,
                                  const Mapping<dim>& mapping,
                                  const Kinematics<dim>& kinematics,
                                  std::vector<SurfaceTraction<dim>> tractions,
                                  std::vector<BodyForce<dim>> body_forces)
    : dof_handler(dof_handler), mapping(mapping), kinematics(kinematics),
      tractions(std::move(tractions)), body_forces(std::move(body_forces))
{
  if (this->body_forces.empty())
    return;
  // The position of every owned DoF of a body with a body force, from the mapping at the
  // element's support points.
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const Quadrature<dim> support_points(fe.get_unit_support_points());
  FEValues<dim> fe_values(mapping, fe, support_points, update_quadrature_points);
  const IndexSet& owned = dof_handler.locally_owned_dofs();
  std::vector<bool> listed(owned.n_elements(), false);
  std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned())
      continue;
    for (unsigned int load = 0; load < this->body_forces.size(); ++load)
    {
      if (this->body_forces[load].body != cell->material_id())
        continue;
      cell->get_dof_indices(local_dofs);
      fe_values.reinit(cell);
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        if (owned.is_element(local_dofs[i]) && !listed[owned.index_within_set(local_dofs[i])])
        {
          listed[owned.index_within_set(local_dofs[i])] = true;
          loaded_dofs.push_back({local_dofs[i],
                                 fe.system_to_component_index(i).first,
                                 load,
                                 fe_values.quadrature_point(i)});
        }
    }
  }
}

template <int dim>
Vector<double> ExternalLoads<dim>::force(const double time, const Vector<double>& lumped_mass) const
{
  AssertDimension(lumped_mass.size(), dof_handler.n_dofs());
  Vector<double> force(dof_handler.n_dofs());
  if (tractions.empty() && body_forces.empty())
    return force;
  add_tractions(time, force);
  for (const auto& load : body_forces)
    load.force->set_time(time);
  for (const LoadedDof& entry : loaded_dofs)
  {
    const BodyForce<dim>& load = body_forces[entry.load];
    force[entry.dof] +=
        lumped_mass[entry.dof] * load.force->value(entry.position, entry.component) / load.density;
  }
  sum_over_ranks(force, dof_handler.get_triangulation().get_communicator());
  return force;
}

template <int dim>
void ExternalLoads<dim>::add_tractions(const double time, Vector<double>& force) const
{
  if (tractions.empty())
    return;
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const QGauss<dim - 1> quadrature(fe.degree + 2);
  FEFaceValues<dim> fe_face_values(
      mapping, fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
  std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());
  for (const auto& load : tractions)
    load.traction->set_time(time);
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned() || !cell->at_boundary())
      continue;
    cell->get_dof_indices(local_dofs);
    for (const unsigned int face : cell->face_indices())
      for (const auto& load : tractions)
        if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == load.boundary_id)
        {
          fe_face_values.reinit(cell, face);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const Point<dim>& X = fe_face_values.quadrature_point(q);
            const double area =
                fe_face_values.JxW(q) * kinematics.measure_factor(X, cell->material_id());
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const unsigned int component = fe.system_to_component_index(i).first;
              force[local_dofs[i]] +=
                  load.traction->value(X, component) * fe_face_values.shape_value(i, q) * area;
            }
          }
        }
  }
}

DYNCONTACT_INSTANTIATE_CLASS(ExternalLoads)
} // namespace dyncontact
