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

/**
 * External nodal forces W(t) from dead surface tractions: the integral of T(X, t) . phi over the
 * reference boundary, with the kinematics' measure factor (2 pi r in axisymmetry). Parallel like
 * ElasticBodies: locally owned cells, summed over the ranks. It does not follow the deformation
 * (no follower pressure).
 */
template <int dim>
class SurfaceTractions
{
public:
  SurfaceTractions(const DoFHandler<dim>& dof_handler,
                   const Mapping<dim>& mapping,
                   const Kinematics<dim>& kinematics,
                   std::vector<SurfaceTraction<dim>> tractions);

  /** W(t), one entry per DoF, on every rank; zero if there are no tractions. */
  Vector<double> force(double time) const;

private:
  const DoFHandler<dim>& dof_handler;
  const Mapping<dim>& mapping;
  const Kinematics<dim>& kinematics;
  std::vector<SurfaceTraction<dim>> tractions;
};
} // namespace dyncontact
