#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/implicit_contact_impulse.h>

namespace dyncontact
{
template <int dim>
void ImplicitContactImpulse<dim>::adjust_predictor(const RateMap& rates,
                                                   const ContactConstraints<dim>& contact,
                                                   const Vector<double>& lumped_mass,
                                                   const StepStart& start,
                                                   Vector<double>& old_acceleration,
                                                   Vector<double>& predictor) const
{
  Vector<double> contact_force(predictor.size());
  contact.add_contact_forces(contact_force);
  const Vector<double> shift = predictor_shift(rates, contact, lumped_mass, start);
  for (types::global_dof_index i = 0; i < predictor.size(); ++i)
  {
    const double shift_i = shift.size() == 0 ? 0. : shift[i];
    if ((contact_force[i] == 0. && shift_i == 0.) || start.is_fixed[i])
      continue; // classical Newmark, bit for bit
    if (contact_force[i] != 0.)
      old_acceleration[i] = (start.external_force[i] - start.internal_force[i]) / lumped_mass[i];
    predictor[i] = rates.predicted_displacement(
                       start.displacement[i], start.velocity[i], old_acceleration[i]) +
                   shift_i;
  }
}

template <int dim>
Vector<double>
ImplicitContactImpulse<dim>::predictor_shift(const RateMap& /*rates*/,
                                             const ContactConstraints<dim>& /*contact*/,
                                             const Vector<double>& /*lumped_mass*/,
                                             const StepStart& /*start*/) const
{
  return {};
}

DYNCONTACT_INSTANTIATE_CLASS(ImplicitContactImpulse)
} // namespace dyncontact
