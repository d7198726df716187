#include <dyncontact/base/dimensions.h>
#include <dyncontact/postprocess/contact_fields.h>

#include <algorithm>
#include <cmath>

namespace dyncontact
{
namespace
{
/** The lumped mass, acceleration and Q(u) - W of the contact nodes (border vectors). */
template <int dim>
struct BorderBalance
{
  BorderBalance(const ContactBorder<dim>& border,
                const Vector<double>& lumped_mass,
                const DistributedVector& acceleration,
                const DistributedVector& net_internal_force)
      : mass(border.gather(lumped_mass)), acceleration(border.gather(acceleration)),
        net_force(border.gather(net_internal_force))
  {
  }

  /**
   * n . (M a + Q(u) - W) at `node` (a border node): the equation-of-motion balance along n, i.e.
   * minus the contact force on a body-A node and plus that on a body-B node.
   */
  double along(const Node<dim>& node, const Tensor<1, dim>& normal) const
  {
    double balance = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      balance +=
          normal[d] * (mass[node.dofs[d]] * acceleration[node.dofs[d]] + net_force[node.dofs[d]]);
    return balance;
  }

  const Vector<double> mass, acceleration, net_force;
};
} // namespace

template <int dim>
ContactFields<dim>::ContactFields(const ContactConstraints<dim>& contact) : contact(contact)
{
}

template <int dim>
double
ContactFields<dim>::recovered_contact_force(const Vector<double>& lumped_mass,
                                            const DistributedVector& acceleration,
                                            const DistributedVector& net_internal_force) const
{
  const auto& pairs = contact.candidate_pairs();
  const BorderBalance<dim> balance(contact.border(), lumped_mass, acceleration, net_internal_force);
  double force = 0.;
  for (unsigned int k = 0; k < pairs.size(); ++k)
    if (contact.is_active(k))
      force -= balance.along(pairs[k].slave, pairs[k].normal);
  return force;
}

template <int dim>
typename ContactFields<dim>::SideForces
ContactFields<dim>::recovered_side_forces(const Vector<double>& lumped_mass,
                                          const DistributedVector& acceleration,
                                          const DistributedVector& net_internal_force,
                                          const Tensor<1, dim>& direction) const
{
  // Every node of an active pair between bodies counts once, on its side (a slave node on A, a
  // master node on B), however many pairs hold it (node-to-segment).
  const auto& pairs = contact.candidate_pairs();
  const BorderBalance<dim> balance(contact.border(), lumped_mass, acceleration, net_internal_force);
  SideForces forces{0., 0.};
  std::vector<bool> counted(contact.border().n_dofs(), false);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    if (contact.is_active(k) && !pairs[k].against_wall())
      pairs[k].for_each_node(
          [&](const Node<dim>& node, const double coefficient)
          {
            if (counted[node.dofs[0]])
              return;
            counted[node.dofs[0]] = true;
            const double along    = balance.along(node, direction);
            (coefficient < 0. ? forces.on_a : forces.on_b) += coefficient < 0. ? -along : along;
          });
  return forces;
}

template <int dim>
double ContactFields<dim>::total_pair_force() const
{
  double total = 0.;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    total += contact.pair_force(k);
  return total;
}

template <int dim>
double ContactFields<dim>::event_work(const DistributedVector& old_displacement,
                                      const DistributedVector& new_displacement,
                                      const typename ContactConstraints<dim>::State& old) const
{
  const Vector<double> old_border = contact.border().gather(old_displacement),
                       new_border = contact.border().gather(new_displacement);
  double work                     = 0.;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    if (contact.is_active(k) && !old.active[k])
      work += 0.5 * contact.pair_force(k) * std::max(0., contact.gap(k, old_border));
    else if (!contact.is_active(k) && old.active[k])
      work += 0.5 * contact.force_per_multiplier() *
              old.multipliers[contact.multiplier_block().index(k)] *
              std::max(0., contact.gap(k, new_border));
  return work;
}

template <int dim>
double ContactFields<dim>::max_penetration(const DistributedVector& displacement) const
{
  const Vector<double> border_displacement = contact.border().gather(displacement);
  double penetration                       = 0.;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    penetration = std::max(penetration, -contact.gap(k, border_displacement));
  return penetration;
}

template <int dim>
double ContactFields<dim>::max_active_normal_jump(const DistributedVector& field) const
{
  const Vector<double> border_field = contact.border().gather(field);
  double jump                       = 0.;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    if (contact.is_active(k))
      jump = std::max(jump, std::abs(contact.candidate_pairs()[k].normal_jump(border_field)));
  return jump;
}

template <int dim>
double ContactFields<dim>::max_stick_jump(const DistributedVector& field) const
{
  const Vector<double> border_field = contact.border().gather(field);
  double jump                       = 0.;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    for (const Tensor<1, dim>& tangent : contact.stick_directions(k))
      jump =
          std::max(jump, std::abs(contact.candidate_pairs()[k].jump_along(tangent, border_field)));
  return jump;
}

template <int dim>
double ContactFields<dim>::contact_radius(const DistributedVector& displacement) const
{
  const Vector<double> border_displacement = contact.border().gather(displacement);
  double radius                            = 0.;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    if (contact.is_active(k))
      radius = std::max(radius,
                        distance_from_axis(current_position(contact.candidate_pairs()[k].slave,
                                                            border_displacement)));
  return radius;
}

template <int dim>
DistributedVector ContactFields<dim>::traction(const std::vector<double>& pressures,
                                               const DistributedVector& layout) const
{
  Vector<double> traction(contact.border().n_dofs());
  // The slave node's pressure along -n on body A; on body B distributed to the master nodes by
  // their weights (node-to-node: the facing node's own pressure).
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
    contact.candidate_pairs()[k].for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          for (unsigned int d = 0; d < dim; ++d)
            traction[node.dofs[d]] +=
                coefficient * pressures[k] * contact.candidate_pairs()[k].normal[d];
        });
  DistributedVector volume_traction(layout.get_partitioner());
  contact.border().scatter_add(traction, volume_traction);
  return volume_traction;
}

template <int dim>
std::vector<typename FieldOutput<dim>::PressureSample>
ContactFields<dim>::pressure_samples(const std::vector<double>& pressures,
                                     const DistributedVector& displacement) const
{
  const ContactBorder<dim>& border         = contact.border();
  const Vector<double> border_displacement = border.gather(displacement);
  std::vector<std::vector<double>> shear(dim);
  if (contact.has_friction())
    for (unsigned int d = 0; d < dim; ++d)
      shear[d] = contact.shear_tractions(border_displacement, d);
  std::vector<typename FieldOutput<dim>::PressureSample> samples;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
  {
    const Node<dim>& slave = contact.candidate_pairs()[k].slave;
    Tensor<1, dim> shear_traction;
    for (unsigned int d = 0; d < dim; ++d)
      shear_traction[d] = shear[d].empty() ? 0. : shear[d][k];
    samples.push_back({border.volume_node(slave.dofs[0] / dim),
                       current_position(slave, border_displacement),
                       contact.gap(k, border_displacement),
                       contact.pair_force(k),
                       pressures[k],
                       contact.is_active(k),
                       contact.tangential_force(k),
                       shear_traction,
                       contact.is_sliding(k)});
  }
  return samples;
}

DYNCONTACT_INSTANTIATE_CLASS(ContactFields)
} // namespace dyncontact
