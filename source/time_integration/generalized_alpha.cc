#include <dyncontact/time_integration/generalized_alpha.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dyncontact
{
GeneralizedAlpha::GeneralizedAlpha(const TimeIntegrationParameters& parameters)
    : family_value(Family::newmark), alpha_m_value(0.), alpha_f_value(0.),
      beta_value(parameters.beta), gamma_value(parameters.gamma), dt(parameters.time_step)
{
  if (parameters.integrator != Family::newmark)
    *this = GeneralizedAlpha(parameters.integrator, parameters.spectral_radius, dt);
  Assert(beta_value > 0., ExcMessage("beta > 0 is checked when the parameters are read."));
}

GeneralizedAlpha::GeneralizedAlpha(const Family family,
                                   const double spectral_radius,
                                   const double time_step)
    : family_value(family), rho_inf(spectral_radius), dt(time_step)
{
  const double rho = spectral_radius;
  AssertThrow(time_step > 0., ExcMessage("The time step must be positive."));
  AssertThrow(family != Family::newmark,
              ExcMessage("Newmark is given by (beta, gamma), not by a spectral radius."));
  const double lowest = lowest_spectral_radius(family);
  AssertThrow(rho >= lowest && rho <= 1.,
              ExcMessage("The spectral radius at infinite frequency must lie in [" +
                         format_number(lowest) + ", 1], not " + format_number(rho) + "."));
  // The one map from rho_inf to the coefficients (see the header for the sources).
  switch (family)
  {
  case Family::hht:
    alpha_m_value = 0.;
    alpha_f_value = (1. - rho) / (1. + rho);
    break;
  case Family::bossak:
    alpha_m_value = (rho - 1.) / (rho + 1.);
    alpha_f_value = 0.;
    break;
  case Family::generalized_alpha:
    alpha_m_value = (2. * rho - 1.) / (rho + 1.);
    alpha_f_value = rho / (rho + 1.);
    break;
  case Family::newmark:
    break;
  }
  // Second order for gamma = 1/2 - alpha_m + alpha_f; this beta maximizes the high-frequency
  // dissipation (Chung & Hulbert 1993; for hht and bossak it is their original choice).
  gamma_value = 0.5 - alpha_m_value + alpha_f_value;
  beta_value  = 0.25 * (1. - alpha_m_value + alpha_f_value) * (1. - alpha_m_value + alpha_f_value);
}

void GeneralizedAlpha::set_time_step(const double time_step)
{
  Assert(time_step > 0., ExcMessage("The time step must be positive."));
  dt = time_step;
}

double GeneralizedAlpha::inertia_factor() const
{
  // (1 - 0) / (1 - 0) is exactly 1, so newmark gets 1 / (beta dt^2) bit for bit.
  return (1. - alpha_m_value) / (1. - alpha_f_value) * rate_map().da_du();
}

void GeneralizedAlpha::predict(const DistributedVector& u_n,
                               const DistributedVector& v_n,
                               const DistributedVector& a_n,
                               DistributedVector& predictor) const
{
  const RateMap rates = rate_map();
  predictor.reinit(u_n, true);
  for (unsigned int i = 0; i < u_n.locally_owned_size(); ++i)
    predictor.local_element(i) = rates.predicted_displacement(
        u_n.local_element(i), v_n.local_element(i), a_n.local_element(i));
}

void GeneralizedAlpha::effective_force(const DistributedVector& external_force,
                                       const DistributedVector& old_inertia_force,
                                       const DistributedVector& old_internal_force,
                                       DistributedVector& effective) const
{
  AssertDimension(old_inertia_force.locally_owned_size(), external_force.locally_owned_size());
  AssertDimension(old_internal_force.locally_owned_size(), external_force.locally_owned_size());
  effective.reinit(external_force, true);
  for (unsigned int i = 0; i < external_force.locally_owned_size(); ++i)
    effective.local_element(i) =
        (external_force.local_element(i) - alpha_m_value * old_inertia_force.local_element(i) -
         alpha_f_value * old_internal_force.local_element(i)) /
        (1. - alpha_f_value);
}

void GeneralizedAlpha::update_rates(const DistributedVector& increment,
                                    const DistributedVector& v_n,
                                    const DistributedVector& a_n,
                                    DistributedVector& v_new,
                                    DistributedVector& a_new) const
{
  const RateMap rates = rate_map();
  a_new.reinit(increment, true);
  v_new.reinit(increment, true);
  for (unsigned int i = 0; i < increment.locally_owned_size(); ++i)
  {
    a_new.local_element(i) = rates.acceleration(increment.local_element(i));
    v_new.local_element(i) =
        rates.velocity(v_n.local_element(i), a_n.local_element(i), a_new.local_element(i));
  }
}

double GeneralizedAlpha::algorithmic_energy(const double kinetic_energy,
                                            const double strain_energy,
                                            const double acceleration_energy,
                                            const double residual_energy) const
{
  // acceleration_energy = 1/2 a.Ma, so (beta - gamma/2) dt^2/2 a.Ma = (beta - gamma/2) dt^2
  // acceleration_energy.
  const double energy = kinetic_energy + strain_energy +
                        (beta_value - 0.5 * gamma_value) * dt * dt * acceleration_energy;
  if (alpha_f_value == alpha_m_value)
    return energy;
  return energy + (0.5 - alpha_f_value) / (alpha_f_value - alpha_m_value) * residual_energy;
}

double GeneralizedAlpha::stability_limit() const
{
  return 2. * beta_value < gamma_value ? 1. / std::sqrt(gamma_value / 2. - beta_value)
                                       : std::numeric_limits<double>::infinity();
}
double GeneralizedAlpha::lowest_spectral_radius(const Family family)
{
  return family == Family::hht ? 0.5 : 0.;
}

std::string GeneralizedAlpha::description(const int precision) const
{
  std::ostringstream text;
  text << std::setprecision(precision);
  if (family_value == Family::newmark)
    text << "Newmark (beta = " << beta_value << ", gamma = " << gamma_value << ")";
  else
    text << integrator_family_names().name(family_value) << " (rho_inf = " << rho_inf
         << ": alpha_m = " << alpha_m_value << ", alpha_f = " << alpha_f_value
         << ", beta = " << beta_value << ", gamma = " << gamma_value << ")";
  return text.str();
}
} // namespace dyncontact
