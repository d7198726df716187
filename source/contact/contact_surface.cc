#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/join_over_ranks.h>
#include <dyncontact/contact/contact_surface.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/qprojector.h>
#include <deal.II/base/quadrature_lib.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <map>

namespace dyncontact
{
namespace
{
/** A face of a contact surface as one rank found it: sent to every rank. */
template <int dim>
struct FaceRecord
{
  unsigned int face_number;
  types::material_id body;
  /** Its nodes, in the order of the face number's tables. */
  std::vector<Node<dim>> nodes;

  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& face_number;
    archive& body;
    archive& nodes;
  }
};

/**
 * The normal of a face before orientation and normalization, from its tangents a_k = dx/ds_k:
 * (a_0[1], -a_0[0]) in 2D, a_0 x a_1 in 3D, e_0 in 1D (a face is a point). Its length is the
 * face's area element per unit reference area (1 in 1D).
 */
template <int dim>
Tensor<1, dim> tangents_normal(const std::array<Tensor<1, dim>, dim - 1>& tangents)
{
  if constexpr (dim == 1)
    return Tensor<1, dim>({1.});
  else if constexpr (dim == 2)
    return cross_product_2d(tangents[0]);
  else
    return cross_product_3d(tangents[0], tangents[1]);
}
} // namespace

template <int dim>
typename ContactSurface<dim>::FaceTable
ContactSurface<dim>::tabulate(const FiniteElement<dim>& scalar,
                              const std::vector<unsigned int>& face_dofs,
                              const unsigned int face_number,
                              const Quadrature<dim - 1>& quadrature)
{
  const Quadrature<dim> on_cell = QProjector<dim>::project_to_face(
      ReferenceCells::get_hypercube<dim>(), quadrature, face_number);
  FaceTable table;
  table.weights = quadrature.get_weights();
  for (unsigned int q = 0; q < on_cell.size(); ++q)
  {
    table.values.emplace_back();
    table.tangential_derivatives.emplace_back();
    for (const unsigned int i : face_dofs)
    {
      table.values.back().push_back(scalar.shape_value(i, on_cell.point(q)));
      const Tensor<1, dim> gradient = scalar.shape_grad(i, on_cell.point(q));
      std::array<double, dim - 1> derivatives;
      for (unsigned int k = 0; k + 1 < dim; ++k)
        derivatives[k] = gradient * GeometryInfo<dim>::unit_tangential_vectors[face_number][k];
      table.tangential_derivatives.back().push_back(derivatives);
    }
  }
  return table;
}

template <int dim>
ContactSurface<dim>::ContactSurface(const DoFHandler<dim>& dof_handler,
                                    const Kinematics<dim>& kinematics,
                                    const NodeIndex<dim>& nodes,
                                    const types::boundary_id boundary)
    : kinematics(kinematics)
{
  const FiniteElement<dim>& fe     = dof_handler.get_fe();
  const FiniteElement<dim>& scalar = fe.base_element(0);
  // Exact for a product of two shape functions times a linear measure factor on a straight face.
  const QGauss<dim - 1> gauss(fe.degree + 2);
  const Quadrature<dim - 1> support_points(scalar.get_unit_face_support_points());
  std::vector<std::vector<unsigned int>> dofs_on_face; // scalar DoFs, per face number
  for (const unsigned int f : GeometryInfo<dim>::face_indices())
  {
    dofs_on_face.emplace_back();
    for (unsigned int i = 0; i < scalar.n_dofs_per_cell(); ++i)
      if (scalar.has_support_on_face(i, f))
        dofs_on_face[f].push_back(i);
    at_gauss_points.push_back(tabulate(scalar, dofs_on_face[f], f, gauss));
    at_nodes.push_back(tabulate(scalar, dofs_on_face[f], f, support_points));
    // The unit cell's own tangents give its outward normal up to this sign; a cell's mapping has
    // a positive Jacobian, which keeps the side.
    std::array<Tensor<1, dim>, dim - 1> unit_tangents;
    for (unsigned int k = 0; k + 1 < dim; ++k)
      unit_tangents[k] = GeometryInfo<dim>::unit_tangential_vectors[f][k];
    outward_sign.push_back(
        tangents_normal<dim>(unit_tangents) * GeometryInfo<dim>::unit_normal_vector[f] > 0. ? 1.
                                                                                            : -1.);
  }

  // The faces of this rank's cells, then those of every rank, in the order of the ranks.
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
  std::vector<FaceRecord<dim>> local_faces;
  for (const auto& cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary)
        {
          cell->get_dof_indices(cell_dofs);
          local_faces.push_back({f, cell->material_id(), {}});
          for (const unsigned int i : dofs_on_face[f])
            local_faces.back().nodes.push_back(
                nodes.node_of_first_dof(cell_dofs[fe.component_to_system_index(0, i)]));
        }
  const std::vector<FaceRecord<dim>> all_faces =
      join_over_ranks(dof_handler.get_triangulation().get_communicator(), local_faces);
  if (all_faces.empty())
    throw InputError("the mesh has no boundary faces with id " + std::to_string(boundary) +
                     ", so this contact surface is empty.");
  // Each node once (as the first rank that has it sent it), ordered as in NodeIndex.
  std::map<types::global_dof_index, Node<dim>> node_of_first_dof;
  for (const FaceRecord<dim>& face : all_faces)
    for (const Node<dim>& node : face.nodes)
      node_of_first_dof.emplace(node.dofs[0], node);
  for (const auto& entry : node_of_first_dof)
    surface_nodes.push_back(entry.second);
  std::sort(surface_nodes.begin(), surface_nodes.end(), precedes<dim>);
  std::map<types::global_dof_index, unsigned int> index_of_first_dof; // in surface_nodes
  for (unsigned int i = 0; i < surface_nodes.size(); ++i)
    index_of_first_dof.emplace(surface_nodes[i].dofs[0], i);
  for (const FaceRecord<dim>& record : all_faces)
  {
    faces.push_back({record.face_number, record.body, {}});
    for (const Node<dim>& node : record.nodes)
      faces.back().nodes.push_back(index_of_first_dof.at(node.dofs[0]));
    // The node at support point j is the one whose (Lagrange) shape function is one there.
    const FaceTable& table = at_nodes[record.face_number];
    support_point_nodes.emplace_back();
    for (unsigned int j = 0; j < table.values.size(); ++j)
      for (unsigned int i = 0; i < faces.back().nodes.size(); ++i)
        if (table.values[j][i] > 0.5)
          support_point_nodes.back().push_back(faces.back().nodes[i]);
  }
}

