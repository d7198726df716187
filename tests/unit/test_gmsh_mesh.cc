// Checks read_gmsh_mesh() and the shipped sphere meshes (meshes/sphere.geo, two_spheres.geo):
//  - the sphere's volume, integral of 2 pi r dA with the Q2 mapping and the attached manifolds,
//    against 4/3 pi R^3: the default mesh within 1e-5 relative, and the error falling under
//    refinement, both in gmsh and by deal.II's refine_global (which needs the manifolds);
//  - the two-sphere mesh: two bodies of equal volume, body 2 the mirror image of body 1 vertex by
//    vertex to 1e-12 (contact surfaces included), fitted centres and radii, grading to the poles;
//  - the graded family for the Hertz impact (PoleGrading 10, CoreOffset 0.3, Refinement 0 and 2):
//    the edge and the element layer at the contact poles, Q2 nodes in the contact radius, no
//    slender cells, the facing surfaces mirrored;
//  - all cells quadrilaterals with a positive Jacobian at every Gauss point of the Q2 mapping;
//  - a second-order .msh file (9-node quadrilaterals) read on its vertices (sphere.geo and the
//    meshes of test_general_meshes.cc);
//  - the sphere pairs of test_general_meshes.cc read as by the sphere-only reader before it: same
//    cells, vertices and spheres, a spherical manifold on each sphere;
//  - bad input: every kind gives one line of InputError naming the file.
#include <dyncontact/models/gmsh_mesh.h>

#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <cmath>
#include <gmsh.h>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mesh_checks.h"

