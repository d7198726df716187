#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/pair_mass_system.h>

#include <map>

namespace dyncontact
{
template <int dim>
std::vector<typename PairMassSystem<dim>::Row>
PairMassSystem<dim>::normal_rows(const std::vector<const ContactPair<dim>*>& pairs)
{
  std::vector<Row> rows;
  for (const ContactPair<dim>* pair : pairs)
    rows.push_back({pair, pair->normal});
  return rows;
}

template <int dim>
PairMassSystem<dim>::PairMassSystem(std::vector<const ContactPair<dim>*> pairs,
                                    const Vector<double>& lumped_mass,
                                    const std::vector<bool>& is_fixed)
    : PairMassSystem(normal_rows(pairs), lumped_mass, is_fixed)
{
}

template <int dim>
PairMassSystem<dim>::PairMassSystem(std::vector<Row> rows_in,
                                    const Vector<double>& lumped_mass,
                                    const std::vector<bool>& is_fixed)
    : rows(std::move(rows_in))
{
  // Every node of the pairs with its rows and coefficients, keyed by its first DoF.
  std::map<types::global_dof_index, NodeAppearances> by_dof;
  for (unsigned int row = 0; row < rows.size(); ++row)
    rows[row].pair->for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          NodeAppearances& entry = by_dof[node.dofs[0]];
          entry.node             = &node;
          entry.mass             = lumped_mass[node.dofs[0]];
          for (unsigned int d = 0; d < dim; ++d)
            entry.free[d] = !is_fixed.empty() && is_fixed[node.dofs[d]] ? 0. : 1.;
          entry.appearances.push_back({row, coefficient});
        });
  std::vector<Eigen::Triplet<double>> entries;
  for (auto& [dof, entry] : by_dof)
  {
    for (const Appearance& k : entry.appearances)
      for (const Appearance& l : entry.appearances)
      {
        double free_normals = 0.; // d_k . d_l over the node's free components
        for (unsigned int d = 0; d < dim; ++d)
          free_normals += entry.free[d] * rows[k.row].direction[d] * rows[l.row].direction[d];
        entries.emplace_back(
            k.row, l.row, k.coefficient * l.coefficient * free_normals / entry.mass);
      }
    nodes.push_back(std::move(entry));
  }
  Eigen::SparseMatrix<double> matrix(rows.size(), rows.size());
  matrix.setFromTriplets(entries.begin(), entries.end());
  factorization.compute(matrix);
}

template <int dim>
Tensor<1, dim> PairMassSystem<dim>::nodal_change(const unsigned int i,
                                                 const Eigen::VectorXd& mu) const
{
  Tensor<1, dim> force;
  for (const Appearance& k : nodes[i].appearances)
    force += k.coefficient * mu[k.row] * rows[k.row].direction;
  for (unsigned int d = 0; d < dim; ++d)
    force[d] = nodes[i].free[d] * force[d] / nodes[i].mass;
  return force;
}

DYNCONTACT_INSTANTIATE_CLASS(PairMassSystem)
} // namespace dyncontact
