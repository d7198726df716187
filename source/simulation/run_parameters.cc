#include <dyncontact/simulation/run_parameters.h>

namespace dyncontact
{
const NameTable<GeometryKind>& geometry_names()
{
  static const NameTable<GeometryKind> names{
      {"bars", GeometryKind::bars}, {"axisymmetric mesh", GeometryKind::axisymmetric_mesh}};
  return names;
}

void ProblemParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Problem");
  prm.declare_entry("geometry",
                    "bars",
                    Patterns::Selection(geometry_names().selection()),
                    "Kind of problem. bars: 1D bars on the x axis (subsection Geometry). "
                    "axisymmetric mesh: bodies of revolution in the (r, z) half plane from a gmsh "
                    "mesh, 9-node quadrilaterals (subsections Mesh and Bodies).");
  prm.leave_subsection();
}

void ProblemParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Problem");
  geometry = geometry_names().parse(prm.get("geometry"), "Problem/geometry");
  prm.leave_subsection();
}
} // namespace dyncontact
