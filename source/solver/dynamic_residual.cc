#include <dyncontact/base/dimensions.h>
#include <dyncontact/solver/dynamic_residual.h>

#include <algorithm>
#include <cmath>

namespace dyncontact
{
template <int dim>
DynamicResidual<dim>::DynamicResidual(const ElasticBodies<dim>& bodies,
                                      const ContactConstraints<dim>& contact,
                                      const Vector<double>& lumped_mass,
                                      const AffineConstraints<double>& constraints)
    : bodies(bodies), contact(contact), lumped_mass(lumped_mass),
      is_fixed(lumped_mass.size(), false),
      constraint_residual(contact.multiplier_block().n_multipliers())
{
  for (types::global_dof_index i = 0; i < is_fixed.size(); ++i)
    is_fixed[i] = constraints.is_constrained(i);
}

template <int dim>
typename DynamicResidual<dim>::Figures
DynamicResidual<dim>::evaluate(const Step& step,
                               const DistributedVector& increment,
                               const DistributedVector& displacement,
                               const Vector<double>& border_displacement,
                               SaddlePointSystem<dim>* tangent)
{
  assemble(step, increment, displacement, border_displacement, tangent);
  return residual_and_figures(step, displacement);
}

template <int dim>
void DynamicResidual<dim>::keep_constant_tangent(SaddlePointSystem<dim>& tangent) const
{
  if (!bodies.has_constant_tangent())
    return;
  tangent.start_assembly();
  bodies.add_constant_tangent(tangent.matrix());
  tangent.finish_assembly();
  tangent.keep_as_constant_part();
}

template <int dim>
void DynamicResidual<dim>::assemble(const Step& step,
                                    const DistributedVector& increment,
                                    const DistributedVector& displacement,
                                    const Vector<double>& border_displacement,
                                    SaddlePointSystem<dim>* tangent)
{
  // The diagonal of an inactive pair's trivial row lambda = 0:
  // the mean inertia stiffness, the scale of K_eff's diagonal in a step with omega dt >> 1.
  const double inactive_diagonal = step.inertia_factor * lumped_mass.mean_value();
  try
  {
    // A constant K (linear bodies) is in the tangent's constant part (keep_constant_tangent()).
    const bool constant_tangent = bodies.has_constant_tangent();
    AssertThrow(tangent == nullptr || !constant_tangent || tangent->has_constant_part(),
                ExcMessage("keep_constant_tangent() was not called"));
    if (tangent != nullptr)
      tangent->start_assembly();
    bodies.assemble_internal_force(displacement,
                                   internal_force_values,
                                   tangent != nullptr && !constant_tangent ? &tangent->matrix()
                                                                           : nullptr,
                                   &strain_energy_value);
  }
  catch (const SolverFailure&)
  {
    if (tangent != nullptr)
      tangent->finish_assembly(); // flush entries added before the failure
    throw;
  }
  inertia_force.reinit(internal_force_values, /*omit_zeroing_entries=*/true);
  for_each_owned_row(increment,
                     [&](const types::global_dof_index i, const unsigned int j)
                     {
                       inertia_force.local_element(j) =
                           step.inertia_factor * lumped_mass[i] * increment.local_element(j);
                     });
  if (tangent != nullptr)
    tangent->add_to_diagonal(lumped_mass, step.inertia_factor);
  // The contact layer works on the contact border: G^T lambda there, scattered to the volume.
  const ContactBorder<dim>& border = contact.border();
  Vector<double> border_force(border.n_dofs());
  contact.add_contact_forces(border_force);
  contact_force.reinit(internal_force_values);
  border.scatter_add(border_force, contact_force);
  contact.assemble_constraint_rows(border_displacement,
                                   inactive_diagonal,
                                   tangent != nullptr ? tangent->multiplier_rows() : nullptr,
                                   constraint_residual);
  if (tangent != nullptr)
  {
    tangent->finish_assembly();
    scales = tangent->displacement_scales();
  }
}

template <int dim>
typename DynamicResidual<dim>::Figures
DynamicResidual<dim>::residual_and_figures(const Step& step, const DistributedVector& displacement)
{
  force_residual.reinit(internal_force_values, /*omit_zeroing_entries=*/true);
  double force_residual_squared = 0.;
  for_each_owned_row(force_residual,
                     [&](const types::global_dof_index i, const unsigned int j)
                     {
                       double& r = force_residual.local_element(j);
                       r         = is_fixed[i] ? 0.
                                               : inertia_force.local_element(j) +
                                             internal_force_values.local_element(j) -
                                             step.external_force.local_element(j) -
                                             contact_force.local_element(j);
                       force_residual_squared += r * r;
                     });
  force_residual_squared =
      Utilities::MPI::sum(force_residual_squared, force_residual.get_mpi_communicator());
  Figures figures{};
  // The reference force: the elastic, external and contact forces, not the inertia. At time
  // steps far beyond the periods of the small elements of a contact zone their inertia
  // c M (u - u~) is huge and unresolved; measured against it, a residual as large as the
  // contact force itself passed a loose tolerance. Below the reference, a round-off floor:
  // the terms that cancel in K u and c M u (a rigid translation has Q = 0 up to round-off
  // of the size eps max diag(K_eff) |u|), which no tolerance can go under.
  // Collective norms, one statement each: the same order on every rank.
  const double internal_norm   = internal_force_values.l2_norm();
  const double external_norm   = step.external_force.l2_norm();
  const double contact_norm    = contact_force.l2_norm();
  figures.reference_force      = internal_norm + external_norm + contact_norm;
  const double inertia_norm    = inertia_force.l2_norm();
  const double u_norm          = displacement.l2_norm();
  figures.round_off_floor      = roundoff_factor * (scales.largest_row_sum * u_norm + inertia_norm);
  figures.force_residual       = std::sqrt(force_residual_squared);
  const MultiplierBlock& block = contact.multiplier_block();
  for (unsigned int k = 0; k < block.n_pairs(); ++k)
    for (unsigned int c = 0; c < block.n_components(k); ++c)
      if (contact.is_active(k))
        figures.constraint_violation = std::max(figures.constraint_violation,
                                                std::abs(constraint_residual[block.index(k, c)]));
  // The line search's merit: the force residual and the active constraints' violations
  // turned into forces by the stiffness scale; without the latter a step that closes a gap
  // but raises a small nonlinear force residual would be rejected forever.
  double constraint_force_squared = 0.;
  for (unsigned int k = 0; k < block.n_pairs(); ++k)
    for (unsigned int c = 0; c < block.n_components(k); ++c)
      constraint_force_squared += std::pow((contact.is_active(k) ? scales.largest_diagonal : 1.) *
                                               constraint_residual[block.index(k, c)],
                                           2);
  figures.merit = std::sqrt(force_residual_squared + constraint_force_squared);
  return figures;
}

DYNCONTACT_INSTANTIATE_CLASS(DynamicResidual)
} // namespace dyncontact
