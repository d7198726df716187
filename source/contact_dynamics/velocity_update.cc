#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact_dynamics/pair_mass_system.h>
#include <dyncontact/contact_dynamics/velocity_update.h>

#include <vector>

namespace dyncontact
{
template <int dim>
void VelocityUpdate<dim>::correct_rates(const RateMap& /*rates*/,
                                        const ContactConstraints<dim>& contact,
                                        const Vector<double>& lumped_mass,
                                        const StepStates& step,
                                        Vector<double>& v_new,
                                        Vector<double>& /*a_new*/) const
{
  std::vector<const ContactPair<dim>*> active;
  std::vector<double> velocity_jump;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    if (contact.is_active(k))
    {
      active.push_back(&contact.candidate_pairs()[k]);
      velocity_jump.push_back(active.back()->normal_jump(v_new));
    }
  if (active.empty())
    return;
  const unsigned int n_active = active.size();
  const PairMassSystem<dim> system(std::move(active), lumped_mass, step.is_fixed);
  const Eigen::VectorXd mu =
      system.solve(Eigen::Map<const Eigen::VectorXd>(velocity_jump.data(), n_active));
  for (unsigned int i = 0; i < system.n_nodes(); ++i)
  {
    const Tensor<1, dim> shift = system.nodal_change(i, mu);
    for (unsigned int d = 0; d < dim; ++d)
      v_new[system.node(i).dofs[d]] -= shift[d];
  }
}

DYNCONTACT_INSTANTIATE_CLASS(VelocityUpdate)
} // namespace dyncontact
