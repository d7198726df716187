#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/time_integration/generalized_alpha.h>
#include <dyncontact/time_integration/step_state.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{
/**
 * The momentum bookkeeping of a run, per body along the impact direction: the forces that change
 * each body's momentum at the current state, their impulses since t = 0 (all forces, and the
 * contact forces alone), the work of the external forces, and the momentum balance of a step's
 * increment. What the momentum guard, history.csv (impulse_<b>) and impact_summary.csv read.
 * Vectors are over the displacement DoFs (the state's: each rank its owned DoFs, the sums over
 * all ranks: the functions that read them are collective); forces [force], impulses
 * [force time], work [energy].
 * The integrator, lumped mass, contact and fixed flags are the caller's and must outlive it.
 */
template <int dim>
class BodyImpulses
{
public:
  /** Per body, along the impact direction: all forces, and the contact part alone [force]. */
  struct Forces
  {
    std::vector<double> total, contact;
  };

  /** The accumulated state: what a failed step returns to and a checkpoint keeps. */
  struct Ledger
  {
    Forces forces; ///< forces() at the current state
    std::vector<double> impulses, contact_impulses;
    double external_work = 0.;

    template <class Archive>
    void serialize(Archive& archive, const unsigned int /*version*/)
    {
      archive& forces.total;
      archive& forces.contact;
      archive& impulses;
      archive& contact_impulses;
      archive& external_work;
    }
  };

  BodyImpulses(const GeneralizedAlpha& integrator,
               const Vector<double>& lumped_mass,
               const std::vector<bool>& is_fixed_dof,
               const ContactConstraints<dim>& contact);

  /**
   * The per-DoF tables: the body of each DoF (from `nodes`), the component of the unit vector of
   * its direction along `impact_direction`, and whether it belongs to a node of a candidate pair.
   */
  void index(const std::vector<Node<dim>>& nodes,
             const Tensor<1, dim>& impact_direction,
             unsigned int n_bodies);

  /** The forces at `state` (the initial one), zero impulses and work. */
  void start(const StepState& state);

  /**
   * Per body, the force along the impact direction on the nodes of its active pairs and fixed
   * DoFs (M a + Q - W) plus its total external force, at `state`: with sum Q = 0 over a free body
   * this is the total force that changes its momentum, up to the Newton residual of its other
   * nodes. The contact part leaves out the external forces and the supports (fixed DoFs).
   * `initial`: `state` is the initial one, not solved, whose massless DoFs (mass redistribution)
   * may be out of balance (W != Q(u_0)); their Q - W then counts too.
   */
  Forces forces(const StepState& state, bool initial = false) const;

  /**
   * Adds the impulses of the step from `before` (its state and ledger) to `state`
   * (Newmark-weighted forces plus rate corrections), total and contact, and the external work;
   * `step_load` is W(t_{n+1-alpha_f}) of a dissipative member, empty for Newmark.
   */
  void accumulate(const StepState& before,
                  const Ledger& before_ledger,
                  const StepState& state,
                  const DistributedVector& step_load);

  /**
   * Removes from the converged `increment` the momentum error of each body: a rigid translation
   * along the impact direction cancels the body's Newton `residual` summed along it over the DoFs
   * that carry no contact force (the inertia term of the residual is `inertia_factor` M).
   */
  void balance_momenta(DistributedVector& increment,
                       const DistributedVector& residual,
                       double inertia_factor) const;

  /** Per body, the momentum along the impact direction of `velocity` [mass length/time]. */
  std::vector<double> momenta(const DistributedVector& velocity) const;

  const Ledger& ledger() const { return accumulated; }
  Ledger& ledger() { return accumulated; }

private:
  /** Per DoF: whether it belongs to a node of an active pair (at the current state). */
  std::vector<bool> active_pair_dofs() const;

  const GeneralizedAlpha& integrator;
  const Vector<double>& mass;
  const std::vector<bool>& is_fixed_dof;
  const ContactConstraints<dim>& contact;
  unsigned int n_bodies = 0;
  std::vector<unsigned int> dof_body;
  std::vector<double> dof_direction;
  std::vector<bool> is_contact_dof;
  Ledger accumulated;
};
} // namespace dyncontact
