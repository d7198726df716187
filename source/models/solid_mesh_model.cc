#include <dyncontact/models/body_properties.h>
#include <dyncontact/models/solid_mesh_model.h>
#include <dyncontact/reference/impact_summary.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <utility>

namespace dyncontact
{
namespace
{
/** "(x, y, z)" of a point, for messages. */
std::string point_text(const Point<3>& point)
{
  return "(" + format_number(point[0]) + ", " + format_number(point[1]) + ", " +
         format_number(point[2]) + ")";
}
} // namespace

SolidMeshModel::SolidMeshModel(const MeshParameters& mesh,
                               const BodiesParameters& bodies,
                               const std::vector<ContactPairParameters>& pairs,
                               const BoundaryParameters& boundary)
    : mesh(mesh), bodies(bodies), boundary(boundary), pairs(pairs), n_cells(0), shortest_edge(0.),
      largest_coordinate(0.)
{
  for (const BodyParameters& body : bodies.bodies)
  {
    initial_velocities.push_back(body.initial_velocity.create<3>(3));
    tractions.push_back(body.surface_traction.create<3>(3));
    forces.push_back(body.body_force.create<3>(3));
  }
}

void SolidMeshModel::create_triangulation(Triangulation<3>& triangulation)
{
  geometry = read_gmsh_solid_mesh(mesh.file, mesh.geo_parameters, triangulation);
  if (geometry.n_bodies != n_bodies())
    throw InputError(
        "Mesh/file = '" + mesh.file + "' has " + std::to_string(geometry.n_bodies) +
        (geometry.n_bodies == 1 ? " body (physical volume)" : " bodies (physical volumes)") +
        " but Bodies/number of bodies = " + std::to_string(n_bodies()) + ".");
  largest_cell_diameter.assign(n_bodies(), 0.);
  boundary_vertices.assign(n_bodies(), {});
  std::set<unsigned int> counted_vertices;
  shortest_edge      = std::numeric_limits<double>::max();
  largest_coordinate = 0.;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    double& largest = largest_cell_diameter[cell->material_id()];
    largest         = std::max(largest, cell->diameter());
    for (unsigned int line = 0; line < cell->n_lines(); ++line)
      shortest_edge = std::min(shortest_edge, cell->line(line)->diameter());
    for (const unsigned int v : cell->vertex_indices())
      for (unsigned int d = 0; d < 3; ++d)
        largest_coordinate = std::max(largest_coordinate, std::abs(cell->vertex(v)[d]));
    for (const auto& face : cell->face_iterators())
      if (face->at_boundary())
        for (const unsigned int v : face->vertex_indices())
          if (counted_vertices.insert(face->vertex_index(v)).second) // each vertex once
            boundary_vertices[cell->material_id()].push_back(face->vertex(v));
  }
  // A body's extreme points lie on its boundary.
  body_boxes.clear();
  for (const std::vector<Point<3>>& vertices : boundary_vertices)
    body_boxes.emplace_back(vertices);
  n_cells = triangulation.n_active_cells();
  // Volumes over each cell in the Q2 mapping of the manifolds (exact for straight cells).
  const MappingQ<3> mapping(2);
  const FE_Q<3> linear(1);
  FEValues<3> cell_values(
      mapping, linear, QGauss<3>(4), update_quadrature_points | update_JxW_values);
  body_volumes.assign(n_bodies(), 0.);
  body_centroids.assign(n_bodies(), Point<3>());
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    cell_values.reinit(cell);
    for (const unsigned int q : cell_values.quadrature_point_indices())
    {
      body_volumes[cell->material_id()] += cell_values.JxW(q);
      body_centroids[cell->material_id()] += cell_values.JxW(q) * cell_values.quadrature_point(q);
    }
  }
  for (unsigned int body = 0; body < n_bodies(); ++body)
    body_centroids[body] /= body_volumes[body];
}

void SolidMeshModel::attach_manifolds(Triangulation<3>& triangulation) const
{
  dyncontact::attach_manifolds(geometry, triangulation);
}

