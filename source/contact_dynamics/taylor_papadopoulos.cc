#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/pair_mass_system.h>
#include <dyncontact/contact_dynamics/taylor_papadopoulos.h>

#include <vector>

namespace dyncontact
{
template <int dim>
void TaylorPapadopoulos<dim>::correct_rates(const RateMap& rates,
                                            const ContactConstraints<dim>& contact,
                                            const Vector<double>& lumped_mass,
                                            const StepStates& step,
                                            Vector<double>& v_new,
                                            Vector<double>& a_new) const
{
  const Vector<double>& v_old = step.old_velocity;
  const Vector<double>& a_old = step.old_acceleration;
  std::vector<const ContactPair<dim>*> active;
  std::vector<double> predicted_position_jump, predicted_velocity_jump;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
  {
    if (!contact.is_active(k))
      continue;
    const ContactPair<dim>& pair = contact.candidate_pairs()[k];
    // Eq. (21) holds for a pair closed at t_{n+1}, where its numerator's [[X + u_n]] equals
    // g_n - g_{n+1}; the latter keeps [[a_{n+1}]] = 0 exact even for the residual gap Newton leaves
    // within its tolerance (the literal form would leave [[a_{n+1}]] = g_{n+1} / (beta dt^2)).
    const double position_jump =
        contact.gap(k, step.old_displacement) - contact.gap(k, step.new_displacement);
    const double velocity_jump     = pair.normal_jump(v_old);
    const double acceleration_jump = pair.normal_jump(a_old);
    predicted_position_jump.push_back(
        rates.predicted_displacement(position_jump, velocity_jump, acceleration_jump));
    predicted_velocity_jump.push_back(rates.predicted_velocity(velocity_jump, acceleration_jump));
    active.push_back(&pair);
  }
  if (active.empty())
    return;

  // Eqs. (21) and (22), for pairs that may share nodes (node-to-segment): the multipliers of the
  // rate constraints [[a]].n = 0 and [[v]].n = 0 of all active pairs at once.
  const unsigned int n_active = active.size();
  const PairMassSystem<dim> system(std::move(active), lumped_mass, step.is_fixed);
  const Eigen::VectorXd lambda_a =
      system.solve(Eigen::Map<const Eigen::VectorXd>(predicted_position_jump.data(), n_active));
  const Eigen::VectorXd lambda_v =
      system.solve(Eigen::Map<const Eigen::VectorXd>(predicted_velocity_jump.data(), n_active));

  // Recovery of each node's rates: the increment over the predictor shifted by M^-1 B^T lambda_a
  // gives a_{n+1}, the velocity update from it shifted by M^-1 B^T lambda_v gives v_{n+1}.
  for (unsigned int i = 0; i < system.n_nodes(); ++i)
  {
    const Tensor<1, dim> shift_a = system.nodal_change(i, lambda_a);
    const Tensor<1, dim> shift_v = system.nodal_change(i, lambda_v);
    for (unsigned int d = 0; d < dim; ++d)
    {
      const types::global_dof_index dof = system.node(i).dofs[d];
      a_new[dof]                        = rates.acceleration(step.increment[dof] + shift_a[d]);
      v_new[dof] = rates.velocity(v_old[dof], a_old[dof], a_new[dof]) - shift_v[d];
    }
  }
}

DYNCONTACT_INSTANTIATE_CLASS(TaylorPapadopoulos)
} // namespace dyncontact
