#include <dyncontact/axisymmetric_mesh_model.h>

#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <limits>

namespace dyncontact
{
AxisymmetricMeshModel::AxisymmetricMeshModel(const MeshParameters& mesh,
                                             const BodiesParameters& bodies,
                                             const ContactParameters& contact)
    : mesh(mesh), bodies(bodies), contact(contact), n_cells(0), shortest_edge(0.)
{
}

void AxisymmetricMeshModel::create_triangulation(Triangulation<2>& triangulation)
{
  spheres = read_gmsh_mesh(mesh.file, mesh.geo_parameters, triangulation);
  std::vector<unsigned int> cells_of_body(n_bodies(), 0);
  shortest_edge = std::numeric_limits<double>::max();
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    if (cell->material_id() >= n_bodies())
      throw InputError("Mesh/file = '" + mesh.file + "' has cells of body " +
                       std::to_string(cell->material_id() + 1) +
                       " but Bodies/number of bodies = " + std::to_string(n_bodies()) + ".");
    ++cells_of_body[cell->material_id()];
    for (unsigned int line = 0; line < cell->n_lines(); ++line)
      shortest_edge = std::min(shortest_edge, cell->line(line)->diameter());
  }
  for (unsigned int body = 0; body < n_bodies(); ++body)
    if (cells_of_body[body] == 0)
      throw InputError("Mesh/file = '" + mesh.file + "' has no cells of body " +
                       std::to_string(body + 1) + " (physical surface " + std::to_string(body + 1) +
                       "), but Bodies/number of bodies = " + std::to_string(n_bodies()) + ".");
  n_cells = triangulation.n_active_cells();
}

double AxisymmetricMeshModel::dilatational_wave_speed(const unsigned int body) const
{
  const BodyParameters& parameters = bodies.bodies[body];
  const double nu                  = parameters.poissons_ratio;
  const double constrained_modulus =
      parameters.youngs_modulus * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
  return std::sqrt(constrained_modulus / parameters.density);
}

double AxisymmetricMeshModel::highest_frequency() const
{
  double speed = 0.;
  for (unsigned int body = 0; body < n_bodies(); ++body)
    speed = std::max(speed, dilatational_wave_speed(body));
  return 2. * std::sqrt(6.) * speed / shortest_edge;
}

std::vector<BodyMaterial> AxisymmetricMeshModel::body_materials() const
{
  std::vector<BodyMaterial> materials;
  for (const auto& body : bodies.bodies)
    materials.push_back(
        {create_material(body.material, body.youngs_modulus, body.poissons_ratio), body.density});
  return materials;
}

std::unique_ptr<Kinematics<2>> AxisymmetricMeshModel::create_kinematics() const
{
  return std::make_unique<AxisymmetricKinematics>();
}

Tensor<1, 2> AxisymmetricMeshModel::initial_velocity(const types::material_id body,
                                                     const Point<2>& X) const
{
  Tensor<1, 2> velocity;
  for (unsigned int d = 0; d < 2; ++d)
    velocity[d] = bodies.bodies[body].initial_velocity->value(X, d);
  return velocity;
}

std::vector<ContactPair<2>> AxisymmetricMeshModel::contact_pairs(const NodeIndex<2>&) const
{
  return {};
}

std::unique_ptr<NodeToNodeContact<2>>
AxisymmetricMeshModel::create_surface_contact(const DoFHandler<2>& dof_handler,
                                              const Kinematics<2>& kinematics,
                                              const NodeIndex<2>& nodes) const
{
  if (n_bodies() == 1)
    return nullptr;
  if (n_bodies() > 2)
    throw InputError("Bodies/number of bodies = " + std::to_string(n_bodies()) +
                     ": contact is implemented between two bodies; use 1 or 2.");
  const double stiffest =
      std::max(bodies.bodies[0].youngs_modulus, bodies.bodies[1].youngs_modulus);
  // Facing nodes of the mirrored meshes coincide in r to round-off of the mesh generator.
  const double matching_tolerance = 1e-6 * shortest_edge;
  try
  {
    return std::make_unique<NodeToNodeContact<2>>(
        ContactSurface<2>(dof_handler, kinematics, nodes, SphereMeshIds::surface(0)),
        ContactSurface<2>(dof_handler, kinematics, nodes, SphereMeshIds::surface(1)),
        contact.penalty_factor * stiffest / shortest_edge,
        matching_tolerance);
  }
  catch (const InputError& error)
  {
    throw InputError("Mesh/file = '" + mesh.file + "': " + error.what());
  }
}

std::vector<types::global_dof_index>
AxisymmetricMeshModel::fixed_dofs(const NodeIndex<2>& nodes) const
{
  // u_r = 0 on the axis; "on the axis" with a tolerance far below any element size.
  std::vector<types::global_dof_index> dofs;
  for (const auto& node : nodes.nodes())
    if (std::abs(node.position[0]) <= 1e-9 * shortest_edge)
      dofs.push_back(node.dofs[0]);
  return dofs;
}

std::vector<Node<2>> AxisymmetricMeshModel::monitor_nodes(const NodeIndex<2>& nodes) const
{
  std::vector<Node<2>> monitors;
  for (unsigned int body = 0; body < n_bodies(); ++body)
    monitors.push_back(nodes.closest_node(body, bodies.bodies[body].monitor_point));
  return monitors;
}

std::vector<SurfaceTraction<2>> AxisymmetricMeshModel::surface_tractions() const
{
  std::vector<SurfaceTraction<2>> tractions;
  for (unsigned int body = 0; body < n_bodies(); ++body)
    tractions.push_back({SphereMeshIds::surface(body), bodies.bodies[body].surface_traction});
  return tractions;
}

Tensor<1, 2> AxisymmetricMeshModel::impact_direction() const
{
  Tensor<1, 2> axial;
  axial[1] = 1.;
  return axial;
}

void AxisymmetricMeshModel::print_summary(std::ostream& out, const double time_step) const
{
  out << "  axisymmetric mesh " << mesh.file << ": " << n_cells << " cells (9-node), shortest edge "
      << shortest_edge << "\n";
  for (unsigned int body = 0; body < n_bodies(); ++body)
  {
    const BodyParameters& parameters = bodies.bodies[body];
    out << "  body " << body + 1 << ": " << parameters.material
        << ", E = " << parameters.youngs_modulus << ", nu = " << parameters.poissons_ratio
        << ", rho = " << parameters.density << ", c_p = " << dilatational_wave_speed(body);
    if (body < spheres.size() && spheres[body].radius > 0.)
      out << ", sphere R = " << spheres[body].radius
          << " centred at z = " << spheres[body].centre[1];
    out << "\n";
  }
  out << "  Courant number c_p dt / h_min = "
      << highest_frequency() * time_step / (2. * std::sqrt(6.)) << "\n";
}
} // namespace dyncontact
