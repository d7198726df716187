#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/persistency.h>

namespace dyncontact
{
template <int dim>
std::vector<double> Persistency<dim>::reference_gaps(const ContactConstraints<dim>& contact,
                                                     const StepStart& start,
                                                     const Vector<double>& predictor) const
{
  std::vector<double> reference(contact.n_pairs(), 0.);
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    if (contact.gap(k, predictor) < 0.)
      reference[k] = contact.gap(k, start.displacement);
  return reference;
}

DYNCONTACT_INSTANTIATE_CLASS(Persistency)
} // namespace dyncontact
