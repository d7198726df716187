#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/models/mesh_section.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * The ids that read_gmsh_mesh() gives an axisymmetric mesh, in the (r, z) plane with x = r, from
 * its gmsh physical groups: physical surface b + 1 is body b (material id b), physical curve 1 is
 * the axis, every other physical curve t a boundary curve of one body with boundary id t and, if it
 * is a circle, manifold id t (bodies 0-based here, 1-based in gmsh). The sphere meshes
 * (meshes/sphere.geo, two_spheres.geo, ...) have one curve per body, b + 2 for body b.
 */
namespace SphereMeshIds
{
/** Boundary id of the faces on the symmetry axis r = 0 (gmsh physical curve 1). */
constexpr types::boundary_id axis = 1;

/**
 * Boundary id of the surface of `body` (0-based) in the sphere meshes, its gmsh physical curve
 * tag b + 2; also the manifold id of its SphericalManifold.
 */
constexpr types::boundary_id surface(const unsigned int body)
{
  return body + 2;
}

/**
 * Manifold id of the TransfiniteInterpolationManifold on the cells with a face on a circular
 * boundary curve; it blends the curve into the cell on refinement and for higher-order mappings.
 * Every other cell, the interior faces, the axis faces and the straight boundary curves are flat
 * (numbers::flat_manifold_id).
 */
constexpr types::manifold_id interior_manifold = 0;
} // namespace SphereMeshIds

/**
 * A circle as measured from a mesh: in an axisymmetric mesh centred on the axis, a sphere; in a
 * plane-strain mesh centred anywhere, a cylinder.
 */
struct SphereGeometry
{
  /** The centre [length]: on the axis, (0, z_c), in an axisymmetric mesh. */
  Point<2> centre;

  /** The radius [length]. */
  double radius;
};

/** A physical curve of the boundary other than the axis, as read_gmsh_mesh() found it. */
struct BoundaryCurve
{
  types::boundary_id id; ///< the gmsh physical curve tag (>= 2), also its boundary id
  unsigned int body;     ///< 0-based body whose cells it bounds
  /// set if it is an arc of a circle (centred on the axis in an axisymmetric mesh)
  std::optional<SphereGeometry> circle;
  /// set if it is straight: a point on it [length] and its unit normal pointing out of the body
  std::optional<std::pair<Point<2>, Tensor<1, 2>>> line;
};

/** What read_gmsh_mesh() found: the bodies and their boundary curves. */
struct MeshGeometry
{
  unsigned int n_bodies = 0;         ///< number of bodies (physical surfaces)
  std::vector<BoundaryCurve> curves; ///< sorted by id

  /** The curve with boundary id `id`, or nullptr. */
  const BoundaryCurve* curve(types::boundary_id id) const;

  /** Body b's sphere if its boundary other than the axis is one circular curve, else empty. */
  std::optional<SphereGeometry> sphere(unsigned int body) const;
};

/**
 * Reads a 2D mesh of one or more bodies, all quadrilaterals, into `triangulation` (which must be
 * empty) and returns its bodies and boundary curves. `section` says what the mesh stands for: the
 * rules below are those of an axisymmetric mesh; a plane-strain mesh may lie anywhere in the
 * (x, y) plane, has no axis (every physical curve t >= 1 is a boundary curve of one body), and its
 * circles may have any centre.
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
 * The mesh must lie in r = x >= 0 and carry these physical groups (see meshes/README.md):
 *  - physical surface b + 1 holds the cells of body b = 0, 1, ... (they get material id b), the
 *    surfaces numbered 1, ..., n without gaps;
 *  - physical curve 1 holds the faces on the axis r = 0 (boundary id 1, flat); it is needed only
 *    if some boundary face lies on r = 0 (a ring has no axis), and then every such face is in it;
 *  - every other physical curve t >= 2 is a boundary curve of the cells of one body (boundary id
 *    t; a body may have several). From its vertices it is either a circle centred on the axis
 *    (its centre and radius fitted by least squares, every vertex within 1e-6 R of it; it gets a
 *    SphericalManifold about that centre, manifold id t) or a straight line (every vertex within
 *    1e-6 of the curve's length from the best-fit line; flat faces). The line test comes first: a
 *    straight segment, however short, is never taken for a circle, and only an arc that bends
 *    by more than the line tolerance can be one.
 * Every boundary face belongs to one of these curves. The cells with a face on a circle get a
 * TransfiniteInterpolationManifold (SphereMeshIds::interior_manifold), the others are flat. The
 * sphere meshes have one circle per body, curve b + 2 (SphereMeshIds::surface()), whose manifold
 * id is thus b + 2.
 *
 * It is not a general mesh reader: meshes with triangles or other non-quadrilateral cells or with
 * boundaries of other shapes are rejected. Any problem with the file throws InputError, one line
 * naming the file: a missing or unreadable file, an unknown extension or parameter, gmsh's or
 * deal.II's complaint about its content condensed into one line, no cells, non-quadrilateral
 * cells with their gmsh element types, cells in no physical surface or surfaces with gaps, a
 * vertex at r < 0, boundary faces in no physical curve, axis faces off r = 0, faces on r = 0
 * outside physical curve 1 (or curve 1 missing), a curve bounding cells of more than one body,
 * a curve that is neither a circle centred on the axis nor a straight line. The triangulation is
 * then left empty.
 */
