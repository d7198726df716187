#include <dyncontact/base/parameter_entries.h>
#include <dyncontact/simulation/parameter_reader.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

namespace dyncontact
{
namespace
{
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
        name == "Geometry" ? "it is for Problem/geometry = bars"
        : name == "Mesh" || name == "Bodies" || name == "Boundary"
            ? "it is for Problem/geometry = axisymmetric mesh, plane strain mesh or 3d mesh"
        : name.rfind("Bar ", 0) == 0  ? "there are only Geometry/number of bars bars"
        : name.rfind("Body ", 0) == 0 ? "there are only Bodies/number of bodies bodies"
        : name.rfind("Pair ", 0) == 0 ? "there are only Contact/number of pairs pairs"
        : name.rfind("Symmetry ", 0) == 0
            ? "there are only Boundary/number of symmetry planes planes"
        : name.rfind("Support ", 0) == 0 ? "there are only Boundary/number of supports supports"
                                         : "no such subsection is declared";
    return "line " + std::string(match[1]) + ": subsection '" + path + "' is not taken: " + why +
           " (dyncontact --print-parameters bars|mesh|3d prints what each kind of problem takes).";
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

/** What the first parsing pass finds out: the kind of problem and the number of bodies. */
struct ProblemSize
{
  GeometryKind geometry;
  unsigned int n_bars;
  unsigned int n_bodies;
  unsigned int n_pairs;
  unsigned int n_symmetry_planes = 0;
  unsigned int n_supports        = 0;
  unsigned int n_dirichlet       = 0;
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
    BodiesParameters::declare_parameters(
        prm, size ? size->n_bodies : 1, size ? space_dimension(size->geometry) : 2);
    BoundaryParameters::declare_parameters(prm,
                                           size ? size->n_symmetry_planes : 1,
                                           size ? size->n_supports : 1,
                                           size ? size->n_dirichlet : 1,
                                           size ? space_dimension(size->geometry) : 2);
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
  size_prm.enter_subsection("Boundary");
  size_prm.declare_entry("number of symmetry planes", "0", Patterns::Integer(0, 10));
  size_prm.declare_entry("number of supports", "0", Patterns::Integer(0, 100));
  size_prm.declare_entry("number of Dirichlet boundaries", "0", Patterns::Integer(0, 100));
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
  size_prm.enter_subsection("Boundary");
  size.n_symmetry_planes = size_prm.get_integer("number of symmetry planes");
  size.n_supports        = size_prm.get_integer("number of supports");
  size.n_dirichlet       = size_prm.get_integer("number of Dirichlet boundaries");
  size_prm.leave_subsection();
  if (size.geometry == GeometryKind::bars && size.n_pairs > 0)
    throw InputError("Contact/number of pairs = " + std::to_string(size.n_pairs) +
                     " is for mesh problems; bars meet at their ends (use 0).");
  return size;
}
} // namespace

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
    const unsigned int dim = space_dimension(size.geometry);
    run_parameters.contact.parse_parameters(prm, dim);
    run_parameters.newton.parse_parameters(prm, dim);
    run_parameters.guards.parse_parameters(prm);
    if (size.geometry == GeometryKind::bars)
      run_parameters.geometry.parse_parameters(prm);
    else
    {
      run_parameters.mesh.parse_parameters(prm,
                                           std::filesystem::path(filename).parent_path().string());
      run_parameters.bodies.parse_parameters(prm, dim);
      run_parameters.boundary.parse_parameters(prm, dim);
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
    if (p.contact.dynamics != ContactParameters::default_dynamics && p.contact.dynamics != meant)
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
  const bool mesh = kind == "mesh", solid = kind == "3d";
  AssertThrow(mesh || solid || kind == "bars", ExcMessage("unknown template kind " + kind));
  const GeometryKind geometry = mesh    ? GeometryKind::axisymmetric_mesh
                                : solid ? GeometryKind::solid_mesh
                                        : GeometryKind::bars;
  ProblemSize size{geometry, 1, mesh ? 2u : 1u, mesh || solid ? 1u : 0u};
  size.n_symmetry_planes = solid ? 2 : 0;
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
  if (solid)
    // meshes/quarter_sphere_3d.geo: surfaces 1, 2 the planes x = 0, y = 0, 3 the sphere. The
    // paper's sphere (R = 8, E = 5e3, rho = 0.001) as a coarse quarter 0.005 above the plane
    // z = 0, falling at speed 1: it touches at t = 0.005 and leaves at about 0.085 (Hertz).
    for (const char* text :
         {"Mesh/file=" DYNCONTACT_MESH_DIRECTORY "/quarter_sphere_3d.geo",
          "Mesh/geo parameters=R: 8, CentreZ: 8.005, N: 4, NR: 3, PoleGrading: 3",
          "Bodies/number of bodies=1",
          "Bodies/Body 1/Young's modulus=5e3",
          "Bodies/Body 1/density=0.001",
          "Bodies/Body 1/Initial velocity/Function expression=0; 0; -1",
          "Boundary/number of symmetry planes=2",
          "Boundary/Symmetry 1/boundary=1",
          "Boundary/Symmetry 2/boundary=2",
          "Contact/number of pairs=1",
          "Contact/Pair 1/slave boundary=3",
          "Contact/Pair 1/rigid plane=0, 0, 0; 0, 0, 1",
          "Newton/method=modified",
          "Output/vtu interval=0",
          "Time integration/time step=0.0025",
          "Time integration/end time=0.095"})
      apply_override(prm, text, false);
  const std::string name = mesh ? "axisymmetric mesh" : solid ? "3d mesh" : "bars";
  out << "# A dyncontact parameter file for " << name
      << " problems, printed by dyncontact --print-parameters " << kind
      << ": every entry, at its default"
      << (mesh    ? " except the problem's (the paper's two spheres approaching each other)"
          : solid ? " except the problem's (the paper's sphere, a quarter of it, dropped on a "
                    "rigid plane)"
                  : "")
      << ".\n# It runs as it is; edit the values. "
         "(--print-parameters bars, mesh and 3d print the three kinds.)\n";
  prm.print_parameters(out, ParameterHandler::PRM | ParameterHandler::KeepDeclarationOrder);
}
} // namespace dyncontact
