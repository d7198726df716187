#include <dyncontact/base/parameters.h>
#include <dyncontact/material/material.h>
#include <dyncontact/models/gmsh_mesh.h>
#include <dyncontact/time_integration/generalized_alpha.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <numeric>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

namespace dyncontact
{
namespace
{
/**
 * The text deal.II attaches to one of its exceptions, without file/line decoration, on one line:
 * every run of white space (line breaks included) becomes one blank.
 */
std::string exception_text(const ExceptionBase& exception)
{
  std::ostringstream text;
  exception.print_info(text);
  std::istringstream words(text.str());
  std::string word, message;
  while (words >> word)
    message += (message.empty() ? "" : " ") + word;
  return message;
}

/**
 * A deal.II pattern description in words: "[Double 0.5...1 (inclusive)]" -> "in [0.5, 1]",
 * "[Double 0...MAX_DOUBLE (inclusive)]" -> ">= 0", "[Integer range 2...1000 (inclusive)]" ->
 * "an integer in [2, 1000]", "[Selection a|b ]" -> "one of 'a', 'b'", "[Bool]" -> "true or
 * false"; any other pattern is returned as given.
 */
std::string readable_pattern(const std::string& pattern)
{
  static const std::regex range(R"(\[(Double|Integer range) (\S+)\.\.\.(\S+) \(inclusive\)\])");
  static const std::regex selection(R"(\[Selection (.*?) ?\])");
  std::smatch match;
  if (std::regex_match(pattern, match, range))
  {
    const std::string kind = match[1] == "Double" ? "a number" : "an integer";
    const auto unbounded   = [](const std::string& bound)
    {
      return bound.find("MAX_") != std::string::npos || bound == "2147483647" ||
             bound == "-2147483648";
    };
    const std::string low = match[2], high = match[3];
    if (unbounded(low) && unbounded(high))
      return kind;
    if (unbounded(high))
      return kind + " >= " + low;
    if (unbounded(low))
      return kind + " <= " + high;
    return kind + " in [" + low + ", " + high + "]";
  }
  if (std::regex_match(pattern, match, selection))
  {
    std::string names, rest = match[1];
    for (std::size_t bar; (bar = rest.find('|')) != std::string::npos; rest = rest.substr(bar + 1))
      names += "'" + rest.substr(0, bar) + "', ";
    return "one of " + names + "'" + rest + "'";
  }
  if (pattern == "[Bool]")
    return "true or false";
  static const std::regex optional(R"(\[List of <(.*)> of length 0\.\.\.1 \(inclusive\)\])");
  if (std::regex_match(pattern, match, optional))
    return "empty or " + readable_pattern(match[1]);
  return pattern;
}

/**
 * deal.II's message on an entry in words: a value that does not match the entry's pattern, from
 * --set ("The string <V> does not match the given pattern <P>.", for `entry_path`) or from a file
 * ("Line <N> of file <F>: The entry value V for the entry named E does not match the given
 * pattern: P"), or an entry that is not declared (--set: "You can't ask for entry <E> ...", file:
 * "Line <N> of file <F>: No entry with name <E> was declared ..."). Any other message is returned
 * as given.
 */
std::string readable_entry_error(const std::string& message, const std::string& entry_path = "")
{
  static const std::regex value_from_set(
      R"(The string <(.*)> does not match the given pattern <(.*)>\.?)");
  static const std::regex value_from_file(
      R"(Line <(\d+)> of file <.*>: The entry value (.*) for the entry named (.*) does not match the given pattern: (.*))");
  static const std::regex unknown_from_set(
      R"(You can't ask for entry <(.*)> you have not yet declared\.?)");
  static const std::regex unknown_from_file(
      R"(Line <(\d+)> of file <.*>: No entry with name <(.*)> was declared in the current subsection\.?)");
  static const std::regex unknown_subsection(
      R"(Line <(\d+)> of file <.*: There is no such subsection to be entered: (.*))");
  const std::string where = entry_path.empty() ? std::string("the value") : entry_path;
  std::smatch match;
  if (std::regex_match(message, match, unknown_subsection))
  {
    // deal.II names a nested subsection with '.' separators ("Contact.Pair 2"): shown with the
    // '/' of every other message, judged by its last part.
    std::string path = match[2];
    std::replace(path.begin(), path.end(), '.', '/');
    const std::string name = path.substr(path.rfind('/') + 1);
    const std::string why =
        name == "Geometry"                   ? "it is for Problem/geometry = bars"
        : name == "Mesh" || name == "Bodies" ? "it is for Problem/geometry = axisymmetric mesh"
        : name.rfind("Bar ", 0) == 0         ? "there are only Geometry/number of bars bars"
        : name.rfind("Body ", 0) == 0        ? "there are only Bodies/number of bodies bodies"
        : name.rfind("Pair ", 0) == 0        ? "there are only Contact/number of pairs pairs"
                                             : "no such subsection is declared";
    return "line " + std::string(match[1]) + ": subsection '" + path + "' is not taken: " + why +
           " (dyncontact --print-parameters bars|mesh prints what each kind of problem takes).";
  }
  if (std::regex_match(message, match, value_from_set))
    return where + " = " + std::string(match[1]) + " is not allowed: it must be " +
           readable_pattern(match[2]) + ".";
  if (std::regex_match(message, match, value_from_file))
    return "line " + std::string(match[1]) + ": " + std::string(match[3]) + " = " +
           std::string(match[2]) + " is not allowed: it must be " + readable_pattern(match[4]) +
           ".";
  if (std::regex_match(message, match, unknown_from_set))
    return "no entry '" + std::string(match[1]) +
           "' is declared in that subsection (dyncontact --print-parameters lists them).";
  if (std::regex_match(message, match, unknown_from_file))
    return "line " + std::string(match[1]) + ": no entry '" + std::string(match[2]) +
           "' is declared in this subsection (dyncontact --print-parameters lists them).";
  return message;
}

/** Reads a double that must be strictly positive, naming `section/entry` if it is not. */
double get_positive(ParameterHandler& prm, const std::string& entry, const std::string& section)
{
  const double value = prm.get_double(entry);
  if (!(value > 0.))
    throw InputError(section + "/" + entry + " = " + prm.get(entry) +
                     " is not allowed: it must be > 0.");
  return value;
}

/** Reads a number that must lie in [low, high], naming `section/entry` and the range if not. */
double get_in_range(ParameterHandler& prm,
                    const std::string& entry,
                    const std::string& section,
                    const double low,
                    const double high)
{
  const double value = prm.get_double(entry);
  if (!(value >= low && value <= high))
    throw InputError(section + "/" + entry + " = " + prm.get(entry) +
                     " is not allowed: it must lie in " + format_number(low) + ".." +
                     format_number(high) + ".");
  return value;
}

/** Splits "A/B/entry=value" into subsection path, entry and value. */
struct Override
{
  std::vector<std::string> subsections;
  std::string entry;
  std::string value;
};

Override split_override(const std::string& text)
{
  const auto equal_sign = text.find('=');
  if (equal_sign == std::string::npos || equal_sign == 0)
    throw InputError("--set '" + text + "': expected \"Section/entry=value\".");
  Override result;
  result.value                  = Utilities::trim(text.substr(equal_sign + 1));
  std::vector<std::string> path = Utilities::split_string_list(text.substr(0, equal_sign), '/');
  result.entry                  = path.back();
  path.pop_back();
  result.subsections = path;
  return result;
}

/**
 * Applies one override. With `ignore_unknown`, an entry that is not declared is skipped (used by
 * the first parsing pass, which only knows the number of bars).
 */
void apply_override(ParameterHandler& prm, const std::string& text, const bool ignore_unknown)
{
  const Override override_entry = split_override(text);
  for (const auto& subsection : override_entry.subsections)
    prm.enter_subsection(subsection);
  try
  {
    prm.set(override_entry.entry, override_entry.value);
  }
  catch (const ExceptionBase& exception)
  {
    for (unsigned int i = 0; i < override_entry.subsections.size(); ++i)
      prm.leave_subsection();
    if (ignore_unknown)
      return;
    std::string path;
    for (const auto& subsection : override_entry.subsections)
      path += subsection + "/";
    throw InputError("--set '" + text + "': " +
                     readable_entry_error(exception_text(exception), path + override_entry.entry));
  }
  for (unsigned int i = 0; i < override_entry.subsections.size(); ++i)
    prm.leave_subsection();
}

/**
 * ParameterHandler's internal path "Geometry.Bar_202.left_20end" back to what the user writes,
 * "Geometry/Bar 2/left end": '.' separates subsections and "_xx" is the hex code of a character.
 */
std::string demangle_entry_path(const std::string& mangled)
{
  std::string path;
  for (unsigned int i = 0; i < mangled.size(); ++i)
    if (mangled[i] == '.')
      path += '/';
    else if (mangled[i] == '_' && i + 2 < mangled.size())
    {
      path += static_cast<char>(std::stoi(mangled.substr(i + 1, 2), nullptr, 16));
      i += 2;
    }
    else
      path += mangled[i];
  return path;
}

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

/**
 * Parses the 2-component ParsedFunction in subsection `name` and evaluates each component once,
 * at the origin and t = 0: muParser compiles an expression only when it is first evaluated, so
 * an unknown function or a syntax error shows here and not in the middle of a run. Any problem
 * becomes an InputError naming the entry and the expression.
 */
std::shared_ptr<Functions::ParsedFunction<2>>
parse_function(ParameterHandler& prm, const std::string& name, const std::string& section)
{
  auto function = std::make_shared<Functions::ParsedFunction<2>>(2);
  std::optional<std::string> error;
  prm.enter_subsection(name);
  const std::string expression = prm.get("Function expression");
  const std::string constants  = prm.get("Function constants");
  try
  {
    function->parse_parameters(prm);
  }
  catch (const ExceptionBase& exception)
  {
    error = exception_text(exception);
  }
  prm.leave_subsection();
  if (!error)
    try
    {
      const CapturedErrorStream quiet;
      for (unsigned int component = 0; component < function->n_components; ++component)
        function->value(Point<2>(), component);
    }
    catch (const ExceptionBase& exception)
    {
      error = exception_text(exception);
    }
  if (error)
    throw InputError(section + "/" + name + "/Function expression = '" + expression + "'" +
                     (constants.empty() ? "" : " (constants '" + constants + "')") + ": " + *error +
                     "; it must give 2 components '(x-component); (y-component)' of x = r, y = z "
                     "and t in muParser syntax.");
  return function;
}

std::string bar_section(const unsigned int bar)
{
  return "Bar " + std::to_string(bar + 1);
}

/**
 * How close the ends of bars `a` and `b` (or of a bar and the wall at `wall`) count as touching:
 * 1e-9 of the shorter element, and at least the round-off of the positions (8 units in the last
 * place of the largest |x| involved), which matters far from the origin.
 */
double touching_tolerance(const BarParameters& a, const BarParameters& b, const double wall = 0.)
{
  const double largest_position = std::max({std::abs(a.left_end),
                                            std::abs(a.right_end()),
                                            std::abs(b.left_end),
                                            std::abs(b.right_end()),
                                            std::abs(wall)});
  return std::max(1e-9 * std::min(a.element_length(), b.element_length()),
                  8. * std::numeric_limits<double>::epsilon() * largest_position);
}

/** What the first parsing pass finds out: the kind of problem and the number of bodies. */
struct ProblemSize
{
  GeometryKind geometry;
  unsigned int n_bars;
  unsigned int n_bodies;
  unsigned int n_pairs;
};

/**
 * Declares the sections a problem of the given size uses: the bars' `Geometry` for bars, `Mesh`
 * and `Bodies` for mesh-based problems (both when `size` is empty, for the documentation).
 */
void declare_all(ParameterHandler& prm, const std::optional<ProblemSize>& size)
{
  ProblemParameters::declare_parameters(prm);
  TimeIntegrationParameters::declare_parameters(prm);
  ContactParameters::declare_parameters(prm, size ? size->n_pairs : 1);
  NewtonParameters::declare_parameters(prm);
  GuardParameters::declare_parameters(prm);
  if (!size || size->geometry == GeometryKind::bars)
    GeometryParameters::declare_parameters(prm, size ? size->n_bars : 1);
  if (!size || size->geometry != GeometryKind::bars)
  {
    MeshParameters::declare_parameters(prm);
    BodiesParameters::declare_parameters(prm, size ? size->n_bodies : 1);
  }
  OutputParameters::declare_parameters(prm);
}

/** The deprecated Time integration/scheme: the Contact/dynamics each name stands for. */
const NameTable<ContactDynamicsKind>& deprecated_scheme_names()
{
  static const NameTable<ContactDynamicsKind> names{
      {"classical", ContactDynamicsKind::none},
      {"modified", ContactDynamicsKind::taylor_papadopoulos}};
  return names;
}

/** Parses `filename` into `prm`, turning deal.II's exceptions into InputError. */
void parse_file(ParameterHandler& prm, const std::string& filename, const bool skip_undefined)
{
  try
  {
    prm.parse_input(filename, "", skip_undefined);
  }
  catch (const ExceptionBase& exception)
  {
    throw InputError("parameter file '" + filename +
                     "': " + readable_entry_error(exception_text(exception)));
  }
}
/**
 * The first pass over `filename` and the `overrides`: the kind of problem and the numbers of bars,
 * bodies and pairs, which decide what the second pass declares. Throws InputError.
 */
ProblemSize read_problem_size(const std::string& filename,
                              const std::vector<std::string>& overrides)
{
  ProblemSize size;
  ParameterHandler size_prm;
  ProblemParameters::declare_parameters(size_prm);
  size_prm.enter_subsection("Geometry");
  size_prm.declare_entry("number of bars", "1", Patterns::Integer(1, 100));
  size_prm.leave_subsection();
  size_prm.enter_subsection("Bodies");
  size_prm.declare_entry("number of bodies", "1", Patterns::Integer(1, 100));
  size_prm.leave_subsection();
  size_prm.enter_subsection("Contact");
  size_prm.declare_entry("number of pairs", "0", Patterns::Integer(0, 100));
  size_prm.leave_subsection();
  parse_file(size_prm, filename, true);
  for (const auto& text : overrides)
    apply_override(size_prm, text, true);
  ProblemParameters problem;
  problem.parse_parameters(size_prm);
  size.geometry = problem.geometry;
  size_prm.enter_subsection("Geometry");
  size.n_bars = size_prm.get_integer("number of bars");
  size_prm.leave_subsection();
  size_prm.enter_subsection("Bodies");
  size.n_bodies = size_prm.get_integer("number of bodies");
  size_prm.leave_subsection();
  size_prm.enter_subsection("Contact");
  size.n_pairs = size_prm.get_integer("number of pairs");
  size_prm.leave_subsection();
  if (size.geometry == GeometryKind::bars && size.n_pairs > 0)
    throw InputError("Contact/number of pairs = " + std::to_string(size.n_pairs) +
                     " is for mesh problems; bars meet at their ends (use 0).");
  return size;
}

/// Contact/dynamics when not given: mass redistribution, on the trapezoidal rule with its contact
/// events resolved (doc/schemes.md, "The default").
const ContactDynamicsKind default_contact_dynamics = ContactDynamicsKind::mass_redistribution;
} // namespace

const NameTable<ContactFormulation>& contact_formulation_names()
{
  static const NameTable<ContactFormulation> names{
      {"lagrange multiplier", ContactFormulation::lagrange_multiplier},
      {"penalty", ContactFormulation::penalty}};
  return names;
}

const NameTable<NewtonMethod>& newton_method_names()
{
  static const NameTable<NewtonMethod> names{{"full", NewtonMethod::full},
                                             {"modified", NewtonMethod::modified}};
  return names;
}

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
                    "the sphere meshes physical curve b + 1 is the surface of body b (see "
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

void BodyParameters::declare_parameters(ParameterHandler& prm)
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
      "(r, z) [length] of the point whose nearest node of this body is reported in "
      "the history as u_tip_<b>, v_tip_<b>, a_tip_<b> (axial components); it must lie "
      "in the body or within one cell of it. Empty: the body's centroid on the axis "
      "(0, z_c), the centre of a sphere.");
  prm.enter_subsection("Initial velocity");
  Functions::ParsedFunction<2>::declare_parameters(prm, 2);
  prm.leave_subsection();
  // Documented in the README: (T_r; T_z) of x = r, y = z, t, force per unit reference area.
  prm.enter_subsection("Surface traction");
  Functions::ParsedFunction<2>::declare_parameters(prm, 2);
  prm.leave_subsection();
}

