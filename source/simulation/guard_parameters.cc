#include <dyncontact/base/parameter_entries.h>
#include <dyncontact/simulation/guard_parameters.h>

namespace dyncontact
{
void GuardParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Guards");
  prm.declare_entry("energy",
                    "true",
                    Patterns::Bool(),
                    "Reject a step whose algorithmic energy, plus the energy friction dissipated "
                    "(history.csv's frictional_dissipation), exceeds the initial energy plus the "
                    "work of the external forces (elastic contact cannot gain energy), or whose "
                    "friction did positive work beyond the energy tolerance. A rejected step is "
                    "cut (Time integration/maximum step cuts).");
  prm.declare_entry("energy tolerance",
                    "1e-4",
                    Patterns::Double(),
                    "Allowed energy gain, relative to the initial energy (for bodies starting at "
                    "rest: the largest energy of the run) [-], 0..1.");
  prm.declare_entry(
      "plain energy tolerance",
      "0.01",
      Patterns::Double(),
      "With Newmark's 2 beta < gamma only (conditionally stable): allowed gain of the "
      "plain energy (kinetic + strain), relative like the energy tolerance [-], "
      "0..1. The algorithmic energy the energy guard reads then weighs a mode's "
      "strain energy by 1 - (omega dt / limit)^2, so it cannot see energy gained in "
      "the highest modes near the stability limit; the plain energy is checked too. "
      "It is not conserved by a stable run either: it exceeds the algorithmic one by "
      "(gamma/2 - beta) dt^2/2 a.Ma (paper 6.1 at Courant 1: 0.58 %).");
  prm.declare_entry("tensile force",
                    "true",
                    Patterns::Bool(),
                    "Reject a step whose recovered total contact force is tensile.");
  prm.declare_entry("tensile force tolerance",
                    "1e-4",
                    Patterns::Double(),
                    "Allowed tension, relative to the largest contact force of the run (or the sum "
                    "of the step's |multipliers|) [-], 0..1.");
  prm.declare_entry("momentum",
                    "true",
                    Patterns::Bool(),
                    "Reject a step after which a body's momentum change along a direction (x, y "
                    "and z in 3D, x and y in plane strain, the axis in axisymmetry) differs from "
                    "the impulse it received along it from the contact and the external forces "
                    "and the supports.");
  prm.declare_entry("momentum tolerance",
                    "1e-6",
                    Patterns::Double(),
                    "Allowed difference, relative to the run's largest momentum magnitude, the sum "
                    "of |m v| over every node and direction (not the net momentum, which is zero "
                    "for a free vibration) [-], 0..1.");
  prm.declare_entry(
      "contact event tolerance",
      "1e-4",
      Patterns::Double(),
      "With massless contact nodes (Contact/dynamics = mass-redistribution) only: a step in "
      "which pairs close or open is cut while the work of these events exceeds this fraction of "
      "the energy [-], 0..1 (1 never cuts): (1/2) the new force times the gap at the step's start "
      "for a closing pair, (1/2) the old force times the gap at its end for an opening one. With "
      "massless contact nodes the bodies do not impact, the contact force rises and falls "
      "elastically, and the event work is the time discretization's energy error at the events "
      "(the trapezoidal rule loses exactly the closing work and gains exactly the opening work), "
      "which each halving divides by about 4 (by 2 where the force drops abruptly). At the "
      "smallest step (Time integration/maximum step cuts) the step is accepted.");
  prm.leave_subsection();
}

void GuardParameters::parse_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Guards");
  energy                  = prm.get_bool("energy");
  energy_tolerance        = get_in_range(prm, "energy tolerance", "Guards", 0., 1.);
  plain_energy_tolerance  = get_in_range(prm, "plain energy tolerance", "Guards", 0., 1.);
  tensile_force           = prm.get_bool("tensile force");
  tensile_force_tolerance = get_in_range(prm, "tensile force tolerance", "Guards", 0., 1.);
  momentum                = prm.get_bool("momentum");
  momentum_tolerance      = get_in_range(prm, "momentum tolerance", "Guards", 0., 1.);
  contact_event_tolerance = get_in_range(prm, "contact event tolerance", "Guards", 0., 1.);
  prm.leave_subsection();
}
} // namespace dyncontact
