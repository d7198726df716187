// Unit tests of node-to-segment contact on Q2 faces (NodeToSegmentContact, QuadraticFace) on the
// paper's mirrored two-sphere mesh, coarse (Refinement 0, shortest edge 0.26 at the poles), and on
// a single circular face; apart from any time stepping.
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact/node_to_segment_contact.h>
#include <dyncontact/contact/quadratic_face.h>
#include <dyncontact/models/gmsh_mesh.h>
#include <dyncontact/models/mesh_model.h>
#include <dyncontact/simulation/parameter_reader.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/manifold_lib.h>

#include <cmath>
#include <gtest/gtest.h>
#include <memory>

#include "case_run.h"

namespace dyncontact::testing
{
namespace
{
/**
 * The two spheres (R = 8) of meshes/two_spheres.geo with their centres `centre_distance` apart
 * (16: touching at the poles, r = 0, z = 0), body 2 shifted along the axis by `body_2_shift`
 * before the DoFs are numbered, its sphere manifolds moved with it (a negative shift makes the
 * bodies overlap, which the .geo file itself refuses).
 */
struct TwoSpheres
{
  explicit TwoSpheres(const double centre_distance, const double body_2_shift = 0.)
      : parameters(
            ParameterReader(
                source_path("prm/spheres_rho0.001.prm"),
                paper_coarse_spheres({}, "CentreDistance: " + format_exact(centre_distance) + ", "))
                .parameters()),
        model(parameters.mesh, parameters.bodies), dof_handler(triangulation), fe(FE_Q<2>(2), 2),
        mapping(2)
  {
    model.create_triangulation(triangulation);
    if (body_2_shift != 0.)
    {
      std::vector<bool> moved(triangulation.n_vertices(), false);
      for (const auto& cell : triangulation.active_cell_iterators())
        if (cell->material_id() == 1)
          for (const unsigned int v : cell->vertex_indices())
            if (!moved[cell->vertex_index(v)])
            {
              cell->vertex(v)[1] += body_2_shift;
              moved[cell->vertex_index(v)] = true;
            }
      // The manifold id of a circular curve is its boundary id.
      triangulation.set_manifold(
          SphereMeshIds::surface(1),
          SphericalManifold<2>(Point<2>(0., centre_distance / 2. + body_2_shift)));
      TransfiniteInterpolationManifold<2> interior;
      interior.initialize(triangulation);
      triangulation.set_manifold(SphereMeshIds::interior_manifold, interior);
    }
    dof_handler.distribute_dofs(fe);
    nodes      = std::make_unique<NodeIndex<2>>(dof_handler, mapping);
    kinematics = model.create_kinematics();
  }

  ContactSurface<2> surface(const unsigned int body) const
  {
    return ContactSurface<2>(dof_handler, *kinematics, *nodes, SphereMeshIds::surface(body));
  }

  NodeToSegmentContact<2> node_to_segment(const double search_radius) const
  {
    return NodeToSegmentContact<2>(
        surface(0),
        surface(1),
        1.,
        search_radius,
        model.contact_description(*nodes).surface_pairs.front().touching_tolerance);
  }

  /** A rigid translation of body 2 by `shift`. */
  Vector<double> translation_of_body_2(const Tensor<1, 2>& shift) const
  {
    Vector<double> displacement(dof_handler.n_dofs());
    for (const auto& node : nodes->nodes())
      if (node.body == 1)
        for (unsigned int d = 0; d < 2; ++d)
          displacement[node.dofs[d]] = shift[d];
    return displacement;
  }