void BodyParameters::parse_parameters(ParameterHandler& prm, const std::string& section)
{
  material       = prm.get("material");
  youngs_modulus = get_positive(prm, "Young's modulus", section);
  poissons_ratio = prm.get_double("Poisson's ratio");
  if (!(poissons_ratio > -1. && poissons_ratio < 0.5))
    throw InputError(section + "/Poisson's ratio = " + prm.get("Poisson's ratio") +
                     " is not allowed: it must satisfy -1 < nu < 0.5.");
  density                      = get_positive(prm, "density", section);
  const std::string point_text = Utilities::trim(prm.get("monitor point"));
  monitor_point.reset();
  if (!point_text.empty())
  {
    const std::vector<std::string> point = Utilities::split_string_list(point_text);
    if (point.size() != 2 || !Patterns::Double().match(point[0]) ||
        !Patterns::Double().match(point[1]))
      throw InputError(section + "/monitor point = '" + point_text +
                       "' is not a point: give r, z (two numbers), or leave it empty for the "
                       "body's centroid.");
    monitor_point =
        Point<2>(Utilities::string_to_double(point[0]), Utilities::string_to_double(point[1]));
  }
  initial_velocity = parse_function(prm, "Initial velocity", section);
  surface_traction = parse_function(prm, "Surface traction", section);
}

