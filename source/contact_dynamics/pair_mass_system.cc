#include <dyncontact/contact_dynamics/pair_mass_system.h>

#include <map>

namespace dyncontact
{
template <int dim>
PairMassSystem<dim>::PairMassSystem(std::vector<const ContactPair<dim>*> pairs_in,
                                    const Vector<double>& lumped_mass)
    : pairs(std::move(pairs_in))
{
  // Every node of the pairs with its pairs' rows and coefficients, keyed by its first DoF.
  std::map<types::global_dof_index, NodeAppearances> by_dof;
  for (unsigned int row = 0; row < pairs.size(); ++row)
    pairs[row]->for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          NodeAppearances& entry = by_dof[node.dofs[0]];
          entry.node             = &node;
          entry.mass             = lumped_mass[node.dofs[0]];
          entry.appearances.push_back({row, coefficient});
        });
  std::vector<Eigen::Triplet<double>> entries;
  for (auto& [dof, entry] : by_dof)
  {
    for (const Appearance& k : entry.appearances)
      for (const Appearance& l : entry.appearances)
        entries.emplace_back(k.row,
                             l.row,
                             k.coefficient * l.coefficient *
                                 (pairs[k.row]->normal * pairs[l.row]->normal) / entry.mass);
    nodes.push_back(std::move(entry));
  }
  Eigen::SparseMatrix<double> matrix(pairs.size(), pairs.size());
  matrix.setFromTriplets(entries.begin(), entries.end());
  factorization.compute(matrix);
}

template <int dim>
Tensor<1, dim> PairMassSystem<dim>::nodal_force(const unsigned int i,
                                                const Eigen::VectorXd& mu) const
{
  Tensor<1, dim> force;
  for (const Appearance& k : nodes[i].appearances)
    force += k.coefficient * mu[k.row] * pairs[k.row]->normal;
  return force;
}

template class PairMassSystem<1>;
template class PairMassSystem<2>;
} // namespace dyncontact
