#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact/contact_pair.h>
#include <dyncontact/contact/contact_parameters.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{

/**
 * The contact layer: the candidate pairs, their active set and multipliers, and their rows in the
 * saddle-point system. The treatment of the contact nodes' rates (the paper's modified Newmark)
 * is a ContactDynamics, which reads the pairs from here.
 *
 * Every candidate owns one multiplier unknown, so the sparsity pattern never changes; an inactive
 * pair gets the trivial row lambda = 0. The Lagrange multiplier formulation enforces g = 0 on the
 * active pairs; the penalty formulation is the same system with -1/eps on the multiplier
 * diagonal (lambda = -eps g, i.e. the classical penalty force eps <-g>). Active set: a pair enters
 * when it penetrates and leaves when its multiplier turns tensile (Hughes et al. 1976) and, on a
 * surface with Lagrange multipliers, the contact pressure at its node is not compressive either
 * (see update_active_set()).
 *
 * Normals are fixed unless the pairs come from a ContactGeometry (NodeToNodeContact): then
 * update_geometry() moves them (normals and, for node-to-segment pairs, master points) to a
 * configuration; the time loop calls it at the start of every step with u_n, and the step's
 * Newton solve, rate correction and measures keep those normals (see ContactGeometry). The
 * master points of node-to-segment pairs follow the Newton iterates (update_master_points()), so
 * that the rate correction and measures see those of the converged configuration.
 *
 * It does not choose time steps, know the integrator, assemble elasticity or solve linear systems.
 */
template <int dim>
class ContactConstraints
{
public:
  /** Pairs with fixed normals (bars, a rigid wall). */
  ContactConstraints(std::vector<ContactPair<dim>> pairs, ContactFormulation formulation);

  /**
   * The pairs of `geometry`, which follow the current configuration (update_geometry()). The
   * geometry must have at least one pair and finite normals (its constructor's InputError sees to
   * it; AssertThrow otherwise).
   */
  ContactConstraints(const ContactGeometry<dim>& geometry, ContactFormulation formulation);

  /**
   * For pairs of a ContactGeometry: moves every pair to `displacement`
   * (ContactGeometry::update_pairs()). Does nothing for fixed pairs.
   */
  void update_geometry(const Vector<double>& displacement);

  /**
   * For pairs of a ContactGeometry: moves every pair's master point to `displacement`, its normal
   * kept (ContactGeometry::update_master_points(); the Newton solver calls it at every iterate).
   * Does nothing for fixed pairs.
   */
  void update_master_points(const Vector<double>& displacement);

  unsigned int n_pairs() const { return pairs.size(); }
  ContactFormulation contact_formulation() const { return formulation; }

  /** Multiplies every pair's penalty stiffness by `factor` > 0 (automatic penalty sizing). */
  void scale_penalty_stiffness(double factor);

  /**
   * The contact force one unit of multiplier stands for [-], > 0: 1 (the default) when the step
   * equation is the balance at t_{n+1} and carries the contact force G^T lambda_{n+1}; 1 - alpha_f
   * for a dissipative generalized-alpha member, whose step equation is the balance at
   * t_{n+1-alpha_f} divided by 1 - alpha_f (GeneralizedAlpha); gamma for a treatment whose step
   * carries the contact impulse dt gamma G^T lambda_{n+1} (ImplicitContactImpulse). The pair
   * forces, their total, the contact pressures and the penalty spring (force = eps <-g>) are
   * then the contact force of the balance the step solves, whatever the integrator weights the
   * multiplier with (doc/method.md, "Contact forces on every integrator").
   */
  void set_force_per_multiplier(double factor);
  /** The factor of set_force_per_multiplier() (1 until set). */
  double force_per_multiplier() const { return force_factor; }
  const std::vector<ContactPair<dim>>& candidate_pairs() const { return pairs; }
  unsigned int n_active() const;
  bool is_active(unsigned int pair) const { return active[pair]; }

  /** The active set and multipliers, to be restored if a Newton step is taken back. */
  struct State
  {
    std::vector<bool> active;
    Vector<double> multipliers;
  };
  State state() const { return {active, multiplier_values}; }
  void restore(const State& saved)
  {
    active            = saved.active;
    multiplier_values = saved.multipliers;
  }