void BodiesParameters::declare_parameters(ParameterHandler& prm, const unsigned int n_bodies)
{
  prm.enter_subsection("Bodies");
  prm.declare_entry("number of bodies",
                    "1",
                    Patterns::Integer(1, 100),
                    "Number of bodies of the mesh [-], 1..100; body b is described in subsection "
                    "'Body b' and is physical surface b of the mesh.");
  for (unsigned int body = 0; body < n_bodies; ++body)
  {
    prm.enter_subsection("Body " + std::to_string(body + 1));
    BodyParameters::declare_parameters(prm);
    prm.leave_subsection();
  }
  prm.leave_subsection();
}

void BodiesParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Bodies");
  bodies.resize(prm.get_integer("number of bodies"));
  for (unsigned int body = 0; body < bodies.size(); ++body)
  {
    const std::string name = "Body " + std::to_string(body + 1);
    prm.enter_subsection(name);
    bodies[body].parse_parameters(prm, "Bodies/" + name);
    prm.leave_subsection();
  }
  prm.leave_subsection();
}

void TimeIntegrationParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Time integration");
  prm.declare_entry("scheme",
                    "",
                    Patterns::Anything(),
                    "Deprecated: use Contact/dynamics. classical = Contact/dynamics none, "
                    "modified = taylor-papadopoulos; given, it sets Contact/dynamics and the run "
                    "prints a warning. Empty: not given.");
  prm.declare_entry(
      "integrator",
      "newmark",
      Patterns::Selection(integrator_family_names().selection()),
      "The time integrator, a member of the generalized-alpha family. newmark: Newmark with the "
      "beta and gamma below; the default, gamma = 0.502 and beta = 0.251001, damps the highest "
      "frequencies slightly (rho_inf = 0.996) and, with the default Contact/dynamics = "
      "mass-redistribution, keeps one contact episode on a stiff striker and never gains energy "
      "in an impact at any time step, where the trapezoidal rule (beta = 1/4, gamma = 1/2, the "
      "paper's) gains up to the contact event tolerance (doc/schemes.md, \"The default\"). hht "
      "(Hilber, Hughes & Taylor 1977), bossak (Wood, Bossak & Zienkiewicz 1980) and "
      "generalized-alpha (Chung & Hulbert 1993): second order and unconditionally stable, damping "
      "the highest frequencies by the spectral radius below; they set beta and gamma themselves "
      "(leave those entries empty, or at 0.25 and 0.5).");
  prm.declare_entry("spectral radius",
                    "0.8",
                    Patterns::Double(0., 1.),
                    "rho_inf [-] of hht (in [0.5, 1]), bossak and generalized-alpha (in [0, 1]): "
                    "the amplification of the highest frequencies per step; 1 dissipates nothing, "
                    "0 annihilates them in one step (generalized-alpha). Unused by newmark.");
  prm.declare_entry("beta",
                    "",
                    Patterns::List(Patterns::Double(), 0, 1),
                    "Newmark beta [-], 0 < beta <= 0.5. Unconditionally stable when "
                    "2 beta >= gamma; beta = 0.25 with gamma = 0.5 is the trapezoidal rule. beta = "
                    "0 (explicit central difference) is rejected: u_{n+1} would not depend on the "
                    "contact force, so no constraint could act on it. Empty: (gamma + 1/2)^2 / 4, "
                    "the stable member with the most high-frequency damping for that gamma "
                    "(0.251001 with both entries empty; 0.25 with a Contact/dynamics built on the "
                    "trapezoidal rule: contact-stabilized, persistency, velocity-update).");
  prm.declare_entry("gamma",
                    "",
                    Patterns::List(Patterns::Double(0.5, 1.), 0, 1),
                    "Newmark gamma [-], 0.5 <= gamma <= 1. Second order only for gamma = 0.5; "
                    "gamma > 0.5 adds numerical dissipation. Empty: 0.5 if beta is given, else "
                    "0.502 (0.5 with a Contact/dynamics built on the trapezoidal rule).");
  prm.declare_entry("time step",
                    "0.1",
                    Patterns::Double(),
                    "Time step dt [time], > 0. The Courant number c dt / h is printed at start.");
  prm.declare_entry("end time", "30", Patterns::Double(), "End of the run [time], > 0.");
  prm.declare_entry("maximum step cuts",
                    "10",
                    Patterns::Integer(),
                    "Step control [-], 0..20: a step that fails (Newton does not converge, an "
                    "element inverts, or a guard of subsection Guards trips) is retried with half "
                    "the size, at most this many times, i.e. down to time step / 2^cuts; the size "
                    "grows back after two accepted sub-steps. If the smallest step still fails the "
                    "run stops (exit 3) keeping its output. 0 = never cut.");
  prm.leave_subsection();
}

void TimeIntegrationParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Time integration");
  deprecated_scheme          = prm.get("scheme"); // resolved, or rejected, by resolve_and_check()
  const auto optional_double = [&prm](const std::string& entry) -> std::optional<double>
  {
    const std::string text = prm.get(entry);
    if (text.empty())
      return std::nullopt;
    return prm.get_double(entry);
  };
  given_beta  = optional_double("beta");
  given_gamma = optional_double("gamma");
  if (given_beta == 0.)
    throw InputError("Time integration/beta = 0 is not supported: with beta = 0 the displacement "
                     "u_{n+1} is explicit and the contact constraint cannot act on it. Use "
                     "0 < beta <= 0.5 (the paper's nearly explicit choice is 0.001).");
  if (given_beta && !(*given_beta > 0. && *given_beta <= 0.5))
    throw InputError("Time integration/beta = " + prm.get("beta") +
                     " is not allowed: it must be in (0, 0.5].");
  time_step = get_positive(prm, "time step", "Time integration");
  integrator =
      integrator_family_names().parse(prm.get("integrator"), "Time integration/integrator");
  spectral_radius = prm.get_double("spectral radius");
  // Newmark's coefficients left empty are resolved in ParameterReader::resolve_and_check(): their
  // defaults depend on Contact/dynamics.
  if (integrator != IntegratorFamily::newmark)
  {
    const std::string member = "Time integration/integrator = " + prm.get("integrator");
    // A file written for the trapezoidal rule (beta = 1/4, gamma = 1/2, as the shipped ones) runs
    // on any member; other values given would be ignored, so they are refused.
    if (given_beta.value_or(0.25) != 0.25 || given_gamma.value_or(0.5) != 0.5)
      throw InputError(member +
                       " sets beta and gamma from the spectral radius; leave Time "
                       "integration/beta and gamma empty (their defaults), out, or at the "
                       "trapezoidal rule's 0.25 and 0.5 (given beta = '" +
                       prm.get("beta") + "', gamma = '" + prm.get("gamma") + "').");
    const double lowest = GeneralizedAlpha::lowest_spectral_radius(integrator);
    if (spectral_radius < lowest)
      throw InputError("Time integration/spectral radius = " + format_number(spectral_radius) +
                       " is not allowed with " + member + ": it must be in [" +
                       format_number(lowest) + ", 1].");
    const GeneralizedAlpha member_coefficients(integrator, spectral_radius, time_step);
    beta  = member_coefficients.beta();
    gamma = member_coefficients.gamma();
  }
  end_time = get_positive(prm, "end time", "Time integration");
  if (end_time / time_step > 1e8)
    throw InputError("Time integration/end time = " + prm.get("end time") +
                     " with time step = " + prm.get("time step") +
                     " asks for more than 1e8 steps; at most 1e8 are allowed.");
  max_step_cuts =
      static_cast<unsigned int>(get_in_range(prm, "maximum step cuts", "Time integration", 0, 20));
  prm.leave_subsection();
}

void TimeIntegrationParameters::resolve_newmark_coefficients(const bool trapezoidal_rule_required)
{
  if (integrator != IntegratorFamily::newmark)
    return;
  if (trapezoidal_rule_required && !given_beta && !given_gamma)
  {
    beta  = 0.25;
    gamma = 0.5;
    return;
  }
  if (!given_beta && !given_gamma)
  {
    beta  = default_newmark_beta;
    gamma = default_newmark_gamma;
    return;
  }
  gamma = given_gamma.value_or(0.5);
  beta  = given_beta.value_or((gamma + 0.5) * (gamma + 0.5) / 4.);
}

unsigned int TimeIntegrationParameters::n_steps() const
{
  // At least one: an end time below 1e-9 of the time step is not a run of zero steps.
  return std::max(1u, static_cast<unsigned int>(std::ceil(end_time / time_step - 1e-9)));
}

void ContactPairParameters::declare_parameters(ParameterHandler& prm)
{
  prm.declare_entry("slave boundary",
                    "0",
                    Patterns::Integer(0),
                    "The slave surface of this pair: a boundary id, i.e. the tag of a gmsh "
                    "physical curve of the mesh (>= 2; 1 is the symmetry axis). Its nodes carry "
                    "the pair's multipliers.");
  prm.declare_entry("master boundary",
                    "0",
                    Patterns::Integer(0),
                    "The master surface: a boundary id (>= 2) of another body, or 0 for the rigid "
                    "plane below. The slave nodes are projected onto it (node-to-segment) or "
                    "paired with its facing nodes (node-to-node).");
  prm.declare_entry("rigid plane",
                    "",
                    Patterns::Anything(),
                    "With master boundary = 0: a fixed rigid plane (a line in the r-z plane) as "
                    "'r, z; n_r, n_z': a point on it [length] and its normal pointing toward the "
                    "body (normalized here), e.g. '0, 0; 0, 1' for the plane z = 0 below a body. "
                    "Empty otherwise.");
}

namespace
{
/** The numbers of "a, b, ..." (comma-separated); empty if one is not a number. */
std::vector<double> parse_numbers(const std::string& text)
{
  std::vector<double> numbers;
  std::istringstream fields(text);
  for (std::string field; std::getline(fields, field, ',');)
  {
    std::istringstream stream(field);
    double value;
    if (!(stream >> value) || !(stream >> std::ws).eof() || !std::isfinite(value))
      return {};
    numbers.push_back(value);
  }
  return numbers;
}
} // namespace

void ContactPairParameters::parse_parameters(ParameterHandler& prm, const std::string& source)
{
  this->source           = source;
  const auto slave       = prm.get_integer("slave boundary");
  const auto master      = prm.get_integer("master boundary");
  const std::string text = prm.get("rigid plane");
  const bool has_plane   = text.find_first_not_of(" \t") != std::string::npos;
  if (slave < 2)
    throw InputError(source + "/slave boundary = " + std::to_string(slave) +
                     " is not allowed: it must be a boundary id >= 2 (a gmsh physical curve "
                     "tag; 1 is the symmetry axis).");
  if (master == 1 || master == slave)
    throw InputError(source + "/master boundary = " + std::to_string(master) +
                     " is not allowed: it must be a boundary id >= 2 other than the slave "
                     "boundary, or 0 for a rigid plane.");
  if ((master != 0) == has_plane)
    throw InputError(source +
                     ": give either master boundary (>= 2) or rigid plane ('r, z; "
                     "n_r, n_z' with master boundary = 0), not " +
                     std::string(has_plane ? "both." : "neither."));
  slave_boundary = slave;
  if (master != 0)
  {
    master_boundary = master;
    return;
  }
  const auto separator = text.find(';');
  const std::vector<double> point =
      parse_numbers(separator == std::string::npos ? text : text.substr(0, separator));
  const std::vector<double> normal = separator == std::string::npos
                                         ? std::vector<double>()
                                         : parse_numbers(text.substr(separator + 1));
  const double length              = normal.size() == 2 ? std::hypot(normal[0], normal[1]) : 0.;
  if (point.size() != 2 || normal.size() != 2 || !(length > 0.))
    throw InputError(source + "/rigid plane = '" + text +
                     "' is not allowed: it must be 'r, z; n_r, n_z', a point and a nonzero "
                     "normal.");
  rigid_plane = std::make_pair(Point<2>(point[0], point[1]),
                               Tensor<1, 2>({normal[0] / length, normal[1] / length}));
}

