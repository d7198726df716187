#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_description.h>
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/discretization/external_loads.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/models/mesh_parameters.h>
#include <dyncontact/postprocess/history.h>

#include <deal.II/grid/tria.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * Displacement components held for all time on the faces of one boundary id: at zero, or at
 * u_i = g_i(x, t) of a prescribed displacement (DirichletParameters).
 */
struct FixedBoundary
{
  types::boundary_id boundary;
  std::vector<unsigned int> components; ///< 0 .. dim - 1
  /// g(x, t) with dim components [length], of which `components` apply; empty: held at zero
  FunctionExpression displacement = {};
  /// the parameter subsection it comes from ("Boundary/Dirichlet 1"), for errors
  std::string section = {};
};

/**
 * What distinguishes one kind of problem (bars, spheres, ...) from another for the one
 * dim-templated Simulation: the mesh with body ids, the bodies' materials and kinematics, the
 * initial velocity, the candidate contact pairs, the node of each body whose motion the history
 * reports, and an independent reference solution if one exists. It does not solve anything.
 */
template <int dim>
class ProblemModel
{
public:
  virtual ~ProblemModel() = default;

  /** Polynomial degree of the Lagrange elements (1: 2-node bars, 2: 9-node quadrilaterals). */
  virtual unsigned int element_degree() const = 0;

  /**
   * All bodies in one triangulation, material id b = body b (0-based), with the manifolds of
   * curved boundaries attached. It is the whole mesh on every rank: BodyDiscretization keeps each
   * rank's part of it (a distributed triangulation), whose manifolds attach_manifolds() attaches.
   */
  virtual void create_triangulation(Triangulation<dim>& triangulation) = 0;

  /**
   * Attaches the manifolds of create_triangulation() to a part of its mesh (the cells and faces
   * carry their manifold ids); the default attaches none (straight cells).
   */
  virtual void attach_manifolds(Triangulation<dim>& triangulation) const;

  /** Number of bodies. */
  virtual unsigned int n_bodies() const = 0;

  /** Material and density of every body, indexed by material id. */
  virtual std::vector<BodyMaterial> body_materials() const = 0;

  /** The kinematic model (1D bar, axisymmetric, ...). */
  virtual std::unique_ptr<Kinematics<dim>> create_kinematics() const = 0;

  /** Velocity at t = 0 of the material point X of `body`. */
  virtual Tensor<1, dim> initial_velocity(types::material_id body, const Point<dim>& X) const = 0;

  /**
   * What the model says about contact, from the mesh's nodes: fixed-normal pairs or a pair of
   * matching surfaces, with the stiffness scales penalties are sized from (create_contact()
   * builds it). Throws InputError for a contact the model cannot describe.
   */
  virtual ContactDescription<dim> contact_description(const NodeIndex<dim>& nodes) const = 0;
  /**
   * DoFs held at zero for all time (e.g. u_r on the symmetry axis), of the nodes given (this
   * rank's: BodyDiscretization gathers them over the ranks). The default: none.
   */
  virtual std::vector<types::global_dof_index> fixed_dofs(const NodeIndex<dim>& nodes) const;

  /**
   * Boundaries with displacement components held for all time (symmetry planes and supports at
   * zero, Dirichlet boundaries at their prescribed displacement), besides fixed_dofs(); valid after
   * create_triangulation(). The default: none.
   * Throws InputError for a boundary the mesh cannot hold so.
   */
  virtual std::vector<FixedBoundary> fixed_boundaries() const;

  /** Dead surface tractions (external loads). The default: none. */
  virtual std::vector<SurfaceTraction<dim>> surface_tractions() const;

  /** Dead body forces (external loads, e.g. gravity). The default: none. */
  virtual std::vector<BodyForce<dim>> body_forces() const;

  /** One node per body ("tip", its contact node) whose u, v, a the history reports. */
  virtual std::vector<Node<dim>> monitor_nodes(const NodeIndex<dim>& nodes) const = 0;

  /** Unit vector along which momentum and tip motion are reported (the impact direction). */
  virtual Tensor<1, dim> impact_direction() const = 0;

  /**
   * The unit vectors along which each body's momentum change must equal the impulse it received
   * (the momentum guard, BodyImpulses), spanning impact_direction(): Cartesian axes, or one
   * vector. The default: the impact direction alone (an axisymmetric model's axis, a bar's x).
   */
  virtual std::vector<Tensor<1, dim>> momentum_directions() const { return {impact_direction()}; }

  /**
   * Writes the model's independent reference solution (e.g. exact.csv) into `directory`, sampled
   * at `times`, for the given monitor nodes. The default writes nothing.
   */
  virtual void write_reference(const std::string& directory,
                               const std::vector<double>& times,
                               const std::vector<Node<dim>>& monitors) const;

  /**
   * Compares the finished run's `history` (every accepted row, the sub-steps of cut steps
   * included) with the model's reference, writing the comparison into `directory` and a short
   * report to `log`. `contact_impulses` [force time], one per body, is the impulse of the contact
   * forces on it along the impact direction since t = 0, as the run accumulated it (the momentum
   * change the contact caused, to the momentum guard's tolerance). `status` is "complete" or
   * "incomplete: <why>" (summary_status()), written in the summary's last column, `status`, on
   * every row. The default does nothing.
   */
  virtual void summarize_run(const std::string& directory,
                             const History& history,
                             const std::vector<double>& contact_impulses,
                             const std::string& status,
                             std::ostream& log) const;

  /** A few lines describing the problem (sizes, wave speeds, Courant numbers). */
  virtual void print_summary(std::ostream& out, double time_step) const = 0;
};
} // namespace dyncontact
