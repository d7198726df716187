#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/name_table.h>
#include <dyncontact/contact/contact_parameters.h>
#include <dyncontact/models/bar_parameters.h>
#include <dyncontact/models/boundary_parameters.h>
#include <dyncontact/models/mesh_parameters.h>
#include <dyncontact/models/mesh_section.h>
#include <dyncontact/postprocess/output_parameters.h>
#include <dyncontact/simulation/guard_parameters.h>
#include <dyncontact/solver/newton_parameters.h>
#include <dyncontact/time_integration/time_integration_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
/** Which kind of problem a run solves; decides the dimension and the sections that apply. */
enum class GeometryKind
{
  bars,              ///< 1D bars built in code, subsection `Geometry`
  axisymmetric_mesh, ///< bodies of revolution from a gmsh mesh, subsections `Mesh` and `Bodies`
  plane_strain_mesh, ///< plane-strain bodies from a gmsh mesh, subsections `Mesh` and `Bodies`
  solid_mesh         ///< 3D bodies from a gmsh mesh of hexahedra, subsections `Mesh` and `Bodies`
};

/** The names of Problem/geometry. */
const NameTable<GeometryKind>& geometry_names();

/** The section of a 2D mesh geometry (not bars or a 3D mesh: Assert). */
MeshSection mesh_section(GeometryKind geometry);

/** The space dimension of the problems of `geometry`: 1 (bars), 2 (2D meshes) or 3. */
unsigned int space_dimension(GeometryKind geometry);

/** Subsection `Problem`. */
struct ProblemParameters
{
  GeometryKind geometry;

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm);
};

/** Every setting of one run, grouped by prm subsection. */
struct RunParameters
{
  ProblemParameters problem;
  TimeIntegrationParameters time;
  ContactParameters contact;
  NewtonParameters newton;
  GuardParameters guards;
  GeometryParameters geometry; ///< bars only
  MeshParameters mesh;         ///< mesh-based problems only
  BodiesParameters bodies;     ///< mesh-based problems only
  BoundaryParameters boundary; ///< mesh-based problems only
  OutputParameters output;
  /// one line each, for the user: deprecated entries and what replaces them
  std::vector<std::string> warnings;
  /**
   * "Section/entry" and value of every entry that defines the problem, in declaration order: all
   * but Output/... and Time integration/end time (a resumed run may write elsewhere and run
   * longer), Contact/dynamics as resolved from the deprecated Time integration/scheme, which is
   * left out. What a resumed run must repeat (ProblemFingerprint).
   */
  std::vector<std::pair<std::string, std::string>> problem_entries;
};
} // namespace dyncontact
