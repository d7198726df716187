#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/solver/saddle_point_system.h>

#include <deal.II/lac/vector.h>

#include <limits>
#include <vector>

namespace dyncontact
{
/**
 * The residual of one implicit time step with contact and its tangent: for a displacement
 * u = u~ + increment (u~ the Newmark predictor),
 *
 *   r = [ c M (u - u~) + Q(u) - W - G^T lambda ;  constraint rows of ContactConstraints ]
 *
 * (n_dofs force rows, zero at fixed DoFs, and one constraint row per multiplier), with c = 1/(beta
 * dt^2), M the lumped mass, Q(u) the internal force of the ElasticBodies, W the external force and
 * G^T lambda the contact force of the multipliers the contact layer holds. The tangent, if asked
 * for, is the symmetric saddle-point matrix [K_eff, -G^T; -G, -D] with K_eff = c M + dQ/du,
 * assembled into a SaddlePointSystem (the rows and columns of constrained DoFs eliminated).
 * It also returns the figures Newton's convergence test and line search need (see Figures).
 *
 * It lives in the solver module rather than in discretization: it combines the bodies
 * (discretization) with the contact layer (which itself builds on discretization) and the matrix
 * of the saddle-point system, so it belongs above all three.
 *
 * State: Q(u) and the strain energy of the last evaluation, and the tangent scale max diag(K_eff)
 * of the last assembled tangent. It does not solve, update the active set or move the normals.
 */
template <int dim>
class DynamicResidual
{
public:
  /**
   * Relative round-off of forces and gaps evaluated in double precision from displacements of
   * size |u|: a thousand units of double precision, far below any tolerance a user may set
   * (>= 1e-16 relative to the forces).
   */
  static constexpr double roundoff_factor = 1e3 * std::numeric_limits<double>::epsilon();

  /** The data of one time step's equation, fixed during its Newton iteration. */
  struct Step
  {
    const DistributedVector& predictor;      ///< u~ [length], owned DoFs
    double inertia_factor;                   ///< c = 1/(beta dt^2) [1/time^2]
    const DistributedVector& external_force; ///< W at t_{n+1} [force], owned DoFs
  };

  /** The figures of one evaluation for Newton's convergence test and line search. */
  struct Figures
  {
    /** |r_u|, the l2 norm of the force rows (fixed DoFs excluded) [force]. */
    double force_residual;
    /**
     * The reference force |Q(u)| + |W| + |G^T lambda| (elastic, external and contact forces; not
     * the inertia, whose unresolved high-frequency part can be arbitrarily large) [force].
     */
    double reference_force;
    /**
     * The round-off floor 1e3 eps (|K_eff|_inf |u| + |c M (u - u~)|): the terms that cancel in
     * K u and c M u, which no tolerance can go under [force]. |K_eff|_inf, the largest absolute
     * row sum, bounds the round-off of K u; max diag(K_eff), which it replaced, is 2 to 5 times
     * smaller on Q2 meshes, and Newton on the free sphere's breathing mode (Bossak) wandered for
     * up to 25 updates in a band 1.5-3 times above that floor.
     */
    double round_off_floor;
    /** max |constraint row residual| over the active pairs, 0 if none [length]. */
    double constraint_violation;
    /**
     * The line search's measure of the residual: sqrt(|r_u|^2 + sum_k (s_k r_k)^2) over the
     * constraint rows r_k, with s_k = max diag(K_eff) for active pairs (a gap turned into a force)
     * and 1 for inactive ones.
     */
    double merit;
  };

  /**
   * `lumped_mass` (n_dofs entries, the diagonal of M) and `contact` are referenced, not copied,
   * and must outlive this object; the DoFs `constraints` holds at zero get a zero force row.
   */
  DynamicResidual(const ElasticBodies<dim>& bodies,
                  const ContactConstraints<dim>& contact,
                  const Vector<double>& lumped_mass,
                  const AffineConstraints<double>& constraints);

  /**
   * Bodies with a constant tangent (ElasticBodies::has_constant_tangent(), linear materials): K
   * assembled into `tangent` and kept as its constant part (SaddlePointSystem), which every later
   * tangent of evaluate() starts from. Once, before the first evaluate() with that tangent; nothing
   * for other bodies. Collective.
   */
  void keep_constant_tangent(SaddlePointSystem<dim>& tangent) const;

  /**
   * Evaluates the residual at `displacement` = step.predictor + `increment` (both this rank's
   * owned DoFs; `border_displacement` its entries on the contact border) with the multipliers and
   * active set the contact layer holds, and, if `tangent` is not null, assembles the tangent into
   * it (from its constant part, keep_constant_tangent(), or from zero) and records its scales
   * (TangentScales). The residual is then available from force_rows() and constraint_rows().
   * Without a tangent the figures use the scales of the last assembly (tangent_scales()).
   *
   * Throws the SolverFailure of ElasticBodies::assemble_internal_force() (an inverted element) as
   * it is, after flushing the entries assembled so far (collectively); the residual, internal
   * force and figures are then not meaningful.
   */
  Figures evaluate(const Step& step,
                   const DistributedVector& increment,
                   const DistributedVector& displacement,
                   const Vector<double>& border_displacement,
                   SaddlePointSystem<dim>* tangent);

  /**
   * The force rows of the last evaluation's residual (zero at fixed DoFs): this rank's owned DoFs,
   * in the layout of internal_force().
   */
  const DistributedVector& force_rows() const { return force_residual; }

  /** The constraint rows of the last evaluation's residual (one per multiplier). */
  const Vector<double>& constraint_rows() const { return constraint_residual; }

  /** Q(u) at the displacement of the last evaluation [force], this rank's owned DoFs. */
  const DistributedVector& internal_force() const { return internal_force_values; }

  /** Strain energy at the displacement of the last evaluation [energy]. */
  double strain_energy() const { return strain_energy_value; }

  /**
   * The scales of the last tangent (0: none yet): the row sum scales the round-off floor, the
   * diagonal the merit's constraint rows; set_tangent_scales() restores them from a checkpoint.
   */
  const TangentScales& tangent_scales() const { return scales; }
  void set_tangent_scales(const TangentScales& tangent_scales) { scales = tangent_scales; }

private:
  /**
   * Q(u), c M (u - u~), G^T lambda and the constraint rows into the work vectors and, if
   * `tangent` is not null, the tangent into it; see evaluate().
   */
  void assemble(const Step& step,
                const DistributedVector& increment,
                const DistributedVector& displacement,
                const Vector<double>& border_displacement,
                SaddlePointSystem<dim>* tangent);

  /** The residual vector and the figures from the work vectors of assemble(). */
  Figures residual_and_figures(const Step& step, const DistributedVector& displacement);

  const ElasticBodies<dim>& bodies;
  const ContactConstraints<dim>& contact;
  const Vector<double>& lumped_mass;
  std::vector<bool> is_fixed;
  /** Q(u), c M (u - u~), G^T lambda and the force rows: this rank's owned DoFs. */
  DistributedVector internal_force_values, inertia_force, contact_force, force_residual;
  Vector<double> constraint_residual;
  TangentScales scales;
  double strain_energy_value = 0.;
};
} // namespace dyncontact
