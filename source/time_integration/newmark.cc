#include <dyncontact/time_integration/newmark.h>

#include <cmath>
#include <limits>

namespace dyncontact
{
Newmark::Newmark(const TimeIntegrationParameters& parameters)
    : beta_value(parameters.beta), gamma_value(parameters.gamma), dt(parameters.time_step)
{
  Assert(beta_value > 0., ExcMessage("beta > 0 is checked when the parameters are read."));
}

void Newmark::set_time_step(const double time_step)
{
  Assert(time_step > 0., ExcMessage("The time step must be positive."));
  dt = time_step;
}

void Newmark::predict(const Vector<double>& u_n,
                      const Vector<double>& v_n,
                      const Vector<double>& a_n,
                      Vector<double>& predictor) const
{
  const RateMap rates = rate_map();
  predictor.reinit(u_n.size(), true);
  for (types::global_dof_index i = 0; i < u_n.size(); ++i)
    predictor[i] = rates.predicted_displacement(u_n[i], v_n[i], a_n[i]);
}

void Newmark::update_rates(const Vector<double>& increment,
                           const Vector<double>& v_n,
                           const Vector<double>& a_n,
                           Vector<double>& v_new,
                           Vector<double>& a_new) const
{
  const RateMap rates = rate_map();
  a_new.reinit(increment.size(), true);
  v_new.reinit(increment.size(), true);
  for (types::global_dof_index i = 0; i < increment.size(); ++i)
  {
    a_new[i] = rates.acceleration(increment[i]);
    v_new[i] = rates.velocity(v_n[i], a_n[i], a_new[i]);
  }
}

double Newmark::algorithmic_energy(const double kinetic_energy,
                                   const double strain_energy,
                                   const double acceleration_energy) const
{
  // acceleration_energy = 1/2 a.Ma, so (beta - gamma/2) dt^2/2 a.Ma = (beta - gamma/2) dt^2
  // acceleration_energy.
  return kinetic_energy + strain_energy +
         (beta_value - 0.5 * gamma_value) * dt * dt * acceleration_energy;
}

double Newmark::stability_limit() const
{
  return 2. * beta_value < gamma_value ? 1. / std::sqrt(gamma_value / 2. - beta_value)
                                       : std::numeric_limits<double>::infinity();
}
} // namespace dyncontact
