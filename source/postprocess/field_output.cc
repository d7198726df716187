#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/join_over_ranks.h>
#include <dyncontact/postprocess/field_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_out_faces.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace dyncontact
{
namespace
{
/** The given faces, each a (active cell index, face number), of locally owned cells. */
template <int dim>
class SelectedFaces : public DataOutFaces<dim>
{
public:
  explicit SelectedFaces(std::set<std::pair<unsigned int, unsigned int>> faces)
      : DataOutFaces<dim>(true), faces(std::move(faces))
  {
  }

  typename DataOutFaces<dim>::FaceDescriptor first_face() override
  {
    return skip_others(DataOutFaces<dim>::first_face());
  }

  typename DataOutFaces<dim>::FaceDescriptor
  next_face(const typename DataOutFaces<dim>::FaceDescriptor& face) override
  {
    return skip_others(DataOutFaces<dim>::next_face(face));
  }

private:
  typename DataOutFaces<dim>::FaceDescriptor
  skip_others(typename DataOutFaces<dim>::FaceDescriptor face)
  {
    while (face.first != this->triangulation->end() &&
           faces.count({face.first->active_cell_index(), face.second}) == 0)
      face = DataOutFaces<dim>::next_face(face);
    return face;
  }

  const std::set<std::pair<unsigned int, unsigned int>> faces;
};

/** VTU flags: high-order (VTK Lagrange) cells, zlib's fastest compression (its best, deal.II's
 * default, took ten times as long on the paper's spheres for an 8 % smaller file). */
DataOutBase::VtkFlags high_order_cells()
{
  DataOutBase::VtkFlags flags;
  flags.write_higher_order_cells = true;
  flags.compression_level        = DataOutBase::VtkFlags::best_speed;
  return flags;
}

/** Writes `<name>_<frame>` pieces and record of `data_out` and rewrites `<name>.pvd` (rank 0). */
template <class DataOutType>
void write_frame(DataOutType& data_out,
                 const std::string& directory,
                 const std::string& name,
                 const unsigned int frame,
                 const double time,
                 const MPI_Comm communicator,
                 std::vector<std::pair<double, std::string>>& records)
{
  const std::string record =
      data_out.write_vtu_with_pvtu_record(directory + "/", name, frame, communicator, 5);
  if (Utilities::MPI::this_mpi_process(communicator) == 0)
  {
    records.emplace_back(time, record);
    std::ofstream pvd(directory + "/" + name + ".pvd");
    DataOutBase::write_pvd_record(pvd, records);
  }
}
} // namespace

template <int dim>
FieldOutput<dim>::FieldOutput(const DoFHandler<dim>& dof_handler,
                              const Mapping<dim>& mapping,
                              const Kinematics<dim>& kinematics,
                              std::vector<std::shared_ptr<const Material>> materials,
                              std::set<types::boundary_id> contact_surfaces,
                              std::string directory)
    : dof_handler(dof_handler), mapping(mapping), stresses(kinematics, std::move(materials)),
      contact_surfaces(std::move(contact_surfaces)), directory(std::move(directory)),
      scalar_fe(dof_handler.get_fe().base_element(0).clone()),
      scalar_dof_handler(dof_handler.get_triangulation())
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  AssertThrow(fe.n_base_elements() == 1 && fe.element_multiplicity(0) == dim,
              ExcMessage("FieldOutput needs an FESystem of dim copies of one scalar element."));
  scalar_dof_handler.distribute_dofs(*scalar_fe);
  IndexSet relevant_dofs;
  DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
  ghosted_layout = std::make_shared<Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(),
      relevant_dofs,
      dof_handler.get_triangulation().get_communicator());
  scalar_dof.assign(relevant_dofs.n_elements(), numbers::invalid_dof_index);
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  std::vector<types::global_dof_index> scalar_dofs(scalar_fe->n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (cell->is_artificial())
      continue;
    cell->get_dof_indices(dofs);
    typename DoFHandler<dim>::active_cell_iterator scalar_cell(
        &dof_handler.get_triangulation(), cell->level(), cell->index(), &scalar_dof_handler);
    scalar_cell->get_dof_indices(scalar_dofs);
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (fe.system_to_component_index(i).first == 0)
        scalar_dof[ghosted_layout->global_to_local(dofs[i])] =
            scalar_dofs[fe.system_to_component_index(i).second];
  }
}

