#include <dyncontact/field_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>

#include <fstream>
#include <iomanip>
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
                                    const Vector<double>& acceleration)
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

template class FieldOutput<1>;
template class FieldOutput<2>;
} // namespace dyncontact
