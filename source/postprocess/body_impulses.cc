#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/sum_over_ranks.h>
#include <dyncontact/postprocess/body_impulses.h>

#include <algorithm>

namespace dyncontact
{
namespace
{
/**
 * Where this rank's partial sums of running sums `sums` start: from `sums` on the first rank of
 * `communicator`, from zero on the others. Each rank then adds its owned DoFs' terms, and the
 * partial sums added over the ranks continue `sums`; on one rank the additions are those of one
 * loop over all DoFs, in the same order.
 */
std::vector<double> partial_sums_start(const std::vector<double>& sums, const MPI_Comm communicator)
{
  return Utilities::MPI::this_mpi_process(communicator) == 0 ? sums
                                                             : std::vector<double>(sums.size(), 0.);
}
} // namespace

template <int dim>
BodyImpulses<dim>::BodyImpulses(const GeneralizedAlpha& integrator,
                                const Vector<double>& lumped_mass,
                                const std::vector<bool>& is_fixed_dof,
                                const ContactConstraints<dim>& contact)
    : integrator(integrator), mass(lumped_mass), is_fixed_dof(is_fixed_dof), contact(contact)
{
}

template <int dim>
void BodyImpulses<dim>::index(const std::vector<Node<dim>>& nodes,
                              const std::vector<Tensor<1, dim>>& directions,
                              const Tensor<1, dim>& impact_direction,
                              const unsigned int n_bodies)
{
  AssertThrow(!directions.empty(), ExcMessage("BodyImpulses: no momentum direction"));
  this->n_bodies   = n_bodies;
  this->directions = directions;
  impact_components.clear();
  for (const Tensor<1, dim>& direction : directions)
    impact_components.push_back(direction * impact_direction);
  const unsigned int n_directions = directions.size();
  names.clear();
  for (unsigned int b = 0; b < n_bodies; ++b)
    for (const Tensor<1, dim>& direction : directions)
    {
      names.push_back("body " + std::to_string(b + 1));
      if (n_directions == 1)
        continue;
      const auto axis = std::find(direction.begin_raw(), direction.end_raw(), 1.);
      AssertThrow(axis != direction.end_raw(),
                  ExcMessage("BodyImpulses: several momentum directions must be Cartesian axes"));
      names.back() += std::string(" along ") + "xyz"[axis - direction.begin_raw()];
    }
  dof_body.assign(mass.size(), 0);
  dof_weights.assign(mass.size() * n_directions, 0.);
  is_contact_dof.assign(mass.size(), false);
  for (const auto& node : nodes)
    for (unsigned int d = 0; d < dim; ++d)
    {
      dof_body[node.dofs[d]] = node.body;
      for (unsigned int k = 0; k < n_directions; ++k)
        dof_weights[node.dofs[d] * n_directions + k] = directions[k][d];
    }
  for (const auto& pair : contact.candidate_pairs())
    pair.for_each_node(
        [&](const Node<dim>& node, double)
        {
          for (unsigned int d = 0; d < dim; ++d)
            is_contact_dof[contact.border().volume_dof(node.dofs[d])] = true;
        });
}

template <int dim>
std::vector<double> BodyImpulses<dim>::along_impact(const std::vector<double>& tracks) const
{
  AssertDimension(tracks.size(), n_tracks());
  std::vector<double> per_body(n_bodies, 0.);
  for (unsigned int t = 0; t < tracks.size(); ++t)
    per_body[t / directions.size()] += impact_components[t % directions.size()] * tracks[t];
  return per_body;
}

template <int dim>
void BodyImpulses<dim>::start(const StepState& state)
{
  accumulated.forces = forces(state, true);
  accumulated.impulses.assign(n_tracks(), 0.);
  accumulated.contact_impulses.assign(n_tracks(), 0.);
  accumulated.external_work          = 0.;
  accumulated.frictional_dissipation = 0.;
}

template <int dim>
std::vector<bool> BodyImpulses<dim>::active_pair_dofs() const
{
  std::vector<bool> in_active_pair(mass.size(), false);
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    if (contact.is_active(k))
      contact.candidate_pairs()[k].for_each_node(
          [&](const Node<dim>& node, double)
          {
            for (unsigned int d = 0; d < dim; ++d)
              in_active_pair[contact.border().volume_dof(node.dofs[d])] = true;
          });
  return in_active_pair;
}

template <int dim>
typename BodyImpulses<dim>::Forces BodyImpulses<dim>::forces(const StepState& state,
                                                             const bool initial) const
{
  // The nodes of the active pairs carry the contact force and fixed DoFs their support's reaction
  // (a clamped bar end); elsewhere M a + Q - W is only the Newton residual, whose sum over a body
  // balance_momenta() has removed. A dissipative member balances at t_{n+1-alpha_f}, not at
  // t_{n+1}, so there every DoF's M a + Q - W counts (its sum over a body is sum M a - sum W, as
  // sum Q = 0): the momentum guard then checks the treatments' velocity corrections only.
  // A massless DoF (mass redistribution) carries no momentum: the load on it reaches the body only
  // through Q. At a solved state its Q - W is the Newton residual, but at the initial one
  // (`initial`) a load acting from t = 0 (a traction on a contact surface) is not yet in balance
  // with Q(u_0) = 0, and that imbalance counts.
  const std::vector<bool> in_active_pair = active_pair_dofs();
  const bool every_dof                   = integrator.family() != IntegratorFamily::newmark;
  Forces forces{std::vector<double>(n_tracks(), 0.), std::vector<double>(n_tracks(), 0.)};
  for_each_owned_row(state.external_force,
                     [&](const types::global_dof_index i, const unsigned int j)
                     {
                       double force               = state.external_force.local_element(j);
                       const bool carries_contact = every_dof || in_active_pair[i];
                       if (carries_contact || is_fixed_dof[i] || (initial && mass[i] == 0.))
                       {
                         const double balance = mass[i] * state.acceleration.local_element(j) +
                                                state.internal_force.local_element(j) -
                                                state.external_force.local_element(j);
                         force += balance;
                         if (carries_contact && !is_fixed_dof[i])
                           for_each_track(i,
                                          [&](const unsigned int t, const double weight)
                                          { forces.contact[t] += weight * balance; });
                       }
                       for_each_track(i,
                                      [&](const unsigned int t, const double weight)
                                      { forces.total[t] += weight * force; });
                     });
  sum_over_ranks(forces.total, state.external_force.get_mpi_communicator());
  sum_over_ranks(forces.contact, state.external_force.get_mpi_communicator());
  return forces;
}

template <int dim>
void BodyImpulses<dim>::accumulate(const StepState& start,
                                   const Ledger& before,
                                   const StepState& state,
                                   const DistributedVector& step_load)
{
  const double dt     = integrator.time_step();
  const double gamma  = integrator.gamma();
  const Forces forces = this->forces(state);
  auto& impulses      = accumulated.impulses;
  auto& contact_part  = accumulated.contact_impulses;
  for (unsigned int b = 0; b < impulses.size(); ++b)
  {
    impulses[b] += dt * ((1. - gamma) * before.forces.total[b] + gamma * forces.total[b]);
    contact_part[b] += dt * ((1. - gamma) * before.forces.contact[b] + gamma * forces.contact[b]);
  }
  accumulated.forces = forces;
  // The modified scheme's velocity correction is an impulse of its own (the paper's lambda_v):
  // the part of M (v_{n+1} - v_n) that the Newmark update of the accelerations does not explain.
  // The work of the external forces as the integrator applies them (doc/method.md, "The energy
  // guard's external work"): Newmark, ((1 - gamma) W_n + gamma W_{n+1}) . (u_{n+1} - u_n), the
  // work term of its energy identity (the trapezoid only for gamma = 1/2); a dissipative member,
  // whose balance takes the load at t_{n+1-alpha_f}, W(t_{n+1-alpha_f}) . (u_{n+1} - u_n).
  const MPI_Comm communicator      = state.displacement.get_mpi_communicator();
  std::vector<double> impulse_sums = partial_sums_start(impulses, communicator),
                      contact_sums = partial_sums_start(contact_part, communicator),
                      work_sum     = partial_sums_start({accumulated.external_work}, communicator);
  for_each_owned_row(
      state.displacement,
      [&](const types::global_dof_index i, const unsigned int j)
      {
        if (is_contact_dof[i])
        {
          const double correction =
              mass[i] * (state.velocity.local_element(j) - start.velocity.local_element(j) -
                         dt * ((1. - gamma) * start.acceleration.local_element(j) +
                               gamma * state.acceleration.local_element(j)));
          for_each_track(i,
                         [&](const unsigned int t, const double weight)
                         {
                           impulse_sums[t] += weight * correction;
                           contact_sums[t] += weight * correction;
                         });
        }
        // At a fixed DoF the load and the reaction together are M a + Q: their work on a prescribed
        // motion counts (a support's does not move), weighted as the balance takes them (Newmark:
        // gamma on the new state; a dissipative member: 1 - alpha_m, 1 - alpha_f).
        const bool at_balance = step_load.size() > 0;
        double force          = at_balance ? step_load.local_element(j)
                                           : (1. - gamma) * start.external_force.local_element(j) +
                                        gamma * state.external_force.local_element(j);
        if (is_fixed_dof[i])
        {
          const double w_a = at_balance ? 1. - integrator.alpha_m() : gamma,
                       w_q = at_balance ? 1. - integrator.alpha_f() : gamma;
          force            = mass[i] * (w_a * state.acceleration.local_element(j) +
                             (1. - w_a) * start.acceleration.local_element(j)) +
                  w_q * state.internal_force.local_element(j) +
                  (1. - w_q) * start.internal_force.local_element(j);
        }
        work_sum[0] +=
            force * (state.displacement.local_element(j) - start.displacement.local_element(j));
      });
  for (std::vector<double>* sums : {&impulse_sums, &contact_sums, &work_sum})
    sum_over_ranks(*sums, communicator);
  impulses                  = impulse_sums;
  contact_part              = contact_sums;
  accumulated.external_work = work_sum[0];
  // The tangential forces weighted as the external ones: Newmark's old and new forces by
  // 1 - gamma and gamma, a dissipative member's one force of its balance by 1.
  if (contact.has_friction())
    accumulated.frictional_dissipation += contact.frictional_dissipation(
        contact.border().gather(state.displacement), step_load.size() > 0 ? 1. : gamma);
}

template <int dim>
void BodyImpulses<dim>::balance_momenta(DistributedVector& increment,
                                        const DistributedVector& residual,
                                        const double c) const
{
  // The residual r = c M (u - u~) + Q(u) - W - G^T lambda left within the Newton tolerance, summed
  // over the nodes of a body that carry no contact force, along the impact direction, is a
  // momentum error of the step that no recovered force accounts for (at the active pairs' nodes
  // the residual is part of the recovered contact force, forces()). A rigid translation t of
  // the body along that direction changes only the inertia term (Q is invariant, W and G^T lambda
  // do not depend on it), by c t m at every DoF. Choosing t to cancel the sum makes the step's
  // momentum change equal its recovered impulse exactly; t is the residual over c M, far below the
  // gap tolerance. The directions are orthonormal, so the translations of a body's tracks do not
  // disturb one another.
  const std::vector<bool> in_active_pair = active_pair_dofs();
  std::vector<double> residual_sum(n_tracks(), 0.), inertia_sum(n_tracks(), 0.);
  for_each_owned_row(increment,
                     [&](const types::global_dof_index i, const unsigned int j)
                     {
                       if (is_fixed_dof[i] || in_active_pair[i])
                         return;
                       for_each_track(i,
                                      [&](const unsigned int t, const double weight)
                                      {
                                        residual_sum[t] += weight * residual.local_element(j);
                                        inertia_sum[t] += c * mass[i] * weight * weight;
                                      });
                     });
  sum_over_ranks(residual_sum, increment.get_mpi_communicator());
  sum_over_ranks(inertia_sum, increment.get_mpi_communicator());
  for_each_owned_row(increment,
                     [&](const types::global_dof_index i, const unsigned int j)
                     {
                       if (is_fixed_dof[i])
                         return;
                       for_each_track(i,
                                      [&](const unsigned int t, const double weight)
                                      {
                                        if (inertia_sum[t] > 0.)
                                          increment.local_element(j) -=
                                              residual_sum[t] / inertia_sum[t] * weight;
                                      });
                     });
}

template <int dim>
std::vector<double> BodyImpulses<dim>::momenta(const DistributedVector& velocity) const
{
  std::vector<double> momenta(n_tracks(), 0.);
  for_each_owned_row(velocity,
                     [&](const types::global_dof_index i, const unsigned int j)
                     {
                       for_each_track(i,
                                      [&](const unsigned int t, const double weight) {
                                        momenta[t] += mass[i] * weight * velocity.local_element(j);
                                      });
                     });
  sum_over_ranks(momenta, velocity.get_mpi_communicator());
  return momenta;
}

DYNCONTACT_INSTANTIATE_CLASS(BodyImpulses)
} // namespace dyncontact
