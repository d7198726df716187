#pragma once

#include <dyncontact/contact/contact_pair.h>

#include <deal.II/lac/vector.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

namespace dyncontact
{
/**
 * The pairs' constraints along their directions weighted by the inverse lumped mass:
 * S = B M^-1 B^T (size: the number of rows), with B_rj = c_kj d_r^T the row r of pair k along the
 * unit direction d_r over the pair's nodes j (slave -1, master nodes their weights; a wall has no
 * node and infinite weight) and M the lumped nodal masses; d_r is the pair's normal n_k, or, for
 * the rows of a stuck pair with friction, also its tangents (TaylorPapadopoulos). The
 * nodal changes M^-1 B^T mu that such a system's solution mu gives a set of nodes move the pairs'
 * normal relative rates or positions by S mu, and conserve linear momentum (each pair's
 * coefficients sum to zero). Shared by the treatments that act on several pairs at once, which may
 * share nodes (node-to-segment): the rate constraints of TaylorPapadopoulos (paper eqs. 21-22) and
 * the predictor projection of ContactStabilizedNewmark. Needs positive masses at the pairs' nodes.
 * A fixed DoF (e.g. u_r = 0 of a node on the symmetry axis) has infinite mass: it takes no part
 * in S and no change, so a pair whose normal is not exactly along the free components is closed by
 * them alone.
 */
template <int dim>
class PairMassSystem
{
public:
  /**
   * `pairs` (not owned, they must outlive this object) in row order; `lumped_mass` per DoF [mass];
   * `is_fixed` per DoF (empty: none fixed). Factorizes S (sparse LDL^T, Eigen).
   */
  PairMassSystem(std::vector<const ContactPair<dim>*> pairs,
                 const Vector<double>& lumped_mass,
                 const std::vector<bool>& is_fixed);

  /** One row of B: a pair (not owned) and the unit direction of its constraint. */
  struct Row
  {
    const ContactPair<dim>* pair;
    Tensor<1, dim> direction;
  };

  /** The rows `rows`, in their order; otherwise as the constructor above. */
  PairMassSystem(std::vector<Row> rows,
                 const Vector<double>& lumped_mass,
                 const std::vector<bool>& is_fixed);

  /** The number of rows of S. */
  unsigned int size() const { return rows.size(); }

  /** mu = S^-1 rhs (`rhs` has size() entries) [rhs over mass]. */
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const { return factorization.solve(rhs); }

  /** The number of distinct nodes of the pairs. */
  unsigned int n_nodes() const { return nodes.size(); }

  /** Node `i` (< n_nodes()) of the pairs. */
  const Node<dim>& node(const unsigned int i) const { return *nodes[i].node; }

  /**
   * (M^-1 B^T mu) at node `i`: the sum over the rows r it appears in of c_rj mu_r d_r, divided by
   * the node's mass, zero in its fixed components [mu over mass].
   */
  Tensor<1, dim> nodal_change(unsigned int i, const Eigen::VectorXd& mu) const;

private:
  /** One appearance of a node in a pair: the pair's row and the node's coefficient c_kj. */
  struct Appearance
  {
    unsigned int row;
    double coefficient;
  };
  /** A node of the pairs with its mass, its free components (1, or 0: fixed) and appearances. */
  struct NodeAppearances
  {
    const Node<dim>* node;
    double mass;
    Tensor<1, dim> free;
    std::vector<Appearance> appearances;
  };

  /** The rows of each pair along its normal. */
  static std::vector<Row> normal_rows(const std::vector<const ContactPair<dim>*>& pairs);

  std::vector<Row> rows;
  std::vector<NodeAppearances> nodes;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factorization;
};
} // namespace dyncontact
