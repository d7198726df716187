#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/parameter_entries.h>
#include <dyncontact/material/material.h>
#include <dyncontact/models/gmsh_mesh.h>
#include <dyncontact/models/mesh_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

namespace dyncontact
{
namespace
{
/**
 * Sends what is written to std::cerr into a string while it exists: deal.II's FunctionParser
 * prints muParser's diagnosis there, line by line, before it throws.
 */
class CapturedErrorStream
{
public:
  CapturedErrorStream() : original(std::cerr.rdbuf(captured.rdbuf())) {}
  ~CapturedErrorStream() { std::cerr.rdbuf(original); }
  CapturedErrorStream(const CapturedErrorStream&)            = delete;
  CapturedErrorStream& operator=(const CapturedErrorStream&) = delete;

private:
  std::ostringstream captured;
  std::streambuf* original;
};

/** Evaluates each component of `function` once, at the origin and t = 0 (see parse_function()). */
template <int dim>
void evaluate_once(const FunctionExpression& function)
{
  const auto parsed = function.create<dim>(dim);
  const CapturedErrorStream quiet;
  for (unsigned int component = 0; component < parsed->n_components; ++component)
    parsed->value(Point<dim>(), component);
}

} // namespace

FunctionExpression parse_function_subsection(ParameterHandler& prm,
                                             const std::string& name,
                                             const std::string& section,
                                             const unsigned int dim)
{
  prm.enter_subsection(name);
  const FunctionExpression function{
      prm.get("Variable names"), prm.get("Function expression"), prm.get("Function constants")};
  prm.leave_subsection();
  try
  {
    if (dim == 3)
      evaluate_once<3>(function);
    else
      evaluate_once<2>(function);
  }
  catch (const ExceptionBase& exception)
  {
    throw InputError(
        section + "/" + name + "/Function expression = '" + function.expression + "'" +
        (function.constants.empty() ? "" : " (constants '" + function.constants + "')") + ": " +
        exception_text(exception) +
        (dim == 3 ? "; it must give 3 components '(x-component); (y-component); "
                    "(z-component)' of x, y, z and t in muParser syntax."
                  : "; it must give 2 components '(x-component); (y-component)' of "
                    "x = r, y = z and t in muParser syntax."));
  }
  return function;
}

void declare_function_subsection(ParameterHandler& prm,
                                 const std::string& name,
                                 const unsigned int dim)
{
  prm.enter_subsection(name);
  if (dim == 3)
    Functions::ParsedFunction<3>::declare_parameters(prm, 3);
  else
    Functions::ParsedFunction<2>::declare_parameters(prm, 2);
  prm.leave_subsection();
}

void MeshParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Mesh");
  prm.declare_entry("file",
                    "",
                    Patterns::FileName(),
                    "gmsh mesh: a .geo file (meshed through the gmsh API) or a .msh file. A "
                    "relative path is relative to the directory of the parameter file. Physical "
                    "surface b is body b, physical curve 1 the symmetry axis, every other physical "
                    "curve a boundary of one body, a circle about the axis or a straight line; in "
                    "the sphere meshes physical curve b + 1 is the surface of body b. A 3D mesh "
                    "(Problem/geometry = 3d mesh): hexahedra, physical volume b is body b, every "
                    "physical surface a boundary of one body, a plane or a part of a sphere (see "
                    "meshes/README.md).",
                    true);
  prm.declare_entry("geo parameters",
                    "",
                    Patterns::Map(Patterns::Anything(), Patterns::Double()),
                    "Numbers set in a .geo file before meshing, as 'name: value' pairs separated "
                    "by commas, e.g. 'R: 8, Refinement: 1' (see the file's header for its "
                    "parameters). Ignored for .msh files.");
  prm.leave_subsection();
}

void MeshParameters::parse_parameters(ParameterHandler& prm,
                                      const std::string& parameter_file_directory)
{
  prm.enter_subsection("Mesh");
  const std::filesystem::path given = prm.get("file");
  file = (given.is_relative() ? std::filesystem::path(parameter_file_directory) / given : given)
             .lexically_normal()
             .string();
  if (!std::filesystem::is_regular_file(file))
    throw InputError("Mesh/file = '" + given.string() + "': no such file ('" + file +
                     "'; relative paths are taken relative to the parameter file).");
  const std::string extension = std::filesystem::path(file).extension().string();
  if (extension != ".geo" && extension != ".msh")
    throw InputError("Mesh/file = '" + given.string() + "': unknown extension '" + extension +
                     "'; allowed are .geo (meshed by gmsh) and .msh (a gmsh mesh).");
  // The record (parameters.prm) names the file absolutely, so it runs from any directory.
  prm.set("file", std::filesystem::absolute(file).lexically_normal().string());
  const std::string given_parameters = prm.get("geo parameters");
  geo_parameters.clear();
  for (const auto& pair : Utilities::split_string_list(given_parameters, ','))
  {
    const std::vector<std::string> name_and_value = Utilities::split_string_list(pair, ':');
    geo_parameters[name_and_value[0]]             = Utilities::string_to_double(name_and_value[1]);
  }
  prm.leave_subsection();

  if (geo_parameters.empty())
    return;
  if (extension == ".msh")
    throw InputError("Mesh/geo parameters = '" + given_parameters + "': Mesh/file = '" +
                     given.string() +
                     "' is a finished mesh and takes no parameters; they apply to .geo files.");
  const std::vector<std::string> known = geo_file_parameters(file);
  for (const auto& [name, value] : geo_parameters)
    if (std::find(known.begin(), known.end(), name) == known.end())
    {
      std::string names;
      for (const std::string& known_name : known)
        names += (names.empty() ? "" : ", ") + known_name;
      throw InputError("Mesh/geo parameters = '" + given_parameters + "': '" + given.string() +
                       "' has no parameter '" + name +
                       "'; its parameters are: " + (names.empty() ? "none" : names) + ".");
    }
}