  /** Gap of candidate `pair` at displacement u (negative = penetration). */
  double gap(unsigned int pair, const Vector<double>& displacement) const;

  /**
   * The gap each pair's constraint holds at or above, per candidate pair [length]: the solve
   * enforces g_k(u) - reference_k >= 0 (equal to it on the active pairs) instead of g_k(u) >= 0.
   * Empty means zero for every pair, the impenetrability condition and the default. A gap-rate
   * (persistency) treatment sets g_k(u_n) for the step's persisting pairs, so that the constraint
   * reads g_{n+1} - g_n >= 0 (Persistency). Throws std::invalid_argument for a wrong length.
   */
  void set_reference_gaps(std::vector<double> reference);

  /** Couples row/column n_dofs + k of candidate k with the DoFs of its nodes. */
  void add_to_sparsity(DynamicSparsityPattern& sparsity, types::global_dof_index n_dofs) const;

  /**
   * The DoFs any candidate pair can couple during the run (those of add_to_sparsity(): with a
   * contact geometry every node of the contact surfaces a pair may project on), as n_dofs flags.
   */
  std::vector<bool> contact_dofs(types::global_dof_index n_dofs) const;

  /** Adds the contact forces G^T lambda on the bodies to `force` (length n_dofs). */
  void add_contact_forces(Vector<double>& force) const;

  /**
   * Writes the constraint rows of the Newton system into `matrix` (rows and columns n_dofs + k,
   * symmetric) and their residuals into `constraint_residual` (length n_pairs): -g (Lagrange) or
   * -g - lambda/eps (penalty) for active pairs, lambda for inactive ones with diagonal
   * `inactive_diagonal`; a penalty pair's row is -g - f lambda / eps, f the force per multiplier,
   * so that its force f lambda is eps <-g>. The update is (delta u, delta lambda) = matrix^{-1}
   * (-residual). A null `matrix` computes the residuals only (ranks that do not own the constraint
   * rows).
   */
  void assemble_constraint_rows(const Vector<double>& displacement,
                                double inactive_diagonal,
                                TrilinosWrappers::SparseMatrix* matrix,
                                Vector<double>& constraint_residual) const;

  /** Adds a Newton increment of the multipliers. */
  void add_multiplier_increment(const Vector<double>& increment);

  /**
   * Updates the active set at displacement u: inactive pairs with g < -gap_tolerance enter,
   * active pairs with lambda < -force_tolerance leave (their multiplier is reset to zero), except,
   * for surface pairs with Lagrange multipliers, those whose contact pressure (contact_pressures())
   * is still compressive:
   * a node whose consistent share of a compressive pressure is zero or negative (the axis node of
   * an axisymmetric Q2 surface has zero tributary area) may carry a slightly tensile multiplier
   * while its surroundings are pressed together. Returns whether anything changed.
   */
  bool update_active_set(const Vector<double>& displacement,
                         double gap_tolerance,
                         double force_tolerance);

  /**
   * The contact force of candidate `pair` [force], compression positive: its multiplier times
   * the force per multiplier (set_force_per_multiplier()) if it is active, else zero.
   */
  double pair_force(unsigned int pair) const
  {
    return active[pair] ? force_factor * multiplier_values[pair] : 0.;
  }

  /**
   * The contact pressure at every pair [force/area] (see ContactGeometry::contact_pressures()) at
   * `displacement` from the pair forces (pair_force()); empty for pairs with fixed normals.
   */
  std::vector<double> contact_pressures(const Vector<double>& displacement) const;

private:
  /** g_k(u) - reference_k: what the solve constrains (see set_reference_gaps()). */
  double constraint_gap(unsigned int pair, const Vector<double>& displacement) const;

  /** Calls f(dof) for every DoF candidate pair `k` can couple (see contact_dofs()). */
  template <typename Function>
  void for_each_coupled_dof(unsigned int k, const Function& f) const;

  std::vector<ContactPair<dim>> pairs;
  const ContactGeometry<dim>* geometry = nullptr; ///< null: fixed pairs
  ContactFormulation formulation;
  std::vector<bool> active;
  Vector<double> multiplier_values;
  std::vector<double> reference_gaps; ///< empty: zero for every pair
  double force_factor = 1.;           ///< see set_force_per_multiplier()
};
} // namespace dyncontact
