#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/models/problem_model.h>
#include <dyncontact/postprocess/contact_fields.h>
#include <dyncontact/postprocess/field_output.h>
#include <dyncontact/postprocess/history.h>
#include <dyncontact/postprocess/output_parameters.h>
#include <dyncontact/postprocess/step_measures.h>
#include <dyncontact/time_integration/step_state.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * The record of a run's accepted states: one row of history.csv per accepted (sub-)step, the rows
 * on the nominal time grid t = n dt, the VTU frames and profiles at their scheduled steps (Output/
 * vtu interval, vtu times, vtu during contact, profile times) and, at the end, the model's
 * reference solution and run summary. Files are written by rank 0 (VTU: one piece per rank).
 * The model, nodes, contact and timer are the caller's and must outlive it.
 */
template <int dim>
class StepRecorder
{
public:
  /** What a row records besides the state and its measures. */
  struct Step
  {
    double time;                      ///< the state's time
    double size;                      ///< the step's size (0 for the initial state)
    unsigned int nominal_step;        ///< the nominal step index on the nominal grid, else 0
    unsigned int linear_solves, cuts; ///< of every attempt at the step
  };

  /**
   * Schedules the profiles and VTU frames on the grid of `time_step` (`n_steps` steps; a time
   * after the end is a warning on `log`). `surface_contact`: the pairs are between meshed surfaces
   * (contact pressures, the surface output); `field_output` writes the frames and profiles.
   */
  StepRecorder(const ProblemModel<dim>& model,
               const NodeIndex<dim>& nodes,
               const ContactConstraints<dim>& contact,
               bool surface_contact,
               std::unique_ptr<FieldOutput<dim>> field_output,
               const OutputParameters& output,
               double time_step,
               unsigned int n_steps,
               TimerOutput& timer,
               const ConditionalOStream& log);

  /**
   * Starts the files of Output/directory: history.csv with the rows so far (the initial row, or a
   * resumed run's) and, in 2D, the cell outlines. Throws InputError if history.csv cannot be
   * written.
   */
  void open();

  /**
   * Appends the row of `state` (its `measures`; `impulses` [force time], per body along the
   * impact direction, the `external_work` [energy] since t = 0 and, with friction, the
   * `frictional_dissipation` [energy] since t = 0) to the history, and writes
   * the VTU frame (numbered by the row) and profiles scheduled at it. Collective.
   */
  void record(const Step& step,
              const Measures& measures,
              const StepState& state,
              const std::vector<double>& impulses,
              double external_work,
              double frictional_dissipation);

  /**
   * Writes the reference solution at the recorded times and the run's summary (rank 0), marked
   * with status(): `stop` says why the run ends before `end_time` (empty when it reached it).
   * `contact_impulses` [force time] per body along the impact direction (BodyImpulses).
   */
  void write_summaries(const std::string& stop,
                       double end_time,
                       const std::vector<double>& contact_impulses,
                       std::ostream& log);

  /** The columns of history.csv. */
  std::vector<std::string> columns() const;

  /**
   * Whether the history has each body's momentum along every axis (momentum_b_x, ...): in 3D, and
   * in a plane-strain run with friction, whose bodies slide along the plane.
   */
  bool has_body_momenta() const
  {
    return dim == 3 || (dim == 2 && contact.has_friction() &&
                        model.momentum_directions().size() == static_cast<unsigned int>(dim));
  }
  /** Every recorded row, one per accepted (sub-)step including t = 0. */
  const History& history() const { return rows; }
  /** The rows on the nominal time grid (uniform steps: what the Hertz comparison takes). */
  History nominal_history() const;
  /** The node per body whose motion is recorded as u_tip_<b>, v_tip_<b>, a_tip_<b>. */
  const std::vector<Node<dim>>& monitor_nodes() const { return monitors; }
  /**
   * "complete" if the summaries cover the whole run and its whole contact, else
   * "incomplete: <why>"; empty before write_summaries().
   */
  const std::string& status() const { return summary_status; }

  /** The rows, the nominal rows and the output records (checkpoint). */
  template <class Archive>
  void serialize(Archive& archive, const unsigned int)
  {
    archive& rows;
    archive& nominal_rows;
    archive&* field_output;
  }

private:
  /**
   * Per body b, the monitor node's displacement, velocity and acceleration along the impact
   * direction at `state` (entries 3 b, 3 b + 1, 3 b + 2). Collective.
   */
  std::vector<double> monitor_motions(const StepState& state) const;
  /** The VTU frame and profiles of the row `frame` if scheduled. */
  void write_fields(unsigned int frame,
                    unsigned int nominal_step,
                    double time,
                    const StepState& state,
                    const std::vector<double>& pressures);

  const ProblemModel<dim>& model;
  const NodeIndex<dim>& nodes;
  const ContactConstraints<dim>& contact;
  const ContactFields<dim> fields;
  const bool surface_contact;
  const std::unique_ptr<FieldOutput<dim>> field_output;
  const OutputParameters output;
  TimerOutput& timer;
  const bool is_root_rank;
  const std::vector<Node<dim>> monitors;
  unsigned int innermost_pair = 0;      ///< candidate pair nearest to the axis (centre_pressure)
  std::set<unsigned int> profile_steps; ///< nominal steps at which a profile is written
  std::set<unsigned int> vtu_steps;     ///< nominal steps of Output/vtu times
  History rows;
  std::vector<unsigned int> nominal_rows; ///< rows on the nominal time grid
  std::string summary_status;
};
} // namespace dyncontact
