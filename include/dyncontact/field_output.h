#pragma once

#include <dyncontact/global.h>
#include <dyncontact/node_index.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * Nodal fields for people to look at: VTU files of displacement, velocity, acceleration and body
 * id for ParaView (one file per MPI rank and a .pvtu record per step), listed with their times in
 * `solution.pvd` (rewritten after every step, so it is valid even if the run stops), and CSV
 * profiles of every node at chosen times (written by rank 0). It computes nothing.
 */
template <int dim>
class FieldOutput
{
public:
  FieldOutput(const DoFHandler<dim>& dof_handler,
              const Mapping<dim>& mapping,
              std::string directory);

  /** Writes `solution_<step>.<rank>.vtu` and `solution_<step>.pvtu`, and updates `solution.pvd`. */
  void write_fields(unsigned int step,
                    double time,
                    const Vector<double>& displacement,
                    const Vector<double>& velocity,
                    const Vector<double>& acceleration);

  /**
   * Writes `profile_t<time>.csv` with one row per node: body (1-based), reference coordinates,
   * then displacement, velocity and acceleration components (1D: body, x, u, v, a).
   */
  void write_profile(double time,
                     const std::vector<Node<dim>>& nodes,
                     const Vector<double>& displacement,
                     const Vector<double>& velocity,
                     const Vector<double>& acceleration) const;

private:
  const DoFHandler<dim>& dof_handler;
  const Mapping<dim>& mapping;
  std::string directory;
  std::vector<std::pair<double, std::string>> pvd_records;
};
} // namespace dyncontact