std::vector<BodyMaterial> SolidMeshModel::body_materials() const
{
  return dyncontact::body_materials(bodies);
}

std::unique_ptr<Kinematics<3>> SolidMeshModel::create_kinematics() const
{
  return std::make_unique<SolidKinematics>();
}

Tensor<1, 3> SolidMeshModel::initial_velocity(const types::material_id body,
                                              const Point<3>& X) const
{
  Tensor<1, 3> velocity;
  for (unsigned int d = 0; d < 3; ++d)
    velocity[d] = initial_velocities[body]->value(X, d);
  if (!std::isfinite(velocity.norm_square()))
    throw InputError("Bodies/Body " + std::to_string(body + 1) +
                     "/Initial velocity/Function expression gives (" + format_number(velocity[0]) +
                     ", " + format_number(velocity[1]) + ", " + format_number(velocity[2]) +
                     ") at the node " + point_text(X) +
                     " of the body; the initial velocity must be finite at every node.");
  return velocity;
}

const BoundarySurface& SolidMeshModel::find_surface(const types::boundary_id id,
                                                    const std::string& entry) const
{
  const BoundarySurface* surface = geometry.surface(id);
  if (surface == nullptr)
    throw InputError(entry + " = " + std::to_string(id) + ": Mesh/file = '" + mesh.file +
                     "' has no boundary surface " + std::to_string(id) + " (physical surface).");
  return *surface;
}

double SolidMeshModel::search_radius(const unsigned int body_a, const unsigned int body_b) const
{
  // As MeshModel's for bodies other than spheres: the gap measured between their boundary vertices
  // (at least the true gap) plus a quarter of the smaller extent of the two bodies.
  double closest = std::numeric_limits<double>::max();
  for (const Point<3>& a : boundary_vertices[body_a])
    for (const Point<3>& b : boundary_vertices[body_b])
      closest = std::min(closest, a.distance(b));
  double extent = std::numeric_limits<double>::max();
  for (const unsigned int body : {body_a, body_b})
    for (unsigned int d = 0; d < 3; ++d)
      extent = std::min(extent, body_boxes[body].side_length(d));
  return closest + 0.25 * extent;
}

double SolidMeshModel::touching_tolerance() const
{
  return dyncontact::touching_tolerance(shortest_edge, largest_coordinate);
}

ContactDescription<3> SolidMeshModel::contact_description(const NodeIndex<3>&) const
{
  if (pairs.empty() && n_bodies() > 1)
    throw InputError("Bodies/number of bodies = " + std::to_string(n_bodies()) +
                     ": in 3D the contact pairs must be declared (Contact/number of pairs and "
                     "Contact/Pair k); the bodies would otherwise pass through each other.");
  double stiffest = 0.;
  for (const BodyParameters& body : bodies.bodies)
    stiffest = std::max(stiffest, body.youngs_modulus);
  ContactDescription<3> description;
  for (const ContactPairParameters& pair : pairs)
  {
    const BoundarySurface& slave =
        find_surface(pair.slave_boundary, pair.source + "/slave boundary");
    if (!pair.master_boundary)
    {
      Point<3> point;
      Tensor<1, 3> normal;
      for (unsigned int d = 0; d < 3; ++d)
      {
        point[d]  = pair.rigid_plane->point[d];
        normal[d] = pair.rigid_plane->normal[d];
      }
      description.plane_pairs.push_back({pair.slave_boundary,
                                         point,
                                         normal,
                                         stiffest,
                                         shortest_edge,
                                         touching_tolerance(),
                                         pair.source,
                                         pair.friction_coefficient});
      continue;
    }
    const BoundarySurface& master =
        find_surface(*pair.master_boundary, pair.source + "/master boundary");
    if (slave.body == master.body)
      throw InputError(pair.source + ": slave boundary " + std::to_string(slave.id) +
                       " and master boundary " + std::to_string(master.id) + " are both on body " +
                       std::to_string(slave.body + 1) +
                       "; contact of a body with itself is not implemented.");
    // Node-to-node pairs facing nodes that coincide across to round-off of the mesh generator.
    description.surface_pairs.push_back({pair.slave_boundary,
                                         *pair.master_boundary,
                                         stiffest,
                                         shortest_edge,
                                         1e-6 * shortest_edge,
                                         search_radius(slave.body, master.body),
                                         touching_tolerance(),
                                         pair.source + " (Mesh/file = '" + mesh.file + "')",
                                         pair.friction_coefficient});
  }
  return description;
}

