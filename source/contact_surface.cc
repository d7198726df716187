#include <dyncontact/contact_surface.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q_eulerian.h>

#include <algorithm>

namespace dyncontact
{
template <int dim>
ContactSurface<dim>::ContactSurface(const DoFHandler<dim>& dof_handler,
                                    const Kinematics<dim>& kinematics,
                                    const NodeIndex<dim>& nodes,
                                    const types::boundary_id boundary)
    : dof_handler(dof_handler), kinematics(kinematics), boundary(boundary)
{
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
  for (const auto& node : nodes.nodes())
    if (std::binary_search(first_dofs.begin(), first_dofs.end(), node.dofs[0]))
    {
      node_of_first_dof.emplace(node.dofs[0], surface_nodes.size());
      surface_nodes.push_back(node);
    }
}

template <int dim>
typename ContactSurface<dim>::Geometry
ContactSurface<dim>::current_geometry(const Vector<double>& displacement) const
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const MappingQEulerian<dim, Vector<double>> current_mapping(fe.degree, dof_handler, displacement);
  // Normals at the nodes: a face quadrature whose points are the face's support points; the node
  // at point q is the DoF whose (Lagrange) shape function is one there. Areas: Gauss quadrature
  // exact for the shape function times a linear measure factor on a straight face.
  const Quadrature<dim - 1> node_points(fe.base_element(0).get_unit_face_support_points());
  FEFaceValues<dim> at_nodes(
      current_mapping, fe, node_points, update_values | update_normal_vectors);
  FEFaceValues<dim> at_gauss_points(current_mapping,
                                    fe,
                                    QGauss<dim - 1>(fe.degree + 2),
                                    update_values | update_quadrature_points | update_JxW_values);

  Geometry geometry{std::vector<Tensor<1, dim>>(surface_nodes.size()),
                    std::vector<double>(surface_nodes.size(), 0.)};
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
  std::vector<unsigned int> face_dofs; // local DoFs of component 0 supported on the face
  for (const auto& [cell, face] : faces)
  {
    cell->get_dof_indices(cell_dofs);
    face_dofs.clear();
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first == 0 && fe.has_support_on_face(i, face))
        face_dofs.push_back(i);

    at_nodes.reinit(cell, face);
    for (unsigned int q = 0; q < node_points.size(); ++q)
      for (const unsigned int i : face_dofs)
        if (at_nodes.shape_value_component(i, q, 0) > 0.5)
          geometry.normals[node_of_first_dof.at(cell_dofs[i])] += at_nodes.normal_vector(q);

    at_gauss_points.reinit(cell, face);
    for (unsigned int q = 0; q < at_gauss_points.n_quadrature_points; ++q)
    {
      const double measure =
          kinematics.measure_factor(at_gauss_points.quadrature_point(q), cell->material_id()) *
          at_gauss_points.JxW(q);
      for (const unsigned int i : face_dofs)
        geometry.areas[node_of_first_dof.at(cell_dofs[i])] +=
            at_gauss_points.shape_value_component(i, q, 0) * measure;
    }
  }
  for (auto& normal : geometry.normals)
    normal /= normal.norm();
  return geometry;
}

template <int dim>
typename ContactSurface<dim>::Geometry ContactSurface<dim>::reference_geometry() const
{
  return current_geometry(Vector<double>(dof_handler.n_dofs()));
}

template class ContactSurface<1>;
template class ContactSurface<2>;
template class ContactSurface<3>;
} // namespace dyncontact
