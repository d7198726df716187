#include <dyncontact/base/dimensions.h>
#include <dyncontact/simulation/body_discretization.h>
#include <dyncontact/simulation/problem_fingerprint.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>

namespace dyncontact
{
template <int dim>
BodyDiscretization<dim>::BodyDiscretization(ProblemModel<dim>& model)
    : triangulation(MPI_COMM_WORLD), fe(FE_Q<dim>(model.element_degree()), dim),
      mapping(model.element_degree())
{
  model.create_triangulation(triangulation);
  mapping.initialize(MappingQ<dim>(model.element_degree()), triangulation);
  dof_handler.reinit(triangulation);
  dof_handler.distribute_dofs(fe);
  nodes      = std::make_unique<NodeIndex<dim>>(dof_handler, mapping);
  kinematics = model.create_kinematics();
  is_fixed_dof.assign(dof_handler.n_dofs(), false);
  for (const auto dof : model.fixed_dofs(*nodes))
  {
    constraints.add_line(dof);
    is_fixed_dof[dof] = true;
  }
  constraints.close();
  bodies = std::make_unique<ElasticBodies<dim>>(
      dof_handler, mapping, *kinematics, model.body_materials(), &constraints);
  loads = std::make_unique<SurfaceTractions<dim>>(
      dof_handler, mapping, *kinematics, model.surface_tractions());
  highest_frequency = bodies->highest_frequency_bound(is_fixed_dof);
}

template <int dim>
std::string BodyDiscretization<dim>::node_checksum() const
{
  std::vector<double> coordinates;
  for (const auto& node : nodes->nodes())
    for (unsigned int d = 0; d < dim; ++d)
      coordinates.push_back(node.position[d]);
  return checksum(coordinates);
}

DYNCONTACT_INSTANTIATE_CLASS(BodyDiscretization)
} // namespace dyncontact