std::vector<FixedBoundary> SolidMeshModel::fixed_boundaries() const
{
  std::vector<FixedBoundary> fixed;
  for (unsigned int k = 0; k < boundary.symmetry_planes.size(); ++k)
  {
    const std::string name = "Boundary/Symmetry " + std::to_string(k + 1);
    const BoundarySurface& surface =
        find_surface(boundary.symmetry_planes[k].boundary, name + "/boundary");
    if (!surface.plane)
      throw InputError(name + "/boundary = " + std::to_string(surface.id) +
                       " is a sphere, not a plane: a symmetry plane must be a plane with its "
                       "normal along x, y or z.");
    // The normal as read_gmsh_solid_mesh() fitted it, to round-off of the vertices.
    const Tensor<1, 3>& normal = surface.plane->normal;
    std::optional<unsigned int> normal_axis;
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(std::abs(normal[d]) - 1.) <= 1e-12)
        normal_axis = d;
    if (!normal_axis)
    {
      std::ostringstream text;
      text << "(" << normal[0] << ", " << normal[1] << ", " << normal[2] << ")";
      throw InputError(name + "/boundary = " + std::to_string(surface.id) +
                       " is a plane whose normal " + text.str() +
                       " is not along x, y or z: a symmetry plane must have its normal along a "
                       "coordinate axis.");
    }
    fixed.push_back({surface.id, {*normal_axis}});
  }
  for (const HeldBoundary& held : boundary.held_boundaries())
  {
    find_surface(held.where.boundary, held.section + "/boundary");
    fixed.push_back({held.where.boundary, held.where.components, held.displacement, held.section});
  }
  return fixed;
}

std::vector<Node<3>> SolidMeshModel::monitor_nodes(const NodeIndex<3>& nodes) const
{
  std::vector<Node<3>> monitors;
  for (unsigned int body = 0; body < n_bodies(); ++body)
  {
    const std::vector<double>& given = bodies.bodies[body].monitor_point;
    const Point<3> point =
        given.empty() ? body_centroids[body] : Point<3>(given[0], given[1], given[2]);
    monitors.push_back(nodes.closest_node(body, point));
    if (given.empty())
      continue;
    // Inside a cell of the body a point is within that cell's diameter of one of its nodes.
    const double distance = point.distance(monitors.back().position);
    if (distance > largest_cell_diameter[body])
      throw InputError("Bodies/Body " + std::to_string(body + 1) +
                       "/monitor point = " + point_text(point) + " is " + format_number(distance) +
                       " from the nearest node of body " + std::to_string(body + 1) + " at " +
                       point_text(monitors.back().position) + ", farther than its largest cell (" +
                       format_number(largest_cell_diameter[body]) + "): give a point in the body.");
  }
  return monitors;
}

std::vector<SurfaceTraction<3>> SolidMeshModel::surface_tractions() const
{
  std::vector<SurfaceTraction<3>> loads;
  for (const BoundarySurface& surface : geometry.surfaces)
    if (!bodies.bodies[surface.body].surface_traction.is_zero())
      loads.push_back({surface.id, tractions[surface.body]});
  return loads;
}

std::vector<BodyForce<3>> SolidMeshModel::body_forces() const
{
  return dyncontact::body_forces(bodies, forces);
}

Tensor<1, 3> SolidMeshModel::impact_direction() const
{
  return Point<3>::unit_vector(2);
}

std::vector<Tensor<1, 3>> SolidMeshModel::momentum_directions() const
{
  return {Point<3>::unit_vector(0), Point<3>::unit_vector(1), Point<3>::unit_vector(2)};
}

