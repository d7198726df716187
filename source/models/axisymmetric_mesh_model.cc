#include <dyncontact/models/axisymmetric_mesh_model.h>
#include <dyncontact/reference/impact_measures.h>

#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dyncontact
{
AxisymmetricMeshModel::AxisymmetricMeshModel(const MeshParameters& mesh,
                                             const BodiesParameters& bodies,
                                             const std::vector<ContactPairParameters>& pairs)
    : mesh(mesh), bodies(bodies), declared_pairs(pairs), n_cells(0), shortest_edge(0.),
      largest_coordinate(0.), closest_boundary_vertices(0.)
{
}

void AxisymmetricMeshModel::create_triangulation(Triangulation<2>& triangulation)
{
  geometry = read_gmsh_mesh(mesh.file, mesh.geo_parameters, triangulation);
  std::vector<unsigned int> cells_of_body(n_bodies(), 0);
  std::vector<double> lowest_z(n_bodies(), std::numeric_limits<double>::max());
  std::vector<double> highest_z(n_bodies(), std::numeric_limits<double>::lowest());
  std::vector<std::vector<Point<2>>> boundary_vertices(n_bodies());
  shortest_edge      = std::numeric_limits<double>::max();
  largest_coordinate = 0.;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    const types::material_id body = cell->material_id();
    if (body >= n_bodies())
      throw InputError("Mesh/file = '" + mesh.file + "' has cells of body " +
                       std::to_string(body + 1) +
                       " but Bodies/number of bodies = " + std::to_string(n_bodies()) + ".");
    ++cells_of_body[body];
    for (unsigned int line = 0; line < cell->n_lines(); ++line)
      shortest_edge = std::min(shortest_edge, cell->line(line)->diameter());
    for (const unsigned int v : cell->vertex_indices())
    {
      const Point<2>& vertex = cell->vertex(v);
      largest_coordinate = std::max({largest_coordinate, std::abs(vertex[0]), std::abs(vertex[1])});
      lowest_z[body]     = std::min(lowest_z[body], vertex[1]);
      highest_z[body]    = std::max(highest_z[body], vertex[1]);
    }
    for (const auto& face : cell->face_iterators())
      if (face->at_boundary())
        for (const unsigned int v : face->vertex_indices())
          boundary_vertices[body].push_back(face->vertex(v));
  }
  for (unsigned int body = 0; body < n_bodies(); ++body)
    if (cells_of_body[body] == 0)
      throw InputError("Mesh/file = '" + mesh.file + "' has no cells of body " +
                       std::to_string(body + 1) + " (physical surface " + std::to_string(body + 1) +
                       "), but Bodies/number of bodies = " + std::to_string(n_bodies()) + ".");
  n_cells = triangulation.n_active_cells();
  body_heights.clear();
  for (unsigned int body = 0; body < n_bodies(); ++body)
    body_heights.push_back(highest_z[body] - lowest_z[body]);
  closest_boundary_vertices = std::numeric_limits<double>::max();
  if (n_bodies() == 2)
    for (const Point<2>& vertex_0 : boundary_vertices[0])
      for (const Point<2>& vertex_1 : boundary_vertices[1])
        closest_boundary_vertices =
            std::min(closest_boundary_vertices, vertex_0.distance(vertex_1));
}

double AxisymmetricMeshModel::touching_tolerance() const
{
  return std::max(1e-9 * shortest_edge,
                  8. * std::numeric_limits<double>::epsilon() * largest_coordinate);
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
  if (!std::isfinite(velocity[0]) || !std::isfinite(velocity[1]))
  {
    std::ostringstream message;
    message << "Bodies/Body " << body + 1 << "/Initial velocity/Function expression gives ("
            << velocity[0] << ", " << velocity[1] << ") at the node (r, z) = (" << X[0] << ", "
            << X[1] << ") of the body; the initial velocity must be finite at every node.";
    throw InputError(message.str());
  }
  return velocity;
}

ContactDescription<2> AxisymmetricMeshModel::contact_description(const NodeIndex<2>&) const
{
  std::vector<ContactPairParameters> pairs = declared_pairs;
  if (pairs.empty() && n_bodies() == 2)
    pairs.push_back({SphereMeshIds::surface(0),
                     SphereMeshIds::surface(1),
                     std::nullopt,
                     "Mesh/file = '" + mesh.file + "'"});
  if (pairs.empty() && n_bodies() > 2)
    throw InputError("Bodies/number of bodies = " + std::to_string(n_bodies()) +
                     ": with more than two bodies the contact pairs must be declared "
                     "(Contact/number of pairs and Contact/Pair k).");
  double stiffest = 0.;
  for (const BodyParameters& body : bodies.bodies)
    stiffest = std::max(stiffest, body.youngs_modulus);
  ContactDescription<2> description;
  for (const ContactPairParameters& pair : pairs)
  {
    const std::string source =
        declared_pairs.empty() ? pair.source : pair.source + " (Mesh/file = '" + mesh.file + "')";
    if (pair.master_boundary)
      // Facing nodes of mirrored meshes coincide in r to round-off of the mesh generator.
      description.surface_pairs.push_back({pair.slave_boundary,
                                           *pair.master_boundary,
                                           stiffest,
                                           shortest_edge,
                                           1e-6 * shortest_edge,
                                           search_radius(),
                                           touching_tolerance(),
                                           source});
    else
      description.plane_pairs.push_back({pair.slave_boundary,
                                         pair.rigid_plane->first,
                                         pair.rigid_plane->second,
                                         stiffest,
                                         shortest_edge,
                                         touching_tolerance(),
                                         source});
  }
  return description;
}