template <int dim>
std::vector<Point<dim>> ContactSurface<dim>::reference_positions() const
{
  std::vector<Point<dim>> positions;
  for (const Node<dim>& node : surface_nodes)
    positions.push_back(node.position);
  return positions;
}

template <int dim>
std::vector<Point<dim>>
ContactSurface<dim>::current_positions(const BorderDisplacement<dim>& displacement) const
{
  std::vector<Point<dim>> positions;
  for (const Node<dim>& node : surface_nodes)
    positions.push_back(displacement.current_position(node));
  return positions;
}

template <int dim>
std::pair<Point<dim>, Tensor<1, dim>>
ContactSurface<dim>::face_point(const Face& face,
                                const FaceTable& table,
                                const unsigned int q,
                                const std::vector<Point<dim>>& positions) const
{
  Tensor<1, dim> point;
  std::array<Tensor<1, dim>, dim - 1> tangents;
  for (unsigned int i = 0; i < face.nodes.size(); ++i)
  {
    const Tensor<1, dim>& x_i = positions[face.nodes[i]];
    point += table.values[q][i] * x_i;
    for (unsigned int k = 0; k + 1 < dim; ++k)
      tangents[k] += table.tangential_derivatives[q][i][k] * x_i;
  }
  return {Point<dim>(point), outward_sign[face.face_number] * tangents_normal<dim>(tangents)};
}

template <int dim>
std::vector<Tensor<1, dim>>
ContactSurface<dim>::normals(const std::vector<Point<dim>>& positions) const
{
  AssertDimension(positions.size(), surface_nodes.size());
  std::vector<Tensor<1, dim>> nodal_normals(surface_nodes.size());
  for (unsigned int f = 0; f < faces.size(); ++f)
  {
    // The table's points are the face's support points, of the nodes support_point_nodes lists.
    const FaceTable& table = at_nodes[faces[f].face_number];
    for (unsigned int j = 0; j < table.values.size(); ++j)
    {
      const Tensor<1, dim> normal = face_point(faces[f], table, j, positions).second;
      nodal_normals[support_point_nodes[f][j]] += normal / normal.norm();
    }
  }
  for (auto& normal : nodal_normals)
    normal /= normal.norm();
  return nodal_normals;
}

template <int dim>
std::vector<double>
ContactSurface<dim>::lumped_areas(const std::vector<Point<dim>>& positions) const
{
  const Eigen::SparseMatrix<double> mass = mass_matrix(positions);
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
ContactSurface<dim>::mass_matrix(const std::vector<Point<dim>>& positions) const
{
  AssertDimension(positions.size(), surface_nodes.size());
  std::vector<Eigen::Triplet<double>> entries; // summed by setFromTriplets
  for (const Face& face : faces)
  {
    const FaceTable& table = at_gauss_points[face.face_number];
    for (unsigned int q = 0; q < table.values.size(); ++q)
    {
      const auto [point, normal] = face_point(face, table, q, positions);
      const double measure =
          kinematics.measure_factor(point, face.body) * (normal.norm() * table.weights[q]);
      for (unsigned int i = 0; i < face.nodes.size(); ++i)
        for (unsigned int j = 0; j < face.nodes.size(); ++j)
          entries.emplace_back(
              face.nodes[i], face.nodes[j], table.values[q][i] * table.values[q][j] * measure);
    }
  }
  Eigen::SparseMatrix<double> mass(surface_nodes.size(), surface_nodes.size());
  mass.setFromTriplets(entries.begin(), entries.end());
  return mass;
}

template <int dim>
std::vector<double>
ContactSurface<dim>::consistent_pressures(const std::vector<Point<dim>>& positions,
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
  const Eigen::SparseMatrix<double> mass = mass_matrix(positions);
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
