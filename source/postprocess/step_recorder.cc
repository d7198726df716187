#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/sum_over_ranks.h>
#include <dyncontact/postprocess/step_recorder.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>

namespace dyncontact
{
namespace
{
/**
 * The nominal steps of `times` on the grid of `dt` (`n_steps` steps); a time after the end is a
 * warning naming Output/`entry`.
 */
std::set<unsigned int> schedule(const std::vector<double>& times,
                                const double dt,
                                const unsigned int n_steps,
                                const std::string& entry,
                                const ConditionalOStream& log)
{
  std::set<unsigned int> steps;
  for (const double t : times)
    if (t > (n_steps + 0.5) * dt)
      log << "WARNING: Output/" << entry << ": " << t
          << " lies after the end of the run (t = " << n_steps * dt
          << "); nothing is written for it.\n";
    else
      steps.insert(static_cast<unsigned int>(std::lround(t / dt)));
  return steps;
}
} // namespace

template <int dim>
StepRecorder<dim>::StepRecorder(const ProblemModel<dim>& model,
                                const NodeIndex<dim>& nodes,
                                const ContactConstraints<dim>& contact,
                                const bool surface_contact,
                                std::unique_ptr<FieldOutput<dim>> field_output,
                                const OutputParameters& output,
                                const double time_step,
                                const unsigned int n_steps,
                                TimerOutput& timer,
                                const ConditionalOStream& log)
    : model(model), nodes(nodes), contact(contact), fields(contact),
      surface_contact(surface_contact), field_output(std::move(field_output)), output(output),
      timer(timer), is_root_rank(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0),
      monitors(model.monitor_nodes(nodes)),
      profile_steps(schedule(output.profile_times, time_step, n_steps, "profile times", log)),
      vtu_steps(schedule(output.vtu_times, time_step, n_steps, "vtu times", log)), rows(columns())
{
  // The pair nearest to the axis (axisymmetry: r = 0), whose pressure is centre_pressure.
  const auto& pairs = contact.candidate_pairs();
  innermost_pair    = std::min_element(pairs.begin(),
                                    pairs.end(),
                                    [](const ContactPair<dim>& a, const ContactPair<dim>& b) {
                                      return distance_from_axis(a.slave.position) <
                                             distance_from_axis(b.slave.position);
                                    }) -
                   pairs.begin();
}

template <int dim>
std::vector<std::string> StepRecorder<dim>::columns() const
{
  std::vector<std::string> columns = {"time",
                                      "contact_force",
                                      "contact_multiplier",
                                      "active_constraints",
                                      "newton_iterations",
                                      "kinetic_energy",
                                      "strain_energy",
                                      "total_energy",
                                      "algorithmic_energy",
                                      "external_work",
                                      "max_penetration",
                                      "force_imbalance",
                                      "velocity_jump",
                                      "acceleration_jump",
                                      "time_step",
                                      "step_cuts"};
  if (dim > 1)
    for (const std::string column : {"contact_radius", "centre_pressure"})
      columns.push_back(column);
  if (contact.has_friction())
    for (const std::string column : {"sliding_pairs",
                                     "frictional_dissipation",
                                     "stick_velocity_jump",
                                     "stick_acceleration_jump"})
      columns.push_back(column);
  if (dim == 3)
    for (const std::string quantity : {"momentum_", "angular_momentum_"})
      for (const std::string axis : {"x", "y", "z"})
        columns.push_back(quantity + axis);
  for (unsigned int b = 1; b <= model.n_bodies(); ++b)
    for (const std::string quantity : {"momentum_", "impulse_", "u_tip_", "v_tip_", "a_tip_"})
      columns.push_back(quantity + std::to_string(b));
  if (has_body_momenta())
    for (unsigned int b = 1; b <= model.n_bodies(); ++b)
      for (unsigned int d = 0; d < dim; ++d)
        columns.push_back("momentum_" + std::to_string(b) + "_" + "xyz"[d]);
  return columns;
}

template <int dim>
void StepRecorder<dim>::open()
{
  if (dim == 2)
    field_output->write_cell_outlines(nodes);
  if (is_root_rank)
    rows.attach_file(output.directory + "/history.csv");
}

template <int dim>
void StepRecorder<dim>::record(const Step& step,
                               const Measures& measures,
                               const StepState& state,
                               const std::vector<double>& impulses,
                               const double external_work,
                               const double frictional_dissipation)
{
  std::vector<double> row = {step.time,
                             measures.contact_force,
                             fields.total_pair_force(),
                             static_cast<double>(contact.n_active()),
                             static_cast<double>(step.linear_solves),
                             measures.kinetic_energy,
                             measures.strain_energy,
                             measures.kinetic_energy + measures.strain_energy,
                             measures.algorithmic_energy,
                             external_work,
                             fields.max_penetration(state.displacement),
                             measures.force_imbalance,
                             measures.velocity_jump,
                             measures.acceleration_jump,
                             step.size,
                             static_cast<double>(step.cuts)};
  // Contact pressures (surface contact only): one solve per step, skipped without contact.
  const std::vector<double> pressures =
      surface_contact && contact.n_active() > 0
          ? contact.contact_pressures(contact.border().gather(state.displacement))
          : std::vector<double>(contact.n_pairs(), 0.);
  if (dim > 1)
  {
    row.push_back(fields.contact_radius(state.displacement));
    row.push_back(surface_contact ? pressures[innermost_pair] : 0.);
  }
  if (contact.has_friction())
  {
    unsigned int sliding = 0;
    for (unsigned int k = 0; k < contact.n_pairs(); ++k)
      sliding += contact.is_sliding(k) ? 1 : 0;
    row.insert(row.end(),
               {static_cast<double>(sliding),
                frictional_dissipation,
                measures.stick_velocity_jump,
                measures.stick_acceleration_jump});
  }
  if (dim == 3)
    for (const Tensor<1, max_dimension>& vector : {measures.momentum, measures.angular_momentum})
      for (unsigned int d = 0; d < max_dimension; ++d)
        row.push_back(vector[d]);
  const std::vector<double> tips = monitor_motions(state);
  for (unsigned int b = 0; b < monitors.size(); ++b)
    row.insert(row.end(),
               {measures.momenta[b], impulses[b], tips[3 * b], tips[3 * b + 1], tips[3 * b + 2]});
  if (has_body_momenta())
    for (const Tensor<1, max_dimension>& momentum : measures.body_momenta)
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(momentum[d]);
  rows.add_row(row);
  write_fields(rows.n_rows() - 1, step.nominal_step, step.time, state, pressures);
}

template <int dim>
std::vector<double> StepRecorder<dim>::monitor_motions(const StepState& state) const
{
  // Each monitor DoF's term from the rank that owns it; the sum over the ranks adds zeros.
  const Tensor<1, dim> direction = model.impact_direction();
  std::vector<double> motions(3 * monitors.size(), 0.);
  for (unsigned int b = 0; b < monitors.size(); ++b)
    for (unsigned int d = 0; d < dim; ++d)
    {
      const types::global_dof_index dof = monitors[b].dofs[d];
      if (!state.displacement.in_local_range(dof))
        continue;
      motions[3 * b] += direction[d] * state.displacement(dof);
      motions[3 * b + 1] += direction[d] * state.velocity(dof);
      motions[3 * b + 2] += direction[d] * state.acceleration(dof);
    }
  sum_over_ranks(motions, state.displacement.get_mpi_communicator());
  return motions;
}

template <int dim>
void StepRecorder<dim>::write_fields(const unsigned int frame,
                                     const unsigned int nominal_step,
                                     const double time,
                                     const StepState& state,
                                     const std::vector<double>& pressures)
{
  const bool on_nominal_grid = frame == 0 || nominal_step > 0;
  if (on_nominal_grid)
    nominal_rows.push_back(frame);
  const unsigned int step = frame == 0 ? 0 : nominal_step;
  const bool vtu_on       = output.vtu_interval > 0 || !vtu_steps.empty();
  const bool vtu_frame =
      (on_nominal_grid && ((output.vtu_interval > 0 && step % output.vtu_interval == 0) ||
                           vtu_steps.count(step) > 0)) ||
      (vtu_on && output.vtu_during_contact && contact.n_active() > 0);
  const bool profile = on_nominal_grid && profile_steps.count(step) > 0;
  if (!vtu_frame && !profile)
    return;
  TimerOutput::Scope scope(timer, "output");
  const auto samples = surface_contact ? fields.pressure_samples(pressures, state.displacement)
                                       : std::vector<typename FieldOutput<dim>::PressureSample>();
  if (vtu_frame)
  {
    // Each rank writes its own cells, from the entries of its owned and ghost DoFs (collective).
    const DistributedVector displacement = field_output->with_ghosts(state.displacement);
    const DistributedVector traction =
        surface_contact ? field_output->with_ghosts(fields.traction(pressures, state.displacement))
                        : DistributedVector();
    field_output->write_fields(frame,
                               time,
                               displacement,
                               field_output->with_ghosts(state.velocity),
                               field_output->with_ghosts(state.acceleration),
                               surface_contact ? &traction : nullptr);
    if (surface_contact)
      field_output->write_contact_surface(frame, time, displacement, samples);
  }
  if (profile)
  {
    // Rank 0 writes every node: the nodes and the fields gathered to it (collective).
    const std::vector<Node<dim>> all_nodes = nodes.gather_on_root();
    const Vector<double> displacement      = gather_on_root(state.displacement),
                         velocity          = gather_on_root(state.velocity),
                         acceleration      = gather_on_root(state.acceleration);
    if (is_root_rank)
    {
      field_output->write_profile(time, all_nodes, displacement, velocity, acceleration);
      if (surface_contact)
        field_output->write_contact_pressure(time, samples, contact.has_friction());
    }
  }
}

template <int dim>
void StepRecorder<dim>::write_summaries(const std::string& stop,
                                        const double end_time,
                                        const std::vector<double>& contact_impulses,
                                        std::ostream& log)
{
  const unsigned int n_rows = rows.n_rows();
  const double last_time    = n_rows > 0 ? rows.value(n_rows - 1, "time") : 0.;
  summary_status            = "complete";
  if (!stop.empty())
    summary_status = "incomplete: " + stop + " after t = " + format_number(last_time) +
                     " before the end time " + format_number(end_time);
  else if (n_rows > 0 && rows.value(n_rows - 1, "contact_force") != 0.)
    summary_status = "incomplete: still in contact at the end time " + format_number(last_time);
  if (!is_root_rank)
    return;
  if (output.write_exact_solution)
    model.write_reference(output.directory, rows.column("time"), monitors);
  // Every accepted row, the sub-steps of cut steps included, and the contact impulses the run
  // accumulated (equal to the momentum changes they caused, see the momentum guard).
  model.summarize_run(output.directory, rows, contact_impulses, summary_status, log);
}

template <int dim>
History StepRecorder<dim>::nominal_history() const
{
  History nominal(rows.column_names());
  for (const unsigned int row : nominal_rows)
    nominal.add_row(rows.row(row));
  return nominal;
}

DYNCONTACT_INSTANTIATE_CLASS(StepRecorder)
} // namespace dyncontact