namespace
{
using namespace dyncontact;
using namespace dyncontact::testing;

const std::string sphere_geo      = mesh_path("sphere.geo");
const std::string two_spheres_geo = mesh_path("two_spheres.geo");

/** A gmsh 2.2 mesh of the unit square cell [0, 1]^2 with the given element lines. */
std::string unit_square_msh(const std::string& elements)
{
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
         "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
         "$Elements\n" +
         elements + "$EndElements\n";
}

TEST(GmshMesh, SphereVolumeConvergesUnderRefinement)
{
  Triangulation<2> triangulation;
  const std::vector<SphereGeometry> spheres = read_spheres(sphere_geo, {}, triangulation);
  ASSERT_EQ(spheres.size(), 1u);
  EXPECT_NEAR(spheres[0].radius, 8, 1e-12);
  EXPECT_NEAR(spheres[0].centre.distance(Point<2>(0, 0)), 0, 1e-12);

  const double default_error = relative_sphere_volume_error(triangulation, 0, spheres[0].radius);
  std::cout << "  sphere.geo default: " << triangulation.n_active_cells()
            << " cells, relative volume error " << default_error << std::endl;
  // The bound asked of the default mesh (24 edges on the half circumference); the Q2 boundary is
  // fourth-order accurate, which puts the error about 5 times below it.
  EXPECT_LT(default_error, 1e-5);

  // gmsh refinement: each level halves every element edge.
  double previous_error = default_error;
  for (const double refinement : {1., 2.})
  {
    Triangulation<2> refined;
    read_gmsh_mesh(sphere_geo, {{"Refinement", refinement}}, refined);
    const double error = relative_sphere_volume_error(refined, 0, spheres[0].radius);
    std::cout << "  sphere.geo Refinement " << refinement << ": " << refined.n_active_cells()
              << " cells, relative volume error " << error << std::endl;
    // Fourth order would give 16 per level; 8 leaves room for the graded (non-nested) meshes.
    EXPECT_LT(error, previous_error / 8);
    previous_error = error;
  }

  // deal.II refinement moves new boundary vertices onto the sphere only through the manifolds.
  previous_error = default_error;
  for (unsigned int level = 1; level <= 2; ++level)
  {
    triangulation.refine_global(1);
    const double error = relative_sphere_volume_error(triangulation, 0, spheres[0].radius);
    std::cout << "  sphere.geo default + refine_global(" << level
              << "): " << triangulation.n_active_cells() << " cells, relative volume error "
              << error << std::endl;
    EXPECT_LT(error, previous_error / 8);
    previous_error = error;
  }
}

TEST(GmshMesh, TwoSpheresAreMirrorImages)
{
  Triangulation<2> default_mesh;
  read_gmsh_mesh(two_spheres_geo, {}, default_mesh);
  std::cout << "  two_spheres.geo default: " << default_mesh.n_active_cells() << " cells"
            << std::endl;

  Triangulation<2> triangulation;
  const std::vector<SphereGeometry> spheres =
      read_spheres(two_spheres_geo, {{"Divisions", 3}}, triangulation);
  std::cout << "  two_spheres.geo (Divisions 3): " << triangulation.n_active_cells() << " cells"
            << std::endl;
  ASSERT_EQ(spheres.size(), 2u);
  EXPECT_LT(spheres[0].centre.distance(Point<2>(0, -10)), 1e-12);
  EXPECT_LT(spheres[1].centre.distance(Point<2>(0, 10)), 1e-12);
  EXPECT_NEAR(spheres[0].radius, 8, 1e-12);
  EXPECT_NEAR(spheres[1].radius, 8, 1e-12);

  unsigned int n_cells_of_body[2] = {0, 0};
  for (const auto& cell : triangulation.active_cell_iterators())
    ++n_cells_of_body[cell->material_id()];
  EXPECT_EQ(n_cells_of_body[0], n_cells_of_body[1]);

  const double volume_1 = body_volume(triangulation, 0);
  const double volume_2 = body_volume(triangulation, 1);
  std::cout << "  body volumes " << volume_1 << ", " << volume_2 << ", relative difference "
            << std::abs(volume_1 - volume_2) / volume_1 << std::endl;
  // Mirror-image meshes integrate to the same number up to round-off.
  EXPECT_NEAR(volume_1, volume_2, 1e-12 * volume_1);

  // Every vertex of body 1 mirrored about z = 0 is a vertex of body 2 and vice versa, in
  // particular on the facing (contact) surfaces; gmsh writes 16 digits, so 1e-12 is round-off.
  std::vector<Point<2>> vertices[2];
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      vertices[cell->material_id()].push_back(cell->vertex(v));
  std::vector<Point<2>> mirrored_body_1;
  for (const Point<2>& vertex : vertices[0])
    mirrored_body_1.emplace_back(vertex[0], -vertex[1]);
  EXPECT_LT(largest_mismatch(mirrored_body_1, vertices[1]), 1e-12);
  EXPECT_LT(largest_mismatch(vertices[1], mirrored_body_1), 1e-12);

  const std::vector<Point<2>> surface_1 =
      boundary_vertices(triangulation, SphereMeshIds::surface(0));
  const std::vector<Point<2>> surface_2 =
      boundary_vertices(triangulation, SphereMeshIds::surface(1));
  ASSERT_EQ(surface_1.size(), surface_2.size());
  std::vector<Point<2>> mirrored_surface_1;
  for (const Point<2>& vertex : surface_1)
    mirrored_surface_1.emplace_back(vertex[0], -vertex[1]);
  const double facing_mismatch = largest_mismatch(mirrored_surface_1, surface_2);
  std::cout << "  facing surfaces: " << surface_1.size()
            << " vertices each, largest mirror mismatch " << facing_mismatch << std::endl;
  EXPECT_LT(facing_mismatch, 1e-12);

  // The contact poles (0, -2) and (0, 2) are surface vertices, and the surface edges grow from
  // them: the edge at the contact pole is PoleGrading = 3 times shorter than at the far pole.
  EXPECT_LT(largest_mismatch({Point<2>(0, -2)}, surface_1), 1e-12);
  EXPECT_LT(largest_mismatch({Point<2>(0, 2)}, surface_2), 1e-12);
  double edge_at_contact_pole = 0, edge_at_far_pole = 0;
  for (const auto& face : triangulation.active_face_iterators())
    if (face->at_boundary() && face->boundary_id() == SphereMeshIds::surface(0))
    {
      const double length = face->vertex(0).distance(face->vertex(1));
      for (unsigned int v = 0; v < 2; ++v)
      {
        if (face->vertex(v).distance(Point<2>(0, -2)) < 1e-12)
          edge_at_contact_pole = length;
        if (face->vertex(v).distance(Point<2>(0, -18)) < 1e-12)
          edge_at_far_pole = length;
      }
    }
  std::cout << "  body 1 surface edge at the contact pole " << edge_at_contact_pole
            << ", at the far pole " << edge_at_far_pole << std::endl;
  EXPECT_NEAR(edge_at_far_pole / edge_at_contact_pole, 3, 0.05);
}

/** Largest ratio of the mean lengths of a cell's two pairs of opposite edges. */
double largest_aspect_ratio(const Triangulation<2>& triangulation)
{
  double largest = 0;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    // deal.II's faces 0, 1 are opposite, and so are 2, 3.
    double length[4];
    for (unsigned int f = 0; f < 4; ++f)
      length[f] = cell->face(f)->vertex(0).distance(cell->face(f)->vertex(1));
    const double ratio = (length[0] + length[1]) / (length[2] + length[3]);
    largest            = std::max({largest, ratio, 1 / ratio});
  }
  return largest;
}

