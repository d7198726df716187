#include <dyncontact/postprocess/field_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace dyncontact
{
template <int dim>
FieldOutput<dim>::FieldOutput(const DoFHandler<dim>& dof_handler,
                              const Mapping<dim>& mapping,
                              std::string directory)
    : dof_handler(dof_handler), mapping(mapping), directory(std::move(directory))
{
}

template <int dim>
void FieldOutput<dim>::write_fields(const unsigned int step,
                                    const double time,
                                    const Vector<double>& displacement,
                                    const Vector<double>& velocity,
                                    const Vector<double>& acceleration,
                                    const Vector<double>* contact_traction)
{
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
      dim, DataComponentInterpretation::component_is_part_of_vector);
  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler);
  data_out.add_data_vector(displacement,
                           std::vector<std::string>(dim, "displacement"),
                           DataOut<dim>::type_dof_data,
                           vector_field);
  data_out.add_data_vector(velocity,
                           std::vector<std::string>(dim, "velocity"),
                           DataOut<dim>::type_dof_data,
                           vector_field);
  data_out.add_data_vector(acceleration,
                           std::vector<std::string>(dim, "acceleration"),
                           DataOut<dim>::type_dof_data,
                           vector_field);
  if (contact_traction != nullptr)
    data_out.add_data_vector(*contact_traction,
                             std::vector<std::string>(dim, "contact_traction"),
                             DataOut<dim>::type_dof_data,
                             vector_field);
  Vector<float> body(dof_handler.get_triangulation().n_active_cells());
  for (const auto& cell : dof_handler.active_cell_iterators())
    body[cell->active_cell_index()] = cell->material_id() + 1;
  data_out.add_data_vector(body, "body");
  data_out.build_patches(mapping, dof_handler.get_fe().degree);

  const MPI_Comm communicator = dof_handler.get_triangulation().get_communicator();
  const std::string record =
      data_out.write_vtu_with_pvtu_record(directory + "/", "solution", step, communicator, 5);
  if (Utilities::MPI::this_mpi_process(communicator) == 0)
  {
    pvd_records.emplace_back(time, record);
    std::ofstream pvd(directory + "/solution.pvd");
    DataOutBase::write_pvd_record(pvd, pvd_records);
  }
}

template <int dim>
void FieldOutput<dim>::write_profile(const double time,
                                     const std::vector<Node<dim>>& nodes,
                                     const Vector<double>& displacement,
                                     const Vector<double>& velocity,
                                     const Vector<double>& acceleration) const
{
  std::ostringstream name;
  name << directory << "/profile_t" << time << ".csv";
  std::ofstream file(name.str());
  const std::string axes = "xyz";
  file << "body";
  for (unsigned int d = 0; d < dim; ++d)
    file << "," << axes[d];
  for (const std::string field : {"u", "v", "a"})
    for (unsigned int d = 0; d < dim; ++d)
      file << "," << field << (dim > 1 ? std::string("_") + axes[d] : std::string());
  file << '\n' << std::setprecision(15);
  for (const auto& node : nodes)
  {
    file << node.body + 1;
    for (unsigned int d = 0; d < dim; ++d)
      file << "," << node.position[d];
    for (const Vector<double>* field : {&displacement, &velocity, &acceleration})
      for (unsigned int d = 0; d < dim; ++d)
        file << "," << (*field)[node.dofs[d]];
    file << '\n';
  }
}

template <int dim>
void FieldOutput<dim>::write_contact_pressure(const double time,
                                              const std::vector<PressureSample>& samples) const
{
  std::ostringstream name;
  name << directory << "/contact_pressure_t" << time << ".csv";
  std::ofstream file(name.str());
  const std::string axes = "xyz";
  for (unsigned int d = 0; d < dim; ++d)
    file << axes[d] << ",";
  file << "gap,multiplier,pressure,active\n" << std::setprecision(15);
  for (const auto& sample : samples)
  {
    for (unsigned int d = 0; d < dim; ++d)
      file << sample.position[d] << ",";
    file << sample.gap << "," << sample.multiplier << "," << sample.pressure << ","
         << (sample.active ? 1 : 0) << '\n';
  }
}

template <int dim>
void FieldOutput<dim>::write_cell_outlines(const std::vector<Node<dim>>& nodes) const
{
  AssertThrow(dim == 2, ExcNotImplemented());
  std::map<types::global_dof_index, unsigned int> row_of_first_dof;
  for (unsigned int row = 0; row < nodes.size(); ++row)
    row_of_first_dof.emplace(nodes[row].dofs[0], row);

  // The boundary support points of the reference cell, counter-clockwise around its centre.
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  Point<dim> centre;
  for (unsigned int d = 0; d < dim; ++d)
    centre[d] = 0.5;
  std::vector<std::pair<double, unsigned int>> outline; // (angle, local DoF of component 0)
  for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
  {
    const Tensor<1, dim> offset = fe.unit_support_point(i) - centre;
    if (fe.system_to_component_index(i).first == 0 && offset.norm() > 1e-12)
      outline.emplace_back(std::atan2(offset[dim - 1], offset[0]), i);
  }
  std::sort(outline.begin(), outline.end());

  std::ofstream file(directory + "/cells.csv");
  file << "body";
  for (unsigned int point = 0; point < outline.size(); ++point)
    file << ",node_" << point;
  file << '\n';
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    cell->get_dof_indices(cell_dofs);
    file << cell->material_id() + 1;
    for (const auto& point : outline)
      file << "," << row_of_first_dof.at(cell_dofs[point.second]);
    file << '\n';
  }
}

template class FieldOutput<1>;
template class FieldOutput<2>;
} // namespace dyncontact
