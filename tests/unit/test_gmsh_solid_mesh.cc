// read_gmsh_solid_mesh(), the reader of 3D meshes (issue 28): a box of meshes/block_3d.geo is read
// as hexahedra with its volume, bodies and six planar boundary surfaces (points and outward
// normals), a quarter ball with its planes, its sphere and the sphere's manifolds, and meshes
// dyncontact cannot take are one-line InputErrors naming the file: tetrahedra, prisms, boundary
// faces in no physical surface, a surface that is neither a plane nor a sphere.
#include <dyncontact/models/gmsh_mesh.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <string>

#include "mesh_checks.h"

namespace dyncontact::testing
{
namespace
{
/**
 * Expects read_gmsh_solid_mesh(filename) to throw InputError whose message is one line, names
 * the file and contains `expected_text`; the triangulation must be left empty.
 */
void expect_solid_input_error(const std::string& filename, const std::string& expected_text)
{
  Triangulation<3> triangulation;
  try
  {
    read_gmsh_solid_mesh(filename, {}, triangulation);
    ADD_FAILURE() << filename << ": no InputError, expected one with '" << expected_text << "'";
  }
  catch (const InputError& error)
  {
    const std::string message = error.what();
    EXPECT_NE(message.find(expected_text), std::string::npos) << message;
    EXPECT_NE(message.find(filename), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_EQ(triangulation.n_cells(), 0u) << filename;
}
} // namespace

TEST(GmshSolidMesh, ReadsHexahedralBoxesWithPlanarSurfaces)
{
  Triangulation<3> triangulation;
  const SolidMeshGeometry geometry =
      read_gmsh_solid_mesh(mesh_path("block_3d.geo"),
                           {{"LX", 2.}, {"LY", 3.}, {"LZ", 1.}, {"X0", -1.}, {"NY", 3.}},
                           triangulation);
  EXPECT_EQ(geometry.n_bodies, 1u);
  EXPECT_EQ(triangulation.n_active_cells(), 4u * 3u * 2u);
  double volume = 0.;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    EXPECT_EQ(cell->reference_cell(), ReferenceCells::Hexahedron);
    EXPECT_EQ(cell->material_id(), 0u);
    volume += cell->measure();
  }
  // Straight-sided boxes: exact to round-off.
  EXPECT_NEAR(volume, 2. * 3. * 1., 1e-12);
  // The six faces, in id order, with their outward normals and a coordinate of their plane.
  const std::map<types::boundary_id, std::pair<Tensor<1, 3>, double>> expected = {
      {1, {Tensor<1, 3>({-1., 0., 0.}), -1.}},
      {2, {Tensor<1, 3>({1., 0., 0.}), 1.}},
      {3, {Tensor<1, 3>({0., -1., 0.}), 0.}},
      {4, {Tensor<1, 3>({0., 1., 0.}), 3.}},
      {5, {Tensor<1, 3>({0., 0., -1.}), 0.}},
      {6, {Tensor<1, 3>({0., 0., 1.}), 1.}}};
  ASSERT_EQ(geometry.surfaces.size(), expected.size());
  for (const BoundarySurface& surface : geometry.surfaces)
  {
    const auto& [normal, coordinate] = expected.at(surface.id);
    EXPECT_EQ(surface.body, 0u);
    ASSERT_TRUE(surface.plane.has_value()) << "surface " << surface.id;
    EXPECT_FALSE(surface.sphere.has_value()) << "surface " << surface.id;
    EXPECT_LT((surface.plane->normal - normal).norm(), 1e-12) << "surface " << surface.id;
    // The plane's coordinate along its normal axis, from the surface's point.
    unsigned int axis = 0;
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(normal[d]) == 1.)
        axis = d;
    EXPECT_NEAR(surface.plane->point[axis], coordinate, 1e-12) << "surface " << surface.id;
    EXPECT_EQ(geometry.surface(surface.id), &surface);
  }
  EXPECT_EQ(geometry.surface(7), nullptr);
}

// meshes/quarter_sphere_3d.geo (R = 2, centre (0, 0, 3), the coarse cubed sphere N = 2, NR = 2):
// the planes x = 0 and y = 0 and the sphere, fitted to the vertices to round-off; the Q2 mapping
// follows the spherical manifold, so the meshed volume is the quarter ball's pi R^3 / 3 to the
// mapping's error (measured 1.2e-4 relative; the straight cells miss 6.5 %, the bound is 1e-3).
TEST(GmshSolidMesh, ReadsAQuarterSphereWithItsManifolds)
{
  Triangulation<3> triangulation;
  const double R = 2., centre_z = 3.;
  const SolidMeshGeometry geometry =
      read_gmsh_solid_mesh(mesh_path("quarter_sphere_3d.geo"),
                           {{"R", R}, {"CentreZ", centre_z}, {"N", 2.}, {"NR", 2.}},
                           triangulation);
  ASSERT_EQ(geometry.surfaces.size(), 3u);
  for (const unsigned int axis : {0u, 1u})
  {
    const BoundarySurface& plane = geometry.surfaces[axis];
    ASSERT_TRUE(plane.plane.has_value()) << "surface " << plane.id;
    EXPECT_NEAR(plane.plane->normal[axis], -1., 1e-12);
    EXPECT_NEAR(plane.plane->point[axis], 0., 1e-12);
  }
  const BoundarySurface& sphere = geometry.surfaces[2];
  ASSERT_TRUE(sphere.sphere.has_value());
  EXPECT_FALSE(sphere.plane.has_value());
  EXPECT_LT(sphere.sphere->centre.distance(Point<3>(0., 0., centre_z)), 1e-12 * R);
  EXPECT_NEAR(sphere.sphere->radius, R, 1e-12 * R);

  const MappingQ<3> mapping(2);
  const FE_Q<3> linear(1);
  FEValues<3> values(mapping, linear, QGauss<3>(4), update_JxW_values);
  double volume = 0., straight_volume = 0.;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    values.reinit(cell);
    for (const unsigned int q : values.quadrature_point_indices())
      volume += values.JxW(q);
    straight_volume += cell->measure();
  }
  const double exact = numbers::PI * R * R * R / 3.;
  std::cout << "  quarter ball volume: Q2 mapping " << volume / exact - 1. << ", straight cells "
            << straight_volume / exact - 1. << "\n";
  EXPECT_NEAR(volume / exact, 1., 1e-3);
  EXPECT_LT(straight_volume / exact, 1. - 1e-2); // the test sees the manifolds
}

