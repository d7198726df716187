#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/sum_over_ranks.h>
#include <dyncontact/postprocess/step_measures.h>

#include <cmath>

namespace dyncontact
{
template <int dim>
StepMeasures<dim>::StepMeasures(const GeneralizedAlpha& integrator,
                                const Vector<double>& lumped_mass,
                                const ElasticBodies<dim>& bodies,
                                const ContactNewtonSolver<dim>& solver,
                                const ContactConstraints<dim>& contact,
                                const ContactDynamics<dim>& dynamics,
                                const ImplicitStepper<dim>& stepper,
                                const BodyImpulses<dim>& body_impulses,
                                const Tensor<1, dim>& impact_direction)
    : integrator(integrator), mass(lumped_mass), bodies(bodies), solver(solver), fields(contact),
      dynamics(dynamics), stepper(stepper), body_impulses(body_impulses),
      impact_direction(impact_direction)
{
}

template <int dim>
Measures StepMeasures<dim>::measure(const bool after_a_step) const
{
  const StepState& state            = stepper.state();
  const DistributedVector &velocity = state.velocity, &acceleration = state.acceleration;
  const MPI_Comm communicator = velocity.get_mpi_communicator();
  Measures measures{};
  for_each_owned_row(velocity,
                     [&](const types::global_dof_index i, const unsigned int j)
                     {
                       const double v = velocity.local_element(j),
                                    a = acceleration.local_element(j);
                       measures.kinetic_energy += 0.5 * mass[i] * v * v;
                       measures.acceleration_energy += 0.5 * mass[i] * a * a;
                       measures.momentum_magnitude += mass[i] * std::abs(v);
                     });
  std::vector<double> sums = {
      measures.kinetic_energy, measures.acceleration_energy, measures.momentum_magnitude};
  sum_over_ranks(sums, communicator); // one reduction for the three
  measures.kinetic_energy      = sums[0];
  measures.acceleration_energy = sums[1];
  measures.momentum_magnitude  = sums[2];
  // After a step the solver's last evaluation was at this displacement: reuse its pass.
  measures.strain_energy =
      after_a_step ? solver.strain_energy() : bodies.strain_energy(state.displacement);
  measures.algorithmic_energy = integrator.algorithmic_energy(
      measures.kinetic_energy, measures.strain_energy, measures.acceleration_energy);
  if (after_a_step)
  {
    // The balance the step solved: at t_{n+1} for Newmark, at the intermediate times of a
    // dissipative member (M a_{n+1-alpha_m} + Q_{n+1-alpha_f} - W(t_{n+1-alpha_f})).
    DistributedVector balance_acceleration, net_force;
    stepper.solved_balance(balance_acceleration, net_force);
    const double force_factor = dynamics.contact_force_factor(integrator.rate_map());
    measures.contact_force =
        force_factor * fields.recovered_contact_force(mass, balance_acceleration, net_force);
    const auto side_forces =
        fields.recovered_side_forces(mass, balance_acceleration, net_force, impact_direction);
    measures.force_imbalance   = force_factor * (side_forces.on_a - side_forces.on_b);
    measures.velocity_jump     = fields.max_active_normal_jump(velocity);
    measures.acceleration_jump = fields.max_active_normal_jump(acceleration);
  }
  measures.momenta = body_impulses.momenta(velocity);
  return measures;
}

DYNCONTACT_INSTANTIATE_CLASS(StepMeasures)
} // namespace dyncontact
