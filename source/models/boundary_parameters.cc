#include <dyncontact/base/parameter_entries.h>
#include <dyncontact/models/boundary_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>

namespace dyncontact
{
namespace
{
/** The boundary id of entry `boundary` of `section`, >= 1 (0 is no physical curve). */
types::boundary_id get_boundary(ParameterHandler& prm, const std::string& section)
{
  const long id = prm.get_integer("boundary");
  if (id < 1)
    throw InputError(section + "/boundary = " + prm.get("boundary") +
                     " is not set: give the gmsh physical curve tag (>= 1) of the boundary.");
  return static_cast<types::boundary_id>(id);
}
} // namespace

void SymmetryParameters::declare_parameters(ParameterHandler& prm)
{
  prm.declare_entry("boundary",
                    "0",
                    Patterns::Integer(0, 1000),
                    "Boundary id (gmsh physical curve tag, >= 1; in 3D the physical surface tag) "
                    "of a straight boundary (in 3D a plane) whose normal, along x (r), y (z) or, "
                    "in 3D, z, is a symmetry plane: its normal displacement is held at zero.");
}

void SymmetryParameters::parse_parameters(ParameterHandler& prm, const std::string& section)
{
  boundary = get_boundary(prm, section);
}

void SupportParameters::declare_parameters(ParameterHandler& prm)
{
  prm.declare_entry("boundary",
                    "0",
                    Patterns::Integer(0, 1000),
                    "Boundary id (gmsh physical curve tag, >= 1; in 3D the physical surface tag) "
                    "of the supported boundary.");
  prm.declare_entry("components",
                    "x, y",
                    Patterns::List(Patterns::Selection("x|y|z"), 1, 3),
                    "The displacement components held at zero on it: x (r), y (z), z (3D only), "
                    "or several (x, y in 2D or x, y, z in 3D: a clamp).");
}

void SupportParameters::parse_parameters(ParameterHandler& prm,
                                         const std::string& section,
                                         const unsigned int dim)
{
  boundary = get_boundary(prm, section);
  components.clear();
  for (const std::string& name : Utilities::split_string_list(prm.get("components")))
    components.push_back(name == "x" ? 0 : name == "y" ? 1 : 2);
  if (*std::max_element(components.begin(), components.end()) >= dim)
    throw InputError(section + "/components = " + prm.get("components") +
                     " is not allowed in 2D: z exists only for Problem/geometry = 3d mesh (give "
                     "x, y or both).");
  std::sort(components.begin(), components.end());
  components.erase(std::unique(components.begin(), components.end()), components.end());
}

void DirichletParameters::declare_parameters(ParameterHandler& prm, const unsigned int dim)
{
  SupportParameters::declare_parameters(prm);
  // Documented in the README: u_i = g_i(x, t) [length] of the chosen components.
  declare_function_subsection(prm, "Displacement", dim);
}

void DirichletParameters::parse_parameters(ParameterHandler& prm,
                                           const std::string& section,
                                           const unsigned int dim)
{
  where.parse_parameters(prm, section, dim);
  displacement = parse_function_subsection(prm, "Displacement", section, dim);
}

std::vector<HeldBoundary> BoundaryParameters::held_boundaries() const
{
  std::vector<HeldBoundary> held;
  for (unsigned int k = 0; k < supports.size(); ++k)
    held.push_back({"Boundary/Support " + std::to_string(k + 1), supports[k], {}});
  for (unsigned int k = 0; k < dirichlet_boundaries.size(); ++k)
    held.push_back({"Boundary/Dirichlet " + std::to_string(k + 1),
                    dirichlet_boundaries[k].where,
                    dirichlet_boundaries[k].displacement});
  return held;
}

void BoundaryParameters::declare_parameters(ParameterHandler& prm,
                                            const unsigned int n_symmetry_planes,
                                            const unsigned int n_supports,
                                            const unsigned int n_dirichlet_boundaries,
                                            const unsigned int dim)
{
  prm.enter_subsection("Boundary");
  prm.declare_entry("number of symmetry planes",
                    "0",
                    Patterns::Integer(0, 10),
                    "How many `Symmetry k` subsections follow, 0..10.");
  prm.declare_entry("number of supports",
                    "0",
                    Patterns::Integer(0, 100),
                    "How many `Support k` subsections follow, 0..100.");
  prm.declare_entry("number of Dirichlet boundaries",
                    "0",
                    Patterns::Integer(0, 100),
                    "How many `Dirichlet k` subsections follow, 0..100: boundaries whose chosen "
                    "displacement components follow a given function of x and t.");
  for_each_numbered_subsection(prm,
                               "Symmetry",
                               n_symmetry_planes,
                               [&prm](unsigned int, const std::string&)
                               { SymmetryParameters::declare_parameters(prm); });
  for_each_numbered_subsection(prm,
                               "Support",
                               n_supports,
                               [&prm](unsigned int, const std::string&)
                               { SupportParameters::declare_parameters(prm); });
  for_each_numbered_subsection(prm,
                               "Dirichlet",
                               n_dirichlet_boundaries,
                               [&prm, dim](unsigned int, const std::string&)
                               { DirichletParameters::declare_parameters(prm, dim); });
  prm.leave_subsection();
}

void BoundaryParameters::parse_parameters(ParameterHandler& prm, const unsigned int dim)
{
  prm.enter_subsection("Boundary");
  symmetry_planes.resize(prm.get_integer("number of symmetry planes"));
  supports.resize(prm.get_integer("number of supports"));
  dirichlet_boundaries.resize(prm.get_integer("number of Dirichlet boundaries"));
  for_each_numbered_subsection(
      prm,
      "Symmetry",
      symmetry_planes.size(),
      [&](const unsigned int k, const std::string& name)
      {
        symmetry_planes[k].parse_parameters(prm, "Boundary/" + name);
        for (unsigned int j = 0; j < k; ++j)
          if (symmetry_planes[j].boundary == symmetry_planes[k].boundary)
            throw InputError("Boundary/" + name +
                             "/boundary = " + std::to_string(symmetry_planes[k].boundary) +
                             " is Boundary/Symmetry " + std::to_string(j + 1) +
                             "'s too: give each symmetry plane once.");
      });
  for_each_numbered_subsection(prm,
                               "Support",
                               supports.size(),
                               [&](const unsigned int k, const std::string& name)
                               { supports[k].parse_parameters(prm, "Boundary/" + name, dim); });
  for_each_numbered_subsection(
      prm,
      "Dirichlet",
      dirichlet_boundaries.size(),
      [&](const unsigned int k, const std::string& name)
      { dirichlet_boundaries[k].parse_parameters(prm, "Boundary/" + name, dim); });
  prm.leave_subsection();
}
} // namespace dyncontact
