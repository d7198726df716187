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
    : volume_pairs(std::move(pairs)), formulation(formulation), active(volume_pairs.size(), false),
      friction(std::vector<double>(volume_pairs.size(), 0.))
{
  std::vector<std::vector<Node<dim>>> nodes_of_pairs(volume_pairs.size());
  for (unsigned int k = 0; k < volume_pairs.size(); ++k)
    volume_pairs[k].for_each_node([&](const Node<dim>& node, double)
                                  { nodes_of_pairs[k].push_back(node); });
  build_border(nodes_of_pairs);
}

template <int dim>
ContactConstraints<dim>::ContactConstraints(const ContactGeometry<dim>& geometry,
                                            const ContactFormulation formulation)
    : ContactConstraints(geometry, formulation, std::vector<double>(geometry.pairs().size(), 0.))
{
}

template <int dim>
ContactConstraints<dim>::ContactConstraints(const ContactGeometry<dim>& geometry,
                                            const ContactFormulation formulation,
                                            std::vector<double> friction_coefficients)
    : volume_pairs(geometry.pairs()), geometry(&geometry), formulation(formulation),
      active(volume_pairs.size(), false), friction(std::move(friction_coefficients))
{
  AssertThrow(friction.states().size() == volume_pairs.size(),
              ExcMessage("one friction coefficient per contact pair"));
  // Every geometry's constructor throws InputError instead (the run indexes its pairs).
  AssertThrow(!volume_pairs.empty(), ExcMessage("a contact geometry without candidate pairs"));
  for (const ContactPair<dim>& pair : volume_pairs)
    AssertThrow(std::isfinite(pair.normal.norm()),
                ExcMessage("a contact pair with a normal that is not finite"));
  std::vector<std::vector<Node<dim>>> nodes_of_pairs;
  for (unsigned int k = 0; k < volume_pairs.size(); ++k)
    nodes_of_pairs.push_back(geometry.coupled_nodes(k));
  build_border(nodes_of_pairs, geometry.surface_nodes());
}

template <int dim>
void ContactConstraints<dim>::build_border(
    const std::vector<std::vector<Node<dim>>>& nodes_of_pairs,
    const std::vector<Node<dim>>& surface_nodes)
{
  std::vector<Node<dim>> all_nodes;
  for (const auto& nodes : nodes_of_pairs)
    all_nodes.insert(all_nodes.end(), nodes.begin(), nodes.end());
  // The pairs' nodes first: where a node is in both, a pair's copy gives the position.
  all_nodes.insert(all_nodes.end(), surface_nodes.begin(), surface_nodes.end());
  contact_border = ContactBorder<dim>(all_nodes);
  for (const auto& nodes : nodes_of_pairs)
  {
    std::vector<unsigned int> indices;
    for (const Node<dim>& node : nodes)
      indices.push_back(contact_border.index(node));
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    coupled_nodes.push_back(std::move(indices));
  }
  // One multiplier per pair, the normal constraint's, and dim - 1 tangential ones with friction.
  std::vector<unsigned int> components;
  for (unsigned int k = 0; k < volume_pairs.size(); ++k)
    components.push_back(friction.n_components(k));
  block = MultiplierBlock(components);
  multiplier_values.reinit(block.n_multipliers());
  move_pairs_to_border();
}

template <int dim>
void ContactConstraints<dim>::move_pairs_to_border()
{
  // The border DoFs only: a node's position (and body) stay the pair's own, which a geometry may
  // have moved (bodies touching at the start).
  pairs = volume_pairs;
  for (ContactPair<dim>& pair : pairs)
  {
    pair.slave.dofs = contact_border.node(contact_border.index(pair.slave)).dofs;
    for (MasterNode<dim>& master : pair.masters)
      master.node.dofs = contact_border.node(contact_border.index(master.node)).dofs;
  }
}

template <int dim>
void ContactConstraints<dim>::update_geometry(const Vector<double>& displacement)
{
  if (geometry != nullptr)
  {
    geometry->update_pairs(BorderDisplacement<dim>{contact_border, displacement}, volume_pairs);
    move_pairs_to_border();
  }
  if (!friction.any())
    return;
  // The NCP's stiffness c: the pairs' penalty scale (Lagrange; any c > 0 gives the same answer,
  // this one keeps lambda_t and c s alike in size), or the penalty's own tangential spring.
  double largest = 0.;
  for (const ContactPair<dim>& pair : pairs)
    largest = std::max(largest, pair.penalty_stiffness);
  std::vector<double> stiffness;
  for (const ContactPair<dim>& pair : pairs)
  {
    const double eps = formulation == ContactFormulation::penalty && pair.penalty_stiffness > 0.
                           ? pair.penalty_stiffness
                           : largest;
    stiffness.push_back(eps > 0. ? eps / force_factor : 1.);
  }
  friction.start_step(pairs, displacement, active, multiplier_values, block, stiffness);
}

