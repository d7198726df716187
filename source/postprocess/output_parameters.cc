#include <dyncontact/base/parameter_entries.h>
#include <dyncontact/postprocess/output_parameters.h>

#include <deal.II/base/utilities.h>

namespace dyncontact
{
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
} // namespace dyncontact
