#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_border.h>
#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact/contact_pair.h>
#include <dyncontact/contact/contact_parameters.h>
#include <dyncontact/contact/coulomb_friction.h>
#include <dyncontact/contact/multiplier_block.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{

/**
 * The contact layer: the candidate pairs, their active set and multipliers, and their rows in the
 * saddle-point system. The treatment of the contact nodes' rates (the paper's modified Newmark)
 * is a ContactDynamics, which reads the pairs from here.
 *
 * The pairs live on the contact border (ContactBorder, border()): their nodes are the border's
 * nodes, whose DoFs index border vectors, and every pair-level query (gap(), the contact forces,
 * the constraint rows) takes border vectors, and so do the configuration updates
 * (update_geometry(), update_master_points(), update_active_set(), contact_pressures()): the
 * border also holds every node of the contact geometry's surfaces, which those read. The caller
 * gathers the border displacement from its volume vector (ContactBorder::gather(), collective for
 * a distributed one) once per configuration.
 *
 * Every candidate owns its multipliers (multiplier_block(): one per pair, the normal constraint),
 * so the sparsity pattern never changes; an inactive pair gets the trivial row lambda = 0. The
 * Lagrange multiplier formulation enforces g = 0 on the active pairs; the penalty formulation is
 * the same system with -1/eps on the multiplier diagonal (lambda = -eps g, i.e. the classical
 * penalty force eps <-g>). Active set: a pair enters when it penetrates and leaves when its
 * multiplier turns tensile (Hughes et al. 1976) and, on a surface with Lagrange multipliers, the
 * contact pressure at its node is not compressive either (see update_active_set()).
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
  /**
   * Pairs with fixed normals (bars, a rigid wall), their nodes given in the volume numbering; the
   * border is their nodes.
   */
  ContactConstraints(std::vector<ContactPair<dim>> pairs, ContactFormulation formulation);

  /**
   * The `geometry`'s pairs as below, each with its friction coefficient [-] (>= 0; one per pair:
   * CoulombFriction). A pair with friction owns dim multipliers, the normal one first.
   */
  ContactConstraints(const ContactGeometry<dim>& geometry,
                     ContactFormulation formulation,
                     std::vector<double> friction_coefficients);

  /**
   * The pairs of `geometry`, which follow the current configuration (update_geometry()); the
   * border is every node a pair may couple (ContactGeometry::coupled_nodes()) and every node of
   * the geometry's surfaces (ContactGeometry::surface_nodes()). The geometry must
   * have at least one pair and finite normals (its constructor's InputError sees to it;
   * AssertThrow otherwise).
   */
  ContactConstraints(const ContactGeometry<dim>& geometry, ContactFormulation formulation);

  /**
   * For pairs of a ContactGeometry: moves every pair to `displacement` (a border vector;
   * ContactGeometry::update_pairs()); fixed pairs stay. With friction, a step starts here: the
   * pairs' nodes, weights and tangent bases and the multipliers are those the step's slip is
   * measured from (CoulombFriction::start_step()).
   */
  void update_geometry(const Vector<double>& displacement);

  /** Whether any pair has friction (the saddle-point matrix is then unsymmetric). */
  bool has_friction() const { return friction.any(); }

  /** The friction coefficient of candidate `pair` [-] (0: frictionless). */
  double friction_coefficient(unsigned int pair) const
  {
    return friction.any() ? friction.coefficient(pair) : 0.;
  }

  /**
   * The border DoFs held at zero (one flag per border DoF: a symmetry plane, the axis): a
   * tangential direction that only they could move carries no friction multiplier.
   */
  void set_fixed_dofs(std::vector<bool> fixed) { friction.set_fixed_dofs(std::move(fixed)); }

  /**
   * The border DoFs whose motion a Dirichlet boundary prescribes (per border DoF), for
   * first_prescribed_active_pair().
   */
  void set_prescribed_dofs(std::vector<bool> prescribed)
  {
    prescribed_dofs = std::move(prescribed);
  }

  /**
   * The first active pair with a prescribed DoF (set_prescribed_dofs()) that its contact force
   * would act on, or n_pairs() if none: at a node it weighs (|c_j| > 1e-8), a prescribed DoF
   * along which the normal has a component (n_d^2 > 1e-6), or, for a master node of a pair with
   * friction, any prescribed DoF. Such a pair is not supported: the reaction there would carry
   * its contact force into the external work, and its constraint could lack the DoF that moves
   * it. A slave node prescribed exactly across the normal (a block's corner pushed along the
   * plane it rests on) is fine: its normal DoF stays free, and a prescribed tangential direction
   * of a slave node carries no friction, as a fixed one.
   */
  unsigned int first_prescribed_active_pair() const;

  /**
   * Whether candidate `pair` slides: active, with friction, on the slip branch of Coulomb's law
   * (CoulombFriction).
   */
  bool is_sliding(unsigned int pair) const
  {
    return active[pair] && friction.states()[pair] != 0 &&
           !friction.friction_directions(pair).empty();
  }

  /**
   * The unit tangents along which candidate `pair` is stuck: active, with friction, on the stick
   * branch (its tangent basis of the step's start, less the directions of fixed DoFs); empty
   * otherwise. Across them the whole relative motion is constrained, as the normal one is.
   */
  std::vector<Tensor<1, dim>> stick_directions(unsigned int pair) const
  {
    return active[pair] && friction.states()[pair] == 0 ? friction.friction_directions(pair)
                                                        : std::vector<Tensor<1, dim>>();
  }

  /**
   * The energy friction dissipated over the step that started at the last update_geometry(), at
   * the border displacement `displacement` [energy]: minus the work of the tangential forces
   * weighted as the integrator weighs the step's old and new forces (`new_weight`, the new one's;
   * CoulombFriction::dissipation()); 0 without friction.
   */
  double frictional_dissipation(const Vector<double>& displacement, double new_weight) const;

  /**
   * The active set with the friction branches, per pair: 0 inactive, 2 active and stuck (or
   * frictionless), 1 or 3 sliding (the 2D slip direction); what a Newton tangent depends on.
   */
  std::vector<signed char> active_set() const;

  /**
   * For pairs of a ContactGeometry: moves every pair's master point to `displacement` (a border
   * vector), and with `move_normals` (unless set_turning_normals(false)) a node-to-segment pair's
   * normal to its master face's there (ContactGeometry::update_master_points(); the Newton solver
   * calls it at every iterate). Does nothing for fixed pairs.
   */
  void update_master_points(const Vector<double>& displacement, bool move_normals);

  /**
   * Whether update_master_points() may turn normals: the geometry can
   * (ContactGeometry::moves_normals()) and set_turning_normals() did not forbid it.
   */
  bool moves_normals() const
  {
    return turning_normals && geometry != nullptr && geometry->moves_normals();
  }

  /**
   * `turn` false holds every pair's normal over a step at its value of the step's start
   * (update_geometry()), whatever update_master_points() is asked: what a contact-dynamics
   * treatment asks for when its energy argument needs the pair's gradient held over the step
   * (ContactDynamics::turns_normals()). True (the default): normals may turn.
   */
  void set_turning_normals(const bool turn) { turning_normals = turn; }

  unsigned int n_pairs() const { return pairs.size(); }
  /** The contact nodes the pairs live on. */
  const ContactBorder<dim>& border() const { return contact_border; }
  /** The layout of the pairs' multipliers. */
  const MultiplierBlock& multiplier_block() const { return block; }
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
  /** The candidate pairs, their nodes on the border (node(), border DoFs). */
  const std::vector<ContactPair<dim>>& candidate_pairs() const { return pairs; }
  unsigned int n_active() const;
  bool is_active(unsigned int pair) const { return active[pair]; }

  /** The active set and multipliers, to be restored if a Newton step is taken back. */
  struct State
  {
    std::vector<bool> active;
    Vector<double> multipliers;
    std::vector<signed char> slip_states; ///< CoulombFriction::states()
    std::vector<double> friction_bases;   ///< CoulombFriction::bases(), those of the multipliers
  };
  State state() const { return {active, multiplier_values, friction.states(), friction.bases()}; }
  void restore(const State& saved)
  {
    active            = saved.active;
    multiplier_values = saved.multipliers;
    friction.set_states(saved.slip_states);
    friction.set_bases(saved.friction_bases);
  }

  /** Gap of candidate `pair` at the border displacement u (negative = penetration) [length]. */
  double gap(unsigned int pair, const Vector<double>& displacement) const;

  /**
   * The pairs `held` (one flag per candidate pair; empty: none, the impenetrability condition and
   * the default) hold their gap of the configuration `reference` (a border vector, u_n): the
   * solve enforces g_k(u) - g_k(reference) >= 0 (equal on the active pairs) instead of
   * g_k(u) >= 0, both gaps measured by the pair as it is at u, its master point and normal
   * included. A gap-rate (persistency) treatment holds the step's persisting pairs, so that the
   * constraint reads g_{n+1} - g_n >= 0 (Persistency). Throws std::invalid_argument for a wrong
   * length.
   */
  void hold_gaps(const Vector<double>& reference, std::vector<bool> held);

  /**
   * Calls f(multiplier, dof) for every volume DoF the multipliers of a candidate pair can couple
   * to during the run (with a contact geometry every node of the contact surfaces a pair may
   * project on): the pattern of the constraint rows, besides each multiplier's diagonal.
   */
  template <typename Function>
  void for_each_coupling(const Function& f) const
  {
    for (unsigned int k = 0; k < pairs.size(); ++k)
      for (const unsigned int node : coupled_nodes[k])
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int c = 0; c < block.n_components(k); ++c)
            f(block.index(k, c), contact_border.volume_node(node).dofs[d]);
  }

  /**
   * The volume DoFs the pairs couple to (for_each_coupling()), as `n_dofs` flags: not the border's
   * surface nodes that no pair couples to.
   */
  std::vector<bool> contact_dofs(types::global_dof_index n_dofs) const;

  /**
   * Adds the contact forces G^T lambda on the bodies to the border vector `force`, the tangential
   * ones of pairs with friction included.
   */
  void add_contact_forces(Vector<double>& force) const;

  /**
   * Writes the constraint rows of the Newton system into `rows` (symmetric) and their residuals
   * into `constraint_residual` (one per multiplier) at the border displacement `displacement`: -g
   * (Lagrange) or -g - lambda/eps (penalty) for active pairs, lambda for inactive ones with
   * diagonal `inactive_diagonal`; a penalty pair's row is -g - f lambda / eps, f the force per
   * multiplier, so that its force f lambda is eps <-g>. A pair with friction adds its tangential
   * rows (CoulombFriction::assemble_rows(); a sliding pair's are not symmetric). The update is
   * (delta u, delta lambda) = matrix^{-1} (-residual). A null `rows` computes the residuals only
   * (ranks that do not own the constraint rows).
   */
  void assemble_constraint_rows(const Vector<double>& displacement,
                                double inactive_diagonal,
                                MultiplierRows* rows,
                                Vector<double>& constraint_residual) const;

  /** Adds a Newton increment of the multipliers (one entry per multiplier, MultiplierBlock). */
  void add_multiplier_increment(const Vector<double>& increment);

  /**
   * Updates the active set at the border displacement u: inactive pairs with g < -gap_tolerance
   * enter, active pairs with lambda < -force_tolerance leave (their multiplier is reset to zero),
   * except, for surface pairs with Lagrange multipliers, those whose contact pressure
   * (contact_pressures()) is still compressive: a node whose consistent share of a compressive
   * pressure is zero or negative (the axis node of an axisymmetric Q2 surface has zero tributary
   * area) may carry a slightly tensile multiplier while its surroundings are pressed together;
   * not a pair that carries friction (CoulombFriction::friction_directions() not empty), which
   * leaves at a tensile multiplier whatever its pressure (Coulomb's nodal law has no stick branch
   * there: doc/method.md section 7, "What carries friction"). Then decides stick or slip for the
   * active pairs with friction (CoulombFriction::update_states() with `force_tolerance`). Returns
   * whether anything changed.
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
    return active[pair] ? force_factor * multiplier_values[block.index(pair)] : 0.;
  }

  /**
   * The contact pressure at every pair [force/area] (see ContactGeometry::contact_pressures()) at
   * the border displacement `displacement` from the pair forces (pair_force()); empty for pairs
   * with fixed normals.
   */
  std::vector<double> contact_pressures(const Vector<double>& displacement) const;

  /**
   * The friction force on the slave node (body A) of candidate `pair` [force], a vector in its
   * tangent plane: minus its tangential multipliers along their tangents (the slave's coefficient
   * in the slip is -1) times the force per multiplier if it is active, else zero (and zero
   * without friction). The master side carries the opposite force.
   */
  Tensor<1, dim> tangential_force(unsigned int pair) const
  {
    return active[pair] && friction.any()
               ? -force_factor * friction.tangential_force(pair, multiplier_values, block)
               : Tensor<1, dim>();
  }

  /**
   * Component `component` of the shear traction at every pair [force/area], recovered from the
   * tangential forces (tangential_force()) as contact_pressures() is from the normal ones, on the
   * support of that component's forces: where the component vanishes at a node of the contact
   * zone (a symmetry plane's normal direction) its zone is smaller than the pressure's. Empty for
   * pairs with fixed normals.
   */
  std::vector<double> shear_tractions(const Vector<double>& displacement,
                                      unsigned int component) const;