template <int dim>
double ContactConstraints<dim>::frictional_dissipation(const Vector<double>& displacement,
                                                       const double new_weight) const
{
  return friction.any() ? friction.dissipation(displacement,
                                               active,
                                               multiplier_values,
                                               block,
                                               force_factor,
                                               new_weight,
                                               formulation)
                        : 0.;
}

template <int dim>
std::vector<signed char> ContactConstraints<dim>::active_set() const
{
  std::vector<signed char> set(pairs.size(), 0);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    if (active[k])
      set[k] = 2 + friction.states()[k];
  return set;
}

template <int dim>
void ContactConstraints<dim>::update_master_points(const Vector<double>& displacement,
                                                   const bool move_normals)
{
  if (geometry == nullptr)
    return;
  geometry->update_master_points(BorderDisplacement<dim>{contact_border, displacement},
                                 volume_pairs,
                                 move_normals && turning_normals);
  move_pairs_to_border();
}

template <int dim>
void ContactConstraints<dim>::scale_penalty_stiffness(const double factor)
{
  for (auto* some_pairs : {&volume_pairs, &pairs})
    for (auto& pair : *some_pairs)
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
void ContactConstraints<dim>::hold_gaps(const Vector<double>& reference, std::vector<bool> held)
{
  if (!held.empty() && held.size() != pairs.size())
    throw std::invalid_argument("ContactConstraints::hold_gaps: " + std::to_string(held.size()) +
                                " flags for " + std::to_string(pairs.size()) + " pairs");
  held_gaps     = std::move(held);
  gap_reference = reference;
}

template <int dim>
double ContactConstraints<dim>::constraint_gap(const unsigned int pair_index,
                                               const Vector<double>& displacement) const
{
  const double g = gap(pair_index, displacement);
  return held_gaps.empty() || !held_gaps[pair_index] ? g : g - gap(pair_index, gap_reference);
}

template <int dim>
std::vector<bool> ContactConstraints<dim>::contact_dofs(const types::global_dof_index n_dofs) const
{
  std::vector<bool> flags(n_dofs, false);
  for (const std::vector<unsigned int>& nodes : coupled_nodes)
    for (const unsigned int node : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        flags[contact_border.volume_node(node).dofs[d]] = true;
  return flags;
}

template <int dim>
void ContactConstraints<dim>::add_contact_forces(Vector<double>& force) const
{
  // G^T lambda with G = dg/du: c_j n at the pair's nodes (-n on the slave node of body A); the
  // tangential forces of pairs with friction below.
  for (unsigned int k = 0; k < pairs.size(); ++k)
    pairs[k].for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          for (unsigned int d = 0; d < dim; ++d)
            force[node.dofs[d]] +=
                coefficient * pairs[k].normal[d] * multiplier_values[block.index(k)];
        });
  if (friction.any())
    friction.add_forces(active, multiplier_values, block, force);
}