template <int dim>
types::global_dof_index FieldOutput<dim>::scalar_dof_of(const types::global_dof_index dof) const
{
  return ghosted_layout->in_local_range(dof) || ghosted_layout->is_ghost_entry(dof)
             ? scalar_dof[ghosted_layout->global_to_local(dof)]
             : numbers::invalid_dof_index;
}

template <int dim>
DistributedVector FieldOutput<dim>::with_ghosts(const DistributedVector& owned) const
{
  DistributedVector ghosted(ghosted_layout);
  ghosted.copy_locally_owned_data_from(owned);
  ghosted.update_ghost_values();
  return ghosted;
}

template <int dim>
void FieldOutput<dim>::write_fields(const unsigned int frame,
                                    const double time,
                                    const DistributedVector& displacement,
                                    const DistributedVector& velocity,
                                    const DistributedVector& acceleration,
                                    const DistributedVector* contact_traction)
{
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
      dim, DataComponentInterpretation::component_is_part_of_vector);
  DataOut<dim> data_out;
  data_out.set_flags(high_order_cells());
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
  data_out.add_data_vector(displacement, stresses);
  Vector<float> body(dof_handler.get_triangulation().n_active_cells());
  for (const auto& cell : dof_handler.active_cell_iterators())
    body[cell->active_cell_index()] = cell->material_id() + 1;
  data_out.add_data_vector(body, "body");
  // One patch per cell with the element's own points: a Q2 cell is one 9-node Lagrange cell.
  data_out.build_patches(mapping, dof_handler.get_fe().degree, DataOut<dim>::curved_inner_cells);
  write_frame(data_out,
              directory,
              "solution",
              frame,
              time,
              dof_handler.get_triangulation().get_communicator(),
              pvd_records);
}

