#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact_dynamics/contact_dynamics.h>
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/postprocess/body_impulses.h>
#include <dyncontact/postprocess/contact_fields.h>
#include <dyncontact/solver/contact_newton_solver.h>
#include <dyncontact/time_integration/generalized_alpha.h>
#include <dyncontact/time_integration/implicit_stepper.h>

#include <deal.II/base/tensor.h>

#include <vector>

namespace dyncontact
{
/** The length of Measures' vectors: every dimension's components fit. */
constexpr int max_dimension = 3;

/** What history.csv, the guards and the log read about one state. */
struct Measures
{
  double kinetic_energy = 0., strain_energy = 0., acceleration_energy = 0.; ///< [energy]
  double algorithmic_energy = 0.; ///< GeneralizedAlpha::algorithmic_energy() of the three
  double contact_force      = 0.; ///< recovered from the balance the step solved [force]
  double force_imbalance    = 0.; ///< body A's recovered force minus body B's [force]
  double velocity_jump = 0., acceleration_jump = 0.; ///< largest normal jump across active pairs
  /// the largest tangential jump across stuck pairs (friction)
  double stick_velocity_jump = 0., stick_acceleration_jump = 0.;
  std::vector<double> momenta;         ///< per body, along the impact direction
  std::vector<double> momentum_tracks; ///< per track of BodyImpulses (a body along a direction)
  double momentum_magnitude = 0.;      ///< sum of |m v| over every DoF
  Tensor<1, max_dimension> momentum;   ///< of all bodies, components x, y (, z) [mass length/time]
  /// of all bodies about their common centre of mass, sum of m (x - x_c) x v over the nodes at
  /// their current positions x [mass length^2/time]; 3D only (zero otherwise)
  Tensor<1, max_dimension> angular_momentum;
  /// per body, its momentum's components x, y, z [mass length/time]; 3D only (empty otherwise)
  std::vector<Tensor<1, max_dimension>> body_momenta;
};

/**
 * The measures of the stepper's current state: energies, the contact force recovered from the
 * balance the last step solved (M a + Q - W on the contact nodes, times the treatment's contact
 * force factor), the force imbalance between the bodies, the normal rate jumps across the active
 * pairs (Taylor & Papadopoulos 1993, eqs. 19-20) and the bodies' momenta. Everything it reads is
 * the caller's and must outlive it.
 */
template <int dim>
class StepMeasures
{
public:
  StepMeasures(const GeneralizedAlpha& integrator,
               const Vector<double>& lumped_mass,
               const ElasticBodies<dim>& bodies,
               const ContactNewtonSolver<dim>& solver,
               const ContactConstraints<dim>& contact,
               const ContactDynamics<dim>& dynamics,
               const ImplicitStepper<dim>& stepper,
               const BodyImpulses<dim>& body_impulses,
               const Tensor<1, dim>& impact_direction,
               const std::vector<Node<dim>>& nodes);

  /**
   * The measures of the current state; `after_a_step` false for the initial state (no balance
   * solved yet: the contact force and the jumps are zero, the strain energy is evaluated).
   * Collective: the sums over DoFs are summed over the ranks.
   */
  Measures measure(bool after_a_step) const;

private:
  const GeneralizedAlpha& integrator;
  const Vector<double>& mass;
  const ElasticBodies<dim>& bodies;
  const ContactNewtonSolver<dim>& solver;
  const ContactFields<dim> fields;
  const bool
      contact_has_friction; ///< the stick jumps are measured (ContactFields::max_stick_jump())
  const ContactDynamics<dim>& dynamics;
  const ImplicitStepper<dim>& stepper;
  const BodyImpulses<dim>& body_impulses;
  const Tensor<1, dim> impact_direction;
  /// this rank's nodes (NodeIndex::nodes()): those whose DoFs it owns carry the momenta
  const std::vector<Node<dim>>& nodes;

  /**
   * Measures::momentum and, in 3D, angular_momentum of `state`. Collective.
   */
  void measure_momentum(const StepState& state, Measures& measures) const;
};
} // namespace dyncontact
