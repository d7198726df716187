#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/mass_redistribution.h>

namespace dyncontact
{
template <int dim>
void MassRedistribution<dim>::correct_rates(const RateMap& rates,
                                            const ContactConstraints<dim>&,
                                            const Vector<double>& lumped_mass,
                                            const StepStates& step,
                                            Vector<double>& v_new,
                                            Vector<double>& a_new) const
{
  for (types::global_dof_index i = 0; i < lumped_mass.size(); ++i)
    if (lumped_mass[i] == 0.)
    {
      v_new[i] = (step.new_displacement[i] - step.old_displacement[i]) / rates.time_step;
      a_new[i] = (v_new[i] - step.old_velocity[i]) / rates.time_step;
    }
}

DYNCONTACT_INSTANTIATE_CLASS(MassRedistribution)
} // namespace dyncontact
