#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/persistency.h>

namespace dyncontact
{
template <int dim>
std::vector<bool> Persistency<dim>::persistent_pairs(const ContactConstraints<dim>& contact,
                                                     const Vector<double>& predictor) const
{
  std::vector<bool> persistent(contact.n_pairs());
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    persistent[k] = contact.gap(k, predictor) < 0.;
  return persistent;
}

DYNCONTACT_INSTANTIATE_CLASS(Persistency)
} // namespace dyncontact