  RunParameters parameters;
  MeshModel model;
  Triangulation<2> triangulation;
  DoFHandler<2> dof_handler;
  const FESystem<2> fe;
  const MappingQ<2> mapping;
  std::unique_ptr<NodeIndex<2>> nodes;
  std::unique_ptr<Kinematics<2>> kinematics;
};

/** `pairs` moved to `displacement` by `geometry`. */
std::vector<ContactPair<2>> moved_to(const ContactGeometry<2>& geometry,
                                     const Vector<double>& displacement)
{
  std::vector<ContactPair<2>> pairs = geometry.pairs();
  const ContactBorder<2> border(geometry.surface_nodes());
  const Vector<double> border_displacement = border.gather(displacement);
  geometry.update_pairs(BorderDisplacement<2>{border, border_displacement}, pairs);
  return pairs;
}

/** xi of a Q2 face's weights (order of QuadraticFace::points): w_1 - w_0 = 2 xi - 1. */
double face_parameter(const ContactPair<2>& pair)
{
  return 0.5 * (1. + pair.masters[1].weight - pair.masters[0].weight);
}

} // namespace

// A non-matching configuration: body 2 of the touching spheres translated radially by 0.1 (0.4
// of the pole's edge) and toward body 1 by 0.02. At the pairs the projection moved to:
//  - ContactPair::gap equals n . (x(xi) - x_s) with x(xi) evaluated here from the face's current
//    nodes and the Lagrange quadratics written out again (1e-12: round-off of sums of ~10 terms of
//    coordinates ~10);
//  - the master point lies on the ray from the slave node along the pair's ray direction (the
//    averaged normal), (x(xi) - x_s) x n = 0 relative to |x - x_s| (1e-12: Newton stops at a step
//    of 1e-14 and converges quadratically, so xi is exact to round-off), at every pair whose
//    point is inside a face (not at a vertex, where a fallback to the closest point may have
//    acted);
//  - the pair's normal is the face's, n . x'(xi) = 0 relative to |x'| (1e-12: round-off), at
//    every pair whose point is 0.01 or more (in xi) from the face's nodes, where the normal turns
//    to the averaged one (at least half of them);
//  - the gap's rows c_j n against central finite differences of the frozen pair's gap (1e-9: the
//    frozen gap is linear in u, so the difference quotient is exact up to round-off over h = 1e-4).
TEST(NodeToSegmentContact, GapIsTheDistanceAlongTheNormalToTheCurvedFace)
{
  const TwoSpheres spheres(16.);
  const NodeToSegmentContact<2> contact = spheres.node_to_segment(0.5);
  const Vector<double> displacement     = spheres.translation_of_body_2(Tensor<1, 2>({0.1, -0.02}));
  const auto pairs                      = moved_to(contact, displacement);
  unsigned int inside_a_face = 0, off_the_nodes = 0;
  for (const ContactPair<2>& pair : pairs)
  {
    ASSERT_EQ(pair.masters.size(), 3u);
    const double xi = face_parameter(pair);
    const std::array<double, 3> shape{
        {(1. - xi) * (1. - 2. * xi), xi * (2. * xi - 1.), 4. * xi * (1. - xi)}};
    Tensor<1, 2> position;
    for (unsigned int i = 0; i < 3; ++i)
    {
      const Point<2> x_i = current_position(pair.masters[i].node, displacement);
      position += shape[i] * x_i;
    }
    const Tensor<1, 2> offset = position - current_position(pair.slave, displacement);
    EXPECT_NEAR(pair.gap(displacement), pair.normal * offset, 1e-12) << pair.slave.position;
    if (xi > 0. && xi < 1.)
    {
      ++inside_a_face;
      const Tensor<1, 2>& ray = pair.ray_direction;
      EXPECT_LE(std::abs(offset[0] * ray[1] - offset[1] * ray[0]), 1e-12 * offset.norm())
          << pair.slave.position;
    }
    // Away from the face's nodes the normal is the face's: normal to its tangent x'(xi).
    if (std::min({xi, std::abs(xi - 0.5), 1. - xi}) >= 0.01)
    {
      ++off_the_nodes;
      Tensor<1, 2> tangent;
      const std::array<double, 3> slope{{4. * xi - 3., 4. * xi - 1., 4. - 8. * xi}};
      for (unsigned int i = 0; i < 3; ++i)
        tangent += slope[i] * (current_position(pair.masters[i].node, displacement) - Point<2>());
      EXPECT_LE(std::abs(pair.normal * tangent), 1e-12 * tangent.norm()) << pair.slave.position;
    }

    const double h = 1e-4;
    pair.for_each_node(
        [&](const Node<2>& node, const double coefficient)
        {
          for (unsigned int d = 0; d < 2; ++d)
          {
            Vector<double> plus = displacement, minus = displacement;
            plus[node.dofs[d]] += h;
            minus[node.dofs[d]] -= h;
            EXPECT_NEAR(
                (pair.gap(plus) - pair.gap(minus)) / (2. * h), coefficient * pair.normal[d], 1e-9);
          }
        });
  }
  EXPECT_GE(inside_a_face, pairs.size() / 2);
  EXPECT_GE(off_the_nodes, pairs.size() / 2);
}

// ContactConstraints::set_turning_normals(): with turning off (what contact-stabilized and
// velocity-update ask for), update_master_points() still moves every pair's master point but
// leaves its normal exactly at its value of the step's start (update_geometry()); with turning on
// the normals of pairs whose master point slid along the curved face turn with it. Body 2 of the
// non-matching configuration above slides by another 0.05 radially between the step's start and
// the iterate. Exact equality for held normals (nothing may touch them); turned ones differ by
// more than 1e-6 (the face's curvature 1/8 over the slide) at half of the pairs or more.
TEST(NodeToSegmentContact, HeldNormalsStayAtTheStepStartWhileMasterPointsMove)
{
  const TwoSpheres spheres(16.);
  const NodeToSegmentContact<2> geometry = spheres.node_to_segment(0.5);
  const Vector<double> start   = spheres.translation_of_body_2(Tensor<1, 2>({0.1, -0.02}));
  const Vector<double> iterate = spheres.translation_of_body_2(Tensor<1, 2>({0.15, -0.02}));
  for (const bool turn : {false, true})
  {
    ContactConstraints<2> contact(geometry, ContactFormulation::lagrange_multiplier);
    contact.set_turning_normals(turn);
    EXPECT_EQ(contact.moves_normals(), turn);
    contact.update_geometry(contact.border().gather(start));
    const std::vector<ContactPair<2>> at_start = contact.candidate_pairs();
    contact.update_master_points(contact.border().gather(iterate), true);
    unsigned int moved_points = 0, turned_normals = 0;
    for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    {
      const ContactPair<2>& pair = contact.candidate_pairs()[k];
      moved_points += face_parameter(pair) != face_parameter(at_start[k]);
      const double turn_angle = (pair.normal - at_start[k].normal).norm();
      turned_normals += turn_angle > 1e-6;
      if (!turn)
      {
        EXPECT_EQ(pair.normal, at_start[k].normal) << pair.slave.position;
      }
    }
    EXPECT_GE(moved_points, contact.n_pairs() / 2) << "turning " << turn;
    if (turn)
    {
      EXPECT_GE(turned_normals, contact.n_pairs() / 2);
    }
  }
}

// The face through (0, 0), (1, 1) and (0.5, 0.25) is the parabola y = x^2, x = xi: its normal, the
// tangent (1, 2 xi) turned by -90 degrees, is (2 xi, -1) exactly (1e-14: round-off).
TEST(QuadraticFace, NormalIsTheTangentTurned)
{
  const QuadraticFace<2> face{{{Point<2>(0., 0.), Point<2>(1., 1.), Point<2>(0.5, 0.25)}}};
  const Tensor<1, 2> normal = face.normal(0.3);
  EXPECT_NEAR(normal[0], 0.6, 1e-14);
  EXPECT_NEAR(normal[1], -1., 1e-14);
}

// One face whose three nodes lie on a circle of radius R = 8 about the origin, at angles -alpha,
// alpha and 0 (xi = 0, 1, 1/2), and slave points on the concentric circle R + d, d = 0.3, at
// angles inside the face. The quadratic interpolates x(phi(xi)), phi = alpha (2 xi - 1), whose
// third derivative in xi has length (2 alpha)^3 R; the Lagrange error bound
// |x'''| / 6 max |xi (xi - 1/2) (xi - 1)| = (8 alpha^3 R / 6) (sqrt(3) / 36) = 0.0642 alpha^3 R
// bounds how far the face lies from the circle, hence how far the distance is from d. Weights
// sum to 1 to 1e-14 (three terms of size <= 1.125). Halving alpha divides the error by at least
// 8 (O(h^3)) less 10 %; measured: by 16.0, since the symmetric arc's radial error is O(h^4).
TEST(QuadraticFace, ProjectionOntoACircularFaceGivesTheRadiusDifference)
{
  const double radius = 8., d = 0.3;
  const auto largest_error = [&](const double alpha)
  {
    const auto on_circle = [](const double r, const double angle)
    { return Point<2>(r * std::sin(angle), r * std::cos(angle)); };
    const QuadraticFace<2> face{
        {{on_circle(radius, -alpha), on_circle(radius, alpha), on_circle(radius, 0.)}}};
    double error = 0.;
    for (const double fraction : {-0.95, -0.6, -0.3, 0., 0.2, 0.5, 0.8, 0.95})
    {
      const double angle    = fraction * alpha;
      const Point<2> slave  = on_circle(radius + d, angle);
      const auto projection = face.closest_point(slave);
      const auto weights    = QuadraticFace<2>::shape_values(projection.xi);
      EXPECT_NEAR(weights[0] + weights[1] + weights[2], 1., 1e-14);
      EXPECT_GT(projection.xi, 0.);
      EXPECT_LT(projection.xi, 1.);
      EXPECT_LE(std::abs(projection.distance - d), 0.0642 * std::pow(alpha, 3) * radius)
          << "alpha " << alpha << ", angle " << angle;
      // The closest point lies on the ray through the slave point, to the same bound.
      const Tensor<1, 2> ray = slave / slave.norm();
      EXPECT_LE((projection.point - (ray * projection.point) * ray).norm(),
                0.0642 * std::pow(alpha, 3) * radius);
      error = std::max(error, std::abs(projection.distance - d));
    }
    return error;
  };
  const double coarse = largest_error(0.1), fine = largest_error(0.05);
  EXPECT_GT(coarse, 0.);
  EXPECT_GE(coarse / fine, 7.2);
}

// Spheres 16.05 apart with body 2 shifted 0.1 toward body 1: they overlap by 0.05 at the poles.
TEST(NodeToSegmentContact, OverlapAtTheStartIsAnInputErrorNamingTheBodies)
{
  const TwoSpheres spheres(16.05, -0.1);
  try
  {
    spheres.node_to_segment(0.5);
    FAIL() << "no InputError";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("body 1 and body 2 overlap at t = 0"),
              std::string::npos)
        << error.what();
  }
}
// ContactSurface evaluates the deformed faces with FEFaceValues on the volume cells. Its normals
// and surface mass matrix must be those of the curved faces the nodes lie on: the quadratic curve
// through each face's three current nodes (QuadraticFace, the face the isoparametric Q2 mapping
// makes of the reference's curved faces). The nodal normal is the normalized sum of the faces'
// unit normals at the node, oriented away from the sphere's centre; M_ij sums over the faces the
// 4-point Gauss rule (ContactSurface's) of N_i N_j 2 pi r |x'(xi)| on [0, 1]. A surface built on
// the straight chords of the reference (MappingQEulerian: displacement added to the Q1 geometry)
// tilted the pole's normal by 0.016 and the far pole's by 0.16 and put the mass matrix 0.8 % off.
// The check also says that a surface can be evaluated from its nodes alone, on any MPI rank
// (issue 27, move 5). At a smooth displacement that stretches and bends both spheres; bounds
// 1e-12 (normals, of order 1) and 1e-12 of the largest entry (mass matrix): round-off of sums over
// two faces and four points.
TEST(ContactSurface, NormalsAndMassMatrixAreThoseOfTheCurvedFaces)
{
  const TwoSpheres spheres(16.);
  Vector<double> u(spheres.dof_handler.n_dofs());
  for (const auto& node : spheres.nodes->nodes())
  {
    const Point<2>& x = node.position;
    u[node.dofs[0]]   = 0.01 * x[0] * std::cos(0.2 * x[1]);
    u[node.dofs[1]]   = 0.02 * x[0] * x[0] / 64. - 0.005 * x[1];
  }
  const std::array<double, 3> node_parameter = {{0., 1., 0.5}}; // xi of QuadraticFace::points
  const QGauss<1> gauss(4);
  for (unsigned int body = 0; body < 2; ++body)
  {
    const ContactSurface<2> surface = spheres.surface(body);
    const auto& nodes               = surface.nodes();
    const Point<2> centre(0., body == 0 ? -8. : 8.);
    std::vector<Tensor<1, 2>> normals(nodes.size());
    Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(nodes.size(), nodes.size());
    for (const auto& face_nodes : surface.face_nodes())
    {
      QuadraticFace<2> face;
      for (unsigned int i = 0; i < 3; ++i)
        face.points[i] = current_position(nodes[face_nodes[i]], u);
      for (unsigned int i = 0; i < 3; ++i)
      {
        const Tensor<1, 2> tangent = face.tangent(node_parameter[i]);
        Tensor<1, 2> normal({tangent[1], -tangent[0]});
        normal /= normal.norm();
        normals[face_nodes[i]] += (normal * (face.points[i] - centre) > 0. ? 1. : -1.) * normal;
      }
      for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        const double xi                   = gauss.point(q)[0];
        const std::array<double, 3> shape = QuadraticFace<2>::shape_values(xi);
        const double measure = spheres.kinematics->measure_factor(face.point(xi), body) *
                               face.tangent(xi).norm() * gauss.weight(q);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            mass(face_nodes[i], face_nodes[j]) += shape[i] * shape[j] * measure;
      }
    }
    ASSERT_GT(nodes.size(), 10u);
    std::vector<Point<2>> positions;
    for (const Node<2>& node : nodes)
      positions.push_back(current_position(node, u));
    const std::vector<Tensor<1, 2>> computed = surface.normals(positions);
    for (unsigned int node = 0; node < nodes.size(); ++node)
      for (unsigned int d = 0; d < 2; ++d)
        EXPECT_NEAR(computed[node][d], normals[node][d] / normals[node].norm(), 1e-12)
            << "body " << body << ", node at " << nodes[node].position;
    const Eigen::MatrixXd computed_mass = Eigen::MatrixXd(surface.mass_matrix(positions));
    EXPECT_LE((computed_mass - mass).cwiseAbs().maxCoeff(), 1e-12 * mass.cwiseAbs().maxCoeff())
        << "body " << body;
  }
}
} // namespace dyncontact::testing
