#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/contact_stabilized_newmark.h>
#include <dyncontact/contact_dynamics/pair_mass_system.h>

#include <vector>

namespace dyncontact
{
namespace
{
/**
 * The shift s = M^-1 B^T mu, mu >= 0, that closes the pairs penetrating at `position` (the mass
 * projection onto g >= 0, by the active-set rounds of the class documentation), as a
 * border vector; zero if no pair penetrates.
 */
template <int dim>
Vector<double> projection_shift(const ContactConstraints<dim>& contact,
                                const Vector<double>& lumped_mass,
                                const std::vector<bool>& is_fixed,
                                const Vector<double>& position)
{
  Vector<double> shift(position.size());
  std::vector<bool> closing(contact.n_pairs(), false);
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    closing[k] = contact.gap(k, position) < 0.;
  for (unsigned int round = 0; round <= contact.n_pairs(); ++round)
  {
    std::vector<unsigned int> rows;
    std::vector<const ContactPair<dim>*> pairs;
    for (unsigned int k = 0; k < contact.n_pairs(); ++k)
      if (closing[k])
      {
        rows.push_back(k);
        pairs.push_back(&contact.candidate_pairs()[k]);
      }
    shift = 0.;
    if (rows.empty())
      return shift;
    Eigen::VectorXd opening(rows.size());
    for (unsigned int r = 0; r < rows.size(); ++r)
      opening[r] = -contact.gap(rows[r], position);
    const PairMassSystem<dim> system(std::move(pairs), lumped_mass, is_fixed);
    const Eigen::VectorXd mu = system.solve(opening);
    bool changed             = false;
    for (unsigned int r = 0; r < rows.size(); ++r)
      if (mu[r] < 0.) // the pair would be pulled shut: it opens by itself
      {
        closing[rows[r]] = false;
        changed          = true;
      }
    if (changed)
      continue;
    for (unsigned int i = 0; i < system.n_nodes(); ++i)
    {
      const Tensor<1, dim> change = system.nodal_change(i, mu);
      for (unsigned int d = 0; d < dim; ++d)
        shift[system.node(i).dofs[d]] += change[d];
    }
    Vector<double> projected = position;
    projected += shift;
    for (unsigned int k = 0; k < contact.n_pairs(); ++k)
      if (!closing[k] && contact.gap(k, projected) < 0.)
      {
        closing[k] = true;
        changed    = true;
      }
    if (!changed)
      return shift;
  }
  return shift; // the last round's projection (the rounds did not settle)
}
} // namespace

template <int dim>
Vector<double>
ContactStabilizedNewmark<dim>::predictor_shift(const RateMap& rates,
                                               const ContactConstraints<dim>& contact,
                                               const Vector<double>& lumped_mass,
                                               const StepStart& start) const
{
  Vector<double> position = start.displacement;
  position.add(rates.time_step, start.velocity);
  return projection_shift(contact, lumped_mass, start.is_fixed, position);
}

DYNCONTACT_INSTANTIATE_CLASS(ContactStabilizedNewmark)
} // namespace dyncontact