TEST(GmshSolidMesh, MeshesItCannotTakeAreOneLineErrors)
{
  const ScratchDirectory directory;
  const std::string box = "Point(1) = {0, 0, 0};\n"
                          "e[] = Extrude {1, 0, 0} { Point{1}; Layers{2}; };\n";
  // A box of tetrahedra: the rectangle triangulated, then extruded without layers.
  expect_solid_input_error(
      directory.write("tetrahedra.geo",
                      box + "f[] = Extrude {0, 1, 0} { Curve{e[1]}; Layers{2}; };\n"
                            "v[] = Extrude {0, 0, 1} { Surface{f[1]}; };\n"
                            "Physical Volume(1) = {v[1]};\n"
                            "Physical Surface(1) = {f[1], v[0], v[2], v[3], v[4], v[5]};\n"),
      "are not hexahedra (");
  // Prisms: triangles extruded in layers.
  expect_solid_input_error(
      directory.write("prisms.geo",
                      box + "f[] = Extrude {0, 1, 0} { Curve{e[1]}; Layers{2}; };\n"
                            "v[] = Extrude {0, 0, 1} { Surface{f[1]}; Layers{2}; Recombine; };\n"
                            "Physical Volume(1) = {v[1]};\n"
                            "Physical Surface(1) = {f[1], v[0], v[2], v[3], v[4], v[5]};\n"),
      "'Prism 6'");
  // Hexahedra whose boundary is in no physical surface.
  expect_solid_input_error(
      directory.write("untagged.geo",
                      box + "f[] = Extrude {0, 1, 0} { Curve{e[1]}; Layers{2}; Recombine; };\n"
                            "v[] = Extrude {0, 0, 1} { Surface{f[1]}; Layers{2}; Recombine; };\n"
                            "Physical Volume(1) = {v[1]};\n"),
      "belongs to no physical surface");
  // One physical surface for the whole boundary of the box: neither a plane nor a sphere.
  expect_solid_input_error(
      directory.write("one_surface.geo",
                      box + "f[] = Extrude {0, 1, 0} { Curve{e[1]}; Layers{2}; Recombine; };\n"
                            "v[] = Extrude {0, 0, 1} { Surface{f[1]}; Layers{2}; Recombine; };\n"
                            "Physical Volume(1) = {v[1]};\n"
                            "Physical Surface(1) = {f[1], v[0], v[2], v[3], v[4], v[5]};\n"),
      "physical surface 1 (of body 1) is neither a plane (a vertex lies 0.700743 from its best-fit "
      "plane) nor a sphere (a vertex lies 0.207107 from its best-fit sphere)");
  // A transfinite surface whose opposite sides have 2 and 3 cells: gmsh cannot mesh it, and its
  // error (thrown inside gmsh's OpenMP region) once ended the process.
  expect_solid_input_error(
      directory.write("mismatched.geo",
                      "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};\n"
                      "Point(4) = {0, 1, 0}; Line(1) = {1, 2}; Line(2) = {2, 3};\n"
                      "Line(3) = {3, 4}; Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4};\n"
                      "Plane Surface(1) = {1}; Transfinite Curve {1} = 3;\n"
                      "Transfinite Curve {3} = 4; Transfinite Surface {1};\n"
                      "Recombine Surface {1};\n"
                      "v[] = Extrude {0, 0, 1} { Surface{1}; Layers{1}; Recombine; };\n"
                      "Physical Volume(1) = {v[1]};\n"
                      "Physical Surface(1) = {1, v[0], v[2], v[3], v[4], v[5]};\n"),
      "cannot be meshed using the transfinite algo");
  // A quarter of a thick ring one cell high: its cylinders' vertices lie on two circles each, which
  // a sphere passes through; without a vertex inside the surface it is no sphere.
  const std::string ring = "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {2, 0, 0};\n"
                           "Point(4) = {0, 2, 0}; Point(5) = {0, 1, 0}; Line(1) = {2, 3};\n"
                           "Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};\n"
                           "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                           "Transfinite Curve {1, 3} = 2; Transfinite Curve {2, 4} = 3;\n"
                           "Transfinite Surface {1}; Recombine Surface {1};\n"
                           "v[] = Extrude {0, 0, 0.3} { Surface{1}; Layers{1}; Recombine; };\n"
                           "Physical Volume(1) = {v[1]};\n";
  expect_solid_input_error(
      directory.write("ring.geo",
                      ring + "Physical Surface(1) = {1}; Physical Surface(2) = {v[0]};\n"
                             "Physical Surface(3) = {v[2]}; Physical Surface(4) = {v[3]};\n"
                             "Physical Surface(5) = {v[4]}; Physical Surface(6) = {v[5]};\n"),
      "physical surface 4 (of body 1) is not a plane (a vertex lies 0.");
  // A block with a spherical top (the sphere of radius 3 about (0, 0, -2), z <= 1) cut by the
  // planes x = 0.2, 0.6: those planes miss the sphere's centre, so the spherical manifold would
  // bend their edges with the sphere out of them.
  expect_solid_input_error(
      directory.write("cap.geo",
                      "SetFactory(\"OpenCASCADE\");\n"
                      "Box(1) = {0.2, 0.2, 0, 0.4, 0.4, 2};\n"
                      "Sphere(2) = {0, 0, -2, 3};\n"
                      "BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };\n"
                      "Transfinite Curve {:} = 4; Transfinite Surface {:}; Recombine Surface {:};\n"
                      "Transfinite Volume {:};\n"
                      "Physical Volume(1) = {3};\n"
                      "s[] = Abs(Boundary{Volume{3};});\n"
                      "For i In {0:#s[] - 1}\n  Physical Surface(i + 1) = {s[i]};\nEndFor\n"),
      "misses its centre by");
  // A 2D mesh (the rectangle of quadrilaterals alone): no volumes.
  expect_solid_input_error(
      directory.write("flat.geo",
                      box + "f[] = Extrude {0, 1, 0} { Curve{e[1]}; Layers{2}; Recombine; };\n"
                            "Physical Surface(1) = {f[1]};\n"),
      "it is a 2D geometry, but a 3D mesh needs volumes");
}
} // namespace dyncontact::testing