double AxisymmetricMeshModel::search_radius() const
{
  // The initial gap between the two spheres plus a quarter of the smaller radius: a head-on
  // impact's contact radius stays far below R / 4 in the small-strain regime (paper spheres:
  // a / R = 0.2 at rho = 0.001), and a slave node within R / 4 of the axis lies within
  // R / 4 + gap of the master surface. Other bodies: the gap measured between their boundary
  // vertices (at least the true gap) plus a quarter of the smaller height (R / 2 for a sphere,
  // more generous than the spheres' R / 4: a flat face has no curvature to bound the contact).
  const std::optional<SphereGeometry> sphere_0 = geometry.sphere(0), sphere_1 = geometry.sphere(1);
  if (!sphere_0 || !sphere_1)
    return closest_boundary_vertices + 0.25 * std::min(body_heights[0], body_heights[1]);
  const double distance = std::abs(sphere_1->centre[1] - sphere_0->centre[1]);
  const double gap      = std::max(0., distance - sphere_0->radius - sphere_1->radius);
  return gap + 0.25 * std::min(sphere_0->radius, sphere_1->radius);
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

std::optional<HertzImpact> AxisymmetricMeshModel::hertz_reference() const
{
  const std::optional<SphereGeometry> sphere_0 = geometry.sphere(0), sphere_1 = geometry.sphere(1);
  if (n_bodies() != 2 || !sphere_0 || !sphere_1)
    return std::nullopt;
  const SphereGeometry spheres[2] = {*sphere_0, *sphere_1};
  const BodyParameters &lower = bodies.bodies[0], &upper = bodies.bodies[1];
  const double distance = spheres[1].centre[1] - spheres[0].centre[1];
  const double approach_speed =
      (distance > 0. ? 1. : -1.) * (lower.initial_velocity->value(spheres[0].centre, 1) -
                                    upper.initial_velocity->value(spheres[1].centre, 1));
  // Spheres touching at t = 0 to the tolerance have gap zero: Hertz's impact starts at once.
  const double gap = std::abs(distance) - spheres[0].radius - spheres[1].radius;
  if (approach_speed <= 0. || gap < -touching_tolerance())
    return std::nullopt;
  const auto sphere = [&](const unsigned int b)
  {
    const BodyParameters& body = bodies.bodies[b];
    return ElasticSphere{spheres[b].radius, body.youngs_modulus, body.poissons_ratio, body.density};
  };
  return HertzImpact::two_spheres(sphere(0),
                                  sphere(1),
                                  approach_speed,
                                  gap <= touching_tolerance() ? 0. : gap / approach_speed);
}

void AxisymmetricMeshModel::write_reference(const std::string& directory,
                                            const std::vector<double>& times,
                                            const std::vector<Node<2>>&) const
{
  const auto hertz = hertz_reference();
  if (!hertz)
    return;
  std::ofstream file(directory + "/hertz.csv");
  file << "# Hertz's quasi-static impact of two spheres: R* = " << hertz->effective_radius()
       << ", E* = " << hertz->effective_modulus() << ", m* = " << hertz->effective_mass()
       << ", v = " << hertz->relative_approach_speed()
       << ", first touch t0 = " << hertz->first_touch_time() << "; peak force "
       << hertz->maximum_force() << ", duration " << hertz->contact_duration() << ", impulse "
       << hertz->impulse() << "\n";
  file << "time,contact_force,approach\n" << std::setprecision(15);
  for (const double time : times)
    file << time << "," << hertz->contact_force(time) << "," << hertz->approach(time) << "\n";
}

void AxisymmetricMeshModel::summarize_run(const std::string& directory,
                                          const History& history,
                                          std::ostream& log) const
{
  const auto hertz = hertz_reference();
  if (!hertz)
    return;
  if (history.n_rows() < 3)
  {
    log << "  no comparison with Hertz (impact_summary.csv): it needs at least 2 time steps.\n";
    return;
  }
  const ImpactMeasures fe = measure_impact(history.column("time"), history.column("contact_force"));
  struct Row
  {
    std::string quantity;
    double computed, reference;
  };
  const std::vector<Row> rows = {
      {"peak_force", fe.peak_force, hertz->maximum_force()},
      {"peak_time", fe.peak_time, hertz->first_touch_time() + 0.5 * hertz->contact_duration()},
      {"contact_start", fe.contact_start, hertz->first_touch_time()},
      {"contact_end", fe.contact_end, hertz->first_touch_time() + hertz->contact_duration()},
      {"duration", fe.duration, hertz->contact_duration()},
      {"impulse", fe.impulse, hertz->impulse()},
      {"ringing", fe.ringing, 0.}};
  std::ofstream file(directory + "/impact_summary.csv");
  file << "quantity,computed,hertz,relative_difference\n" << std::setprecision(12);
  log << "  impact against Hertz (computed / Hertz / relative difference):\n";
  for (const Row& row : rows)
  {
    const double difference =
        row.reference != 0. ? (row.computed - row.reference) / row.reference : 0.;
    file << row.quantity << "," << row.computed << "," << row.reference << "," << difference
         << "\n";
    log << "    " << std::left << std::setw(14) << row.quantity << std::right << std::setw(14)
        << row.computed << std::setw(14) << row.reference << std::setw(14) << difference << "\n";
  }
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
    if (const std::optional<SphereGeometry> sphere = geometry.sphere(body))
      out << ", sphere R = " << sphere->radius << " centred at z = " << sphere->centre[1];
    out << "\n";
  }
  out << "  Courant number c_p dt / h_min = "
      << highest_frequency() * time_step / (2. * std::sqrt(6.)) << "\n";
}
} // namespace dyncontact
