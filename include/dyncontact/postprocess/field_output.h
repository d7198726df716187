#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
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

  /**
   * Writes `solution_<step>.<rank>.vtu` and `solution_<step>.pvtu`, and updates `solution.pvd`.
   * `contact_traction` (a nodal vector field, the traction the other body exerts; its magnitude is
   * the contact pressure) is written if not null.
   */
  void write_fields(unsigned int step,
                    double time,
                    const Vector<double>& displacement,
                    const Vector<double>& velocity,
                    const Vector<double>& acceleration,
                    const Vector<double>* contact_traction);

  /** One contact pair at one time, as written by write_contact_pressure(). */
  struct PressureSample
  {
    Point<dim> position; ///< current position of the pair's node on body A
    double gap;
    double multiplier; ///< the pair's nodal contact force (compression positive), zero if inactive
    double pressure;   ///< consistent contact pressure, see NodeToNodeContact::contact_pressures()
    bool active;
  };

  /**
   * Writes `contact_pressure_t<time>.csv`: per candidate pair the current coordinates of its
   * body-A node, the gap, the multiplier (nodal force), the contact pressure and whether it is
   * active.
   */
  void write_contact_pressure(double time, const std::vector<PressureSample>& samples) const;

  /**
   * Writes `cells.csv`: per cell its body (1-based) and the rows, in the node order of
   * write_profile() (0-based), of the support points on its boundary in counter-clockwise order
   * (8 for a 9-node quadrilateral), so that profiles can be drawn as deformed meshes. 2D only.
   */
  void write_cell_outlines(const std::vector<Node<dim>>& nodes) const;

  /**
   * Writes `profile_t<time>.csv` with one row per node: body (1-based), reference coordinates,
   * then displacement, velocity and acceleration components (1D: body, x, u, v, a).
   */
  void write_profile(double time,
                     const std::vector<Node<dim>>& nodes,
                     const Vector<double>& displacement,
                     const Vector<double>& velocity,
                     const Vector<double>& acceleration) const;

  /** Writes or reads the list of fields in solution.pvd (checkpoints). */
  template <class Archive>
  void serialize(Archive& archive, const unsigned int)
  {
    archive& pvd_records;
  }

private:
  const DoFHandler<dim>& dof_handler;
  const Mapping<dim>& mapping;
  std::string directory;
  std::vector<std::pair<double, std::string>> pvd_records;
};
} // namespace dyncontact