TEST(GmshMesh, HertzFamilyResolvesTheContactPoles)
{
  // The coarse and fine members of the graded family of two_spheres.geo for the Hertz impact
  // (contact radius 0.47 in the accuracy-critical case): the medium one is Refinement 1.
  struct Member
  {
    double refinement;
    unsigned int n_cells;
    double smallest_edge, largest_edge;
    unsigned int least_q2_nodes_in_contact; // surface nodes of body 1 with r < 0.47, at least
  };
  for (const Member& member : {Member{0, 432, 0.2, 0.35, 5}, Member{2, 6912, 0.06, 0.08, 14}})
  {
    Triangulation<2> triangulation;
    const std::vector<SphereGeometry> spheres =
        read_spheres(two_spheres_geo,
                     {{"Refinement", member.refinement}, {"PoleGrading", 10}, {"CoreOffset", 0.3}},
                     triangulation);
    ASSERT_EQ(spheres.size(), 2u);
    EXPECT_EQ(triangulation.n_active_cells(), member.n_cells);
    EXPECT_EQ(count_nonpositive_jacobians(triangulation), 0u);

    // The surface edge and the outermost element layer (on the axis) at both contact poles.
    const Point<2> pole_1(0, -2), pole_2(0, 2);
    const double edge_1  = boundary_edge_at(triangulation, SphereMeshIds::surface(0), pole_1);
    const double edge_2  = boundary_edge_at(triangulation, SphereMeshIds::surface(1), pole_2);
    const double layer_1 = boundary_edge_at(triangulation, SphereMeshIds::axis, pole_1);
    const double layer_2 = boundary_edge_at(triangulation, SphereMeshIds::axis, pole_2);
    const double aspect  = largest_aspect_ratio(triangulation);

    // Q2 nodes of body 1's surface inside the contact radius: vertices and mid-sides, the latter
    // where the spherical manifold puts them.
    const std::vector<Point<2>> surface_1 =
        boundary_vertices(triangulation, SphereMeshIds::surface(0));
    const std::vector<Point<2>> surface_2 =
        boundary_vertices(triangulation, SphereMeshIds::surface(1));
    unsigned int n_contact_nodes = 0;
    for (const Point<2>& node : boundary_q2_nodes(triangulation, SphereMeshIds::surface(0)))
      n_contact_nodes += node[0] < 0.47;

    std::vector<Point<2>> mirrored_surface_1;
    for (const Point<2>& vertex : surface_1)
      mirrored_surface_1.emplace_back(vertex[0], -vertex[1]);
    const double mismatch = std::max(largest_mismatch(mirrored_surface_1, surface_2),
                                     largest_mismatch(surface_2, mirrored_surface_1));

    std::cout << "  Refinement " << member.refinement << ": " << triangulation.n_active_cells()
              << " cells, contact pole edge " << edge_1 << ", layer " << layer_1 << ", "
              << n_contact_nodes << " Q2 surface nodes at r < 0.47, largest aspect ratio " << aspect
              << ", facing surfaces mirrored to " << mismatch << std::endl;
    EXPECT_GT(edge_1, member.smallest_edge);
    EXPECT_LT(edge_1, member.largest_edge);
    EXPECT_NEAR(edge_2, edge_1, 1e-12);
    EXPECT_NEAR(layer_2, layer_1, 1e-12);
    // The elements at the poles are about square, and none anywhere is slender.
    EXPECT_LT(std::max(layer_1 / edge_1, edge_1 / layer_1), 1.5);
    EXPECT_LT(aspect, 3);
    EXPECT_GE(n_contact_nodes, member.least_q2_nodes_in_contact);
    ASSERT_EQ(surface_1.size(), surface_2.size());
    EXPECT_LT(mismatch, 1e-12 * spheres[0].radius);
  }
}

