#pragma once

#include <dyncontact/global.h>
#include <dyncontact/kinematics.h>
#include <dyncontact/material.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace dyncontact
{
/** The constitutive data of one body: its hyperelastic law and reference mass density. */
struct BodyMaterial
{
  std::shared_ptr<const Material> material;
  double density;
};

/**
 * The elastic bodies of a problem on one DoFHandler (body b = cells with material id b): the
 * lumped mass, the internal force Q(u), its tangent dQ/du and the strain energy, all in the
 * total-Lagrangian setting. It knows neither contact nor time stepping.
 *
 * The lumped mass is the mass matrix integrated with the Gauss-Lobatto rule whose points are the
 * element's nodes, which makes it diagonal; its entries are positive for Q1 and Q2 (weights 1/6,
 * 2/3, 1/6 per direction) and sum to the body's mass.
 */
template <int dim>
class ElasticBodies
{
public:
  ElasticBodies(const DoFHandler<dim>& dof_handler,
                const Mapping<dim>& mapping,
                const Kinematics<dim>& kinematics,
                std::vector<BodyMaterial> bodies);

  /** Diagonal of the lumped mass matrix, one entry per DoF. */
  Vector<double> lumped_mass() const;

  /**
   * Internal force Q(u) into `internal_force` (overwritten) and, if `tangent` is not null, dQ/du
   * added into its leading n_dofs x n_dofs block (the caller zeroes it).
   */
  void assemble_internal_force(const Vector<double>& displacement,
                               Vector<double>& internal_force,
                               TrilinosWrappers::SparseMatrix* tangent) const;

  /** Total strain energy, the integral of W(F) over all bodies. */
  double strain_energy(const Vector<double>& displacement) const;

private:
  /** One pass over all quadrature points filling whichever of the outputs is not null. */
  void integrate(const Vector<double>& displacement,
                 Vector<double>* internal_force,
                 TrilinosWrappers::SparseMatrix* tangent,
                 double* strain_energy) const;

  const DoFHandler<dim>& dof_handler;
  const Mapping<dim>& mapping;
  const Kinematics<dim>& kinematics;
  std::vector<BodyMaterial> bodies;
};
} // namespace dyncontact
