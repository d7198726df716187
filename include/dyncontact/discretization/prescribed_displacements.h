#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/models/problem_model.h>

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
 * integrator's rates of u follow. A DoF that several boundaries hold takes the first in
 * ProblemModel::fixed_boundaries() order (symmetry planes and supports, at zero, come first).
 */
template <int dim>
class PrescribedDisplacements
{
public:
  /**
   * The entries of `boundaries` with a displacement. Throws InputError naming the boundary's
   * section if g(X, 0) is not zero at one of its nodes (the bodies start undeformed), to 1e-12 of
   * the largest distance of the boundary's nodes from the origin.
   */
  PrescribedDisplacements(const DoFHandler<dim>& dof_handler,
                          const NodeIndex<dim>& nodes,
                          const std::vector<FixedBoundary>& boundaries);

  /** Whether this rank owns no prescribed DoF. */
  bool empty() const { return entries.empty(); }

  /** Sets the owned prescribed entries of `u` (a volume vector) to g(X, t) [length]. */
  void set_displacement(double t, DistributedVector& u) const;

  /**
   * Sets the owned prescribed entries of `v` and `a` to dg/dt and d2g/dt2 at t, by central
   * differences with step `h` [time] (error O(h^2), round-off O(eps |g| / h^2)).
   */
  void set_rates(double t, double h, DistributedVector& v, DistributedVector& a) const;

private:
  struct Entry
  {
    types::global_dof_index dof;
    unsigned int component;
    Point<dim> position;
    unsigned int function; ///< index in functions
  };

  /** g_component(position, t) of `entry`. */
  double value(const Entry& entry, double t) const;

  std::vector<std::shared_ptr<Functions::ParsedFunction<dim>>> functions;
  std::vector<Entry> entries;
};
} // namespace dyncontact
