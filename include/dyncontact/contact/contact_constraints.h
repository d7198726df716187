#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/parameters.h>
#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact/contact_pair.h>
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
   * Total interface force, compression positive, recovered from the equations of motion of the
   * body-A nodes of the active pairs: the sum of -n . (M a + Q(u) - W) at those nodes
   * (`net_internal_force` = Q(u) - W). It equals the sum of the multipliers for the classical
   * scheme and differs at an impact step of the modified one, whose corrected accelerations carry
   * the interface force.
   */
  double recovered_contact_force(const Vector<double>& lumped_mass,
                                 const Vector<double>& acceleration,
                                 const Vector<double>& net_internal_force) const;

  /**
   * The interface force of the active pairs between bodies (wall pairs left out) recovered from
   * the nodes' balances (M a + Q - W) along `direction` (a unit vector, e.g. the impact
   * direction) on each side: `on_a` from the slave nodes of body A (compression positive),
   * `on_b` from the master nodes of body B (the force A exerts on B), each node once however
   * many pairs hold it. Equal up to round-off, also after the modified scheme's correction, which
   * conserves momentum; their difference measures the force balance.
   */
  struct SideForces
  {
    double on_a;
    double on_b;
  };
  SideForces recovered_side_forces(const Vector<double>& lumped_mass,
                                   const Vector<double>& acceleration,
                                   const Vector<double>& net_internal_force,
                                   const Tensor<1, dim>& direction) const;

  /**
   * The contact force of candidate `pair` [force], compression positive: its multiplier times
   * the force per multiplier (set_force_per_multiplier()) if it is active, else zero.
   */
  double pair_force(unsigned int pair) const
  {
    return active[pair] ? force_per_multiplier * multiplier_values[pair] : 0.;
  }

  /** Sum of pair_force() over the pairs [force]. */
  double total_pair_force() const;

  /**
   * The work of the contact events of a step [force x length], from the state `old` at u_n
   * (`old_displacement`) to the current one at u_{n+1} (`new_displacement`): (1/2) sum over the
   * pairs that closed (active now, not in `old`) of pair_force() times the gap g_k(u_n), plus
   * (1/2) sum over the pairs that opened (active in `old`, not now) of their old force
   * force_per_multiplier lambda_k,n times the gap g_k(u_{n+1}) (positive parts). With massless
   * contact nodes (mass redistribution) on the trapezoidal rule these are exactly the energy the
   * step loses at the closings and gains at the releases, for linear elasticity and gaps: the
   * step's energy change is (1/2) sum_k (lambda_k,n + lambda_k,n+1)(g_k,n+1 - g_k,n)
   * (doc/schemes.md, "Mass redistribution with resolved contact events").
   */
  double event_work(const Vector<double>& old_displacement,
                    const Vector<double>& new_displacement,
                    const State& old) const;

  /** The largest penetration max(0, -g) over all candidate pairs at `displacement`. */
  double max_penetration(const Vector<double>& displacement) const;

  /**
   * The largest |[[f]]| = |n . (f_B - f_A)| over the active pairs of a nodal field (velocity:
   * length/time, acceleration: length/time^2); zero if none is active. The paper's modified
   * Newmark (Taylor & Papadopoulos 1993, eqs. 22-23) makes it zero for velocity and acceleration.
   */
  double max_active_normal_jump(const Vector<double>& field) const;

  /**
   * The largest distance of the current position of node A from the axis of the last coordinate
   * (r in axisymmetry, where it is the contact radius) over the active pairs; zero if none is
   * active. Meaningless in 1D, where it is zero.
   */
  double contact_radius(const Vector<double>& displacement) const;

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

  /**
   * n . (M a + Q(u) - W) at `node`: the equation-of-motion balance along n, i.e. minus the contact
   * force on a body-A node and plus that on a body-B node.
   */
  double normal_balance(const Node<dim>& node,
                        const Tensor<1, dim>& normal,
                        const Vector<double>& lumped_mass,
                        const Vector<double>& acceleration,
                        const Vector<double>& net_internal_force) const;

  std::vector<ContactPair<dim>> pairs;
  const ContactGeometry<dim>* geometry = nullptr; ///< null: fixed pairs
  ContactFormulation formulation;
  std::vector<bool> active;
  Vector<double> multiplier_values;
  std::vector<double> reference_gaps; ///< empty: zero for every pair
  double force_per_multiplier = 1.;   ///< see set_force_per_multiplier()
};
} // namespace dyncontact
