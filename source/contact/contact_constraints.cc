#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact/contact_constraints.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dyncontact
{
template <int dim>
ContactConstraints<dim>::ContactConstraints(std::vector<ContactPair<dim>> pairs,
                                            const ContactFormulation formulation)
    : pairs(std::move(pairs)), formulation(formulation), active(this->pairs.size(), false),
      multiplier_values(this->pairs.size())
{
}

template <int dim>
ContactConstraints<dim>::ContactConstraints(const ContactGeometry<dim>& geometry,
                                            const ContactFormulation formulation)
    : ContactConstraints(geometry.pairs(), formulation)
{
  this->geometry = &geometry;
  // Every geometry's constructor throws InputError instead (the run indexes its pairs).
  AssertThrow(!pairs.empty(), ExcMessage("a contact geometry without candidate pairs"));
  for (const ContactPair<dim>& pair : pairs)
    AssertThrow(std::isfinite(pair.normal.norm()),
                ExcMessage("a contact pair with a normal that is not finite"));
}

template <int dim>
void ContactConstraints<dim>::update_geometry(const Vector<double>& displacement)
{
  if (geometry != nullptr)
    geometry->update_pairs(displacement, pairs);
}

template <int dim>
void ContactConstraints<dim>::update_master_points(const Vector<double>& displacement)
{
  if (geometry != nullptr)
    geometry->update_master_points(displacement, pairs);
}

template <int dim>
void ContactConstraints<dim>::scale_penalty_stiffness(const double factor)
{
  for (auto& pair : pairs)
    pair.penalty_stiffness *= factor;
}

template <int dim>
void ContactConstraints<dim>::set_force_per_multiplier(const double factor)
{
  AssertThrow(factor > 0., ExcMessage("The force per multiplier must be positive."));
  force_factor = factor;
}

template <int dim>
unsigned int ContactConstraints<dim>::n_active() const
{
  return std::count(active.begin(), active.end(), true);
}

template <int dim>
double ContactConstraints<dim>::gap(const unsigned int pair_index,
                                    const Vector<double>& displacement) const
{
  return pairs[pair_index].gap(displacement);
}

template <int dim>
void ContactConstraints<dim>::set_reference_gaps(std::vector<double> reference)
{
  if (!reference.empty() && reference.size() != pairs.size())
    throw std::invalid_argument(
        "ContactConstraints::set_reference_gaps: " + std::to_string(reference.size()) +
        " gaps for " + std::to_string(pairs.size()) + " pairs");
  reference_gaps = std::move(reference);
}

template <int dim>
double ContactConstraints<dim>::constraint_gap(const unsigned int pair_index,
                                               const Vector<double>& displacement) const
{
  const double g = gap(pair_index, displacement);
  return reference_gaps.empty() ? g : g - reference_gaps[pair_index];
}

template <int dim>
template <typename Function>
void ContactConstraints<dim>::for_each_coupled_dof(const unsigned int k, const Function& f) const
{
  if (geometry != nullptr)
    for (const auto dof : geometry->coupled_dofs(k))
      f(dof);
  else
    pairs[k].for_each_node(
        [&](const Node<dim>& node, double)
        {
          for (unsigned int d = 0; d < dim; ++d)
            f(node.dofs[d]);
        });
}

template <int dim>
void ContactConstraints<dim>::add_to_sparsity(DynamicSparsityPattern& sparsity,
                                              const types::global_dof_index n_dofs) const
{
  for (unsigned int k = 0; k < pairs.size(); ++k)
  {
    const types::global_dof_index row = n_dofs + k;
    sparsity.add(row, row);
    for_each_coupled_dof(k,
                         [&](const types::global_dof_index dof)
                         {
                           sparsity.add(row, dof);
                           sparsity.add(dof, row);
                         });
  }
}

template <int dim>
std::vector<bool> ContactConstraints<dim>::contact_dofs(const types::global_dof_index n_dofs) const
{
  std::vector<bool> flags(n_dofs, false);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    for_each_coupled_dof(k, [&](const types::global_dof_index dof) { flags[dof] = true; });
  return flags;
}

template <int dim>
void ContactConstraints<dim>::add_contact_forces(Vector<double>& force) const
{
  // G^T lambda with G = dg/du: c_j n at the pair's nodes (-n on the slave node of body A).
  for (unsigned int k = 0; k < pairs.size(); ++k)
    pairs[k].for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          for (unsigned int d = 0; d < dim; ++d)
            force[node.dofs[d]] += coefficient * pairs[k].normal[d] * multiplier_values[k];
        });
}

