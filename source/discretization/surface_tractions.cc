#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/sum_over_ranks.h>
#include <dyncontact/discretization/surface_tractions.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace dyncontact
{
template <int dim>
SurfaceTractions<dim>::SurfaceTractions(const DoFHandler<dim>& dof_handler,
                                        const Mapping<dim>& mapping,
                                        const Kinematics<dim>& kinematics,
                                        std::vector<SurfaceTraction<dim>> tractions)
    : dof_handler(dof_handler), mapping(mapping), kinematics(kinematics),
      tractions(std::move(tractions))
{
}

template <int dim>
Vector<double> SurfaceTractions<dim>::force(const double time) const
{
  Vector<double> force(dof_handler.n_dofs());
  if (tractions.empty())
    return force;
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const QGauss<dim - 1> quadrature(fe.degree + 2);
  FEFaceValues<dim> fe_face_values(
      mapping, fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
  std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned() || !cell->at_boundary())
      continue;
    cell->get_dof_indices(local_dofs);
    for (const unsigned int face : cell->face_indices())
      for (const auto& load : tractions)
        if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == load.boundary_id)
        {
          load.traction->set_time(time);
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
  sum_over_ranks(force, dof_handler.get_triangulation().get_communicator());
  return force;
}

DYNCONTACT_INSTANTIATE_CLASS(SurfaceTractions)
} // namespace dyncontact
