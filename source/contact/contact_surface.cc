#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact/contact_surface.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe_field.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <map>

namespace dyncontact
{
template <int dim>
ContactSurface<dim>::ContactSurface(const DoFHandler<dim>& dof_handler,
                                    const Kinematics<dim>& kinematics,
                                    const NodeIndex<dim>& nodes,
                                    const types::boundary_id boundary)
    : dof_handler(dof_handler), kinematics(kinematics), boundary(boundary),
      reference_positions(dof_handler.n_dofs())
{
  for (const auto& node : nodes.nodes())
    for (unsigned int d = 0; d < dim; ++d)
      reference_positions[node.dofs[d]] = node.position[d];
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
  std::vector<types::global_dof_index> first_dofs;
  for (const auto& cell : dof_handler.active_cell_iterators())
    for (const unsigned int face : cell->face_indices())
      if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == boundary)
      {
        faces.emplace_back(cell, face);
        cell->get_dof_indices(cell_dofs);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          if (fe.system_to_component_index(i).first == 0 && fe.has_support_on_face(i, face))
            first_dofs.push_back(cell_dofs[i]);
      }
  if (faces.empty())
    throw InputError("the mesh has no boundary faces with id " + std::to_string(boundary) +
                     ", so this contact surface is empty.");
  std::sort(first_dofs.begin(), first_dofs.end());
  first_dofs.erase(std::unique(first_dofs.begin(), first_dofs.end()), first_dofs.end());
  std::map<types::global_dof_index, unsigned int> node_of_first_dof; // index in surface_nodes
  for (const auto& node : nodes.nodes())
    if (std::binary_search(first_dofs.begin(), first_dofs.end(), node.dofs[0]))
    {
      node_of_first_dof.emplace(node.dofs[0], surface_nodes.size());
      surface_nodes.push_back(node);
    }
  for (const auto& [cell, face] : faces)
  {
    cell->get_dof_indices(cell_dofs);
    nodes_of_face.emplace_back();
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first == 0 && fe.has_support_on_face(i, face))
        nodes_of_face.back().emplace_back(i, node_of_first_dof.at(cell_dofs[i]));
    const FiniteElement<dim>& scalar = fe.base_element(0);
    support_point_nodes.emplace_back();
    for (unsigned int j = 0; j < scalar.n_dofs_per_face(face); ++j)
      support_point_nodes.back().push_back(node_of_first_dof.at(
          cell_dofs[fe.component_to_system_index(0, scalar.face_to_cell_index(j, face))]));
  }
}

template <int dim>
Vector<double> ContactSurface<dim>::current_positions(const Vector<double>& displacement) const
{
  Vector<double> positions = reference_positions;
  positions += displacement;
  return positions;
}

template <int dim>
template <typename Integrand>
void ContactSurface<dim>::integrate_over_faces(const Mapping<dim>& mapping,
                                               const Integrand& integrand) const
{
  // Exact for a product of two shape functions times a linear measure factor on a straight face.
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  FEFaceValues<dim> at_gauss_points(mapping,
                                    fe,
                                    QGauss<dim - 1>(fe.degree + 2),
                                    update_values | update_quadrature_points | update_JxW_values);
  for (unsigned int f = 0; f < faces.size(); ++f)
  {
    const auto& [cell, face] = faces[f];
    at_gauss_points.reinit(cell, face);
    for (unsigned int q = 0; q < at_gauss_points.n_quadrature_points; ++q)
      integrand(
          nodes_of_face[f],
          at_gauss_points,
          q,
          kinematics.measure_factor(at_gauss_points.quadrature_point(q), cell->material_id()) *
              at_gauss_points.JxW(q));
  }
}

template <int dim>
std::vector<Tensor<1, dim>> ContactSurface<dim>::normals(const Vector<double>& displacement) const
{
  const FiniteElement<dim>& fe   = dof_handler.get_fe();
  const Vector<double> positions = current_positions(displacement);
  const MappingFEField<dim, dim, Vector<double>> current_mapping(dof_handler, positions);
  // A face quadrature whose points are the face's support points; the node at point q is the one
  // whose (Lagrange) shape function is one there.
  const Quadrature<dim - 1> node_points(fe.base_element(0).get_unit_face_support_points());
  FEFaceValues<dim> at_nodes(
      current_mapping, fe, node_points, update_values | update_normal_vectors);
  std::vector<Tensor<1, dim>> nodal_normals(surface_nodes.size());
  for (unsigned int f = 0; f < faces.size(); ++f)
  {
    at_nodes.reinit(faces[f].first, faces[f].second);
    for (unsigned int q = 0; q < node_points.size(); ++q)
      for (const auto& [local_dof, node] : nodes_of_face[f])
        if (at_nodes.shape_value_component(local_dof, q, 0) > 0.5)
          nodal_normals[node] += at_nodes.normal_vector(q);
  }
  for (auto& normal : nodal_normals)
    normal /= normal.norm();
  return nodal_normals;
}

