#include <dyncontact/base/output_directory.h>
#include <dyncontact/models/bar_model.h>
#include <dyncontact/simulation/mesh_model_factory.h>
#include <dyncontact/simulation/setup_check.h>
#include <dyncontact/simulation/simulation.h>

#include <ostream>

namespace dyncontact
{
namespace
{
/** Runs Simulation::prepare() for `model`, which logs the set-up to `log`. */
template <int dim>
void prepare(const RunParameters& parameters,
             std::unique_ptr<ProblemModel<dim>> model,
             std::ostream& log)
{
  Simulation<dim>(parameters, std::move(model), log).prepare();
}
} // namespace

void check_run_setup(const RunParameters& parameters, std::ostream& log)
{
  check_output_directory(parameters.output.directory);
  if (parameters.problem.geometry == GeometryKind::bars)
  {
    auto model = std::make_unique<BarModel>(parameters.geometry);
    if (parameters.output.write_exact_solution)
      model->exact_solution(parameters.time.n_steps() * parameters.time.time_step);
    prepare<1>(parameters, std::move(model), log);
  }
  else if (parameters.problem.geometry == GeometryKind::solid_mesh)
    prepare<3>(parameters, create_solid_mesh_model(parameters), log);
  else
    prepare<2>(parameters, create_mesh_model(parameters), log);
}
} // namespace dyncontact
