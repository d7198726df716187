#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/pair_mass_system.h>
#include <dyncontact/contact_dynamics/taylor_papadopoulos.h>

#include <optional>
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
  std::vector<typename PairMassSystem<dim>::Row> rows;
  std::vector<double> predicted_position_jump, predicted_velocity_jump;
  // A row along the pair's normal (normal_jump(), the sums of the frictionless scheme, bit for
  // bit) or along one of its tangents.
  const auto add_row = [&](const ContactPair<dim>& pair,
                           const std::optional<Tensor<1, dim>>& tangent,
                           const double position_jump)
  {
    const double velocity_jump =
        tangent ? pair.jump_along(*tangent, v_old) : pair.normal_jump(v_old);
    const double acceleration_jump =
        tangent ? pair.jump_along(*tangent, a_old) : pair.normal_jump(a_old);
    predicted_position_jump.push_back(
        rates.predicted_displacement(position_jump, velocity_jump, acceleration_jump));
    predicted_velocity_jump.push_back(rates.predicted_velocity(velocity_jump, acceleration_jump));
    rows.push_back({&pair, tangent.value_or(pair.normal)});
  };
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
  {
    if (!contact.is_active(k))
      continue;
    const ContactPair<dim>& pair = contact.candidate_pairs()[k];
    // Eq. (21) holds for a pair closed at t_{n+1}, where its numerator's [[X + u_n]] equals
    // g_n - g_{n+1}; the latter keeps [[a_{n+1}]] = 0 exact even for the residual gap Newton leaves
    // within its tolerance (the literal form would leave [[a_{n+1}]] = g_{n+1} / (beta dt^2)).
    add_row(pair,
            std::nullopt,
            contact.gap(k, step.old_displacement) - contact.gap(k, step.new_displacement));
    // A stuck pair moves with its master point (doc/method.md section 7): its whole relative
    // rates are continuous, eqs. (21) and (22) along each tangent too, with [[u_n - u_{n+1}]] . t
    // (zero to the Newton tolerance in stick) in the place of g_n - g_{n+1}.
    for (const Tensor<1, dim>& tangent : contact.stick_directions(k))
      add_row(pair,
              tangent,
              pair.jump_along(tangent, step.old_displacement) -
                  pair.jump_along(tangent, step.new_displacement));
  }
  if (rows.empty())
    return;

  // Eqs. (21) and (22), for pairs that may share nodes (node-to-segment): the multipliers of the
  // rate constraints [[a]].d = 0 and [[v]].d = 0 of all rows at once.
  const unsigned int n_rows = rows.size();
  const PairMassSystem<dim> system(std::move(rows), lumped_mass, step.is_fixed);
  const Eigen::VectorXd lambda_a =
      system.solve(Eigen::Map<const Eigen::VectorXd>(predicted_position_jump.data(), n_rows));
  const Eigen::VectorXd lambda_v =
      system.solve(Eigen::Map<const Eigen::VectorXd>(predicted_velocity_jump.data(), n_rows));

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