template <int dim>
std::vector<double> ContactSurface<dim>::lumped_areas(const Vector<double>& displacement) const
{
  const Eigen::SparseMatrix<double> mass = mass_matrix(displacement);
  // The shape functions sum to one, so the row sums of the mass matrix are the consistent nodal
  // areas, and their sum is the surface's area.
  const Eigen::VectorXd diagonal = mass.diagonal();
  const double scale             = mass.sum() / diagonal.sum();
  std::vector<double> areas(surface_nodes.size());
  for (unsigned int node = 0; node < areas.size(); ++node)
    areas[node] = scale * diagonal(node);
  return areas;
}

template <int dim>
Eigen::SparseMatrix<double>
ContactSurface<dim>::mass_matrix(const Vector<double>& displacement) const
{
  const Vector<double> positions = current_positions(displacement);
  const MappingFEField<dim, dim, Vector<double>> current_mapping(dof_handler, positions);
  std::vector<Eigen::Triplet<double>> entries; // summed by setFromTriplets
  integrate_over_faces(current_mapping,
                       [&entries](const auto& face_nodes,
                                  const FEFaceValues<dim>& values,
                                  const unsigned int q,
                                  const double measure)
                       {
                         for (const auto& [dof_i, node_i] : face_nodes)
                           for (const auto& [dof_j, node_j] : face_nodes)
                             entries.emplace_back(node_i,
                                                  node_j,
                                                  values.shape_value_component(dof_i, q, 0) *
                                                      values.shape_value_component(dof_j, q, 0) *
                                                      measure);
                       });
  Eigen::SparseMatrix<double> mass(surface_nodes.size(), surface_nodes.size());
  mass.setFromTriplets(entries.begin(), entries.end());
  return mass;
}

template <int dim>
std::vector<double>
ContactSurface<dim>::consistent_pressures(const Vector<double>& displacement,
                                          const std::vector<unsigned int>& surface_nodes_of_pairs,
                                          const std::vector<double>& multipliers) const
{
  AssertDimension(multipliers.size(), surface_nodes_of_pairs.size());
  std::vector<unsigned int> zone; // pairs whose node carries the pressure field
  for (unsigned int k = 0; k < multipliers.size(); ++k)
    if (multipliers[k] != 0.)
      zone.push_back(k);
  std::vector<double> pressures(multipliers.size(), 0.);
  if (zone.empty())
    return pressures;

  // The surface mass matrix restricted to the zone's nodes, kept sparse.
  const Eigen::SparseMatrix<double> mass = mass_matrix(displacement);
  std::vector<int> zone_index(mass.rows(), -1); // surface node -> row in the zone, or -1
  Eigen::VectorXd zone_forces(zone.size());
  for (unsigned int i = 0; i < zone.size(); ++i)
  {
    zone_index[surface_nodes_of_pairs[zone[i]]] = i;
    zone_forces(i)                              = multipliers[zone[i]];
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (int column = 0; column < mass.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(mass, column); entry; ++entry)
      if (zone_index[entry.row()] >= 0 && zone_index[entry.col()] >= 0)
        entries.emplace_back(zone_index[entry.row()], zone_index[entry.col()], entry.value());
  Eigen::SparseMatrix<double> zone_mass(zone.size(), zone.size());
  zone_mass.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factorization(zone_mass);
  if (factorization.info() != Eigen::Success)
    throw SolverFailure("the contact pressure recovery failed: the surface mass matrix of the "
                        "contact zone is not positive definite (a collapsed contact face?)");
  const Eigen::VectorXd zone_pressures = factorization.solve(zone_forces);
  for (unsigned int i = 0; i < zone.size(); ++i)
    pressures[zone[i]] = zone_pressures(i);
  return pressures;
}

DYNCONTACT_INSTANTIATE_CLASS(ContactSurface)
} // namespace dyncontact