void BodyParameters::declare_parameters(ParameterHandler& prm, const unsigned int dim)
{
  prm.declare_entry("material",
                    "linear elastic",
                    Patterns::Selection(material_names()),
                    "Hyperelastic law: linear elastic (small strain), st venant-kirchhoff, or "
                    "neo-hookean (compressible, W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2).");
  prm.declare_entry("Young's modulus", "1", Patterns::Double(), "E [force/length^2], > 0.", true);
  prm.declare_entry(
      "Poisson's ratio", "0.3", Patterns::Double(-1., 0.5), "nu [-], -1 < nu < 0.5.", true);
  prm.declare_entry("density", "1", Patterns::Double(), "rho [mass/length^3], > 0.", true);
  prm.declare_entry(
      "monitor point",
      "",
      Patterns::Anything(),
      "(r, z), or (x, y) in plane strain, or (x, y, z) in 3D, [length] of the point whose "
      "nearest node of this body is reported in the history as u_tip_<b>, v_tip_<b>, a_tip_<b> "
      "(components along the impact direction: z, y, or z in 3D); it must lie in the body or "
      "within one cell of it. Empty: the body's centroid, (0, z_c) on the axis (the centre of a "
      "sphere), or (x_c, y_c) or (x_c, y_c, z_c).");
  // Documented in the README: (v_r; v_z) [length/time], or (v_x; v_y; v_z) in 3D, of x (= r),
  // y (= z), z and t.
  declare_function_subsection(prm, "Initial velocity", dim);
  // Documented in the README: force per unit reference area.
  declare_function_subsection(prm, "Surface traction", dim);
  // Documented in the README: force per unit reference volume.
  declare_function_subsection(prm, "Body force", dim);
}

void BodyParameters::parse_parameters(ParameterHandler& prm,
                                      const std::string& section,
                                      const unsigned int dim)
{
  material       = prm.get("material");
  youngs_modulus = get_positive(prm, "Young's modulus", section);
  poissons_ratio = prm.get_double("Poisson's ratio");
  if (!(poissons_ratio > -1. && poissons_ratio < 0.5))
    throw InputError(section + "/Poisson's ratio = " + prm.get("Poisson's ratio") +
                     " is not allowed: it must satisfy -1 < nu < 0.5.");
  density                      = get_positive(prm, "density", section);
  const std::string point_text = Utilities::trim(prm.get("monitor point"));
  monitor_point.clear();
  if (!point_text.empty())
  {
    const std::vector<std::string> point = Utilities::split_string_list(point_text);
    const bool numbers =
        std::all_of(point.begin(),
                    point.end(),
                    [](const std::string& number) { return Patterns::Double().match(number); });
    if (point.size() != dim || !numbers)
      throw InputError(section + "/monitor point = '" + point_text + "' is not a point: give " +
                       (dim == 3 ? "x, y, z (three numbers)" : "r, z (two numbers)") +
                       ", or leave it empty for the body's centroid.");
    for (const std::string& number : point)
      monitor_point.push_back(Utilities::string_to_double(number));
  }
  initial_velocity = parse_function_subsection(prm, "Initial velocity", section, dim);
  surface_traction = parse_function_subsection(prm, "Surface traction", section, dim);
  body_force       = parse_function_subsection(prm, "Body force", section, dim);
}

void BodiesParameters::declare_parameters(ParameterHandler& prm,
                                          const unsigned int n_bodies,
                                          const unsigned int dim)
{
  prm.enter_subsection("Bodies");
  prm.declare_entry("number of bodies",
                    "1",
                    Patterns::Integer(1, 100),
                    "Number of bodies of the mesh [-], 1..100; body b is described in subsection "
                    "'Body b' and is physical surface b of the mesh.");
  for_each_numbered_subsection(prm,
                               "Body",
                               n_bodies,
                               [&prm, dim](unsigned int, const std::string&)
                               { BodyParameters::declare_parameters(prm, dim); });
  prm.leave_subsection();
}

void BodiesParameters::parse_parameters(ParameterHandler& prm, const unsigned int dim)
{
  prm.enter_subsection("Bodies");
  bodies.resize(prm.get_integer("number of bodies"));
  for_each_numbered_subsection(prm,
                               "Body",
                               bodies.size(),
                               [&](const unsigned int body, const std::string& name)
                               { bodies[body].parse_parameters(prm, "Bodies/" + name, dim); });
  prm.leave_subsection();
}
bool FunctionExpression::is_zero() const
{
  for (const std::string& component : Utilities::split_string_list(expression, ';'))
    if (!Patterns::Double().match(component) || Utilities::string_to_double(component) != 0.)
      return false;
  return true;
}

template <int dim>
std::shared_ptr<Functions::ParsedFunction<dim>>
FunctionExpression::create(const unsigned int n_components) const
{
  ParameterHandler prm;
  Functions::ParsedFunction<dim>::declare_parameters(prm, n_components);
  prm.set("Variable names", variables);
  prm.set("Function expression", expression);
  prm.set("Function constants", constants);
  auto function = std::make_shared<Functions::ParsedFunction<dim>>(n_components);
  function->parse_parameters(prm);
  return function;
}

#define DYNCONTACT_INSTANTIATE(dim)                                                                \
  template std::shared_ptr<Functions::ParsedFunction<dim>> FunctionExpression::create<dim>(        \
      unsigned int) const;
DYNCONTACT_FOR_EACH_DIMENSION(DYNCONTACT_INSTANTIATE)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