template <int dim>
void FieldOutput<dim>::write_contact_surface(const unsigned int frame,
                                             const double time,
                                             const DistributedVector& displacement,
                                             const std::vector<PressureSample>& samples)
{
  if (contact_surfaces.empty())
    return;
  // Zero at nodes without a pair: they are not written, but the face values are sums over all
  // of a cell's DoFs (a NaN there would spoil them, even times a zero shape function).
  Vector<double> pressure(scalar_dof_handler.n_dofs()), gap(scalar_dof_handler.n_dofs()),
      active(scalar_dof_handler.n_dofs());
  std::vector<bool> has_pair(scalar_dof_handler.n_dofs(), false);
  for (const auto& sample : samples)
  {
    const types::global_dof_index dof = scalar_dof_of(sample.node.dofs[0]);
    if (dof == numbers::invalid_dof_index)
      continue; // a node of another rank's cells
    pressure[dof] = sample.pressure;
    gap[dof]      = sample.gap;
    active[dof]   = sample.active ? 1. : 0.;
    has_pair[dof] = true;
  }
  if constexpr (dim == 1)
  {
    // Bars have no contact surfaces (and deal.II has no DataOutFaces<1>).
    AssertThrow(false, ExcNotImplemented());
  }
  else
  {
    // The faces of the contact surfaces whose every node belongs to a pair.
    std::set<std::pair<unsigned int, unsigned int>> faces;
    std::vector<types::global_dof_index> face_dofs(dof_handler.get_fe().n_dofs_per_face());
    for (const auto& cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              contact_surfaces.count(cell->face(f)->boundary_id()) > 0)
          {
            cell->face(f)->get_dof_indices(face_dofs);
            if (std::all_of(face_dofs.begin(),
                            face_dofs.end(),
                            [&](const types::global_dof_index dof) {
                              return scalar_dof_of(dof) == numbers::invalid_dof_index ||
                                     has_pair[scalar_dof_of(dof)];
                            }))
              faces.emplace(cell->active_cell_index(), f);
          }
    SelectedFaces<dim> data_out(std::move(faces));
    data_out.set_flags(high_order_cells());
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(dim, "displacement"),
                             DataOutFaces<dim>::type_dof_data,
                             std::vector<DataComponentInterpretation::DataComponentInterpretation>(
                                 dim, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(scalar_dof_handler, pressure, "contact_pressure");
    data_out.add_data_vector(scalar_dof_handler, gap, "gap");
    data_out.add_data_vector(scalar_dof_handler, active, "active");
    data_out.build_patches(mapping, dof_handler.get_fe().degree);
    write_frame(data_out,
                directory,
                "contact_surface",
                frame,
                time,
                dof_handler.get_triangulation().get_communicator(),
                surface_pvd_records);
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
                                              const std::vector<PressureSample>& samples,
                                              const bool with_friction) const
{
  std::ostringstream name;
  name << directory << "/contact_pressure_t" << time << ".csv";
  std::ofstream file(name.str());
  const std::string axes = "xyz";
  for (unsigned int d = 0; d < dim; ++d)
    file << axes[d] << ",";
  file << "gap,multiplier,pressure,active";
  if (with_friction)
  {
    for (const std::string quantity : {",tangential_force_", ",shear_"})
      for (unsigned int d = 0; d < dim; ++d)
        file << quantity << axes[d];
    file << ",sliding";
  }
  file << '\n' << std::setprecision(15);
  for (const auto& sample : samples)
  {
    for (unsigned int d = 0; d < dim; ++d)
      file << sample.position[d] << ",";
    file << sample.gap << "," << sample.multiplier << "," << sample.pressure << ","
         << (sample.active ? 1 : 0);
    if (with_friction)
    {
      for (const Tensor<1, dim>* vector : {&sample.tangential_force, &sample.shear})
        for (unsigned int d = 0; d < dim; ++d)
          file << "," << (*vector)[d];
      file << "," << (sample.sliding ? 1 : 0);
    }
    file << '\n';
  }
}

template <int dim>
void FieldOutput<dim>::write_cell_outlines(const NodeIndex<dim>& node_index) const
{
  AssertThrow(dim == 2, ExcNotImplemented());
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

  // Per locally owned cell: its body, then the first DoFs of its outline's nodes.
  std::vector<types::global_dof_index> cells, cell_dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
    {
      cell->get_dof_indices(cell_dofs);
      cells.push_back(cell->material_id());
      for (const auto& point : outline)
        cells.push_back(cell_dofs[point.second]);
    }
  const MPI_Comm communicator        = dof_handler.get_triangulation().get_communicator();
  const std::vector<Node<dim>> nodes = node_index.gather_on_root();
  const std::vector<types::global_dof_index> all_cells = join_on_root(communicator, cells);
  if (Utilities::MPI::this_mpi_process(communicator) != 0)
    return;
  std::map<types::global_dof_index, unsigned int> row_of_first_dof;
  for (unsigned int row = 0; row < nodes.size(); ++row)
    row_of_first_dof.emplace(nodes[row].dofs[0], row);
  std::ofstream file(directory + "/cells.csv");
  file << "body";
  for (unsigned int point = 0; point < outline.size(); ++point)
    file << ",node_" << point;
  file << '\n';
  for (std::size_t start = 0; start < all_cells.size(); start += outline.size() + 1)
  {
    file << all_cells[start] + 1;
    for (unsigned int point = 0; point < outline.size(); ++point)
      file << "," << row_of_first_dof.at(all_cells[start + 1 + point]);
    file << '\n';
  }
}

DYNCONTACT_INSTANTIATE_CLASS(FieldOutput)
} // namespace dyncontact
