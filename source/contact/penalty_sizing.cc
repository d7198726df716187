#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact/penalty_sizing.h>
#include <dyncontact/time_integration/mode_resolution.h>

#include <algorithm>
#include <cmath>

namespace dyncontact
{
template <int dim>
double penalty_spring_omega_dt(const ContactConstraints<dim>& contact,
                               const Vector<double>& lumped_mass,
                               const double time_step)
{
  double spring_omega_dt = 0.;
  if (contact.contact_formulation() != ContactFormulation::penalty)
    return spring_omega_dt;
  const Vector<double> border_mass = contact.border().gather(lumped_mass);
  for (const auto& pair : contact.candidate_pairs())
  {
    // A spring on a massless node (Contact/dynamics = mass-redistribution) is no mode of its own:
    // that node follows its neighbours quasi-statically, in series with the spring.
    const double inverse_mass = pair.inverse_effective_mass(border_mass);
    if (std::isfinite(inverse_mass))
      spring_omega_dt =
          std::max(spring_omega_dt, time_step * std::sqrt(pair.penalty_stiffness * inverse_mass));
  }
  return spring_omega_dt;
}

template <int dim>
double size_automatic_penalty(ContactConstraints<dim>& contact, const PenaltySizingInput& input)
{
  const double spring_omega_dt =
      penalty_spring_omega_dt(contact, input.lumped_mass, input.time_step);
  if (!is_resolved(input.body_omega_dt) || spring_omega_dt <= 1.)
    return 1.;
  const double scale = 1. / (spring_omega_dt * spring_omega_dt);
  contact.scale_penalty_stiffness(scale);
  return scale;
}

#define DYNCONTACT_INSTANTIATE(dim)                                                                \
  template double penalty_spring_omega_dt(                                                         \
      const ContactConstraints<dim>&, const Vector<double>&, double);                              \
  template double size_automatic_penalty(ContactConstraints<dim>&, const PenaltySizingInput&);
DYNCONTACT_FOR_EACH_DIMENSION(DYNCONTACT_INSTANTIATE)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