double SolidMeshModel::whole_body_factor() const
{
  // fixed_boundaries() lists the symmetry planes first, each x_d = c with its axis d; the same d
  // and c to 1e-6 of the shortest edge is the same plane.
  const std::vector<FixedBoundary> fixed = fixed_boundaries();
  std::vector<std::pair<unsigned int, double>> planes;
  for (unsigned int k = 0; k < boundary.symmetry_planes.size(); ++k)
  {
    const unsigned int axis = fixed[k].components.front();
    const double offset     = find_surface(fixed[k].boundary, "").plane->point[axis];
    const auto same         = [&](const std::pair<unsigned int, double>& other)
    { return other.first == axis && std::abs(other.second - offset) <= 1e-6 * shortest_edge; };
    if (std::none_of(planes.begin(), planes.end(), same))
      planes.emplace_back(axis, offset);
  }
  return std::pow(2., planes.size());
}

std::optional<SolidMeshModel::SphereOnPlane> SolidMeshModel::sphere_on_plane() const
{
  if (pairs.size() != 1 || pairs.front().master_boundary)
    return std::nullopt;
  const ContactPairParameters& pair = pairs.front();
  const BoundarySurface* slave      = geometry.surface(pair.slave_boundary);
  const std::vector<double>& normal = pair.rigid_plane->normal;
  if (slave == nullptr || !slave->sphere || std::abs(std::abs(normal[2]) - 1.) > 1e-12)
    return std::nullopt;
  const SurfaceSphere& sphere = *slave->sphere;
  const double tolerance      = 1e-9 * sphere.radius;
  // Symmetry planes through the centre containing the plane's normal z cut the sphere into equal
  // parts, each with its share of the pole.
  std::set<types::boundary_id> symmetry;
  for (const SymmetryParameters& plane : boundary.symmetry_planes)
  {
    const BoundarySurface* surface = geometry.surface(plane.boundary);
    if (surface == nullptr || !surface->plane || surface->body != slave->body ||
        std::abs(surface->plane->normal[2]) > 1e-12 ||
        std::abs((sphere.centre - surface->plane->point) * surface->plane->normal) > tolerance)
      return std::nullopt;
    symmetry.insert(plane.boundary);
  }
  const double plane_normal_z = normal[2] > 0. ? 1. : -1.;
  // The pole, the sphere's point nearest the plane, must be the body's extreme point toward it
  // (a cap, not a seat or a patch away from the pole), and no other boundary of the body may pass
  // through it but the symmetry planes (a free face there is no Hertz contact).
  Point<3> pole = sphere.centre;
  pole[2] -= plane_normal_z * sphere.radius;
  const BoundingBox<3>& box = body_boxes[slave->body];
  const double extreme_z    = plane_normal_z > 0. ? box.lower_bound(2) : box.upper_bound(2);
  if (std::abs(extreme_z - pole[2]) > tolerance)
    return std::nullopt;
  bool whole_sphere = true;
  for (const BoundarySurface& surface : geometry.surfaces)
    if (surface.body == slave->body && surface.id != slave->id && symmetry.count(surface.id) == 0)
    {
      whole_sphere = false;
      if (!surface.plane ||
          std::abs((pole - surface.plane->point) * surface.plane->normal) <= tolerance)
        return std::nullopt;
    }
  const double speed = -plane_normal_z * initial_velocities[slave->body]->value(sphere.centre, 2);
  double gap = plane_normal_z * (sphere.centre[2] - pair.rigid_plane->point[2]) - sphere.radius;
  if (!(speed > 0.) || gap < -touching_tolerance())
    return std::nullopt;
  if (gap <= touching_tolerance())
    gap = 0.;
  return SphereOnPlane{slave->body, sphere, speed, gap, plane_normal_z, whole_sphere};
}