void ContactParameters::declare_parameters(ParameterHandler& prm, const unsigned int n_pairs)
{
  prm.enter_subsection("Contact");
  prm.declare_entry("number of pairs",
                    "0",
                    Patterns::Integer(0, 100),
                    "Mesh problems: how many contact pairs are declared, as subsections "
                    "'Pair 1', 'Pair 2', ... 0: with two bodies, their surfaces of the sphere "
                    "meshes (physical curves 2 and 3, body 1 the slave side); with one body, "
                    "no contact; more bodies need declared pairs. Bars: 0.");
  for (unsigned int k = 1; k <= n_pairs; ++k)
  {
    prm.enter_subsection("Pair " + std::to_string(k));
    ContactPairParameters::declare_parameters(prm);
    prm.leave_subsection();
  }
  prm.declare_entry("dynamics",
                    contact_dynamics_names().name(default_contact_dynamics),
                    Patterns::Selection(contact_dynamics_names().selection()),
                    contact_dynamics_documentation(default_contact_dynamics));
  prm.declare_entry("formulation",
                    "lagrange multiplier",
                    Patterns::Selection(contact_formulation_names().selection()),
                    "Enforcement of the non-penetration condition g >= 0. lagrange multiplier: "
                    "exact, one multiplier unknown per candidate pair (saddle-point solve). "
                    "penalty: force eps <-g> along the normal (allows small penetration).");
  prm.declare_entry(
      "discretization",
      "node-to-node",
      Patterns::Selection(contact_discretization_names().selection()),
      "How the two bodies' contact surfaces meet (axisymmetric meshes). node-to-node: each "
      "facing node of body 1 against the node of body 2 across from it; the facing surfaces "
      "must have matching nodes (mirrored meshes). node-to-segment: each surface node of body 1 "
      "(slave) against its closest point on the curved quadratic faces of body 2 (master), "
      "for any meshes; the paper's rate correction (Contact/dynamics) acts on the slave node "
      "and the master face's nodes. Both are the same on matching meshes.");
  prm.declare_entry("penalty factor",
                    "auto",
                    Patterns::Anything(),
                    "Penalty only: stiffness eps of a pair [force/length] = this factor [-] times "
                    "E A / h of the stiffer side; a number > 0, or auto. Bars: A the "
                    "cross-section, h the element length at the contact node; meshes: A the "
                    "pair's contact area (2 pi r weighted), h the shortest cell edge. "
                    "auto: 100 where the time step does not resolve the bodies' highest mode "
                    "(omega dt > 2, the quasi-static contact of the spheres: penetration about "
                    "1e-3 of the Hertz approach), else the largest factor <= 100 whose stiffest "
                    "spring has omega dt <= 1 (wave problems such as the bars: an unresolved "
                    "spring chatters, forces several times the exact ones). The run prints the "
                    "factor it chose. "
                    "With the classical scheme and beta < gamma/2 a large penalty needs a small "
                    "time step (a run refuses one above the stability limit).");
  prm.leave_subsection();
}

void ContactParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Contact");
  formulation = contact_formulation_names().parse(prm.get("formulation"), "Contact/formulation");
  dynamics    = contact_dynamics_names().parse(prm.get("dynamics"), "Contact/dynamics");
  discretization =
      contact_discretization_names().parse(prm.get("discretization"), "Contact/discretization");
  const std::string factor = prm.get("penalty factor");
  automatic_penalty        = factor == "auto";
  penalty_factor           = quasi_static_penalty_factor;
  if (!automatic_penalty)
  {
    std::istringstream stream(factor);
    if (!(stream >> penalty_factor) || !(stream >> std::ws).eof() || !(penalty_factor > 0.))
      throw InputError("Contact/penalty factor = " + factor +
                       " is not allowed: it must be a number > 0 or auto.");
  }
  pairs.resize(prm.get_integer("number of pairs"));
  for (unsigned int k = 0; k < pairs.size(); ++k)
  {
    const std::string name = "Pair " + std::to_string(k + 1);
    prm.enter_subsection(name);
    pairs[k].parse_parameters(prm, "Contact/" + name);
    prm.leave_subsection();
  }
  prm.leave_subsection();
}

void NewtonParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Newton");
  prm.declare_entry("maximum iterations",
                    "25",
                    Patterns::Integer(2, 1000),
                    "Maximum number of linear solves per time step, including the re-solves "
                    "after active-set changes [-], 2..1000 (an active-set change needs two). "
                    "Exceeding it stops the run with a "
                    "message; the output written so far is kept.");
  prm.declare_entry(
      "residual tolerance",
      "1e-10",
      Patterns::Double(),
      "Newton converges when the residual norm is below this fraction of the "
      "reference force |Q(u)| + |W| + |G^T lambda| (elastic, external and contact "
      "forces; not the inertia) plus a round-off floor, every active pair is closed to "
      "this fraction of the smallest cell diameter and compressive, every inactive "
      "pair open to it, and, with active pairs, after at least one linear solve "
      "[-], 1e-16..1e-6. Looser values are rejected: they leave residuals at the "
      "contact nodes that break the momentum balance (1e-6 relative) of a step.");
  prm.declare_entry(
      "direct solver",
      "klu",
      Patterns::Selection(direct_solver_names().selection()),
      "Sparse direct solver of the Newton iterations; a factorization is reused while the "
      "matrix does not change. klu: Amesos KLU, any number of MPI ranks (the matrix is gathered "
      "to one), results identical run to run. umfpack: UMFPACK, one rank only. mumps: Amesos "
      "MUMPS, distributed; on several ranks its results may differ in the last digits from run "
      "to run.");
  prm.declare_entry(
      "method",
      "full",
      Patterns::Selection(newton_method_names().selection()),
      "full: a fresh tangent (assembly and factorization) for every Newton update. modified: the "
      "tangent of a step's first update also serves its later updates while the active set stays "
      "the same and each update reduces the residual at least 10 times, else a fresh one is "
      "taken, and when pairs enter or leave the active set (at most 4 at a time) the factors are "
      "updated (low-rank) instead of recomputed; the same convergence test, fewer "
      "factorizations (the converged steps differ within the Newton tolerance).");
  prm.leave_subsection();
}

void NewtonParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Newton");
  max_iterations     = prm.get_integer("maximum iterations");
  residual_tolerance = get_in_range(prm, "residual tolerance", "Newton", 1e-16, 1e-6);
  direct_solver = direct_solver_names().parse(prm.get("direct solver"), "Newton/direct solver");
  method        = newton_method_names().parse(prm.get("method"), "Newton/method");
  prm.leave_subsection();
}

void GuardParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Guards");
  prm.declare_entry("energy",
                    "true",
                    Patterns::Bool(),
                    "Reject a step whose algorithmic energy exceeds the initial energy plus the "
                    "work of the external forces (frictionless elastic contact cannot gain "
                    "energy). A rejected step is cut (Time integration/maximum step cuts).");
  prm.declare_entry("energy tolerance",
                    "1e-4",
                    Patterns::Double(),
                    "Allowed energy gain, relative to the initial energy (for bodies starting at "
                    "rest: the largest energy of the run) [-], 0..1.");
  prm.declare_entry(
      "plain energy tolerance",
      "0.01",
      Patterns::Double(),
      "With Newmark's 2 beta < gamma only (conditionally stable): allowed gain of the "
      "plain energy (kinetic + strain), relative like the energy tolerance [-], "
      "0..1. The algorithmic energy the energy guard reads then weighs a mode's "
      "strain energy by 1 - (omega dt / limit)^2, so it cannot see energy gained in "
      "the highest modes near the stability limit; the plain energy is checked too. "
      "It is not conserved by a stable run either: it exceeds the algorithmic one by "
      "(gamma/2 - beta) dt^2/2 a.Ma (paper 6.1 at Courant 1: 0.58 %).");
  prm.declare_entry("tensile force",
                    "true",
                    Patterns::Bool(),
                    "Reject a step whose recovered total contact force is tensile.");
  prm.declare_entry("tensile force tolerance",
                    "1e-4",
                    Patterns::Double(),
                    "Allowed tension, relative to the largest contact force of the run (or the sum "
                    "of the step's |multipliers|) [-], 0..1.");
  prm.declare_entry("momentum",
                    "true",
                    Patterns::Bool(),
                    "Reject a step after which a body's momentum change (along the impact "
                    "direction) differs from the impulse it received from the contact and the "
                    "external forces.");
  prm.declare_entry("momentum tolerance",
                    "1e-6",
                    Patterns::Double(),
                    "Allowed difference, relative to the run's largest momentum magnitude, the sum "
                    "of |m v| over every node and direction (not the net momentum, which is zero "
                    "for a free vibration) [-], 0..1.");
  prm.declare_entry(
      "contact event tolerance",
      "1e-4",
      Patterns::Double(),
      "With massless contact nodes (Contact/dynamics = mass-redistribution) only: a step in "
      "which pairs close or open is cut while the work of these events exceeds this fraction of "
      "the energy [-], 0..1 (1 never cuts): (1/2) the new force times the gap at the step's start "
      "for a closing pair, (1/2) the old force times the gap at its end for an opening one. With "
      "massless contact nodes the bodies do not impact, the contact force rises and falls "
      "elastically, and the event work is the time discretization's energy error at the events "
      "(the trapezoidal rule loses exactly the closing work and gains exactly the opening work), "
      "which each halving divides by about 4 (by 2 where the force drops abruptly). At the "
      "smallest step (Time integration/maximum step cuts) the step is accepted.");
  prm.leave_subsection();
}

void GuardParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Guards");
  energy                  = prm.get_bool("energy");
  energy_tolerance        = get_in_range(prm, "energy tolerance", "Guards", 0., 1.);
  plain_energy_tolerance  = get_in_range(prm, "plain energy tolerance", "Guards", 0., 1.);
  tensile_force           = prm.get_bool("tensile force");
  tensile_force_tolerance = get_in_range(prm, "tensile force tolerance", "Guards", 0., 1.);
  momentum                = prm.get_bool("momentum");
  momentum_tolerance      = get_in_range(prm, "momentum tolerance", "Guards", 0., 1.);
  contact_event_tolerance = get_in_range(prm, "contact event tolerance", "Guards", 0., 1.);
  prm.leave_subsection();
}

double BarParameters::wave_speed() const
{
  return std::sqrt(youngs_modulus / density);
}

void BarParameters::declare_parameters(ParameterHandler& prm)
{
  // Every entry of a bar must be given: a bar the user forgot must not appear with defaults.
  prm.declare_entry(
      "left end", "0", Patterns::Double(), "x of the bar's left end at t = 0 [length].", true);
  prm.declare_entry("length", "10", Patterns::Double(), "Bar length L [length], > 0.", true);
  prm.declare_entry("number of elements",
                    "100",
                    Patterns::Integer(1, 10000000),
                    "Number of equal 2-node linear elements along the bar [-], >= 1.",
                    true);
  prm.declare_entry("Young's modulus", "1", Patterns::Double(), "E [force/length^2], > 0.", true);
  prm.declare_entry("density", "1", Patterns::Double(), "rho [mass/length^3], > 0.", true);
  prm.declare_entry("cross-section area", "1", Patterns::Double(), "A [length^2], > 0.", true);
  prm.declare_entry("initial velocity",
                    "0",
                    Patterns::Double(),
                    "Uniform velocity along +x at t = 0 [length/time]; the bar starts "
                    "stress-free.",
                    true);
}

void BarParameters::parse_parameters(ParameterHandler& prm, const std::string& section)
{
  left_end         = prm.get_double("left end");
  length           = get_positive(prm, "length", section);
  n_elements       = prm.get_integer("number of elements");
  youngs_modulus   = get_positive(prm, "Young's modulus", section);
  density          = get_positive(prm, "density", section);
  area             = get_positive(prm, "cross-section area", section);
  initial_velocity = prm.get_double("initial velocity");
}

void GeometryParameters::declare_parameters(ParameterHandler& prm, const unsigned int n_bars)
{
  prm.enter_subsection("Geometry");
  prm.declare_entry("number of bars",
                    "1",
                    Patterns::Integer(1, 100),
                    "Number of bars [-], 1..100; bar b is described in subsection 'Bar b' and is "
                    "body b of the outputs. Contact is checked between facing ends of bars "
                    "that are neighbours along x, and between the rightmost bar and the wall.");
  for (unsigned int bar = 0; bar < n_bars; ++bar)
  {
    prm.enter_subsection(bar_section(bar));
    BarParameters::declare_parameters(prm);
    prm.leave_subsection();
  }
  prm.declare_entry("clamped left end",
                    "false",
                    Patterns::Bool(),
                    "Whether the left end of the leftmost bar is clamped (u = 0 there, a fixed "
                    "support). With a rigid wall and one bar: the Signorini bar, a bar clamped at "
                    "one end bouncing on an obstacle.");
  prm.enter_subsection("Rigid wall");
  prm.declare_entry("enabled", "false", Patterns::Bool(), "Whether a fixed rigid wall exists.");
  prm.declare_entry("position",
                    "0",
                    Patterns::Double(),
                    "x of the wall [length]. The wall faces -x: every bar must lie to its left "
                    "(touching is allowed).");
  prm.leave_subsection();
  prm.leave_subsection();
}

void GeometryParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Geometry");
  const unsigned int n_bars = prm.get_integer("number of bars");
  bars.resize(n_bars);
  for (unsigned int bar = 0; bar < n_bars; ++bar)
  {
    prm.enter_subsection(bar_section(bar));
    bars[bar].parse_parameters(prm, "Geometry/" + bar_section(bar));
    prm.leave_subsection();
  }
  clamped_left_end = prm.get_bool("clamped left end");
  prm.enter_subsection("Rigid wall");
  wall_enabled  = prm.get_bool("enabled");
  wall_position = prm.get_double("position");
  prm.leave_subsection();
  prm.leave_subsection();

  // Positions are compared with a tolerance: a left end typed as 0.3 and a right end computed as
  // 0.1 + 0.2 = 0.30000000000000004 touch. Within it, bodies touch and are snapped together, so
  // that the reference gap is exactly zero and contact starts closed; beyond it they overlap.
  for (unsigned int a = 0; a < n_bars; ++a)
    for (unsigned int b = a + 1; b < n_bars; ++b)
    {
      const double tolerance = touching_tolerance(bars[a], bars[b]);
      const double overlap   = std::min(bars[a].right_end(), bars[b].right_end()) -
                             std::max(bars[a].left_end, bars[b].left_end);
      if (overlap > tolerance)
        throw InputError(
            "Geometry: Bar " + std::to_string(a + 1) + " [" + format_exact(bars[a].left_end) +
            ", " + format_exact(bars[a].right_end()) + "] and Bar " + std::to_string(b + 1) + " [" +
            format_exact(bars[b].left_end) + ", " + format_exact(bars[b].right_end()) +
            "] overlap at t = 0 by " + format_number(overlap) + "; bars may touch (to " +
            format_number(tolerance) + ", 1e-9 of the shorter element) but not overlap.");
    }
  std::vector<unsigned int> x_order(n_bars);
  std::iota(x_order.begin(), x_order.end(), 0u);
  std::sort(x_order.begin(),
            x_order.end(),
            [this](const unsigned int a, const unsigned int b)
            { return bars[a].left_end < bars[b].left_end; });
  for (unsigned int i = 0; i + 1 < n_bars; ++i)
  {
    const BarParameters& left = bars[x_order[i]];
    BarParameters& right      = bars[x_order[i + 1]];
    if (right.left_end - left.right_end() <= touching_tolerance(left, right))
      right.left_end = left.right_end();
  }

  if (!wall_enabled)
    return;
  const BarParameters& rightmost = bars[x_order.back()];
  const double tolerance         = touching_tolerance(rightmost, rightmost, wall_position);
  // Every bar lies left of the rightmost one's right end: the bars do not overlap.
  if (rightmost.right_end() - wall_position > tolerance)
    throw InputError("Geometry/Rigid wall/position = " + format_exact(wall_position) +
                     " is left of the right end " + format_exact(rightmost.right_end()) +
                     " of Bar " + std::to_string(x_order.back() + 1) + " [" +
                     format_exact(rightmost.left_end) + ", " + format_exact(rightmost.right_end()) +
                     "], which reaches " + format_number(rightmost.right_end() - wall_position) +
                     " past it; the wall faces -x, so every bar must lie at x <= position "
                     "(touching, to " +
                     format_number(tolerance) + " = 1e-9 of an element, is allowed).");
  if (wall_position - rightmost.right_end() <= tolerance)
    wall_position = rightmost.right_end();
}

void OutputParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Output");
  prm.declare_entry("directory",
                    "output",
                    Patterns::DirectoryName(),
                    "Directory for all results of the run (created if missing; relative paths "
                    "are relative to the working directory).");
  prm.declare_entry("profile times",
                    "",
                    Patterns::List(Patterns::Double(0.)),
                    "Comma-separated times [time] at which profile_t<time>.csv (body, x, u, v, a "
                    "of every node) is written, at the time step closest to each.");
  prm.declare_entry("vtu interval",
                    "10",
                    Patterns::Integer(0),
                    "Write a VTU frame of the fields (solution_<row>.pvtu, listed with its time in "
                    "solution.pvd; <row> is the frame's row of history.csv) every this many "
                    "steps [-]; 0 = not at an interval.");
  prm.declare_entry("vtu times",
                    "",
                    Patterns::List(Patterns::Double(0.)),
                    "Comma-separated times [time] at which a VTU frame is also written, at the "
                    "time step closest to each.");
  prm.declare_entry("vtu during contact",
                    "true",
                    Patterns::Bool(),
                    "If VTU output is on (vtu interval > 0 or vtu times given), also write a "
                    "frame at every step with active contact pairs, cut steps included, so that "
                    "every contact is seen however short; surface contact also writes "
                    "contact_surface.pvd (pressure, gap and active flag on the slave surfaces).");
  prm.declare_entry(
      "checkpoint interval",
      "0",
      Patterns::Integer(),
      "Write checkpoint.bin (the whole state: u, v, a, multipliers, active set, step "
      "size, time, history) every this many steps [-], 0..1e8; 0 = only when the run "
      "is interrupted (SIGINT or SIGTERM finish the current step, write a checkpoint "
      "and stop). `dyncontact FILE.prm --resume DIR` continues from it; the history "
      "equals that of an uninterrupted run. A run that reaches its end time keeps "
      "checkpoint.bin only if it holds the end state (resume it with a later end time "
      "to extend the run), else removes it.");
  prm.declare_entry("write exact solution",
                    "true",
                    Patterns::Bool(),
                    "Write the independent reference solution at every step beside history.csv: "
                    "exact.csv (bars, exact 1D waves) or hertz.csv (Hertz's theory, for two "
                    "identical spheres approaching along the axis).");
  prm.leave_subsection();
}

void OutputParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Output");
  directory = prm.get("directory");
  if (directory.empty())
    throw InputError("Output/directory is empty; give a directory name.");
  const auto times = [&prm](const std::string& entry)
  {
    std::vector<double> values;
    for (const auto& time : Utilities::split_string_list(prm.get(entry)))
      values.push_back(Utilities::string_to_double(time));
    return values;
  };
  profile_times      = times("profile times");
  vtu_interval       = prm.get_integer("vtu interval");
  vtu_times          = times("vtu times");
  vtu_during_contact = prm.get_bool("vtu during contact");
  checkpoint_interval =
      static_cast<unsigned int>(get_in_range(prm, "checkpoint interval", "Output", 0., 1e8));
  write_exact_solution = prm.get_bool("write exact solution");
  prm.leave_subsection();
}

ParameterReader::ParameterReader(const std::string& filename,
                                 const std::vector<std::string>& overrides)
    : input_filename(filename), overrides(overrides)
{
  if (!std::filesystem::exists(filename))
    throw InputError("cannot read parameter file '" + filename + "': no such file.");
  if (std::filesystem::is_directory(filename))
    throw InputError("cannot read parameter file '" + filename + "': it is a directory.");
  std::ifstream input(filename);
  if (!input)
    throw InputError("cannot read parameter file '" + filename +
                     "': permission denied or unreadable.");
  std::stringstream buffer;
  buffer << input.rdbuf();
  input_text = buffer.str();

  const ProblemSize size = read_problem_size(filename, overrides);
  declare_all(prm, size);
  parse_file(prm, filename, false);
  for (const auto& text : overrides)
    apply_override(prm, text, false);

  try
  {
    const std::set<std::string> missing = prm.get_entries_wrongly_not_set();
    if (!missing.empty())
    {
      std::string names;
      for (const auto& path : missing)
        names += (names.empty() ? "" : ", ") + demangle_entry_path(path);
      throw InputError("parameter file '" + filename + "': " + names +
                       (missing.size() > 1 ? " are" : " is") +
                       " not set; every entry of every bar and body must be given.");
    }
    run_parameters.problem.parse_parameters(prm);
    run_parameters.time.parse_parameters(prm);
    run_parameters.contact.parse_parameters(prm);
    run_parameters.newton.parse_parameters(prm);
    run_parameters.guards.parse_parameters(prm);
    if (size.geometry == GeometryKind::bars)
      run_parameters.geometry.parse_parameters(prm);
    else
    {
      run_parameters.mesh.parse_parameters(prm,
                                           std::filesystem::path(filename).parent_path().string());
      run_parameters.bodies.parse_parameters(prm);
    }
    run_parameters.output.parse_parameters(prm);
  }
  catch (const ExceptionBase& exception)
  {
    throw InputError("parameter file '" + filename + "': " + exception_text(exception));
  }
  resolve_and_check();
  record_problem_entries();
}

