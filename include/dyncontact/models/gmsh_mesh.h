#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * The ids that read_gmsh_mesh() gives an axisymmetric sphere mesh, in the (r, z) plane with
 * x = r. They come from the gmsh physical groups of meshes/sphere.geo and meshes/two_spheres.geo:
 * physical surface b + 1 is body b, physical curve 1 is the axis, physical curve b + 2 is the
 * sphere surface of body b (bodies 0-based here, 1-based in gmsh).
 */
namespace SphereMeshIds
{
/** Boundary id of the faces on the symmetry axis r = 0 (gmsh physical curve 1). */
constexpr types::boundary_id axis = 1;

/** Boundary id of the sphere surface of `body` (0-based), equal to its gmsh physical curve tag. */
constexpr types::boundary_id surface(const unsigned int body)
{
  return body + 2;
}

/**
 * Manifold id of the SphericalManifold on the surface faces of `body`: the same number as the
 * boundary id of that surface.
 */
constexpr types::manifold_id surface_manifold(const unsigned int body)
{
  return body + 2;
}

/**
 * Manifold id of the TransfiniteInterpolationManifold on every cell and interior face of every
 * body; it blends the curved surface into the interior on refinement and for higher-order
 * mappings. The axis faces are flat (numbers::flat_manifold_id).
 */
constexpr types::manifold_id interior_manifold = 0;
} // namespace SphereMeshIds

/** Where one body's sphere sits in the (r, z) plane, as measured from its mesh. */
struct SphereGeometry
{
  /** The centre, on the axis: (0, z_c). */
  Point<2> centre;

  /** The radius [length]. */
  double radius;
};

/**
 * Reads an axisymmetric mesh of one or more spheres, all quadrilaterals, into `triangulation`
 * (which must be empty) and returns each body's sphere, indexed by body.
 *
 * A `.geo` file is meshed in 2D by the gmsh library (linear quadrilaterals: deal.II's Q2 mapping
 * with the attached manifolds supplies the curvature) after its parameters are set: every key of
 * `geo_parameters` must be a number the file declares as
 * `DefineConstant[key = {default, Name "Parameters/key"}]`, the same name as for
 * `gmsh -setnumber key value` (see geo_file_parameters()). A `.msh` file (any format gmsh reads)
 * takes no parameters; it is read by the gmsh library, and if its elements are of higher order
 * (e.g. 9-node quadrilaterals from `gmsh -2 -order 2`) they are reduced to first order on the
 * same vertices, the curvature again coming from the mapping. Either way the first-order mesh
 * goes through a unique temporary `.msh` file, removed afterwards, which deal.II's
 * GridIn::read_msh() reads; gmsh prints nothing. gmsh is global state, so no other thread may use
 * it meanwhile; every MPI rank may call this function, each meshes on its own (gmsh is
 * deterministic, so all get the same mesh).
 *
 * With bodies b = 0, 1, ... the mesh must lie in r = x >= 0 and carry the physical groups of
 * meshes/sphere.geo: physical surface b + 1 holds the cells of body b (they get material id b),
 * physical curve 1 the faces on the axis r = 0, physical curve b + 2 the surface of body b,
 * which must be a circle centred on the axis (its centre and radius are fitted to the surface
 * vertices and returned). Every boundary face belongs to one of these curves. Boundary and
 * manifold ids are those of SphereMeshIds: a SphericalManifold about each sphere's centre on its
 * surface faces, flat axis faces, a TransfiniteInterpolationManifold on the cells.
 *
 * It is not a general mesh reader: meshes with triangles or other non-quadrilateral cells,
 * without these physical groups, or with other boundaries are rejected. Any problem with the file
 * throws InputError naming the file (a missing or unreadable file, an unknown extension or
 * parameter, gmsh's or deal.II's complaint about its content condensed into one line, no cells,
 * non-quadrilateral cells with their gmsh element types, a missing or unexpected physical group, a
 * surface that is not a sphere on the axis); the triangulation is then left empty.
 */
std::vector<SphereGeometry> read_gmsh_mesh(const std::string& filename,
                                           const std::map<std::string, double>& geo_parameters,
                                           Triangulation<2>& triangulation);

/**
 * The names of the parameters that the `.geo` file `geo_file` declares for setting from outside
 * (`DefineConstant[name = {default, Name "Parameters/name"}]`), sorted: the keys that
 * read_gmsh_mesh() accepts in `geo_parameters`. gmsh reads the file without meshing it; if it
 * cannot, InputError names the file and gmsh's complaint.
 */
std::vector<std::string> geo_file_parameters(const std::string& geo_file);
} // namespace dyncontact
