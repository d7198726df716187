#include <dyncontact/contact_dynamics/contact_dynamics.h>
#include <dyncontact/contact_dynamics/contact_stabilized_newmark.h>
#include <dyncontact/contact_dynamics/mass_redistribution.h>
#include <dyncontact/contact_dynamics/no_rate_correction.h>
#include <dyncontact/contact_dynamics/persistency.h>
#include <dyncontact/contact_dynamics/taylor_papadopoulos.h>
#include <dyncontact/contact_dynamics/velocity_update.h>

namespace dyncontact
{
const NameTable<ContactDynamicsKind>& contact_dynamics_names()
{
  static const NameTable<ContactDynamicsKind> names{
      {"none", ContactDynamicsKind::none},
      {"taylor-papadopoulos", ContactDynamicsKind::taylor_papadopoulos},
      {"mass-redistribution", ContactDynamicsKind::mass_redistribution},
      {"contact-stabilized", ContactDynamicsKind::contact_stabilized},
      {"persistency", ContactDynamicsKind::persistency},
      {"velocity-update", ContactDynamicsKind::velocity_update}};
  return names;
}

template <int dim>
std::unique_ptr<ContactDynamics<dim>> create_contact_dynamics(const ContactDynamicsKind kind)
{
  switch (kind)
  {
  case ContactDynamicsKind::none:
    return std::make_unique<NoRateCorrection<dim>>();
  case ContactDynamicsKind::taylor_papadopoulos:
    return std::make_unique<TaylorPapadopoulos<dim>>();
  case ContactDynamicsKind::mass_redistribution:
    return std::make_unique<MassRedistribution<dim>>();
  case ContactDynamicsKind::contact_stabilized:
    return std::make_unique<ContactStabilizedNewmark<dim>>();
  case ContactDynamicsKind::persistency:
    return std::make_unique<Persistency<dim>>();
  case ContactDynamicsKind::velocity_update:
    return std::make_unique<VelocityUpdate<dim>>();
  }
  throw std::logic_error("create_contact_dynamics: a ContactDynamicsKind without a treatment");
}

template std::unique_ptr<ContactDynamics<1>> create_contact_dynamics<1>(ContactDynamicsKind);
template std::unique_ptr<ContactDynamics<2>> create_contact_dynamics<2>(ContactDynamicsKind);
} // namespace dyncontact