void ParameterReader::record_problem_entries()
{
  std::ostringstream text;
  prm.print_parameters(text, ParameterHandler::ShortPRM | ParameterHandler::KeepDeclarationOrder);
  std::istringstream lines(text.str());
  std::vector<std::string> sections;
  const auto trimmed = [](const std::string& word)
  {
    const auto first = word.find_first_not_of(" \t");
    return first == std::string::npos
               ? std::string()
               : word.substr(first, word.find_last_not_of(" \t") - first + 1);
  };
  for (std::string line; std::getline(lines, line);)
  {
    line = trimmed(line);
    if (line.rfind("subsection ", 0) == 0)
      sections.push_back(trimmed(line.substr(11)));
    else if (line == "end" && !sections.empty())
      sections.pop_back();
    else if (line.rfind("set ", 0) == 0 && line.find('=') != std::string::npos)
    {
      const std::size_t equals = line.find('=');
      std::string path;
      for (const std::string& section : sections)
        path += section + "/";
      path += trimmed(line.substr(4, equals - 4));
      std::string value = trimmed(line.substr(equals + 1));
      if (path.rfind("Output/", 0) == 0 || path == "Time integration/end time" ||
          path == "Time integration/scheme")
        continue;
      if (path == "Contact/dynamics")
        value = contact_dynamics_names().name(run_parameters.contact.dynamics);
      run_parameters.problem_entries.emplace_back(path, value);
    }
  }
}

void ParameterReader::resolve_and_check()
{
  RunParameters& p            = run_parameters;
  const std::string& old_name = p.time.deprecated_scheme;
  const auto& dynamics_names  = contact_dynamics_names();
  if (!old_name.empty())
  {
    const ContactDynamicsKind meant =
        deprecated_scheme_names().parse(old_name, "Time integration/scheme");
    // Contact/dynamics left at its default takes the meaning of the old entry; set otherwise, the
    // two must agree.
    if (p.contact.dynamics != default_contact_dynamics && p.contact.dynamics != meant)
      throw InputError("Time integration/scheme = " + old_name + " (deprecated, meaning Contact/" +
                       "dynamics = " + dynamics_names.name(meant) + ") contradicts Contact/" +
                       "dynamics = " + dynamics_names.name(p.contact.dynamics) +
                       "; remove Time integration/scheme.");
    p.contact.dynamics = meant;
    p.warnings.push_back("Time integration/scheme is deprecated: write Contact/dynamics = " +
                         dynamics_names.name(meant) + " instead of scheme = " + old_name + ".");
  }
  const std::string dynamics = "Contact/dynamics = " + dynamics_names.name(p.contact.dynamics);
  const ContactDynamicsTraits& treatment = contact_dynamics_traits(p.contact.dynamics);
  const bool trapezoidal_rule_required   = !treatment.trapezoidal_rule_reason.empty();
  p.time.resolve_newmark_coefficients(trapezoidal_rule_required);
  if (p.time.integrator == IntegratorFamily::newmark)
  {
    // The record (parameters.prm) names the coefficients the run used, so it reruns alike.
    prm.enter_subsection("Time integration");
    prm.set("beta", format_exact(p.time.beta));
    prm.set("gamma", format_exact(p.time.gamma));
    prm.leave_subsection();
  }
  if (trapezoidal_rule_required && (p.time.integrator != IntegratorFamily::newmark ||
                                    p.time.beta != 0.25 || p.time.gamma != 0.5))
    throw InputError(dynamics + " needs the trapezoidal rule, Time integration/integrator = " +
                     "newmark with beta = 0.25 and gamma = 0.5 (given " +
                     integrator_family_names().name(p.time.integrator) + ", beta = " +
                     format_number(p.time.beta) + ", gamma = " + format_number(p.time.gamma) +
                     "): " + treatment.trapezoidal_rule_reason);
  if (p.contact.formulation == ContactFormulation::penalty && !treatment.penalty_refusal.empty())
    throw InputError("Contact/formulation = penalty cannot be combined with " + dynamics + ": " +
                     treatment.penalty_refusal);
}

void ParameterReader::write_records(const std::string& directory) const
{
  std::ofstream original(directory + "/original.prm");
  original << input_text;
  if (!overrides.empty())
  {
    original << "\n# Overrides given on the command line, applied in this order:\n";
    for (const auto& text : overrides)
      original << "#   --set \"" << text << "\"\n";
  }
  std::ofstream effective(directory + "/parameters.prm");
  prm.print_parameters(effective, ParameterHandler::PRM | ParameterHandler::KeepDeclarationOrder);
  if (!original || !effective)
    throw InputError("Output/directory = '" + directory + "': cannot write the parameter records.");
}

void ParameterReader::print_template(std::ostream& out, const std::string& kind)
{
  const bool mesh = kind == "mesh";
  AssertThrow(mesh || kind == "bars", ExcMessage("unknown template kind " + kind));
  const ProblemSize size{mesh ? GeometryKind::axisymmetric_mesh : GeometryKind::bars,
                         1,
                         mesh ? 2u : 1u,
                         mesh ? 1u : 0u};
  ParameterHandler prm;
  declare_all(prm, size);
  apply_override(prm, "Problem/geometry=" + geometry_names().name(size.geometry), false);
  if (mesh)
    // meshes/two_spheres.geo: physical surfaces 1, 2 are the spheres, curves 2, 3 their surfaces.
    // The paper's spheres (section 6.4: R = 8, E = 5e3, rho = 0.001, speeds +-1) on the coarse
    // graded mesh, 0.4 apart: they touch at t = 0.2 and part at about 0.28 (Hertz).
    for (const char* text :
         {"Mesh/file=" DYNCONTACT_MESH_DIRECTORY "/two_spheres.geo",
          "Mesh/geo parameters=CentreDistance: 16.4, PoleGrading: 10, CoreOffset: 0.3",
          "Bodies/number of bodies=2",
          "Bodies/Body 1/Young's modulus=5e3",
          "Bodies/Body 2/Young's modulus=5e3",
          "Bodies/Body 1/density=0.001",
          "Bodies/Body 2/density=0.001",
          "Bodies/Body 1/Initial velocity/Function expression=0; 1",
          "Bodies/Body 2/Initial velocity/Function expression=0; -1",
          "Contact/number of pairs=1",
          "Contact/Pair 1/slave boundary=2",
          "Contact/Pair 1/master boundary=3",
          "Time integration/time step=0.0025",
          "Time integration/end time=0.35"})
      apply_override(prm, text, false);
  out << "# A dyncontact parameter file for " << (mesh ? "axisymmetric mesh" : "bars")
      << " problems, printed by dyncontact --print-parameters " << kind
      << ": every entry, at its default"
      << (mesh ? " except the problem's (the paper's two spheres approaching each other)" : "")
      << ".\n# It runs as it is; edit the values. "
         "(--print-parameters "
      << (mesh ? "bars" : "mesh") << " prints the other kind.)\n";
  prm.print_parameters(out, ParameterHandler::PRM | ParameterHandler::KeepDeclarationOrder);
}
} // namespace dyncontact
