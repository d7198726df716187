#include <dyncontact/models/body_properties.h>
#include <dyncontact/models/mesh_model.h>
#include <dyncontact/reference/impact_summary.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace dyncontact
{
MeshModel::MeshModel(const MeshParameters& mesh,
                     const BodiesParameters& bodies,
                     const std::vector<ContactPairParameters>& pairs,
                     const MeshSection section,
                     const BoundaryParameters& boundary)
    : mesh(mesh), bodies(bodies), section(section), boundary(boundary), declared_pairs(pairs),
      n_cells(0), shortest_edge(0.), largest_coordinate(0.), closest_boundary_vertices(0.)
{
  for (const BodyParameters& body : bodies.bodies)
  {
    initial_velocities.push_back(body.initial_velocity.create<2>(2));
    tractions.push_back(body.surface_traction.create<2>(2));
    forces.push_back(body.body_force.create<2>(2));
  }
}

void MeshModel::create_triangulation(Triangulation<2>& triangulation)
{
  geometry = read_gmsh_mesh(mesh.file, mesh.geo_parameters, triangulation, section);
  std::vector<unsigned int> cells_of_body(n_bodies(), 0);
  body_lowest_z.assign(n_bodies(), std::numeric_limits<double>::max());
  body_highest_z.assign(n_bodies(), std::numeric_limits<double>::lowest());
  std::vector<std::vector<Point<2>>> boundary_vertices(n_bodies());
  largest_cell_diameter.assign(n_bodies(), 0.);
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
    largest_cell_diameter[body] = std::max(largest_cell_diameter[body], cell->diameter());
    for (unsigned int line = 0; line < cell->n_lines(); ++line)
      shortest_edge = std::min(shortest_edge, cell->line(line)->diameter());
    for (const unsigned int v : cell->vertex_indices())
    {
      const Point<2>& vertex = cell->vertex(v);
      largest_coordinate = std::max({largest_coordinate, std::abs(vertex[0]), std::abs(vertex[1])});
      body_lowest_z[body]  = std::min(body_lowest_z[body], vertex[1]);
      body_highest_z[body] = std::max(body_highest_z[body], vertex[1]);
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
  // Volumes (of revolution: 2 pi r) over each cell in the Q2 mapping of the manifolds.
  const MappingQ<2> mapping(2);
  const FE_Q<2> linear(1);
  FEValues<2> cell_values(
      mapping, linear, QGauss<2>(4), update_quadrature_points | update_JxW_values);
  const std::unique_ptr<Kinematics<2>> kinematics = create_kinematics();
  body_volumes.assign(n_bodies(), 0.);
  body_centroids.assign(n_bodies(), Point<2>());
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    cell_values.reinit(cell);
    for (const unsigned int q : cell_values.quadrature_point_indices())
    {
      const Point<2>& point = cell_values.quadrature_point(q);
      const double volume =
          kinematics->measure_factor(point, cell->material_id()) * cell_values.JxW(q);
      body_volumes[cell->material_id()] += volume;
      body_centroids[cell->material_id()] += volume * point;
    }
  }
  for (unsigned int body = 0; body < n_bodies(); ++body)
  {
    body_centroids[body] /= body_volumes[body];
    // A body of revolution has its centroid on the axis.
    if (section == MeshSection::axisymmetric)
      body_centroids[body][0] = 0.;
  }
  closest_boundary_vertices = std::numeric_limits<double>::max();
  if (n_bodies() == 2)
    for (const Point<2>& vertex_0 : boundary_vertices[0])
      for (const Point<2>& vertex_1 : boundary_vertices[1])
        closest_boundary_vertices =
            std::min(closest_boundary_vertices, vertex_0.distance(vertex_1));
}

void MeshModel::attach_manifolds(Triangulation<2>& triangulation) const
{
  dyncontact::attach_manifolds(geometry, triangulation);
}

double MeshModel::touching_tolerance() const
{
  return dyncontact::touching_tolerance(shortest_edge, largest_coordinate);
}

std::vector<BodyMaterial> MeshModel::body_materials() const
{
  return dyncontact::body_materials(bodies);
}

std::unique_ptr<Kinematics<2>> MeshModel::create_kinematics() const
{
  if (section == MeshSection::plane_strain)
    return std::make_unique<PlaneStrainKinematics>();
  return std::make_unique<AxisymmetricKinematics>();
}

Tensor<1, 2> MeshModel::initial_velocity(const types::material_id body, const Point<2>& X) const
{
  Tensor<1, 2> velocity;
  for (unsigned int d = 0; d < 2; ++d)
    velocity[d] = initial_velocities[body]->value(X, d);
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

ContactDescription<2> MeshModel::contact_description(const NodeIndex<2>&) const
{
  const std::vector<ContactPairParameters> pairs = effective_pairs();
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
    if (section == MeshSection::axisymmetric)
      for (const auto& [role, id] :
           {std::pair<std::string, types::boundary_id>{"slave", pair.slave_boundary},
            {"master", pair.master_boundary.value_or(0)}})
        if (id == SphereMeshIds::axis)
          throw InputError(source + ": " + role +
                           " boundary = 1 is the symmetry axis of an axisymmetric mesh (physical "
                           "curve 1), not a contact surface.");
    const BoundaryCurve* slave = geometry.curve(pair.slave_boundary);
    const BoundaryCurve* master =
        pair.master_boundary ? geometry.curve(*pair.master_boundary) : nullptr;
    if (slave != nullptr && master != nullptr && slave->body == master->body)
      throw InputError(source + ": slave boundary " + std::to_string(pair.slave_boundary) +
                       " and master boundary " + std::to_string(*pair.master_boundary) +
                       " are both on body " + std::to_string(slave->body + 1) +
                       "; contact of a body with itself is not implemented.");
    if (pair.master_boundary)
      // Facing nodes of mirrored meshes coincide in r to round-off of the mesh generator.
      description.surface_pairs.push_back({pair.slave_boundary,
                                           *pair.master_boundary,
                                           stiffest,
                                           shortest_edge,
                                           1e-6 * shortest_edge,
                                           search_radius(),
                                           touching_tolerance(),
                                           source,
                                           pair.friction_coefficient});
    else
      description.plane_pairs.push_back(
          {pair.slave_boundary,
           Point<2>(pair.rigid_plane->point[0], pair.rigid_plane->point[1]),
           Tensor<1, 2>({pair.rigid_plane->normal[0], pair.rigid_plane->normal[1]}),
           stiffest,
           shortest_edge,
           touching_tolerance(),
           source,
           pair.friction_coefficient});
  }
  return description;
}

double MeshModel::search_radius() const
{
  // The initial gap between the two spheres plus a quarter of the smaller radius: a head-on
  // impact's contact radius stays far below R / 4 in the small-strain regime (paper spheres:
  // a / R = 0.2 at rho = 0.001), and a slave node within R / 4 of the axis lies within
  // R / 4 + gap of the master surface. Other bodies: the gap measured between their boundary
  // vertices (at least the true gap) plus a quarter of the smaller height (R / 2 for a sphere,
  // more generous than the spheres' R / 4: a flat face has no curvature to bound the contact).
  const std::optional<SphereGeometry> sphere_0 = geometry.sphere(0), sphere_1 = geometry.sphere(1);
  if (!sphere_0 || !sphere_1)
    return closest_boundary_vertices + 0.25 * std::min(body_highest_z[0] - body_lowest_z[0],
                                                       body_highest_z[1] - body_lowest_z[1]);
  const double distance = sphere_1->centre.distance(sphere_0->centre);
  const double gap      = std::max(0., distance - sphere_0->radius - sphere_1->radius);
  return gap + 0.25 * std::min(sphere_0->radius, sphere_1->radius);
}

std::vector<types::global_dof_index> MeshModel::fixed_dofs(const NodeIndex<2>& nodes) const
{
  // u_r = 0 on the axis; "on the axis" with a tolerance far below any element size.
  std::vector<types::global_dof_index> dofs;
  if (section != MeshSection::axisymmetric)
    return dofs;
  for (const auto& node : nodes.nodes())
    if (std::abs(node.position[0]) <= 1e-9 * shortest_edge)
      dofs.push_back(node.dofs[0]);
  return dofs;
}

std::vector<FixedBoundary> MeshModel::fixed_boundaries() const
{
  std::vector<FixedBoundary> fixed;
  const auto find_curve = [this](const types::boundary_id id, const std::string& section_name)
  {
    const BoundaryCurve* curve = geometry.curve(id);
    if (curve == nullptr)
      throw InputError(section_name + "/boundary = " + std::to_string(id) + ": Mesh/file = '" +
                       mesh.file + "' has no boundary curve " + std::to_string(id) + ".");
    return curve;
  };
  for (unsigned int k = 0; k < boundary.symmetry_planes.size(); ++k)
  {
    const std::string name      = "Boundary/Symmetry " + std::to_string(k + 1);
    const types::boundary_id id = boundary.symmetry_planes[k].boundary;
    const BoundaryCurve* curve  = find_curve(id, name);
    // The normal of a straight curve as read_gmsh_mesh() fitted it, to round-off of the vertices.
    std::optional<unsigned int> normal_axis;
    for (unsigned int d = 0; d < 2; ++d)
      if (curve->line && std::abs(std::abs(curve->line->second[d]) - 1.) <= 1e-12)
        normal_axis = d;
    if (!normal_axis)
      throw InputError(name + "/boundary = " + std::to_string(id) + " is " +
                       (curve->line ? "a straight line whose normal is not along x or y"
                                    : "not a straight line") +
                       ": a symmetry plane must be a straight boundary with its normal along x (r) "
                       "or y (z).");
    fixed.push_back({id, {*normal_axis}});
  }
  for (const HeldBoundary& held : boundary.held_boundaries())
  {
    find_curve(held.where.boundary, held.section);
    fixed.push_back({held.where.boundary, held.where.components, held.displacement, held.section});
  }
  return fixed;
}

std::vector<Node<2>> MeshModel::monitor_nodes(const NodeIndex<2>& nodes) const
{
  std::vector<Node<2>> monitors;
  for (unsigned int body = 0; body < n_bodies(); ++body)
  {
    const std::vector<double>& given = bodies.bodies[body].monitor_point;
    const Point<2> point = given.empty() ? body_centroids[body] : Point<2>(given[0], given[1]);
    monitors.push_back(nodes.closest_node(body, point));
    if (given.empty())
      continue;
    // Inside a cell of the body a point is within that cell's diameter of one of its nodes.
    const Point<2>& node  = monitors.back().position;
    const double distance = point.distance(node);
    const auto text       = [](const Point<2>& p)
    { return "(" + format_number(p[0]) + ", " + format_number(p[1]) + ")"; };
    if (distance > largest_cell_diameter[body])
      throw InputError(
          "Bodies/Body " + std::to_string(body + 1) + "/monitor point = " + text(point) + " is " +
          format_number(distance) + " from the nearest node of body " + std::to_string(body + 1) +
          " at " + text(node) + ", farther than its largest cell (" +
          format_number(largest_cell_diameter[body]) + "): give a point in the body (" +
          (section == MeshSection::axisymmetric ? "r >= 0, z" : "y") + " within " +
          format_number(body_lowest_z[body]) + ".." + format_number(body_highest_z[body]) + ").");
  }
  return monitors;
}

std::vector<SurfaceTraction<2>> MeshModel::surface_tractions() const
{
  std::vector<SurfaceTraction<2>> surface_loads;
  for (const BoundaryCurve& curve : geometry.curves)
    if (!bodies.bodies[curve.body].surface_traction.is_zero())
      surface_loads.push_back({curve.id, tractions[curve.body]});
  return surface_loads;
}

std::vector<BodyForce<2>> MeshModel::body_forces() const
{
  return dyncontact::body_forces(bodies, forces);
}

Tensor<1, 2> MeshModel::impact_direction() const
{
  Tensor<1, 2> axial;
  axial[1] = 1.;
  return axial;
}

std::vector<Tensor<1, 2>> MeshModel::momentum_directions() const
{
  if (section == MeshSection::axisymmetric)
    return {impact_direction()};
  return {Point<2>::unit_vector(0), Point<2>::unit_vector(1)};
}

std::vector<ContactPairParameters> MeshModel::effective_pairs() const
{
  if (!declared_pairs.empty() || n_bodies() != 2)
    return declared_pairs;
  return {{SphereMeshIds::surface(0),
           SphereMeshIds::surface(1),
           std::nullopt,
           "the default pair of Contact/number of pairs = 0 (curve " +
               std::to_string(SphereMeshIds::surface(0)) + " of body 1 with curve " +
               std::to_string(SphereMeshIds::surface(1)) +
               " of body 2, as in the sphere meshes; declare Contact/Pair 1 for others), Mesh/file "
               "= '" +
               mesh.file + "'",
           std::nullopt}};
}

std::optional<MeshModel::ImpactSide> MeshModel::impact_side(const types::boundary_id id) const
{
  const BoundaryCurve* curve = geometry.curve(id);
  if (curve == nullptr)
    return std::nullopt;
  if (curve->circle)
    return ImpactSide{curve->circle, 0., curve->body, geometry.sphere(curve->body).has_value()};
  if (curve->line && std::abs(std::abs(curve->line->second[1]) - 1.) <= 1e-12)
    return ImpactSide{std::nullopt, curve->line->first[1], curve->body, false};
  return std::nullopt;
}

std::optional<MeshModel::HeadOnImpact> MeshModel::head_on_impact() const
{
  const std::vector<ContactPairParameters> pairs = effective_pairs();
  if (section != MeshSection::axisymmetric || pairs.size() != 1)
    return std::nullopt;
  const ContactPairParameters& pair = pairs.front();
  std::optional<ImpactSide> first   = impact_side(pair.slave_boundary), second;
  if (pair.master_boundary)
    second = impact_side(*pair.master_boundary);
  else if (std::abs(std::abs(pair.rigid_plane->normal[1]) - 1.) <= 1e-12)
    second = ImpactSide{std::nullopt, pair.rigid_plane->point[1], std::nullopt, false};
  if (!first || !second)
    return std::nullopt;
  if (!first->sphere)
    std::swap(first, second);
  if (!first->sphere)
    return std::nullopt;
  const Point<2>& centre = first->sphere->centre;
  // The other side's position and velocity along the axis: its centre, or its flat surface.
  const double other_z = second->sphere ? second->sphere->centre[1] : second->surface_z;
  const double velocity_of_other =
      second->body ? initial_velocities[*second->body]->value(
                         second->sphere ? second->sphere->centre : Point<2>(0., other_z), 1)
                   : 0.;
  const double direction = other_z > centre[1] ? 1. : -1.;
  const double approach_speed =
      direction * (initial_velocities[*first->body]->value(centre, 1) - velocity_of_other);
  // Bodies touching at t = 0 to the tolerance have gap zero: the impact starts at once.
  double gap = std::abs(other_z - centre[1]) - first->sphere->radius -
               (second->sphere ? second->sphere->radius : 0.);
  if (approach_speed <= 0. || gap < -touching_tolerance())
    return std::nullopt;
  // A spherical end is Hertz's only where its pole, on the axis, is the body's extreme point
  // toward the other side (a cap, not a ring cut from a circle or a concave seat).
  const auto pole_faces = [&](const ImpactSide& side, const double toward)
  {
    if (!side.sphere || side.whole_sphere)
      return true;
    const double pole    = side.sphere->centre[1] + toward * side.sphere->radius;
    const double extreme = toward > 0. ? body_highest_z[*side.body] : body_lowest_z[*side.body];
    return std::abs(pole - extreme) <= touching_tolerance();
  };
  if (!pole_faces(*first, direction) || !pole_faces(*second, -direction))
    return std::nullopt;
  if (gap <= touching_tolerance())
    gap = 0.;
  return HeadOnImpact{*first, *second, approach_speed, gap, direction};
}

ElasticSphere MeshModel::elastic_sphere(const unsigned int body, const SphereGeometry& sphere) const
{
  const BodyParameters& parameters = bodies.bodies[body];
  return {sphere.radius, parameters.youngs_modulus, parameters.poissons_ratio, parameters.density};
}

double MeshModel::spherical_side_mass(const ImpactSide& side) const
{
  const BodyParameters& body = bodies.bodies[*side.body];
  return side.whole_sphere ? sphere_mass(elastic_sphere(*side.body, *side.sphere))
                           : body.density * body_volumes[*side.body];
}

ElasticFlatBody MeshModel::flat_body(const ImpactSide& side) const
{
  constexpr double infinity = std::numeric_limits<double>::infinity();
  if (!side.body)
    return {infinity, 0., infinity}; // the rigid plane
  const BodyParameters& body = bodies.bodies[*side.body];
  return {body.youngs_modulus, body.poissons_ratio, body.density * body_volumes[*side.body]};
}

std::optional<HertzImpact> MeshModel::hertz_reference() const
{
  const std::optional<HeadOnImpact> impact = head_on_impact();
  if (!impact)
    return std::nullopt;
  const ElasticSphere sphere = elastic_sphere(*impact->sphere.body, *impact->sphere.sphere);
  const double touch         = impact->gap / impact->approach_speed;
  // The effective quantities of HertzImpact::two_spheres() and sphere_on_flat(), with the mass of
  // a spherical end's whole body (spherical_side_mass()); E and nu of the other side as
  // flat_body() gives them (the rigid plane's E infinite).
  const ElasticFlatBody other = flat_body(impact->other);
  return HertzImpact(
      impact->other.sphere ? effective_radius(sphere.radius, impact->other.sphere->radius)
                           : sphere.radius,
      effective_modulus(
          sphere.youngs_modulus, sphere.poissons_ratio, other.youngs_modulus, other.poissons_ratio),
      effective_mass(spherical_side_mass(impact->sphere),
                     impact->other.sphere ? spherical_side_mass(impact->other) : other.mass),
      impact->approach_speed,
      touch);
}

std::optional<FiniteSphereImpact> MeshModel::finite_sphere_reference() const
{
  const std::optional<HeadOnImpact> impact = head_on_impact();
  if (!impact)
    return std::nullopt;
  // The law is that of whole spheres.
  if (!impact->sphere.whole_sphere || (impact->other.sphere && !impact->other.whole_sphere))
    return std::nullopt;
  const ElasticSphere sphere = elastic_sphere(*impact->sphere.body, *impact->sphere.sphere);
  const double touch         = impact->gap / impact->approach_speed;
  // The law's C0 is known for nu = 0.3 only (FiniteSphereImpact): no reference otherwise.
  try
  {
    if (impact->other.sphere)
      return FiniteSphereImpact(sphere,
                                elastic_sphere(*impact->other.body, *impact->other.sphere),
                                impact->approach_speed,
                                touch);
    if (impact->other.body)
      return FiniteSphereImpact::sphere_on_flat(
          sphere, flat_body(impact->other), impact->approach_speed, touch);
    return FiniteSphereImpact(sphere, sphere, 2. * impact->approach_speed, touch);
  }
  catch (const std::exception&)
  {
    return std::nullopt;
  }
}

void MeshModel::write_reference(const std::string& directory,
                                const std::vector<double>& times,
                                const std::vector<Node<2>>&) const
{
  if (const auto hertz = hertz_reference())
    // Against the rigid plane the law is that of the mirrored pair, whose approach is twice the
    // sphere's; the approach column is that of hertz.csv.
    write_impact_references(directory,
                            times,
                            *hertz,
                            finite_sphere_reference(),
                            head_on_impact()->other.sphere ? 1. : 0.5);
}

void MeshModel::summarize_run(const std::string& directory,
                              const History& history,
                              const std::vector<double>& contact_impulses,
                              const std::string& status,
                              std::ostream& log) const
{
  const auto hertz = hertz_reference();
  if (!hertz)
    return;
  // The direction along z in which body 1 moves into the contact; the contact pushes body 1 back
  // against it.
  const HeadOnImpact impact    = *head_on_impact();
  const double body_1_approach = impact.sphere.body == 0u ? impact.direction : -impact.direction;
  write_impact_summary(directory,
                       history,
                       1.,
                       -body_1_approach * contact_impulses[0],
                       *hertz,
                       finite_sphere_reference(),
                       status,
                       log);
}

void MeshModel::print_summary(std::ostream& out, const double time_step) const
{
  out << (section == MeshSection::axisymmetric ? "  axisymmetric mesh " : "  plane strain mesh ")
      << mesh.file << ": " << n_cells << " cells (9-node), shortest edge " << shortest_edge << "\n";
  for (unsigned int body = 0; body < n_bodies(); ++body)
  {
    const BodyParameters& parameters = bodies.bodies[body];
    out << "  body " << body + 1 << ": " << parameters.material
        << ", E = " << parameters.youngs_modulus << ", nu = " << parameters.poissons_ratio
        << ", rho = " << parameters.density << ", c_p = " << dilatational_wave_speed(parameters);
    if (const std::optional<SphereGeometry> sphere = geometry.sphere(body))
    {
      if (section == MeshSection::axisymmetric)
        out << ", sphere R = " << sphere->radius << " centred at z = " << sphere->centre[1];
      else
        out << ", disc R = " << sphere->radius << " centred at (" << sphere->centre[0] << ", "
            << sphere->centre[1] << ")";
    }
    out << "\n";
  }
  double speed = 0.;
  for (unsigned int body = 0; body < n_bodies(); ++body)
    speed = std::max(speed, dilatational_wave_speed(bodies.bodies[body]));
  out << "  Courant number c_p dt / h_min = " << speed * time_step / shortest_edge << "\n";
  if (const auto hertz = hertz_reference())
    out << "  reference: Hertz's head-on impact (hertz.csv, impact_summary.csv): R* = "
        << hertz->effective_radius() << ", E* = " << hertz->effective_modulus()
        << ", m* = " << hertz->effective_mass() << ", first touch t = " << hertz->first_touch_time()
        << ", peak force " << hertz->maximum_force() << ", duration " << hertz->contact_duration()
        << (finite_sphere_reference() ? "; and the finite-sphere law (finite_sphere.csv)" : "")
        << "\n";
  else if (section == MeshSection::axisymmetric)
    out << "  reference: none (Hertz needs one pair, a sphere or spherical end facing a sphere or "
           "a flat face across the axis, the bodies approaching)\n";
  else
    out << "  reference: none (plane strain)\n";
}
} // namespace dyncontact
