#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/contact_dynamics.h>
#include <dyncontact/contact_dynamics/contact_stabilized_newmark.h>
#include <dyncontact/contact_dynamics/mass_redistribution.h>
#include <dyncontact/contact_dynamics/no_rate_correction.h>
#include <dyncontact/contact_dynamics/persistency.h>
#include <dyncontact/contact_dynamics/taylor_papadopoulos.h>
#include <dyncontact/contact_dynamics/velocity_update.h>

#include <map>
#include <string>
#include <vector>

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

const ContactDynamicsTraits& contact_dynamics_traits(const ContactDynamicsKind kind)
{
  static const std::string one_force_per_step =
      "its one contact force per step and its energy argument are built on it";
  static const std::string rate_correction_glues =
      "its rate correction assumes exactly closed pairs; a penalized pair stays penetrated and "
      "the correction glues it (the bars of case 6.2 never separate with taylor-papadopoulos). "
      "Use Contact/dynamics = none, mass-redistribution or contact-stabilized with a penalty, or "
      "Lagrange multipliers.";
  static const std::map<ContactDynamicsKind, ContactDynamicsTraits> traits{
      {ContactDynamicsKind::none,
       {"classical Newmark, contact constrains displacements only.", "", ""}},
      {ContactDynamicsKind::taylor_papadopoulos,
       {"the paper's modified Newmark (Taylor & Papadopoulos 1993, eqs. 19-24): after each step "
        "the normal velocity and acceleration of every active pair are made continuous, "
        "conserving momentum.",
        "",
        rate_correction_glues}},
      {ContactDynamicsKind::mass_redistribution,
       {"the nodes that can come into contact carry no mass, each cell's mass going to its other "
        "nodes (Khenous, Laborde & Renard 2008); the contact force is then the adjacent "
        "elements' elastic force, without the oscillation of massive contact nodes, and the steps "
        "where pairs close or open are cut until their energy error is within Guards/contact "
        "event tolerance; needs a node off the contact surfaces in every cell.",
        "",
        ""}},
      {ContactDynamicsKind::contact_stabilized,
       {"the contact-stabilized Newmark of Deuflhard, Krause & Ertel (2008): the predictor "
        "projected onto the admissible set, the old contact force left out of the explicit part; "
        "energy dissipative at contact.",
        one_force_per_step + "; with the paper's beta = 0.001 its projected contact nodes gained "
                             "3300 times the initial energy on 6.1.",
        ""}},
      {ContactDynamicsKind::persistency,
       {"the gap-rate (persistency) condition of Laursen & Chawla (1997) on the pairs predicted "
        "to close, one contact force per step; conserves energy through impact and release, "
        "contact may act across a gap of one step's approach.",
        one_force_per_step + ".",
        "a penalty on the gap rate dissipates, and Armero & Petocz's energy-conserving penalty "
        "force is not implemented. Use Lagrange multipliers."}},
      {ContactDynamicsKind::velocity_update,
       {"impenetrability with one contact force per step, then a velocity jump that zeroes "
        "every active pair's relative normal velocity (Laursen & Love 2002); dissipates at "
        "impact only.",
        one_force_per_step + ".",
        rate_correction_glues}}};
  return traits.at(kind);
}

std::string contact_dynamics_documentation(const ContactDynamicsKind default_kind)
{
  const auto& names = contact_dynamics_names();
  std::string text  = "Treatment of the contact nodes' velocities and accelerations "
                      "(doc/schemes.md compares them).";
  std::vector<std::string> trapezoidal, lagrange;
  for (const auto& [name, kind] : names.pairs())
  {
    const ContactDynamicsTraits& traits = contact_dynamics_traits(kind);
    text += " " + name + (kind == default_kind ? " (the default)" : "") + ": " + traits.help;
    if (!traits.trapezoidal_rule_reason.empty())
      trapezoidal.push_back(name);
    if (!traits.penalty_refusal.empty())
      lagrange.push_back(name);
  }
  const auto listed = [](const std::vector<std::string>& names)
  {
    std::string list;
    for (unsigned int i = 0; i < names.size(); ++i)
      list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return list;
  };
  return text + " " + listed(trapezoidal) +
         " need Time integration/integrator = newmark with beta = 1/4, gamma = 1/2; " +
         listed(lagrange) + " need Lagrange multipliers.";
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

#define DYNCONTACT_INSTANTIATE(dim)                                                                \
  template std::unique_ptr<ContactDynamics<dim>> create_contact_dynamics<dim>(ContactDynamicsKind);
DYNCONTACT_FOR_EACH_DIMENSION(DYNCONTACT_INSTANTIATE)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
