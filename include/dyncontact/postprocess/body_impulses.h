#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/time_integration/generalized_alpha.h>
#include <dyncontact/time_integration/step_state.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace dyncontact
{
/**
 * The momentum bookkeeping of a run, per body along each of the model's momentum directions
 * (ProblemModel::momentum_directions(): orthonormal; a plane-strain or 3D model's Cartesian axes,
 * an axisymmetric model's axis, a bar's x): the forces that change each body's momentum at the
 * current state, their impulses since t = 0 (all forces, and the contact forces alone), the work
 * of the external forces, and the momentum balance of a step's increment. A body along one
 * direction is a track, t = b * n_directions + k (body b, direction k); the per-track vectors have
 * n_tracks() entries. The momentum guard reads every track; history.csv (impulse_<b>) and
 * impact_summary.csv read their projections on the impact direction (along_impact()).
 * Vectors are over the displacement DoFs (the state's: each rank its owned DoFs, the sums over
 * all ranks: the functions that read them are collective); forces [force], impulses
 * [force time], work [energy].
 * The integrator, lumped mass, contact and fixed flags are the caller's and must outlive it.
 */
template <int dim>
class BodyImpulses
{
public:
  /** Per track: all forces, and the contact part alone [force]. */
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
    /// the energy friction dissipated since t = 0 (ContactConstraints::frictional_dissipation())
    double frictional_dissipation = 0.;

    template <class Archive>
    void serialize(Archive& archive, const unsigned int /*version*/)
    {
      archive& forces.total;
      archive& forces.contact;
      archive& impulses;
      archive& contact_impulses;
      archive& external_work;
      archive& frictional_dissipation;
    }
  };

  BodyImpulses(const GeneralizedAlpha& integrator,
               const Vector<double>& lumped_mass,
               const std::vector<bool>& is_fixed_dof,
               const ContactConstraints<dim>& contact);

  /**
   * The per-DoF tables: the body of each DoF (from `nodes`), the components of the unit vector of
   * its direction along each of `directions` (one unit vector, or several Cartesian axes), and
   * whether it belongs to a node of a candidate pair; `impact_direction` (a unit vector in the
   * span of `directions`) for along_impact(); the track names.
   */
  void index(const std::vector<Node<dim>>& nodes,
             const std::vector<Tensor<1, dim>>& directions,
             const Tensor<1, dim>& impact_direction,
             unsigned int n_bodies);

  /** n_bodies times the number of directions. */
  unsigned int n_tracks() const { return n_bodies * directions.size(); }

  /** Per track, what the log calls it: "body b" with one direction, else "body b along x" (y, z).
   */
  const std::vector<std::string>& track_names() const { return names; }

  /** Per body, the projection of a per-track vector on the impact direction. */
  std::vector<double> along_impact(const std::vector<double>& tracks) const;

  /** The forces at `state` (the initial one), zero impulses and work. */
  void start(const StepState& state);

  /**
   * Per track, the force on the nodes of the body's active pairs and fixed DoFs (M a + Q - W)
   * plus its total external force, at `state`: with sum Q = 0 over a free body
   * this is the total force that changes its momentum, up to the Newton residual of its other
   * nodes. The contact part leaves out the external forces and the supports (fixed DoFs).
   * `initial`: `state` is the initial one, not solved, whose massless DoFs (mass redistribution)
   * may be out of balance (W != Q(u_0)); their Q - W then counts too.
   */
  Forces forces(const StepState& state, bool initial = false) const;

  /**
   * Adds the impulses of the step from `before` (its state and ledger) to `state`
   * (Newmark-weighted forces plus rate corrections), total and contact, the external work and
   * the frictional dissipation, its forces weighted as the external ones; `step_load` is
   * W(t_{n+1-alpha_f}) of a dissipative member, empty for Newmark.
   */
  void accumulate(const StepState& before,
                  const Ledger& before_ledger,
                  const StepState& state,
                  const DistributedVector& step_load);

  /**
   * Removes from the converged `increment` the momentum error of each track: a rigid translation
   * of the body along the direction cancels the body's Newton `residual` summed along it over the
   * DoFs that carry no contact force (the inertia term of the residual is `inertia_factor` M).
   */
  void balance_momenta(DistributedVector& increment,
                       const DistributedVector& residual,
                       double inertia_factor) const;

  /** Per track, the momentum of `velocity` [mass length/time]. */
  std::vector<double> momenta(const DistributedVector& velocity) const;

  const Ledger& ledger() const { return accumulated; }
  Ledger& ledger() { return accumulated; }

private:
  /** Per DoF: whether it belongs to a node of an active pair (at the current state). */
  std::vector<bool> active_pair_dofs() const;

  /** Calls f(track, weight) for each direction along which DoF `i` has a nonzero component. */
  template <class Function>
  void for_each_track(const types::global_dof_index i, const Function& f) const
  {
    for (unsigned int k = 0; k < directions.size(); ++k)
      if (const double weight = dof_weights[i * directions.size() + k]; weight != 0.)
        f(dof_body[i] * directions.size() + k, weight);
  }

  const GeneralizedAlpha& integrator;
  const Vector<double>& mass;
  const std::vector<bool>& is_fixed_dof;
  const ContactConstraints<dim>& contact;
  unsigned int n_bodies = 0;
  std::vector<Tensor<1, dim>> directions;
  std::vector<std::string> names;        ///< per track, track_names()
  std::vector<double> impact_components; ///< per direction, its component along the impact
  std::vector<unsigned int> dof_body;
  /// per DoF and direction (DoF-major), the component of the DoF's unit vector along it
  std::vector<double> dof_weights;
  std::vector<bool> is_contact_dof;
  Ledger accumulated;
};
} // namespace dyncontact