template <int dim>
void ContactConstraints<dim>::assemble_constraint_rows(const Vector<double>& displacement,
                                                       const double inactive_diagonal,
                                                       MultiplierRows* rows,
                                                       Vector<double>& constraint_residual) const
{
  for (unsigned int k = 0; k < pairs.size(); ++k)
  {
    const unsigned int multiplier = block.index(k);
    if (!active[k])
    {
      if (rows != nullptr)
        rows->add_diagonal(multiplier, inactive_diagonal);
      constraint_residual[multiplier] = inactive_diagonal * multiplier_values[multiplier];
      continue;
    }
    // Rows of the symmetric system [K_eff, -G^T; -G, -D]: -G = -c_j n at the pair's nodes.
    if (rows != nullptr)
      pairs[k].for_each_node(
          [&](const Node<dim>& node, const double coefficient)
          {
            for (unsigned int d = 0; d < dim; ++d)
              rows->add_coupling(multiplier,
                                 contact_border.volume_dof(node.dofs[d]),
                                 -coefficient * pairs[k].normal[d]);
          });
    constraint_residual[multiplier] = -constraint_gap(k, displacement);
    if (formulation == ContactFormulation::penalty)
    {
      if (rows != nullptr)
        rows->add_diagonal(multiplier, -force_factor / pairs[k].penalty_stiffness);
      constraint_residual[multiplier] -=
          force_factor * multiplier_values[multiplier] / pairs[k].penalty_stiffness;
    }
  }
  if (friction.any())
    friction.assemble_rows(displacement,
                           active,
                           multiplier_values,
                           block,
                           formulation,
                           inactive_diagonal,
                           contact_border,
                           rows,
                           constraint_residual);
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
  AssertDimension(displacement.size(), contact_border.n_dofs());
  bool changed = false;
  std::vector<unsigned int> tensile_pairs;
  for (unsigned int k = 0; k < pairs.size(); ++k)
    if (!active[k] && constraint_gap(k, displacement) < -gap_tolerance)
    {
      active[k] = true;
      changed   = true;
    }
    else if (active[k] && multiplier_values[block.index(k)] < -force_tolerance)
      tensile_pairs.push_back(k);
  // On a surface, a tensile nodal force inside compressed surroundings (the zero-area axis node of
  // an axisymmetric Q2 surface) is not a tensile traction: such a pair stays closed. Not so for a
  // penalty, whose tensile force means an open gap: keeping that pair would glue it. Nor for a
  // pair carrying friction: Coulomb's nodal law has no stick branch at a tensile normal force, and
  // its slip branch would pull along the slip; kept closed, the pair has a solution in neither,
  // and Newton alternated between them (a side-pushed block on Newmark at dt = 0.05: one corner
  // pair stuck at lambda_n = -1.4e-3 and slid at +2.7e-2 for 25 solves, exit 3 after 10 cuts).
  const auto pressure_decides = [&](const unsigned int k)
  {
    return formulation == ContactFormulation::lagrange_multiplier &&
           friction.friction_directions(k).empty();
  };
  const std::vector<double> pressures =
      std::any_of(tensile_pairs.begin(), tensile_pairs.end(), pressure_decides)
          ? contact_pressures(displacement)
          : std::vector<double>();
  for (const unsigned int k : tensile_pairs)
    // A zero or undefined pressure releases too, and so does a pair without one (fixed normals).
    if (!pressure_decides(k) || pressures.empty() || !(pressures[k] > 0.))
    {
      active[k] = false;
      for (unsigned int c = 0; c < block.n_components(k); ++c)
        multiplier_values[block.index(k, c)] = 0.;
      changed = true;
    }
  if (friction.any())
    changed = friction.update_states(
                  displacement, active, multiplier_values, block, formulation, force_tolerance) ||
              changed;
  return changed;
}

template <int dim>
std::vector<double>
ContactConstraints<dim>::contact_pressures(const Vector<double>& displacement) const
{
  std::vector<double> forces(pairs.size(), 0.);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    forces[k] = pair_force(k);
  return pressures_of(displacement, forces);
}

template <int dim>
unsigned int ContactConstraints<dim>::first_prescribed_active_pair() const
{
  for (unsigned int k = 0; k < pairs.size(); ++k)
  {
    bool prescribed = false, slave = true; // for_each_node() visits the slave node first
    if (active[k] && !prescribed_dofs.empty())
      pairs[k].for_each_node(
          [&](const Node<dim>& node, const double coefficient)
          {
            const bool master_with_friction = !slave && friction_coefficient(k) > 0.;
            slave                           = false;
            if (std::abs(coefficient) <= 1e-8) // a master node the projection hardly weighs
              return;
            for (unsigned int d = 0; d < dim; ++d)
              if (prescribed_dofs[node.dofs[d]])
                prescribed = prescribed || master_with_friction ||
                             pairs[k].normal[d] * pairs[k].normal[d] > 1e-6;
          });
    if (prescribed)
      return k;
  }
  return pairs.size();
}

template <int dim>
std::vector<double> ContactConstraints<dim>::shear_tractions(const Vector<double>& displacement,
                                                             const unsigned int component) const
{
  std::vector<double> forces(pairs.size(), 0.);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    forces[k] = tangential_force(k)[component];
  return pressures_of(displacement, forces);
}

template <int dim>
std::vector<double> ContactConstraints<dim>::pressures_of(const Vector<double>& displacement,
                                                          const std::vector<double>& forces) const
{
  if (geometry == nullptr)
    return {};
  return geometry->contact_pressures(BorderDisplacement<dim>{contact_border, displacement}, forces);
}

DYNCONTACT_INSTANTIATE_CLASS(ContactConstraints)
} // namespace dyncontact
