#include <dyncontact/base/command_line.h>

#include <algorithm>

namespace dyncontact
{
namespace
{
/**
 * Throws InputError for a combination of options and parameter file that makes no run;
 * `action_given`: an option or the parameter file chose the action, named by `action_option`.
 */
void check_combination(const CommandLine& command_line,
                       const bool action_given,
                       const std::string& action_option)
{
  using Action = CommandLine::Action;
  if (!command_line.resume_directory.empty() &&
      std::count_if(command_line.overrides.begin(),
                    command_line.overrides.end(),
                    [](const std::string& o) { return o.rfind("Output/directory=", 0) == 0; }) > 1)
    throw InputError("--resume DIR continues in DIR; do not give --output or Output/directory "
                     "with it.");
  if (!action_given && !command_line.overrides.empty())
    throw InputError("no parameter file given; see --help.");
  if ((command_line.action == Action::help || command_line.action == Action::version ||
       command_line.action == Action::print_parameters) &&
      !command_line.parameter_file.empty())
    throw InputError("conflicting options: a parameter file ('" + command_line.parameter_file +
                     "') is given with " + action_option + ", which takes none; see --help.");
  if ((command_line.action == Action::run || command_line.action == Action::validate) &&
      command_line.parameter_file.empty())
    throw InputError("no parameter file given; see --help.");
}
} // namespace

CommandLine CommandLine::parse(const std::vector<std::string>& arguments)
{
  CommandLine command_line;
  bool action_given = false;
  std::string action_option; // the option that chose the action, for the messages
  const auto set_action = [&](const Action action, const std::string& option)
  {
    if (action_given && command_line.action != action)
      throw InputError("conflicting options " + action_option + " and " + option +
                       ": give one of --help, --version, --print-parameters, --validate; see "
                       "--help.");
    command_line.action = action;
    action_given        = true;
    action_option       = option;
  };
  const auto value_of = [&](unsigned int& i) -> const std::string&
  {
    if (i + 1 >= arguments.size())
      throw InputError("option " + arguments[i] + " needs a value; see --help.");
    return arguments[++i];
  };

  for (unsigned int i = 0; i < arguments.size(); ++i)
  {
    const std::string& argument = arguments[i];
    if (argument == "--help" || argument == "-h")
      set_action(Action::help, argument);
    else if (argument == "--print-parameters")
    {
      set_action(Action::print_parameters, argument);
      // An optional kind: any word that is not an option is one, and must be a known kind.
      if (i + 1 < arguments.size() && !arguments[i + 1].empty() && arguments[i + 1][0] != '-')
      {
        command_line.template_kind = arguments[++i];
        if (command_line.template_kind != "bars" && command_line.template_kind != "mesh" &&
            command_line.template_kind != "3d")
          throw InputError("--print-parameters " + command_line.template_kind +
                           ": unknown kind of problem; the kinds are bars (1D bars, the default), "
                           "mesh (axisymmetric bodies from a gmsh mesh) and 3d (3D bodies from a "
                           "gmsh mesh of hexahedra).");
      }
    }
    else if (argument == "--version")
      set_action(Action::version, argument);
    else if (argument == "--validate") // the parameter file may come before or after it
      set_action(Action::validate, argument);
    else if (argument == "--set")
      command_line.overrides.push_back(value_of(i));
    else if (argument == "--output")
      command_line.overrides.push_back("Output/directory=" + value_of(i));
    else if (argument == "--quiet")
      command_line.quiet = true;
    else if (argument == "--resume")
    {
      // The resumed run continues in the interrupted run's directory.
      command_line.resume_directory = value_of(i);
      command_line.overrides.push_back("Output/directory=" + command_line.resume_directory);
    }
    else if (!argument.empty() && argument[0] == '-')
      throw InputError("unknown option '" + argument + "'; see --help.");
    else if (command_line.parameter_file.empty())
      command_line.parameter_file = argument;
    else
      throw InputError("more than one parameter file given ('" + command_line.parameter_file +
                       "' and '" + argument + "').");
  }
  if (!action_given && !command_line.parameter_file.empty())
    set_action(Action::run, command_line.parameter_file);
  check_combination(command_line, action_given, action_option);
  return command_line;
}

std::string CommandLine::usage()
{
  return "dyncontact: implicit dynamics of elastic bodies in contact (Taylor & Papadopoulos "
         "1993).\n"
         "\n"
         "Usage:\n"
         "  dyncontact FILE.prm [--set \"Section/entry=value\"]... [--output DIR] [--quiet]\n"
         "      run the problem; every --set overrides one entry of FILE.prm (repeatable),\n"
         "      --output DIR is short for --set \"Output/directory=DIR\".\n"
         "      --quiet leaves out the progress lines (warnings and the summary stay).\n"
         "  dyncontact FILE.prm --resume DIR [--set ...]\n"
         "      continue the interrupted run of FILE.prm from DIR/checkpoint.bin, in DIR.\n"
         "  dyncontact --validate FILE.prm [--set ...]   (or FILE.prm --validate)\n"
         "      check the parameters and the mesh as a run does before its first step, run\n"
         "      nothing, write nothing.\n"
         "  dyncontact --print-parameters [bars|mesh|3d]   (bars if not given)\n"
         "      print a parameter file for that kind of problem with every entry it takes,\n"
         "      its documentation, default and allowed values; it runs as printed (bars: one\n"
         "      bar at rest; mesh: the paper's two spheres approaching each other in the\n"
         "      shipped meshes/two_spheres.geo, one contact pair, 6 s; 3d: the paper's sphere\n"
         "      as a coarse quarter dropped on a rigid plane, meshes/quarter_sphere_3d.geo,\n"
         "      20 s). Save it, edit it, run it.\n"
         "  dyncontact --version\n"
         "      print the version and the git commit of the build.\n"
         "  dyncontact --help\n"
         "\n"
         "A run writes into Output/directory: history.csv (one row per step), the reference\n"
         "solution (exact.csv for bars; hertz.csv and impact_summary.csv for a head-on impact\n"
         "of a sphere or a spherical end), profile_t<T>.csv (and contact_pressure_t<T>.csv,\n"
         "cells.csv for meshes), solution_*.vtu with solution.pvd (and contact_surface_*.vtu,\n"
         "contact_surface.pvd), original.prm (the input as given), parameters.prm (every value\n"
         "in effect, re-runnable from any directory) and run.json (version, commit, command\n"
         "line, times, outcome). It first removes these files of an earlier run from the\n"
         "directory (other files stay).\n";
}
} // namespace dyncontact
