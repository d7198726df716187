#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact_dynamics/contact_dynamics_kind.h>
#include <dyncontact/time_integration/rate_map.h>

#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace dyncontact
{
/**
 * How the time integration treats the rates of the contact nodes: the family of fixes for the
 * velocity and acceleration jumps that implicit time stepping produces at contact events
 * (Contact/dynamics). A treatment sees the integrator only through a RateMap and the contact
 * layer only through its active pairs; every vector it gets is a border vector (ContactBorder: dim
 * entries per contact node, the DoFs the pairs' nodes carry), gathered from the volume by the
 * stepper, which writes back what the treatment changes. Adding one is its own file, its enumerator
 * and name in contact_dynamics_kind.h / contact_dynamics_names(), its case in
 * create_contact_dynamics(), and its unit test; nothing else changes (not Simulation, not the
 * parameters).
 */
template <int dim>
class ContactDynamics
{
public:
  virtual ~ContactDynamics() = default;

  /**
   * Whether the nodes that can come into contact carry no mass (MassRedistribution): Simulation
   * then builds the lumped mass with ContactConstraints::contact_dofs() massless. False by default.
   */
  virtual bool contact_nodes_massless() const { return false; }

  /**
   * The contact force at t_{n+1} per unit of the recovered one, M a_{n+1} + Q - W at the pairs'
   * nodes (which equals G^T lambda_{n+1}): 1 by default; gamma for ContactStabilizedNewmark, whose
   * step carries the contact impulse dt gamma G^T lambda_{n+1} alone.
   */
  virtual double contact_force_factor(const RateMap& /*rates*/) const { return 1.; }

  /**
   * Whether a pair's normal may turn with its master face within a step (node-to-segment pairs
   * and mortar's projected fallback pairs; ContactConstraints::set_turning_normals()). True by
   * default: a step whose contact force is the trapezoidal average of the old and new ones
   * (lambda_n G_n and lambda_{n+1} G_{n+1}) does work on a sliding pair unless its normal follows
   * the face (held normals: 3.9e-4 of the energy gained on the coarse oblique spheres,
   * turned: 6.7e-6). ImplicitContactImpulse treatments other than Persistency hold the normals:
   * their one force per step, gamma G^T lambda_{n+1}, does the work gamma lambda_{n+1} (g_{n+1} -
   * g_n), and g_n measured by a turned pair is not the closed gap of u_n (turned: an energy swing
   * of 4.5e-4 on the same case, held: 1.8e-5).
   */
  virtual bool turns_normals() const { return true; }

  /**
   * Whether the treatment handles pairs with Coulomb friction (CoulombFriction) in its own
   * paper's way; a run with friction refuses a treatment that does not. False by default: a
   * treatment that corrects the normal rates only would leave the tangential ones of a stuck pair
   * with their jumps, and its energy argument does not cover the tangential forces.
   */
  virtual bool carries_friction() const { return false; }

  /** The state at t_n a treatment may start a step from (border vectors). */
  struct StepStart
  {
    const Vector<double>& displacement;   ///< u_n [length]
    const Vector<double>& velocity;       ///< v_n [length/time]
    const Vector<double>& internal_force; ///< Q(u_n) [force]
    const Vector<double>& external_force; ///< W(t_n) [force]
    const std::vector<bool>& is_fixed;    ///< per DoF: fixed (e.g. u_r = 0 on an axis)
  };

  /**
   * Before the step's solve (ContactStabilizedNewmark): may change the Newmark predictor u~
   * (`predictor`, from u_n, v_n and `old_acceleration` = a_n on entry) and the acceleration at t_n
   * the step uses in its predictor and velocity update (`old_acceleration`, in and out), neither at
   * a fixed DoF. The contact layer holds the pairs of u_n and the multipliers of t_n. Does nothing
   * by default.
   */
  virtual void adjust_predictor(const RateMap& /*rates*/,
                                const ContactConstraints<dim>& /*contact*/,
                                const Vector<double>& /*lumped_mass*/,
                                const StepStart& /*start*/,
                                Vector<double>& /*old_acceleration*/,
                                Vector<double>& /*predictor*/) const
  {
  }

  /**
   * Before the step's solve, after adjust_predictor(): per candidate pair, whether its constraint
   * holds its gap of u_n in this step instead of g_{n+1} >= 0 (ContactConstraints::hold_gaps();
   * `predictor` is the adjusted one). Empty, the impenetrability condition for every pair, by
   * default; Persistency flags the pairs that persist.
   */
  virtual std::vector<bool> persistent_pairs(const ContactConstraints<dim>& /*contact*/,
                                             const Vector<double>& /*predictor*/) const
  {
    return {};
  }

  /**
   * After a converged step (classical rates v_new, a_new at every DoF, from the increment of
   * `step`): may correct the rates of the DoFs of the active pairs of `contact`. `lumped_mass` is
   * per DoF [mass]; all vectors are border vectors. Keeps the classical rates by default.
   */
  virtual void correct_rates(const RateMap& /*rates*/,
                             const ContactConstraints<dim>& /*contact*/,
                             const Vector<double>& /*lumped_mass*/,
                             const StepStates& /*step*/,
                             Vector<double>& /*v_new*/,
                             Vector<double>& /*a_new*/) const
  {
  }
};

/** The treatment `kind` of Contact/dynamics. */
template <int dim>
std::unique_ptr<ContactDynamics<dim>> create_contact_dynamics(ContactDynamicsKind kind);
} // namespace dyncontact
