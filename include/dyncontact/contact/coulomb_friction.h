#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_border.h>
#include <dyncontact/contact/contact_pair.h>
#include <dyncontact/contact/contact_parameters.h>
#include <dyncontact/contact/multiplier_block.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace dyncontact
{
/**
 * Coulomb friction on the contact pairs: the tangential half of a pair's multipliers, its stick
 * and slip rows and its dissipation. A pair with friction coefficient mu > 0 owns dim multipliers
 * (MultiplierBlock): component 0 the normal force lambda_n (ContactConstraints), components 1 ..
 * dim - 1 the tangential force lambda_t [force] along an orthonormal tangent basis t_1 .. t_{dim-1}
 * of the pair's normal at the step's start, held over the step.
 *
 * Slip increment (frame-indifferent over the step): s = T^T sum_j c_j (u_j - u_j^n) over the
 * pair's nodes as they were at the step's start, c_j = -1 for the slave node and the master
 * weights w_i of the master point of u_n (ContactPair::for_each_node()): the motion of the master
 * material point the slave node touched at t_n relative to the slave node [length]. Under a rigid
 * rotation of both bodies it is zero for a closed pair (the two points coincide). The tangential
 * force on the pair's node j is c_j T lambda_t, so the friction force on the slave node is
 * -T lambda_t and the work of the pair's tangential forces over the step is lambda_t . s.
 *
 * Coulomb's law |lambda_t| <= mu lambda_n, lambda_t = -mu lambda_n s / |s| when s != 0 is written
 * as the NCP function of Hueber, Stadler & Wohlmuth (2008), with z = lambda_t - c s (c > 0 a
 * stiffness scale; the converged answer does not depend on it):
 *   stick (|z| <= mu lambda_n): s = 0;  slip (|z| > mu lambda_n): lambda_t = mu lambda_n z / |z|,
 * decided at every Newton iterate (update_states(), a semismooth Newton with the consistent
 * linearization of both branches, assemble_rows()). The penalty formulation regularizes stick:
 * lambda_t = lambda_t^n - (eps / f) s (an elastic tangential spring of the pair's penalty
 * stiffness eps, f the force per multiplier), z = lambda_t^n - (eps / f) s.
 *
 * A tangential direction along which the slave node cannot move (its DoFs there fixed: a node on a
 * symmetry plane or the axis of an axisymmetric mesh) carries no friction (its row is lambda = 0):
 * the symmetry holds the master point the same way. The tangent basis is aligned with the slave
 * node's fixed axis (start_step()) so that such a direction is one of the basis vectors.
 */
template <int dim>
class CoulombFriction
{
public:
  /** No friction on any pair. */
  CoulombFriction() = default;

  /**
   * The friction coefficient [-] of every candidate pair (>= 0; 0: frictionless, one multiplier).
   */
  explicit CoulombFriction(std::vector<double> coefficients);

  /** Whether any pair has friction. */
  bool any() const { return has_friction; }

  /** The friction coefficient of `pair`. */
  double coefficient(unsigned int pair) const { return coefficients[pair]; }

  /** The multipliers `pair` owns: dim with friction, else 1. */
  unsigned int n_components(unsigned int pair) const;

  /** The border DoFs held at zero (one flag per border DoF): see the class documentation. */
  void set_fixed_dofs(std::vector<bool> fixed) { fixed_dofs = std::move(fixed); }

  /**
   * Starts a step at u_n (`displacement`, a border vector) with the pairs of u_n (`pairs`, on the
   * border): their nodes, master weights and tangent bases are held over the step, and the
   * tangential multipliers of `multipliers` are the step's start (penalty's lambda_t^n), and the
   * tangential forces of the pairs `active` at the start the step's old forces (dissipation()).
   * `stiffness` per pair: c of the class documentation (Lagrange) or eps / f (penalty)
   * [force/length], > 0.
   */
  void start_step(const std::vector<ContactPair<dim>>& pairs,
                  const Vector<double>& displacement,
                  const std::vector<bool>& active,
                  const Vector<double>& multipliers,
                  const MultiplierBlock& block,
                  const std::vector<double>& stiffness);

  /** The slip increment s_alpha of `pair` at the border displacement `u` [length]. */
  double slip(unsigned int pair, unsigned int alpha, const Vector<double>& u) const;

  /** Adds the tangential forces c_j T lambda_t of every active pair to the border vector `force`.
   */
  void add_forces(const std::vector<bool>& active,
                  const Vector<double>& multipliers,
                  const MultiplierBlock& block,
                  Vector<double>& force) const;

  /**
   * The tangential rows of every friction pair into `rows` (null: residuals only) and their
   * residuals into `residual` [length], at the border displacement `u`: an inactive pair's
   * lambda_t = 0 (diagonal `inactive_diagonal`), a stuck pair's -s (penalty: -s - f (lambda_t -
   * lambda_t^n) / eps), a sliding pair's (lambda_t - mu lambda_n z / |z|) / c. The columns are the
   * volume DoFs of `border`'s.
   */
  void assemble_rows(const Vector<double>& u,
                     const std::vector<bool>& active,
                     const Vector<double>& multipliers,
                     const MultiplierBlock& block,
                     ContactFormulation formulation,
                     double inactive_diagonal,
                     const ContactBorder<dim>& border,
                     MultiplierRows* rows,
                     Vector<double>& residual) const;

  /**
   * Decides stick or slip for every active friction pair at the border displacement `u` (the
   * class documentation; a pair changes branch only when |z| - mu lambda_n passes
   * `force_tolerance` [force] the other way); inactive pairs are set sliding, the branch they
   * enter on (their force mu lambda_n starts at zero). Returns whether any pair
   * changed branch (in 2D also its slip direction).
   */
  bool update_states(const Vector<double>& u,
                     const std::vector<bool>& active,
                     const Vector<double>& multipliers,
                     const MultiplierBlock& block,
                     ContactFormulation formulation,
                     double force_tolerance);

  /**
   * The tangent bases the tangential multipliers are in, flattened (per pair dim - 1 vectors of dim
   * components; empty before the first step): what a saved state must keep with the multipliers,
   * so that start_step() reads them in their own bases after a restore (set_bases()).
   */
  std::vector<double> bases() const;
  /** Restores bases() (throws for a wrong length). */
  void set_bases(const std::vector<double>& flat);

  /**
   * The tangential force of `pair` as a vector, sum_alpha lambda_t,alpha t_alpha [multiplier
   * units], from `multipliers` (the block's layout); zero for a pair without friction.
   */
  Tensor<1, dim> tangential_force(unsigned int pair,
                                  const Vector<double>& multipliers,
                                  const MultiplierBlock& block) const;

  /**
   * The tangents of `pair` along which it carries friction (its basis of the step's start, less
   * the directions of fixed DoFs): dim - 1 at most, none without friction.
   */
  std::vector<Tensor<1, dim>> friction_directions(unsigned int pair) const;

  /**
   * Per pair: 0 stick (or no friction), +1 or -1 slip (2D: the sign of z; 3D: +1); an inactive pair
   * with friction +1, the branch it enters on.
   */
  const std::vector<signed char>& states() const { return slip_states; }
  void set_states(const std::vector<signed char>& states) { slip_states = states; }

  /**
   * The energy the friction of the step dissipated [energy], minus the work of the tangential
   * forces as the integrator applies them over the step: -sum_k F_k . sum_j c_j (u_j - u_j^n) at
   * the border displacement `u`, F_k = (1 - w) F_k^n + w f T lambda_t (f the force per
   * multiplier, F_k^n the pair's force at the step's start, zero for an inactive pair), w =
   * `new_weight` (Newmark: gamma, the weight of its external work; a generalized-alpha member: 1,
   * its one contact force per step). Negative when the friction did positive work. With the
   * penalty `formulation`, less the change of the energy its stick springs store,
   * sum_k f |lambda_t|^2 / (2 c_k).
   */
  double dissipation(const Vector<double>& u,
                     const std::vector<bool>& active,
                     const Vector<double>& multipliers,
                     const MultiplierBlock& block,
                     double force_factor,
                     double new_weight,
                     ContactFormulation formulation) const;

private:
  /**
   * Calls f(dof, g) for every border DoF of `pair`'s nodes at the step's start, with g = c_j
   * t_alpha[d] its coefficient in the slip increment s_alpha: the row ds_alpha / du that the
   * slip, the tangential forces and the tangential rows are made of.
   */
  template <typename Function>
  void for_each_slip_coefficient(unsigned int pair, unsigned int alpha, const Function& f) const
  {
    start_pairs[pair].for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          for (unsigned int d = 0; d < dim; ++d)
            f(node.dofs[d], coefficient * tangents[pair][alpha][d]);
        });
  }

  /** The trial vector z of `pair` (its components along the non-free directions zero). */
  std::array<double, dim - 1> trial(unsigned int pair,
                                    const Vector<double>& u,
                                    const Vector<double>& multipliers,
                                    const MultiplierBlock& block,
                                    ContactFormulation formulation) const;

  std::vector<double> coefficients;
  bool has_friction = false;
  std::vector<bool> fixed_dofs;
  /** Per pair at the step's start: its nodes and weights, tangent basis, free directions. */
  std::vector<ContactPair<dim>> start_pairs;
  std::vector<std::array<Tensor<1, dim>, dim - 1>> tangents;
  std::vector<std::array<bool, dim - 1>> free_direction;
  std::vector<double> stiffness;
  Vector<double> start_displacement;
  Vector<double> start_multipliers;
  /** Per pair: its tangential force T lambda_t at the step's start, per unit f [force]. */
  std::vector<Tensor<1, dim>> start_forces;
  std::vector<signed char> slip_states;
};
} // namespace dyncontact
