#pragma once
// Test support for meshes read from gmsh files (test_gmsh_mesh.cc, test_general_meshes.cc):
// reading sphere meshes, volumes of solids of revolution, boundary nodes, node matching across a
// contact interface, Jacobians, scratch files and the expected form of InputError.

#include <dyncontact/base/global.h>
#include <dyncontact/models/gmsh_mesh.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace dyncontact::testing
{
/** Path of a mesh file in meshes/ of the source tree, e.g. "sphere.geo". */
std::string mesh_path(const std::string& name);

/**
 * Volume of the solid of revolution of `body`, integral of 2 pi r dA, with the Q2 mapping.
 * QGauss<2>(3) integrates r det J exactly (degree 5 per direction on a Q2 cell), so the error is
 * the geometry's alone.
 */
double body_volume(const Triangulation<2>& triangulation, types::material_id body);

/** |volume of `body` - 4/3 pi radius^3| / (4/3 pi radius^3). */
double relative_sphere_volume_error(const Triangulation<2>& triangulation,
                                    types::material_id body,
                                    double radius);

/** Vertices on the boundary with the given id, each once. */
std::vector<Point<2>> boundary_vertices(const Triangulation<2>& triangulation,
                                        types::boundary_id id);

/**
 * The Q2 support points on the boundary with the given id: its vertices (each once) and the
 * mid-points of its faces where the faces' manifold puts them.
 */
std::vector<Point<2>> boundary_q2_nodes(const Triangulation<2>& triangulation,
                                        types::boundary_id id);

/** Largest distance from a point of `points` to the nearest of `targets`. */
double largest_mismatch(const std::vector<Point<2>>& points, const std::vector<Point<2>>& targets);

/**
 * The points of the sphere surface about `centre` that face the direction `approach` (a unit
 * vector along the axis, toward the other body): outer normal within 60 degrees of it, the
 * facing nodes of node-to-node contact.
 */
std::vector<Point<2>> facing_cap(const std::vector<Point<2>>& surface_points,
                                 const Point<2>& centre,
                                 const Tensor<1, 2>& approach);

/**
 * How many of `slave_nodes` have no node of `master_nodes` across from them along the axis, i.e.
 * none with the same r to `tolerance`: 0 for matching (e.g. mirrored) facing surfaces.
 */
unsigned int count_without_partner_across(const std::vector<Point<2>>& slave_nodes,
                                          const std::vector<Point<2>>& master_nodes,
                                          double tolerance);

/** Number of Gauss points (QGauss<2>(3)) where the Q2 mapping's Jacobian is not positive. */
unsigned int count_nonpositive_jacobians(const Triangulation<2>& triangulation);

/** Length of the boundary face with id `id` that has a vertex at `point` (0 if there is none). */
double boundary_edge_at(const Triangulation<2>& triangulation,
                        types::boundary_id id,
                        const Point<2>& point);

/**
 * Meshes `geo_file` with `parameters` in second order (9-node quadrilaterals), as
 * `gmsh -2 -order 2 -setnumber ...` does, into `msh_file` with the gmsh library; returns the gmsh
 * element types of its cells.
 */
std::vector<int> write_second_order_msh(const std::string& geo_file,
                                        const std::map<std::string, double>& parameters,
                                        const std::string& msh_file);

/** A fresh directory for test files, removed with everything in it at the end of the test. */
class ScratchDirectory
{
public:
  ScratchDirectory();
  ~ScratchDirectory();
  ScratchDirectory(const ScratchDirectory&)            = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  /** The full name of the file `name` in the directory. */
  std::string file(const std::string& name) const;

  /** Writes `content` into the file `name` of the directory and returns its full name. */
  std::string write(const std::string& name, const std::string& content) const;

private:
  std::filesystem::path path;
};

/**
 * Reads `filename` with `parameters` by read_gmsh_mesh() into the empty `triangulation` and
 * returns each body's sphere (MeshGeometry::sphere()), indexed by body; expects every body to be
 * one (a body that is not is left out, which shortens the result).
 */
std::vector<SphereGeometry> read_spheres(const std::string& filename,
                                         const std::map<std::string, double>& parameters,
                                         Triangulation<2>& triangulation);

/**
 * Expects read_gmsh_mesh(filename, parameters) to throw InputError whose message is one line,
 * names the file and contains `expected_text`; the triangulation must be left empty.
 */
void expect_input_error(const std::string& filename,
                        const std::map<std::string, double>& parameters,
                        const std::string& expected_text);
} // namespace dyncontact::testing
