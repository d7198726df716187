#include <dyncontact/contact_dynamics/taylor_papadopoulos.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <map>
#include <vector>

namespace dyncontact
{
namespace
{
/** One appearance of a node in an active pair: the pair's row among the active ones, c_kj. */
struct Incidence
{
  unsigned int row;
  double coefficient;
};

/** A node of an active pair with all its appearances. */
template <int dim>
struct NodeIncidence
{
  const Node<dim>* node;
  std::vector<Incidence> appearances;
};

/** The nodes of the active pairs, keyed by their first DoF. */
template <int dim>
using IncidenceMap = std::map<types::global_dof_index, NodeIncidence<dim>>;

/**
 * Solves (B M^-1 B^T) x = rhs for both right-hand sides, B the active pairs' rows
 * B_kj = c_kj n_k^T over the nodes j (slave -1, master w_i) and M the lumped nodal masses.
 */
template <int dim>
std::pair<Eigen::VectorXd, Eigen::VectorXd>
solve_rate_multipliers(const std::vector<const ContactPair<dim>*>& active,
                       const IncidenceMap<dim>& incidence,
                       const Vector<double>& lumped_mass,
                       const Eigen::VectorXd& rhs_a,
                       const Eigen::VectorXd& rhs_v)
{
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& [dof, node] : incidence)
    for (const Incidence& k : node.appearances)
      for (const Incidence& l : node.appearances)
        entries.emplace_back(k.row,
                             l.row,
                             k.coefficient * l.coefficient *
                                 (active[k.row]->normal * active[l.row]->normal) /
                                 lumped_mass[dof]);
  Eigen::SparseMatrix<double> matrix(active.size(), active.size());
  matrix.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factorization(matrix);
  return {factorization.solve(rhs_a), factorization.solve(rhs_v)};
}
} // namespace

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
  // Every node of an active pair with its pairs' rows and coefficients.
  IncidenceMap<dim> incidence;
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
    const unsigned int row = active.size();
    active.push_back(&pair);
    pair.for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          NodeIncidence<dim>& entry = incidence[node.dofs[0]];
          entry.node                = &node;
          entry.appearances.push_back({row, coefficient});
        });
  }
  if (active.empty())
    return;

  // Eqs. (21) and (22), for pairs that may share nodes (node-to-segment): the multipliers of the
  // rate constraints [[a]].n = 0 and [[v]].n = 0 of all active pairs at once.
  const auto [lambda_a, lambda_v] = solve_rate_multipliers(
      active,
      incidence,
      lumped_mass,
      Eigen::Map<const Eigen::VectorXd>(predicted_position_jump.data(), active.size()),
      Eigen::Map<const Eigen::VectorXd>(predicted_velocity_jump.data(), active.size()));

  // Recovery of each node's rates: the increment over the predictor shifted by M^-1 B^T lambda_a
  // gives a_{n+1}, the velocity update from it shifted by M^-1 B^T lambda_v gives v_{n+1}.
  for (const auto& [first_dof, entry] : incidence)
  {
    const Node<dim>& node = *entry.node;
    Tensor<1, dim> shift_a, shift_v;
    for (const Incidence& k : entry.appearances)
    {
      shift_a += k.coefficient * lambda_a[k.row] * active[k.row]->normal;
      shift_v += k.coefficient * lambda_v[k.row] * active[k.row]->normal;
    }
    const double mass = lumped_mass[first_dof];
    for (unsigned int d = 0; d < dim; ++d)
    {
      const types::global_dof_index dof = node.dofs[d];
      a_new[dof] = rates.acceleration(step.increment[dof] + shift_a[d] / mass);
      v_new[dof] = rates.velocity(v_old[dof], a_old[dof], a_new[dof]) - shift_v[d] / mass;
    }
  }
}

template class TaylorPapadopoulos<1>;
template class TaylorPapadopoulos<2>;
} // namespace dyncontact
