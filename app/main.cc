// The dyncontact executable: reads the command line and the parameter file, dispatches to the
// problem's dimension, and turns every failure into one clear message and a non-zero exit code.
#include <dyncontact/base/command_line.h>
#include <dyncontact/base/output_directory.h>
#include <dyncontact/base/version.h>
#include <dyncontact/models/bar_model.h>
#include <dyncontact/simulation/interruption.h>
#include <dyncontact/simulation/mesh_model_factory.h>
#include <dyncontact/simulation/parameter_reader.h>
#include <dyncontact/simulation/run_record.h>
#include <dyncontact/simulation/setup_check.h>
#include <dyncontact/simulation/simulation.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace
{
/**
 * Runs `task` on rank 0 only; an InputError it throws is rethrown on every rank, so that all ranks
 * stop with the same message instead of the others waiting forever.
 */
template <typename Task>
void on_root_rank(const Task& task)
{
  std::string error;
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    try
    {
      task();
    }
    catch (const dyncontact::InputError& input_error)
    {
      error = input_error.what();
    }
  error = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, error, 0);
  if (!error.empty())
    throw dyncontact::InputError(error);
}

/** Throws InputError unless `directory` holds a checkpoint to resume from. */
void check_checkpoint_exists(const std::string& directory)
{
  if (!std::filesystem::exists(directory + "/checkpoint.bin"))
    throw dyncontact::InputError("--resume " + directory + ": there is no checkpoint " + directory +
                                 "/checkpoint.bin (a run writes one when interrupted or every "
                                 "Output/checkpoint interval steps).");
}

/** The parameter file's warnings (deprecated entries), one line each, from rank 0. */
void print_warnings(const dyncontact::RunParameters& parameters)
{
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    for (const std::string& warning : parameters.warnings)
      std::cout << "WARNING: " << warning << "\n";
}
/** --validate: everything a run checks before its first step, writing nothing. */
void validate(const dyncontact::CommandLine& command_line)
{
  using namespace dyncontact;
  const ParameterReader reader(command_line.parameter_file, command_line.overrides);
  print_warnings(reader.parameters());
  check_run_setup(reader.parameters(), std::cout);
  if (!command_line.resume_directory.empty())
    check_checkpoint_exists(command_line.resume_directory);
  std::cout << "dyncontact: " << command_line.parameter_file << " is valid.\n";
}

/**
 * Prepares the output directory on rank 0 (a fresh run owns it: an earlier run's results are
 * removed; a resumed run continues the interrupted one's) and writes the parameter records.
 */
void prepare_run_directory(const dyncontact::ParameterReader& reader, const std::string& resume)
{
  using namespace dyncontact;
  on_root_rank(
      [&]
      {
        const std::string& directory = reader.parameters().output.directory;
        if (!resume.empty())
          return;
        prepare_output_directory(directory);
        const unsigned int n_removed = remove_previous_results(directory);
        if (n_removed > 0)
          std::cout << "dyncontact: removed " << n_removed << " result file"
                    << (n_removed > 1 ? "s" : "") << " of an earlier run from " << directory
                    << "\n";
        reader.write_records(directory);
      });
}

/**
 * Runs the simulation of `model` in `dim` dimensions. Everything a run checks before its first
 * step is done before the output directory is touched, so that an input error leaves an earlier
 * run's results in place; then the directory is prepared, and the run is recorded in run.json.
 */
