#pragma once

#include <dyncontact/global.h>
#include <dyncontact/newmark.h>
#include <dyncontact/node_index.h>
#include <dyncontact/parameters.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <optional>
#include <vector>

namespace dyncontact
{
/**
 * One candidate contact constraint: a node of body A against a node of body B (node-to-node) or
 * against a fixed rigid wall. The gap is g = n . (x_B - x_A) with current positions x = X + u and
 * the unit normal n from A toward B, which is fixed (exact for the bars; small-sliding
 * approximation otherwise). Compression is a positive multiplier.
 */
template <int dim>
struct ContactPair
{
  Node<dim> node_a;
  std::optional<Node<dim>> node_b; ///< empty: a rigid wall through `wall_point`
  Point<dim> wall_point;
  Tensor<1, dim> normal;
  double penalty_stiffness; ///< used by the penalty formulation only

  bool against_wall() const { return !node_b.has_value(); }

  /** n . (X_B - X_A), or n . (wall point - X_A): the gap at zero displacement. */
  double reference_gap() const
  {
    return normal * ((against_wall() ? wall_point : node_b->position) - node_a.position);
  }
};

/**
 * The contact layer: the candidate pairs, their active set and multipliers, their rows in the
 * saddle-point system, and the modified Newmark's rate correction (Taylor & Papadopoulos 1993,
 * section 5).
 *
 * Every candidate owns one multiplier unknown, so the sparsity pattern never changes; an inactive
 * pair gets the trivial row lambda = 0. The Lagrange multiplier formulation enforces g = 0 on the
 * active pairs; the penalty formulation is the same system with -1/eps on the multiplier
 * diagonal (lambda = -eps g, i.e. the classical penalty force eps <-g>). Active set: a pair enters
 * when it penetrates and leaves when its multiplier turns tensile (Hughes et al. 1976).
 *
 * It does not choose time steps, assemble elasticity or solve linear systems.
 */
template <int dim>
class ContactConstraints
{
public:
  ContactConstraints(std::vector<ContactPair<dim>> pairs, ContactFormulation formulation);

  unsigned int n_pairs() const { return pairs.size(); }
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

  /** Couples row/column n_dofs + k of candidate k with the DoFs of its nodes. */
  void add_to_sparsity(DynamicSparsityPattern& sparsity, types::global_dof_index n_dofs) const;

  /** Adds the contact forces G^T lambda on the bodies to `force` (length n_dofs). */
  void add_contact_forces(Vector<double>& force) const;

  /**
   * Writes the constraint rows of the Newton system into `matrix` (rows and columns n_dofs + k,
   * symmetric) and their residuals into `constraint_residual` (length n_pairs): -g (Lagrange) or
   * -g - lambda/eps (penalty) for active pairs, lambda for inactive ones with diagonal
   * `inactive_diagonal`. The update is (delta u, delta lambda) = matrix^{-1} (-residual). A null
   * `matrix` computes the residuals only (ranks that do not own the constraint rows).
   */
  void assemble_constraint_rows(const Vector<double>& displacement,
                                double inactive_diagonal,
                                TrilinosWrappers::SparseMatrix* matrix,
                                Vector<double>& constraint_residual) const;

  /** Adds a Newton increment of the multipliers. */
  void add_multiplier_increment(const Vector<double>& increment);

  /**
   * Updates the active set at displacement u: inactive pairs with g < -gap_tolerance enter,
   * active pairs with lambda < -force_tolerance leave (their multiplier is reset to zero).
   * Returns whether anything changed.
   */
  bool update_active_set(const Vector<double>& displacement,
                         double gap_tolerance,
                         double force_tolerance);

  /**
   * The modified Newmark correction, the paper's eqs. (21)-(22) and the recovery formulas after
   * them, with weights equal to the lumped nodal masses (a wall has infinite weight): on every
   * active pair the normal components of v_{n+1} and a_{n+1} are corrected so that their jumps
   * vanish. Tangential components and all other nodes keep the classical values.
   */
  void apply_rate_correction(const Newmark& newmark,
                             const Vector<double>& lumped_mass,
                             const NewmarkStep& step,
                             Vector<double>& v_new,
                             Vector<double>& a_new) const;

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

  /** Sum of the multipliers of the active pairs. */
  double total_multiplier() const;

private:
  /** Normal component n . f of a nodal vector field at `node`. */
  double normal_component(const Node<dim>& node,
                          const Tensor<1, dim>& normal,
                          const Vector<double>& field) const;

  std::vector<ContactPair<dim>> pairs;
  ContactFormulation formulation;
  std::vector<bool> active;
  Vector<double> multiplier_values;
};
} // namespace dyncontact