template <int dim>
void ContactConstraints<dim>::assemble_constraint_rows(const Vector<double>& displacement,
                                                       const double inactive_diagonal,
                                                       TrilinosWrappers::SparseMatrix* matrix,
                                                       Vector<double>& constraint_residual) const
{
  const types::global_dof_index n_dofs = displacement.size();
  const auto add                       = [matrix](const types::global_dof_index row,
                            const types::global_dof_index column,
                            const double value)
  {
    if (matrix != nullptr)
      matrix->add(row, column, value);
  };
  for (unsigned int k = 0; k < pairs.size(); ++k)
  {
    const types::global_dof_index row = n_dofs + k;
    if (!active[k])
    {
      add(row, row, inactive_diagonal);
      constraint_residual[k] = inactive_diagonal * multiplier_values[k];
      continue;
    }
    // Rows of the symmetric system [K_eff, -G^T; -G, -D]: -G = -c_j n at the pair's nodes.
    pairs[k].for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          for (unsigned int d = 0; d < dim; ++d)
          {
            const double entry = -coefficient * pairs[k].normal[d];
            add(row, node.dofs[d], entry);
            add(node.dofs[d], row, entry);
          }
        });
    constraint_residual[k] = -constraint_gap(k, displacement);
    if (formulation == ContactFormulation::penalty)
    {
      add(row, row, -force_factor / pairs[k].penalty_stiffness);
      constraint_residual[k] -= force_factor * multiplier_values[k] / pairs[k].penalty_stiffness;
    }
  }
}

template <int dim>
void ContactConstraints<dim>::add_multiplier_increment(const Vector<double>& increment)
{
  multiplier_values += increment;
}

template <int dim>
bool ContactConstraints<dim>::update_active_set(const Vector<double>& displacement,
                                                const double gap_tolerance,
                                                const double force_tolerance)
{
  bool changed = false;
  std::vector<unsigned int> tensile_pairs;
  for (unsigned int k = 0; k < pairs.size(); ++k)
    if (!active[k] && constraint_gap(k, displacement) < -gap_tolerance)
    {
      active[k] = true;
      changed   = true;
    }
    else if (active[k] && multiplier_values[k] < -force_tolerance)
      tensile_pairs.push_back(k);
  // On a surface, a tensile nodal force inside compressed surroundings (the zero-area axis node of
  // an axisymmetric Q2 surface) is not a tensile traction: such a pair stays closed. Not so for a
  // penalty, whose tensile force means an open gap: keeping that pair would glue it.
  const bool check_pressure =
      !tensile_pairs.empty() && formulation == ContactFormulation::lagrange_multiplier;
  const std::vector<double> pressures =
      check_pressure ? contact_pressures(displacement) : std::vector<double>();
  for (const unsigned int k : tensile_pairs)
    if (pressures.empty() || !(pressures[k] > 0.)) // a zero or undefined pressure releases too
    {
      active[k]            = false;
      multiplier_values[k] = 0.;
      changed              = true;
    }
  return changed;
}

template <int dim>
std::vector<double>
ContactConstraints<dim>::contact_pressures(const Vector<double>& displacement) const
{
  if (geometry == nullptr)
    return {};
  std::vector<double> forces(pairs.size(), 0.);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    forces[k] = pair_force(k);
  return geometry->contact_pressures(displacement, forces);
}

DYNCONTACT_INSTANTIATE_CLASS(ContactConstraints)
} // namespace dyncontact