TEST(GmshMesh, CellsAreQuadrilateralsWithPositiveJacobians)
{
  for (const auto& [file, parameters] :
       std::vector<std::pair<std::string, std::map<std::string, double>>>{
           {sphere_geo, {}},
           {sphere_geo, {{"PoleSide", -1}, {"CentreZ", 3}, {"R", 2}}},
           {sphere_geo, {{"Divisions", 1}, {"RadialDivisions", 1}}},
           {sphere_geo, {{"PoleGrading", 10}, {"SurfaceGrading", 3}}},
           {sphere_geo, {{"PoleGrading", 20}, {"CoreOffset", 0.5}, {"PoleSide", -1}}},
           {two_spheres_geo, {{"Divisions", 2}, {"RadialDivisions", 2}}}})
  {
    Triangulation<2> triangulation;
    read_gmsh_mesh(file, parameters, triangulation);
    for (const auto& cell : triangulation.active_cell_iterators())
      EXPECT_EQ(cell->reference_cell(), ReferenceCells::Quadrilateral);
    EXPECT_EQ(count_nonpositive_jacobians(triangulation), 0u) << file;
    triangulation.refine_global(1);
    EXPECT_EQ(count_nonpositive_jacobians(triangulation), 0u) << file << " refined";
  }
}

TEST(GmshMesh, ReadsMshFilesLikeGeoFiles)
{
  // two_spheres.geo meshed into a .msh by the gmsh library itself, then read directly.
  const ScratchDirectory directory;
  const std::string msh_file = directory.file("two_spheres.msh");
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(two_spheres_geo);
  gmsh::model::mesh::generate(2);
  gmsh::write(msh_file);
  gmsh::finalize();

  Triangulation<2> from_msh, from_geo;
  const std::vector<SphereGeometry> spheres = read_spheres(msh_file, {}, from_msh);
  read_gmsh_mesh(two_spheres_geo, {}, from_geo);
  EXPECT_EQ(spheres.size(), 2u);
  EXPECT_EQ(from_msh.n_active_cells(), from_geo.n_active_cells());
  EXPECT_NEAR(body_volume(from_msh, 1), body_volume(from_geo, 1), 1e-12 * body_volume(from_geo, 1));
}

TEST(GmshMesh, ReadsSecondOrderMshFilesOnTheirVertices)
{
  // sphere.geo (Refinement 0), the sphere pairs on non-matching meshes and the sphere on the
  // block exported with 9-node quadrilaterals, as by `gmsh -2 -order 2`: read on its vertices,
  // each is the first-order mesh of the same file, cell by cell; the mapping curves the boundary
  // in both.
  for (const std::string& geo_file : {sphere_geo,
                                      mesh_path("two_spheres_nonmatching.geo"),
                                      mesh_path("dissimilar_spheres.geo"),
                                      mesh_path("sphere_on_block.geo")})
  {
    const ScratchDirectory directory;
    const std::string msh_file = directory.file("order_2.msh");
    // 10: gmsh's 9-node quadrilateral
    ASSERT_EQ(write_second_order_msh(geo_file, {}, msh_file), std::vector<int>{10});

    Triangulation<2> from_msh, from_geo;
    const unsigned int n_bodies = read_gmsh_mesh(msh_file, {}, from_msh).n_bodies;
    read_gmsh_mesh(geo_file, {}, from_geo);
    ASSERT_EQ(from_msh.n_active_cells(), from_geo.n_active_cells()) << geo_file;
    ASSERT_EQ(from_msh.n_vertices(), from_geo.n_vertices()) << geo_file;
    for (auto msh_cell = from_msh.begin_active(), geo_cell = from_geo.begin_active();
         msh_cell != from_msh.end();
         ++msh_cell, ++geo_cell)
    {
      EXPECT_EQ(msh_cell->material_id(), geo_cell->material_id());
      for (const unsigned int v : msh_cell->vertex_indices())
        EXPECT_LT(msh_cell->vertex(v).distance(geo_cell->vertex(v)), 1e-12);
    }
    for (types::material_id body = 0; body < n_bodies; ++body)
      EXPECT_NEAR(body_volume(from_msh, body),
                  body_volume(from_geo, body),
                  1e-12 * body_volume(from_geo, body))
          << geo_file;
  }
}