MeshGeometry read_gmsh_mesh(const std::string& filename,
                            const std::map<std::string, double>& geo_parameters,
                            Triangulation<2>& triangulation,
                            MeshSection section = MeshSection::axisymmetric);

/**
 * Attaches the manifolds of `geometry` to `triangulation`, whose cells and faces carry the manifold
 * ids that read_gmsh_mesh() set (a copy of its mesh, or a distributed part of it): a
 * SphericalManifold with the curve's id on each circular curve, and the
 * TransfiniteInterpolationManifold (SphereMeshIds::interior_manifold) on the cells with a face on
 * one; flat everywhere else (the axis, straight curves, the other cells and the interior faces).
 * The transfinite manifold searches all cells it is attached to for every point it places (deal.II
 * 9.4), so attached to every cell it made set-up quadratic in the number of cells (a 10^6-DoF mesh
 * did not finish in 3 minutes); the cells away from the curves are bilinear, where it and the flat
 * manifold place the same points (as in deal.II's step-65).
 */
void attach_manifolds(const MeshGeometry& geometry, Triangulation<2>& triangulation);

/** A plane boundary of a 3D mesh. */
struct SurfacePlane
{
  Point<3> point;      ///< a point of the plane (its vertices' mean) [length]
  Tensor<1, 3> normal; ///< the unit normal, pointing out of the body
};

/** A spherical boundary of a 3D mesh (a whole sphere or a part of one). */
struct SurfaceSphere
{
  Point<3> centre; ///< [length]
  double radius;   ///< [length]
};

/**
 * A physical surface of a 3D mesh, as read_gmsh_solid_mesh() found it: a plane or a part of a
 * sphere (exactly one of the two is set).
 */
struct BoundarySurface
{
  types::boundary_id id; ///< the gmsh physical surface tag (>= 1), also its boundary id
  unsigned int body;     ///< 0-based body whose cells it bounds
  std::optional<SurfacePlane> plane;
  /// set if it is spherical; its faces and their edges then carry manifold id `id`
  std::optional<SurfaceSphere> sphere;
};

/** What read_gmsh_solid_mesh() found: the bodies and their boundary surfaces. */
struct SolidMeshGeometry
{
  unsigned int n_bodies = 0;             ///< number of bodies (physical volumes)
  std::vector<BoundarySurface> surfaces; ///< sorted by id

  /** The surface with boundary id `id`, or nullptr. */
  const BoundarySurface* surface(types::boundary_id id) const;
};

/**
 * Attaches the manifolds of `geometry` to `triangulation`, whose cells, faces and edges carry the
 * manifold ids read_gmsh_solid_mesh() set: a SphericalManifold on each spherical surface and the
 * TransfiniteInterpolationManifold on the cells with a face on one (as attach_manifolds() in 2D).
 */
void attach_manifolds(const SolidMeshGeometry& geometry, Triangulation<3>& triangulation);

/**
 * Reads a 3D mesh of one or more bodies, all hexahedra, into `triangulation` (which must be
 * empty), as read_gmsh_mesh() reads a 2D one: a `.geo` file meshed in 3D by the gmsh library in
 * first order (its parameters set first), or a `.msh` of any order reduced to first order on its
 * vertices. Physical volume b + 1 holds the cells of body b (material id b, numbered without
 * gaps); every boundary face lies in a physical surface t >= 1 of one body (boundary id t).
 * Each surface is classified from its vertices: a plane (every vertex within 1e-6 of the mesh's
 * diameter from its best-fit plane; flat faces) or else a part of a sphere (every vertex within
 * 1e-6 R of the least-squares sphere; its faces and their edges get a SphericalManifold about its
 * centre, manifold id t, and the cells with a face on it the TransfiniteInterpolationManifold
 * SphereMeshIds::interior_manifold, which the Q2 mapping follows as in 2D). Throws InputError,
 * one line naming the file: a missing or unreadable file, an unknown extension or parameter,
 * cells that are not hexahedra (with their gmsh element types: tetrahedra, prisms, pyramids),
 * cells in no physical volume, volumes with gaps, boundary faces in no physical surface, a
 * surface bounding two bodies, a surface that is neither a plane nor a sphere. The triangulation
 * is then left empty.
 */
SolidMeshGeometry read_gmsh_solid_mesh(const std::string& filename,
                                       const std::map<std::string, double>& geo_parameters,
                                       Triangulation<3>& triangulation);

/**
 * The names of the parameters that the `.geo` file `geo_file` declares for setting from outside
 * (`DefineConstant[name = {default, Name "Parameters/name"}]`), sorted: the keys that
 * read_gmsh_mesh() accepts in `geo_parameters`. gmsh reads the file without meshing it; if it
 * cannot, InputError names the file and gmsh's complaint.
 */
std::vector<std::string> geo_file_parameters(const std::string& geo_file);
} // namespace dyncontact