private:
  /** ContactGeometry::contact_pressures() of the per-pair `forces` at `displacement`. */
  std::vector<double> pressures_of(const Vector<double>& displacement,
                                   const std::vector<double>& forces) const;

  /** g_k(u) - g_k(reference) or g_k(u): what the solve constrains (see hold_gaps()). */
  double constraint_gap(unsigned int pair, const Vector<double>& displacement) const;

  /**
   * Builds the border from `nodes_of_pairs` (per pair, volume nodes) and `surface_nodes` (the
   * geometry's, volume nodes), and the border pairs.
   */
  void build_border(const std::vector<std::vector<Node<dim>>>& nodes_of_pairs,
                    const std::vector<Node<dim>>& surface_nodes = {});

  /** `pairs` = `volume_pairs` with their nodes on the border. */
  void move_pairs_to_border();

  /** The pairs with their nodes in the volume numbering: what the geometry updates. */
  std::vector<ContactPair<dim>> volume_pairs;
  /**
   * The same pairs on the border, derived from volume_pairs by move_pairs_to_border(): a change
   * made to these alone is lost at the next update; change volume_pairs and derive them again.
   */
  std::vector<ContactPair<dim>> pairs;
  ContactBorder<dim> contact_border;
  /** Per pair: the contact nodes its rows may couple to over the run. */
  std::vector<std::vector<unsigned int>> coupled_nodes;
  MultiplierBlock block;
  const ContactGeometry<dim>* geometry = nullptr; ///< null: fixed pairs
  ContactFormulation formulation;
  std::vector<bool> active;
  Vector<double> multiplier_values;
  std::vector<bool> held_gaps;  ///< hold_gaps(): empty, none
  Vector<double> gap_reference; ///< hold_gaps(): the configuration whose gaps are held
  CoulombFriction<dim> friction;
  double force_factor = 1.;          ///< see set_force_per_multiplier()
  std::vector<bool> prescribed_dofs; ///< see set_prescribed_dofs(); empty: none
  bool turning_normals = true;       ///< see set_turning_normals()
};
} // namespace dyncontact
