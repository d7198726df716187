#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/kinematics.h>

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace dyncontact
{
/** A nominal (dead) traction, force per unit reference area, on the faces with one boundary id. */
template <int dim>
struct SurfaceTraction
{
  types::boundary_id boundary_id;
  std::shared_ptr<Function<dim>> traction; ///< dim components of (X, t)
};

/** A dead body force, force per unit reference volume, on the cells of one body. */
template <int dim>
struct BodyForce
{
  types::material_id body;
  std::shared_ptr<Function<dim>> force; ///< dim components of (X, t): rho g for gravity g
  double density;                       ///< the body's rho [mass/length^3], > 0
};

/**
 * External nodal forces W(t) from dead loads. A surface traction T(X, t) gives the integral of
 * T . phi over the reference boundary faces with its boundary id, with the kinematics' measure
 * factor (2 pi r in axisymmetry). A body force b(X, t) is lumped as the mass is: the DoF of
 * component c at node X gets m b_c(X, t) / rho, m its lumped mass, so a uniform field gives every
 * node of a free body the same acceleration b / rho and the body moves rigidly, without stress
 * (with the consistent integral of b . phi the HRZ-lumped nodes of curved cells would accelerate
 * unequally and ring); a massless DoF (mass redistribution) gets none, as its mass went to its
 * neighbours. Parallel like ElasticBodies: locally owned cells and DoFs, summed over the ranks.
 * Neither load follows the deformation (no follower pressure).
 */
template <int dim>
class ExternalLoads
{
public:
  ExternalLoads(const DoFHandler<dim>& dof_handler,
                const Mapping<dim>& mapping,
                const Kinematics<dim>& kinematics,
                std::vector<SurfaceTraction<dim>> tractions,
                std::vector<BodyForce<dim>> body_forces = {});

  /**
   * W(t), one entry per DoF, on every rank; zero if there are no loads. `lumped_mass` [mass], one
   * entry per DoF (the run's, after any mass redistribution), weighs the body forces.
   */
  Vector<double> force(double time, const Vector<double>& lumped_mass) const;

private:
  /** Adds the tractions' part of W(t) on this rank's cells to `force`. */
  void add_tractions(double time, Vector<double>& force) const;

  /** A DoF loaded by a body force: this rank owns it. */
  struct LoadedDof
  {
    types::global_dof_index dof;
    unsigned int component;
    unsigned int load; ///< index into body_forces
    Point<dim> position;
  };

  const DoFHandler<dim>& dof_handler;
  const Mapping<dim>& mapping;
  const Kinematics<dim>& kinematics;
  std::vector<SurfaceTraction<dim>> tractions;
  std::vector<BodyForce<dim>> body_forces;
  std::vector<LoadedDof> loaded_dofs;
};
} // namespace dyncontact
