#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/material/material.h>
#include <dyncontact/postprocess/stress_postprocessor.h>

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * Fields for people to look at. For ParaView: VTU files with high-order (VTK Lagrange) cells, so a
 * Q2 cell is one curved 9-node quadrilateral, carrying displacement, velocity, acceleration,
 * contact traction, Cauchy stress, Green-Lagrange strain, von Mises stress (StressPostprocessor)
 * and body id (one file per MPI rank and a .pvtu record per frame), listed with their times in
 * `solution.pvd`; and the contact surfaces (the slave sides) as curves with the contact pressure,
 * gap and active flag of every pair, in `contact_surface.pvd`. Both records are rewritten after
 * every frame, so they are valid even if the run stops. Also CSV profiles of every node and of the
 * contact pressure at chosen times (written by rank 0). It computes nothing but the stresses.
 */
template <int dim>
class FieldOutput
{
public:
  /**
   * `materials[b]` is the law of body b (for the stresses); `contact_surfaces` are the boundary
   * ids of the slave contact surfaces (empty: no contact surface output). The DoFHandler must
   * carry an FESystem of dim copies of one scalar element. Everything passed must outlive this.
   */
  FieldOutput(const DoFHandler<dim>& dof_handler,
              const Mapping<dim>& mapping,
              const Kinematics<dim>& kinematics,
              std::vector<std::shared_ptr<const Material>> materials,
              std::set<types::boundary_id> contact_surfaces,
              std::string directory);

  /**
   * `owned` (a volume vector over each rank's owned displacement DoFs) with the entries of this
   * rank's ghost cells too, as the fields' writers read them. Collective.
   */
  DistributedVector with_ghosts(const DistributedVector& owned) const;

  /**
   * Writes `solution_<frame>.<rank>.vtu` (each rank its own cells) and `solution_<frame>.pvtu`,
   * and updates `solution.pvd` with `time`. The fields are with_ghosts() vectors.
   * `contact_traction` (a nodal vector field, the traction the other body exerts; its magnitude is
   * the contact pressure) is written if not null. Collective.
   */
  void write_fields(unsigned int frame,
                    double time,
                    const DistributedVector& displacement,
                    const DistributedVector& velocity,
                    const DistributedVector& acceleration,
                    const DistributedVector* contact_traction);

  /** One contact pair at one time, as written by write_contact_pressure(). */
  struct PressureSample
  {
    Node<dim> node;      ///< the pair's node on body A (the slave node)
    Point<dim> position; ///< its current position
    double gap;
    double multiplier; ///< the pair's nodal contact force (compression positive), zero if inactive
    /// contact pressure, ContactGeometry::contact_pressures() (mortar pairs: lambda_j / D_j)
    double pressure;
    bool active;
    /// with friction: the friction force on the slave node [force] and the shear traction on
    /// body A [force/area], recovered as `pressure` (ContactConstraints::shear_tractions()), zero
    /// without
    Tensor<1, dim> tangential_force, shear;
    bool sliding; ///< with friction: the pair slides (ContactConstraints::is_sliding())
  };

  /**
   * Writes `contact_pressure_t<time>.csv`: per candidate pair the current coordinates of its
   * body-A node, the gap, the multiplier (nodal force), the contact pressure and whether it is
   * active; `with_friction`, also the tangential force and shear traction components
   * (tangential_force_x, ..., shear_x, ...) and whether it slides (`sliding`).
   */
  void write_contact_pressure(double time,
                              const std::vector<PressureSample>& samples,
                              bool with_friction) const;

  /**
   * Writes the faces of the contact surfaces as `contact_surface_<frame>.<rank>.vtu` and
   * `contact_surface_<frame>.pvtu`, and updates `contact_surface.pvd`: displacement (a
   * with_ghosts() vector, to warp the
   * curves by), and per node of a pair the contact pressure [force/area], the gap [length] and
   * `active` (1 or 0); nodes of these faces without a pair get NaN. Does nothing without contact
   * surfaces.
   */
  void write_contact_surface(unsigned int frame,
                             double time,
                             const DistributedVector& displacement,
                             const std::vector<PressureSample>& samples);

  /**
   * Writes `cells.csv` (on rank 0): per cell its body (1-based) and the rows, in the node order of
   * write_profile() with NodeIndex::gather_on_root()'s nodes (0-based), of the support points on
   * its boundary in counter-clockwise order (8 for a 9-node quadrilateral), so that profiles can
   * be drawn as deformed meshes. Cells in the order of the ranks, then of each rank's cells.
   * Collective; 2D only.
   */
  void write_cell_outlines(const NodeIndex<dim>& nodes) const;

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
    archive& surface_pvd_records;
  }

private:
  const DoFHandler<dim>& dof_handler;
  const Mapping<dim>& mapping;
  StressPostprocessor<dim> stresses;
  std::set<types::boundary_id> contact_surfaces;
  std::string directory;
  /** The scalar element of the FESystem and its DoFs, for the nodal fields of the surfaces. */
  std::unique_ptr<FiniteElement<dim>> scalar_fe;
  DoFHandler<dim> scalar_dof_handler;
  /**
   * The scalar DoF of each of this rank's owned and ghost DoFs (by ghosted_layout's local index)
   * of component 0; invalid for the other components.
   */
  std::vector<types::global_dof_index> scalar_dof;
  std::vector<std::pair<double, std::string>> pvd_records;
  std::vector<std::pair<double, std::string>> surface_pvd_records;
  /** The owned DoFs and those of the ghost cells, the layout of with_ghosts(). */
  std::shared_ptr<const Utilities::MPI::Partitioner> ghosted_layout;

  /** The scalar DoF of `dof` (scalar_dof); invalid if it is not this rank's or of component 0. */
  types::global_dof_index scalar_dof_of(types::global_dof_index dof) const;
};
} // namespace dyncontact
