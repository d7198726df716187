#include <dyncontact/simulation/run_parameters.h>

namespace dyncontact
{
const NameTable<GeometryKind>& geometry_names()
{
  static const NameTable<GeometryKind> names{{"bars", GeometryKind::bars},
                                             {"axisymmetric mesh", GeometryKind::axisymmetric_mesh},
                                             {"plane strain mesh", GeometryKind::plane_strain_mesh},
                                             {"3d mesh", GeometryKind::solid_mesh}};
  return names;
}

MeshSection mesh_section(const GeometryKind geometry)
{
  Assert(geometry != GeometryKind::bars && geometry != GeometryKind::solid_mesh,
         ExcMessage("Only 2D meshes have a mesh section."));
  return geometry == GeometryKind::plane_strain_mesh ? MeshSection::plane_strain
                                                     : MeshSection::axisymmetric;
}

unsigned int space_dimension(const GeometryKind geometry)
{
  return geometry == GeometryKind::bars ? 1 : geometry == GeometryKind::solid_mesh ? 3 : 2;
}

void ProblemParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Problem");
  prm.declare_entry(
      "geometry",
      "bars",
      Patterns::Selection(geometry_names().selection()),
      "Kind of problem. bars: 1D bars on the x axis (subsection Geometry). "
      "axisymmetric mesh: bodies of revolution in the (r, z) half plane from a gmsh "
      "mesh, 9-node quadrilaterals (subsections Mesh and Bodies). plane strain "
      "mesh: cross-sections of long bodies in the (x, y) plane, unit thickness, "
      "from a gmsh mesh as for axisymmetric mesh but without an axis. 3d mesh: bodies in "
      "(x, y, z) from a gmsh mesh of hexahedra, 27-node cells (physical volume b is "
      "body b, every physical surface a boundary of one body: a plane or a part of a "
      "sphere).");
  prm.leave_subsection();
}

void ProblemParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Problem");
  geometry = geometry_names().parse(prm.get("geometry"), "Problem/geometry");
  prm.leave_subsection();
}
} // namespace dyncontact