std::optional<HertzImpact> SolidMeshModel::hertz_reference() const
{
  const std::optional<SphereOnPlane> impact = sphere_on_plane();
  if (!impact)
    return std::nullopt;
  const BodyParameters& body = bodies.bodies[impact->body];
  const double mass =
      impact->whole_sphere
          ? sphere_mass(
                {impact->sphere.radius, body.youngs_modulus, body.poissons_ratio, body.density})
          : body.density * body_volumes[impact->body] * whole_body_factor();
  constexpr double infinity = std::numeric_limits<double>::infinity();
  return HertzImpact(impact->sphere.radius,
                     effective_modulus(body.youngs_modulus, body.poissons_ratio, infinity, 0.),
                     effective_mass(mass, infinity),
                     impact->approach_speed,
                     impact->gap / impact->approach_speed);
}

std::optional<FiniteSphereImpact> SolidMeshModel::finite_sphere_reference() const
{
  const std::optional<SphereOnPlane> impact = sphere_on_plane();
  if (!impact || !impact->whole_sphere)
    return std::nullopt;
  const BodyParameters& body = bodies.bodies[impact->body];
  const ElasticSphere sphere{
      impact->sphere.radius, body.youngs_modulus, body.poissons_ratio, body.density};
  // The law's C0 is known for nu = 0.3 only (FiniteSphereImpact): no reference otherwise.
  try
  {
    return FiniteSphereImpact(
        sphere, sphere, 2. * impact->approach_speed, impact->gap / impact->approach_speed);
  }
  catch (const std::exception&)
  {
    return std::nullopt;
  }
}

void SolidMeshModel::write_reference(const std::string& directory,
                                     const std::vector<double>& times,
                                     const std::vector<Node<3>>&) const
{
  // Against the rigid plane the law is that of the mirrored pair, whose approach is twice the
  // sphere's.
  if (const auto hertz = hertz_reference())
    write_impact_references(directory, times, *hertz, finite_sphere_reference(), 0.5);
}

void SolidMeshModel::summarize_run(const std::string& directory,
                                   const History& history,
                                   const std::vector<double>& contact_impulses,
                                   const std::string& status,
                                   std::ostream& log) const
{
  const std::optional<SphereOnPlane> impact = sphere_on_plane();
  if (!impact)
    return;
  // contact_impulses[b] is along z; the plane pushes the sphere along its normal.
  write_impact_summary(directory,
                       history,
                       whole_body_factor(),
                       impact->plane_normal_z * contact_impulses[impact->body] *
                           whole_body_factor(),
                       *hertz_reference(),
                       finite_sphere_reference(),
                       status,
                       log);
}

void SolidMeshModel::print_summary(std::ostream& out, const double time_step) const
{
  out << "  3d mesh " << mesh.file << ": " << n_cells << " cells (27-node), shortest edge "
      << shortest_edge << "\n";
  double speed = 0.;
  for (unsigned int body = 0; body < n_bodies(); ++body)
  {
    const BodyParameters& parameters = bodies.bodies[body];
    speed                            = std::max(speed, dilatational_wave_speed(parameters));
    out << "  body " << body + 1 << ": " << parameters.material
        << ", E = " << parameters.youngs_modulus << ", nu = " << parameters.poissons_ratio
        << ", rho = " << parameters.density << ", c_p = " << dilatational_wave_speed(parameters)
        << "\n";
  }
  out << "  Courant number c_p dt / h_min = " << speed * time_step / shortest_edge << "\n";
  if (const auto hertz = hertz_reference())
    out << "  reference: Hertz's impact of the "
        << (sphere_on_plane()->whole_sphere ? "whole sphere" : "body's spherical end")
        << " on the rigid plane (hertz.csv, impact_summary.csv; the model's force times "
        << whole_body_factor() << "): R = " << hertz->effective_radius()
        << ", E* = " << hertz->effective_modulus() << ", m = " << hertz->effective_mass()
        << ", first touch t = " << hertz->first_touch_time() << ", peak force "
        << hertz->maximum_force() << ", duration " << hertz->contact_duration()
        << (finite_sphere_reference() ? "; and the finite-sphere law (finite_sphere.csv)" : "")
        << "\n";
  else
    out << "  reference: none (Hertz needs one pair, a sphere approaching a rigid plane "
           "perpendicular to z, its pole on no boundary of the body but symmetry planes)\n";
}
} // namespace dyncontact
