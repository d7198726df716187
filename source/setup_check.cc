#include <dyncontact/axisymmetric_mesh_model.h>
#include <dyncontact/bar_model.h>
#include <dyncontact/output_directory.h>
#include <dyncontact/setup_check.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

namespace dyncontact
{
namespace
{
/** Builds what Simulation::run() builds from `model` before its first step, and discards it. */
template <int dim>
void set_up(ProblemModel<dim>& model)
{
  Triangulation<dim> triangulation;
  model.create_triangulation(triangulation);
  const unsigned int degree = model.element_degree();
  const MappingQ<dim> mapping(degree);
  const FESystem<dim> fe(FE_Q<dim>(degree), dim);
  DoFHandler<dim> dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  const NodeIndex<dim> nodes(dof_handler, mapping);
  const std::unique_ptr<Kinematics<dim>> kinematics = model.create_kinematics();
  if (!model.create_surface_contact(dof_handler, *kinematics, nodes))
    model.contact_pairs(nodes);
  model.fixed_dofs(nodes);
  model.monitor_nodes(nodes);
  for (const Node<dim>& node : nodes.nodes())
    model.initial_velocity(node.body, node.position);
}
} // namespace

void check_run_setup(const RunParameters& parameters)
{
  check_output_directory(parameters.output.directory);
  if (parameters.problem.geometry == GeometryKind::bars)
  {
    BarModel model(parameters.geometry, parameters.contact);
    set_up<1>(model);
    if (parameters.output.write_exact_solution)
      model.exact_solution(parameters.time.n_steps() * parameters.time.time_step);
  }
  else
  {
    AxisymmetricMeshModel model(parameters.mesh, parameters.bodies, parameters.contact);
    set_up<2>(model);
  }
}
} // namespace dyncontact
