// read_gmsh_solid_mesh(), the reader of 3D meshes (issue 28): a box of meshes/block_3d.geo is read
// as hexahedra with its volume, bodies and six planar boundary surfaces (points and outward
// normals), and meshes dyncontact cannot take are one-line InputErrors naming the file:
// tetrahedra, prisms, boundary faces in no physical surface, a curved surface.
#include <dyncontact/models/gmsh_mesh.h>

#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>
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
    EXPECT_LT((surface.normal - normal).norm(), 1e-12) << "surface " << surface.id;
    // The plane's coordinate along its normal axis, from the surface's point.
    unsigned int axis = 0;
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(normal[d]) == 1.)
        axis = d;
    EXPECT_NEAR(surface.point[axis], coordinate, 1e-12) << "surface " << surface.id;
    EXPECT_EQ(geometry.surface(surface.id), &surface);
  }
  EXPECT_EQ(geometry.surface(7), nullptr);
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
  // One physical surface for the whole boundary of the box: not a plane.
  expect_solid_input_error(
      directory.write("one_surface.geo",
                      box + "f[] = Extrude {0, 1, 0} { Curve{e[1]}; Layers{2}; Recombine; };\n"
                            "v[] = Extrude {0, 0, 1} { Surface{f[1]}; Layers{2}; Recombine; };\n"
                            "Physical Volume(1) = {v[1]};\n"
                            "Physical Surface(1) = {f[1], v[0], v[2], v[3], v[4], v[5]};\n"),
      "physical surface 1 (of body 1) is not planar");
  // A 2D mesh (the rectangle of quadrilaterals alone): no volumes.
  expect_solid_input_error(
      directory.write("flat.geo",
                      box + "f[] = Extrude {0, 1, 0} { Curve{e[1]}; Layers{2}; Recombine; };\n"
                            "Physical Surface(1) = {f[1]};\n"),
      "it is a 2D geometry, but a 3D mesh needs volumes");
}
} // namespace dyncontact::testing
