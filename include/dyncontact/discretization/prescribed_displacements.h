#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/models/problem_model.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/dofs/dof_handler.h>

#include <memory>
#include <vector>

namespace dyncontact
{
/**
 * The displacement components that Dirichlet boundaries prescribe, u_i = g_i(X, t) at the nodes of
 * their faces (FixedBoundary with a displacement; X the reference position), on this rank's owned
 * DoFs. These DoFs are among the fixed DoFs (BodyDiscretization's constraints), so Newton's updates
 * leave them alone: the step puts g(t_{n+1}) into its initial guess (ImplicitStepper), and the
 * integrator's rates of u follow. A DoF that several boundaries hold takes the first: the DoFs
 * held at zero (the axis, symmetry planes, supports) come before every Dirichlet boundary, which
 * come in ProblemModel::fixed_boundaries() order. g should be continuously differentiable in time
 * (twice for a smooth reaction): the trapezoidal rule carries a kink of g as a velocity that
 * alternates from step to step ever after.
 *
 * Collective: the constructor (which throws the same InputError on every rank) and flags().
 */
template <int dim>
class PrescribedDisplacements
{
public:
  /**
   * The entries of `boundaries` with a displacement, `held` their DoFs (one set per boundary, this
   * rank's, as BodyDiscretization extracts them), less `zero_dofs` (the DoFs held at zero besides
   * the boundaries', every rank's). Throws InputError, on every rank, naming the first boundary
   * where g(X, 0) is not zero (the bodies start undeformed), to 1e-12 of the largest distance of
   * its nodes from the origin.
   */
  PrescribedDisplacements(const DoFHandler<dim>& dof_handler,
                          const NodeIndex<dim>& nodes,
                          const std::vector<FixedBoundary>& boundaries,
                          const std::vector<IndexSet>& held,
                          const std::vector<types::global_dof_index>& zero_dofs);

  /** Per DoF of the mesh (`n_dofs` entries): prescribed, on any rank. Collective. */
  std::vector<bool> flags(types::global_dof_index n_dofs) const;

  /** Sets the owned prescribed entries of `u` (a volume vector) to g(X, t) [length]. */
  void set_displacement(double t, DistributedVector& u) const;

  /**
   * Sets the owned prescribed entries of `v` and `a` to dg/dt and d2g/dt2 at t, by one-sided
   * differences forward from t with step `h` [time] (error O(h^2) for v, O(h) for a; g is not
   * evaluated before t, where an expression written for t >= 0 need not hold).
   */
  void set_rates(double t, double h, DistributedVector& v, DistributedVector& a) const;

private:
  struct Entry
  {
    types::global_dof_index dof;
    unsigned int component;
    Point<dim> position;
    unsigned int boundary; ///< index in `functions`
  };

  /** g_component(position, t) of `entry`. */
  double value(const Entry& entry, double t) const;

  MPI_Comm communicator;
  /// per boundary: its g (null for those held at zero)
  std::vector<std::shared_ptr<Functions::ParsedFunction<dim>>> functions;
  std::vector<Entry> entries;
};
} // namespace dyncontact
