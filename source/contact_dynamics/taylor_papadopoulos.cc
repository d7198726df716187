#include <dyncontact/contact_dynamics/taylor_papadopoulos.h>

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
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
  {
    if (!contact.is_active(k))
      continue;
    const ContactPair<dim>& pair = contact.candidate_pairs()[k];
    const Tensor<1, dim>& normal = pair.normal;
    // Eq. (21) holds for a pair closed at t_{n+1}, where its numerator's [[X + u_n]] equals
    // g_n - g_{n+1}; the latter keeps [[a_{n+1}]] = 0 exact even for the residual gap Newton leaves
    // within its tolerance (the literal form would leave [[a_{n+1}]] = g_{n+1} / (beta dt^2)).
    const double position_jump =
        contact.gap(k, step.old_displacement) - contact.gap(k, step.new_displacement);
    const double inverse_weight_sum = pair.inverse_effective_mass(lumped_mass);

    // Eqs. (21) and (22): the multipliers of the rate constraints [[a]].n = 0 and [[v]].n = 0.
    const double velocity_jump     = pair.normal_jump(v_old);
    const double acceleration_jump = pair.normal_jump(a_old);
    const double lambda_a =
        rates.predicted_displacement(position_jump, velocity_jump, acceleration_jump) /
        inverse_weight_sum;
    const double lambda_v =
        rates.predicted_velocity(velocity_jump, acceleration_jump) / inverse_weight_sum;

    // Recovery of the normal rates of each node j of the pair, with its coefficient c_j (-1 for
    // the slave node of body A, the weight w_i for a master node of body B).
    const auto correct_side = [&](const Node<dim>& node, const double coefficient)
    {
      const double mass = lumped_mass[node.dofs[0]];
      // The increment over the predictor, n . (u_{n+1} - u~), shifted by the rate multiplier.
      const double a_normal = rates.acceleration(normal_component(node, normal, step.increment) +
                                                 coefficient * lambda_a / mass);
      const double v_normal = rates.velocity(normal_component(node, normal, v_old),
                                             normal_component(node, normal, a_old),
                                             a_normal) -
                              coefficient * lambda_v / mass;
      const double a_shift = a_normal - normal_component(node, normal, a_new);
      const double v_shift = v_normal - normal_component(node, normal, v_new);
      for (unsigned int d = 0; d < dim; ++d)
      {
        a_new[node.dofs[d]] += a_shift * normal[d];
        v_new[node.dofs[d]] += v_shift * normal[d];
      }
    };
    pair.for_each_node(correct_side);
  }
}

template class TaylorPapadopoulos<1>;
template class TaylorPapadopoulos<2>;
} // namespace dyncontact
