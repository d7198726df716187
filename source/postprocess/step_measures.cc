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
                                const Tensor<1, dim>& impact_direction,
                                const std::vector<Node<dim>>& nodes)
    : integrator(integrator), mass(lumped_mass), bodies(bodies), solver(solver), fields(contact),
      contact_has_friction(contact.has_friction()), dynamics(dynamics), stepper(stepper),
      body_impulses(body_impulses), impact_direction(impact_direction), nodes(nodes)
{
}

template <int dim>
void StepMeasures<dim>::measure_momentum(const StepState& state, Measures& measures) const
{
  // Sums over the owned nodes: momentum P, mass M, first mass moment S = sum m x and moment of
  // momentum about the origin sum x cross m v (3D); then L about x_c = S / M is that minus
  // x_c cross P.
  std::vector<double> sums(3 * max_dimension + 1, 0.);
  for (const Node<dim>& node : nodes)
  {
    if (!state.velocity.in_local_range(node.dofs[0]))
      continue;
    Tensor<1, max_dimension> position, momentum;
    for (unsigned int d = 0; d < dim; ++d)
    {
      const types::global_dof_index dof = node.dofs[d];
      position[d]                       = node.position[d] + state.displacement(dof);
      momentum[d]                       = mass[dof] * state.velocity(dof);
    }
    const double node_mass                = mass[node.dofs[0]];
    const Tensor<1, max_dimension> moment = cross_product_3d(position, momentum);
    for (unsigned int d = 0; d < max_dimension; ++d)
    {
      sums[d] += momentum[d];
      sums[max_dimension + d] += node_mass * position[d];
      sums[2 * max_dimension + d] += moment[d];
    }
    sums.back() += node_mass;
  }
  sum_over_ranks(sums, state.velocity.get_mpi_communicator());
  Tensor<1, max_dimension> first_moment, moment;
  for (unsigned int d = 0; d < max_dimension; ++d)
  {
    measures.momentum[d] = sums[d];
    first_moment[d]      = sums[max_dimension + d];
    moment[d]            = sums[2 * max_dimension + d];
  }
  if (dim == 3 && sums.back() > 0.)
    measures.angular_momentum =
        moment - cross_product_3d(first_moment / sums.back(), measures.momentum);
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
    if (contact_has_friction)
    {
      measures.stick_velocity_jump     = fields.max_stick_jump(velocity);
      measures.stick_acceleration_jump = fields.max_stick_jump(acceleration);
    }
  }
  measures.momentum_tracks = body_impulses.momenta(velocity);
  measures.momenta         = body_impulses.along_impact(measures.momentum_tracks);
  if (dim == 3) // history.csv has these columns in 3D only
    measure_momentum(state, measures);
  // Each body's components where BodyImpulses' tracks are x, y (and z) of each body: 3D and plane
  // strain (StepRecorder::has_body_momenta()), not an axisymmetric model's axis alone.
  const unsigned int n_bodies = measures.momenta.size();
  AssertThrow(dim != 3 || measures.momentum_tracks.size() == n_bodies * dim,
              ExcMessage("StepMeasures: the momentum directions of a 3D model are x, y and z"));
  if (measures.momentum_tracks.size() == n_bodies * dim)
  {
    measures.body_momenta.resize(n_bodies);
    for (unsigned int b = 0; b < n_bodies; ++b)
      for (unsigned int d = 0; d < dim; ++d)
        measures.body_momenta[b][d] = measures.momentum_tracks[b * dim + d];
  }
  return measures;
}

DYNCONTACT_INSTANTIATE_CLASS(StepMeasures)
} // namespace dyncontact