template <int dim>
void simulate(const dyncontact::ParameterReader& reader,
              std::unique_ptr<dyncontact::ProblemModel<dim>> model,
              const dyncontact::CommandLine& command_line,
              const std::vector<std::string>& arguments)
{
  using namespace dyncontact;
  const RunParameters& parameters = reader.parameters();
  Simulation<dim> simulation(parameters, std::move(model), std::cout);
  simulation.set_progress(!command_line.quiet);
  if (command_line.resume_directory.empty())
    check_output_directory(parameters.output.directory);
  simulation.prepare();
  if (!command_line.resume_directory.empty())
    simulation.check_checkpoint(command_line.resume_directory);
  prepare_run_directory(reader, command_line.resume_directory);
  std::unique_ptr<RunRecord> record; // rank 0 only
  on_root_rank(
      [&]
      {
        record = std::make_unique<RunRecord>(parameters.output.directory,
                                             arguments,
                                             command_line.parameter_file,
                                             Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
      });
  try
  {
    simulation.run(command_line.resume_directory);
  }
  catch (...)
  {
    if (record)
    {
      record->set_wall_times(simulation.wall_times());
      record->set_summary_status(simulation.summary_status());
      record->finish(RunOutcome::of(std::current_exception()));
    }
    throw;
  }
  if (record)
  {
    record->set_wall_times(simulation.wall_times());
    record->set_summary_status(simulation.summary_status());
    record->finish({0, "completed", "", 0});
  }
}

/** A run of the parameter file, or the resumption of an interrupted one, recorded in run.json. */
void run(const dyncontact::CommandLine& command_line, const std::vector<std::string>& arguments)
{
  using namespace dyncontact;
  const ParameterReader reader(command_line.parameter_file, command_line.overrides);
  const RunParameters& parameters = reader.parameters();
  print_warnings(parameters);
  if (parameters.problem.geometry == GeometryKind::bars)
    simulate<1>(reader, std::make_unique<BarModel>(parameters.geometry), command_line, arguments);
  else if (parameters.problem.geometry == GeometryKind::solid_mesh)
    simulate<3>(reader, create_solid_mesh_model(parameters), command_line, arguments);
  else
    simulate<2>(reader, create_mesh_model(parameters), command_line, arguments);
}
} // namespace

int main(int argc, char** argv)
{
  using namespace dyncontact;
  Utilities::MPI::MPI_InitFinalize mpi_initialization(argc, argv, 1);
  // From the start, so that a signal during the set-up (meshing, a long parameter check) is also
  // answered with a checkpoint after the first step instead of ending the process unrecorded.
  install_interrupt_handlers();
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  try
  {
    const CommandLine command_line = CommandLine::parse(arguments);
    switch (command_line.action)
    {
    case CommandLine::Action::help:
      std::cout << CommandLine::usage();
      return 0;
    case CommandLine::Action::version:
      std::cout << "dyncontact " << version() << " (commit " << commit() << ")\n";
      return 0;
    case CommandLine::Action::print_parameters:
      ParameterReader::print_template(std::cout, command_line.template_kind);
      return 0;
    case CommandLine::Action::validate:
      validate(command_line);
      return 0;
    case CommandLine::Action::run:
      run(command_line, std::vector<std::string>(argv, argv + argc));
      return 0;
    }
  }
  catch (const RunInterrupted& interruption)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      const CommandLine command_line = CommandLine::parse(arguments);
      std::cerr << "dyncontact: interrupted by " << interruption.what()
                << "; resume with: dyncontact " << command_line.parameter_file << " --resume "
                << interruption.directory()
                << (std::any_of(command_line.overrides.begin(),
                                command_line.overrides.end(),
                                [](const std::string& o)
                                { return o.rfind("Output/directory=", 0) != 0; })
                        ? " and the same --set options"
                        : "")
                << std::endl;
    }
    // No rank leaves before rank 0 has written the checkpoint and said how to resume: a launcher
    // such as mpirun ends the whole job as soon as one rank exits with a non-zero code.
    MPI_Barrier(MPI_COMM_WORLD);
    return 128 + interruption.signal();
  }
  catch (...)
  {
    const RunOutcome outcome = RunOutcome::of(std::current_exception());
    if (outcome.kind != "input error")
      std::cerr << "dyncontact: " << outcome.kind << ": " << outcome.message << std::endl;
    else if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cerr << "dyncontact: error: " << outcome.message << std::endl;
    return outcome.exit_code;
  }
  return 0;
}