TEST(GmshMesh, SphereMeshesReadAsBefore)
{
  // The general reader on the shipped sphere pairs at their defaults: the cell and vertex counts
  // of the sphere-only reader it replaced (measured with it), one circle per body, curve b + 2,
  // the body's sphere (R1 = 8 centred at z = -10; R2 = 8 or 4 at z = 10 or 6), the spherical
  // manifold on the circle (id b + 2) and flat axis faces. Compared bit for bit with the previous
  // reader once (vertices, ids, manifold ids, fitted spheres, face and cell centres placed by the
  // manifolds, also the Hertz family): identical.
  struct Expected
  {
    std::string file;
    unsigned int n_cells, n_vertices;
    double radius_2, centre_z_2;
  };
  for (const Expected& expected : {Expected{"two_spheres.geo", 432, 482, 8, 10},
                                   Expected{"two_spheres_nonmatching.geo", 482, 535, 8, 10},
                                   Expected{"dissimilar_spheres.geo", 432, 482, 4, 6}})
  {
    Triangulation<2> triangulation;
    const MeshGeometry geometry = read_gmsh_mesh(mesh_path(expected.file), {}, triangulation);
    std::cout << "  " << expected.file << ": " << triangulation.n_active_cells() << " cells, "
              << triangulation.n_vertices() << " vertices" << std::endl;
    EXPECT_EQ(triangulation.n_active_cells(), expected.n_cells);
    EXPECT_EQ(triangulation.n_vertices(), expected.n_vertices);
    ASSERT_EQ(geometry.n_bodies, 2u);
    ASSERT_EQ(geometry.curves.size(), 2u);
    const SphereGeometry nominal[2] = {{Point<2>(0, -10), 8},
                                       {Point<2>(0, expected.centre_z_2), expected.radius_2}};
    for (unsigned int body = 0; body < 2; ++body)
    {
      const BoundaryCurve* curve = geometry.curve(SphereMeshIds::surface(body));
      ASSERT_NE(curve, nullptr);
      EXPECT_EQ(curve->body, body);
      EXPECT_FALSE(curve->line);
      ASSERT_TRUE(curve->circle);
      const std::optional<SphereGeometry> sphere = geometry.sphere(body);
      ASSERT_TRUE(sphere);
      EXPECT_EQ(sphere->centre, curve->circle->centre);
      EXPECT_EQ(sphere->radius, curve->circle->radius);
      // The least-squares fit to 16-digit vertices.
      EXPECT_LT(sphere->centre.distance(nominal[body].centre), 1e-12 * nominal[body].radius);
      EXPECT_NEAR(sphere->radius, nominal[body].radius, 1e-12 * nominal[body].radius);
    }
    double largest_off_circle = 0;
    for (const auto& face : triangulation.active_face_iterators())
      if (face->at_boundary())
      {
        if (face->boundary_id() == SphereMeshIds::axis)
        {
          EXPECT_EQ(face->manifold_id(), numbers::flat_manifold_id);
          continue;
        }
        const BoundaryCurve* curve = geometry.curve(face->boundary_id());
        ASSERT_NE(curve, nullptr);
        EXPECT_EQ(face->manifold_id(), curve->id);
        largest_off_circle = std::max(
            largest_off_circle,
            std::abs(face->center(/*respect_manifold=*/true).distance(curve->circle->centre) -
                     curve->circle->radius));
      }
    // The spherical manifold puts mid-sides on the fitted circle to round-off.
    EXPECT_LT(largest_off_circle, 1e-12 * 8);
  }
}

