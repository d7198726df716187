#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact_dynamics/contact_dynamics.h>
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/discretization/external_loads.h>
#include <dyncontact/discretization/prescribed_displacements.h>
#include <dyncontact/solver/contact_newton_solver.h>
#include <dyncontact/time_integration/generalized_alpha.h>
#include <dyncontact/time_integration/step_state.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{
/**
 * One implicit step of the generalized-alpha family with contact, from a StepState at t_n to the
 * one at t_{n+1}, in two phases around the caller's correction of the increment (Simulation
 * removes the bodies' momentum error there):
 *  - solve(): the pairs of u_n, Newmark's predictor (eq. 11 of Taylor & Papadopoulos 1993)
 *    adjusted by the contact-dynamics treatment, the treatment's reference gaps, the load, and the
 *    Newton solve of the balance (at t_{n+1}, or at t_{n+1-alpha_f} for a dissipative member);
 *  - finish(): u_{n+1} = predictor + increment, the integrator's rates (eq. 12) and the
 *    treatment's rate correction (eqs. 19-24 for the paper's scheme).
 * The treatment sees the contact nodes only: the stepper gathers the states it reads onto the
 * contact border (ContactBorder) and writes back what it changes. It owns the current StepState,
 * whose vectors, like the predictor and the increment, hold each rank's owned DoFs (the layout of
 * the solver's dof_layout()); the contact geometry of u_n is updated from its displacement on the
 * contact border. The integrator, lumped mass (whole), fixed DoFs, prescribed displacements,
 * loads, contact, its treatment and the Newton solver are the caller's and must outlive it. Every
 * member function is collective.
 */
template <int dim>
class ImplicitStepper
{
public:
  ImplicitStepper(const GeneralizedAlpha& integrator,
                  const Vector<double>& lumped_mass,
                  const std::vector<bool>& is_fixed_dof,
                  const PrescribedDisplacements<dim>& prescribed,
                  const ExternalLoads<dim>& loads,
                  ContactConstraints<dim>& contact,
                  const ContactDynamics<dim>& dynamics,
                  ContactNewtonSolver<dim>& solver);

  /**
   * The initial state: u_0 = 0, `initial_velocity` (whole, n_dofs), Q(u_0) of `bodies`, W(0) and
   * the acceleration of equilibrium M a_0 = W(0) - Q(u_0) (no contact at t = 0); v_0 and a_0 zero
   * at fixed DoFs, dg/dt and d2g/dt2 at prescribed ones (Dirichlet boundaries), a_0 zero at
   * massless DoFs (Contact/dynamics = mass-redistribution), whose rates carry no momentum.
   */
  void start(const Vector<double>& initial_velocity, const ElasticBodies<dim>& bodies);

  /** The state at the last completed step (or the initial one). */
  const StepState& state() const { return current; }
  StepState& state() { return current; }

  /**
   * Solves the step from `before` to `time` at the integrator's step size: sets the state's
   * internal force Q and external force W(`time`) and the increment over the predictor
   * (`increment`, owned DoFs; at prescribed DoFs g(`time`) minus the predictor). Returns the linear
   * solves; throws SolverFailure. Collective.
   */
  unsigned int solve(const StepState& before, double time, DistributedVector& increment);

  /**
   * After solve() and the caller's correction of `increment`: the displacement, velocity and
   * acceleration of the state at the step's end, the treatment's rate correction applied.
   */
  void finish(const StepState& before, const DistributedVector& increment);

  /**
   * The balance the last step solved, M a + (Q - W) = contact force: its acceleration and net
   * force (Q - W) at t_{n+1} for Newmark, at the intermediate times of a dissipative member
   * (a_{n+1-alpha_m}, Q_{n+1-alpha_f} - W(t_{n+1-alpha_f})). Valid after finish().
   */
  void solved_balance(DistributedVector& acceleration, DistributedVector& net_force) const;

  /** W(t_{n+1-alpha_f}) of the last step for a dissipative member; empty for Newmark. */
  const DistributedVector& step_load() const { return load_at_balance; }

private:
  const GeneralizedAlpha& integrator;
  const Vector<double>& mass;
  const std::vector<bool>& is_fixed_dof;
  const PrescribedDisplacements<dim>& prescribed;
  const ExternalLoads<dim>& loads;
  ContactConstraints<dim>& contact;
  const ContactDynamics<dim>& dynamics;
  ContactNewtonSolver<dim>& solver;
  /**
   * The lumped mass and fixed flags of the contact nodes (border vectors), gathered at
   * construction: the lumped mass must be final by then (mass redistribution sets it first).
   */
  const Vector<double> border_mass;
  const std::vector<bool> border_fixed;
  StepState current;
  /** The step's predictor, and the acceleration at t_n it used (a treatment may replace a_n). */
  DistributedVector predictor, start_acceleration;
  /**
   * For a dissipative member, the old state's parts of the last step's balance: a_n as the step
   * used it, and alpha_f Q(u_n) - W(t_{n+1-alpha_f}); and that load. Empty for Newmark.
   */
  DistributedVector old_balance_acceleration, old_balance_net_force, load_at_balance;
};
} // namespace dyncontact