TEST(GmshMesh, BadInputGivesOneLineNamingTheFile)
{
  const ScratchDirectory directory;

  expect_input_error(directory.file("missing.geo"), {}, "does not exist");
  expect_input_error(directory.write("mesh.vtk", "x"), {}, "unknown extension");
  expect_input_error(sphere_geo, {{"Refinment", 1}}, "no parameter 'Refinment'");
  expect_input_error(sphere_geo, {{"R", -1}}, "R = -1");
  expect_input_error(sphere_geo, {{"Divisions", 2.5}}, "Divisions = 2.5");
  expect_input_error(sphere_geo, {{"CoreOffset", 0.6}}, "CoreOffset = 0.6");
  expect_input_error(two_spheres_geo, {{"CentreDistance", 15}}, "overlap");

  expect_input_error(directory.write("malformed.geo", "Point(1) = {0, 0, 0};\nLine(2) = {1, 7};\n"),
                     {},
                     "gmsh failed");
  expect_input_error(directory.write("syntax.geo", "Point(1) = {0, 0, 0;\n"), {}, "gmsh failed");
  expect_input_error(directory.write("triangle.geo",
                                     "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};\n"
                                     "Point(3) = {0, 1, 0}; Line(1) = {1, 2}; Line(2) = {2, 3};\n"
                                     "Line(3) = {3, 1}; Curve Loop(1) = {1, 2, 3};\n"
                                     "Transfinite Curve {1, 2, 3} = 2; Plane Surface(1) = {1};\n"
                                     "Physical Surface(1) = {1};\n"),
                     {},
                     "not quadrilaterals");
  expect_input_error(directory.write("no_groups.geo",
                                     "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};\n"
                                     "Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\n"
                                     "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
                                     "Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4};\n"
                                     "Plane Surface(1) = {1}; Transfinite Surface {1};\n"),
                     {},
                     "no physical surface");

  expect_input_error(
      directory.write("garbage.msh", "this is not a mesh\n"), {}, "not a readable gmsh mesh");
  expect_input_error(directory.write("parameters.msh", unit_square_msh("1\n1 3 2 1 1 1 2 3 4\n")),
                     {{"R", 1}},
                     "takes no parameters");
  expect_input_error(directory.write("no_cells.msh", unit_square_msh("1\n1 1 2 1 1 1 2\n")),
                     {},
                     "did not find any cells");
  expect_input_error(
      directory.write("triangles.msh", unit_square_msh("2\n1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n")),
      {},
      "2 of its 2 cells are not quadrilaterals (2 'Triangle 3')");
  // A 6-node (second-order) triangle and a quadrilateral.
  expect_input_error(directory.write("mixed.msh",
                                     "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                                     "$Nodes\n7\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n"
                                     "5 0.5 0 0\n6 0.5 0.5 0\n7 0 0.5 0\n$EndNodes\n"
                                     "$Elements\n2\n1 9 2 1 1 1 2 4 5 6 7\n"
                                     "2 3 2 1 1 2 3 4 1\n$EndElements\n"),
                     {},
                     "1 of its 2 cells are not quadrilaterals (1 'Triangle 6')");
  // Physical surface 2 missing: the only body is tagged 2.
  expect_input_error(directory.write("no_body_1.msh", unit_square_msh("1\n1 3 2 2 1 1 2 3 4\n")),
                     {},
                     "numbered 1, 2, ...");
  // Physical curve 1 (axis) missing: every edge is tagged as the surface.
  expect_input_error(directory.write("no_axis.msh",
                                     unit_square_msh("5\n1 3 2 1 1 1 2 3 4\n2 1 2 2 1 1 2\n"
                                                     "3 1 2 2 1 2 3\n4 1 2 2 1 3 4\n"
                                                     "5 1 2 2 1 4 1\n")),
                     {},
                     "physical curve 1 (the axis r = 0) is missing");
  // Boundary edges in no physical curve.
  expect_input_error(directory.write("untagged_edges.msh",
                                     unit_square_msh("2\n1 3 2 1 1 1 2 3 4\n2 1 2 1 1 4 1\n")),
                     {},
                     "no physical curve");
  // Three sides of a square in one curve: no circle, no line.
  expect_input_error(directory.write("square.msh",
                                     unit_square_msh("5\n1 3 2 1 1 1 2 3 4\n2 1 2 2 1 1 2\n"
                                                     "3 1 2 2 1 2 3\n4 1 2 2 1 3 4\n"
                                                     "5 1 2 1 1 4 1\n")),
                     {},
                     "physical curve 2 (of body 1) is neither a circle centred on the axis r = 0 "
                     "nor a straight line");
}
} // namespace
