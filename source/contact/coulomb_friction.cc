#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact/coulomb_friction.h>

#include <algorithm>
#include <cmath>

namespace dyncontact
{
namespace
{
/// The largest b / |z| the slip branch's linearization takes (assemble_rows()).
constexpr double max_slip_theta = 0.9;

/**
 * An orthonormal basis of the plane normal to the unit `normal`, its first vector along the one
 * fixed axis of `fixed_axes` where there is one (a node on a symmetry plane: that direction's
 * slip is then held by the plane, and the other one is free of it).
 */
template <int dim>
std::array<Tensor<1, dim>, dim - 1> tangent_basis(const Tensor<1, dim>& normal,
                                                  const std::array<bool, dim>& fixed_axes)
{
  std::array<Tensor<1, dim>, dim - 1> basis;
  if constexpr (dim == 2)
  {
    basis[0][0] = -normal[1];
    basis[0][1] = normal[0];
  }
  else if constexpr (dim == 3)
  {
    unsigned int axis  = 0;
    const auto n_fixed = std::count(fixed_axes.begin(), fixed_axes.end(), true);
    if (n_fixed == 1)
      axis = std::find(fixed_axes.begin(), fixed_axes.end(), true) - fixed_axes.begin();
    else
      for (unsigned int d = 1; d < dim; ++d)
        if (std::abs(normal[d]) < std::abs(normal[axis]))
          axis = d;
    Tensor<1, dim> e;
    e[axis]               = 1.;
    Tensor<1, dim> second = cross_product_3d(normal, e);
    if (second.norm() < 1e-8) // the fixed axis along the normal: any basis
    {
      e                   = Tensor<1, dim>();
      e[(axis + 1) % dim] = 1.;
      second              = cross_product_3d(normal, e);
    }
    basis[1] = second / second.norm();
    basis[0] = cross_product_3d(basis[1], normal);
  }
  return basis;
}
} // namespace

template <int dim>
CoulombFriction<dim>::CoulombFriction(std::vector<double> coefficients)
    : coefficients(std::move(coefficients)), slip_states(this->coefficients.size(), 0)
{
  for (unsigned int k = 0; k < this->coefficients.size(); ++k)
  {
    AssertThrow(this->coefficients[k] >= 0., ExcMessage("a negative friction coefficient"));
    has_friction   = has_friction || this->coefficients[k] > 0.;
    slip_states[k] = this->coefficients[k] > 0. ? 1 : 0; // pairs enter sliding (update_states())
  }
  AssertThrow(!has_friction || dim > 1, ExcMessage("friction needs a tangential direction"));
}

template <int dim>
unsigned int CoulombFriction<dim>::n_components(const unsigned int pair) const
{
  return pair < coefficients.size() && coefficients[pair] > 0. ? dim : 1;
}

template <int dim>
void CoulombFriction<dim>::start_step(const std::vector<ContactPair<dim>>& pairs,
                                      const Vector<double>& displacement,
                                      const std::vector<bool>& active,
                                      const Vector<double>& multipliers,
                                      const MultiplierBlock& block,
                                      const std::vector<double>& pair_stiffness)
{
  if (!has_friction)
    return;
  // The old forces in the bases the multipliers are in (the last step's, or a restored state's:
  // set_bases()), before the bases turn with the pairs (f applies at the end).
  start_forces.assign(pairs.size(), Tensor<1, dim>());
  for (unsigned int k = 0; k < tangents.size(); ++k)
    if (active[k] && block.n_components(k) > 1)
      for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
        start_forces[k] += tangents[k][alpha] * multipliers[block.index(k, alpha + 1)];
  start_pairs        = pairs;
  start_displacement = displacement;
  start_multipliers  = multipliers;
  stiffness          = pair_stiffness;
  tangents.resize(pairs.size());
  free_direction.resize(pairs.size());
  for (unsigned int k = 0; k < pairs.size(); ++k)
  {
    if (block.n_components(k) == 1)
      continue;
    std::array<bool, dim> fixed_axes{};
    for (unsigned int d = 0; d < dim; ++d)
      fixed_axes[d] = !fixed_dofs.empty() && fixed_dofs[pairs[k].slave.dofs[d]];
    tangents[k] = tangent_basis<dim>(pairs[k].normal, fixed_axes);
    // A direction the slave node cannot move along (mostly along its fixed DoFs: a symmetry
    // plane, the axis) carries no friction: its master point is held the same way by the
    // symmetry. Its row's couplings to free DoFs are small (the normal's tilt out of the plane, a
    // master node's small weight): kept, the row is near-singular (measured on the oblique
    // spheres: a tangential multiplier 1e-3 of the normal one along the symmetry plane's normal,
    // and Newton stalled with the gap at 1e-7).
    for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
    {
      double free_part = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        if (!fixed_axes[d])
          free_part += tangents[k][alpha][d] * tangents[k][alpha][d];
      free_direction[k][alpha] = free_part > 0.5;
    }
    // lambda_t^n in the new basis (the penalty spring's force carried into the step): the old
    // force projected, not its components reused (a basis that turns with the normal's smallest
    // component can jump by 110 degrees for a normal turning 0.008 degrees).
    for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
      start_multipliers[block.index(k, alpha + 1)] =
          free_direction[k][alpha] ? tangents[k][alpha] * start_forces[k] : 0.;
  }
}

template <int dim>
std::vector<double> CoulombFriction<dim>::bases() const
{
  std::vector<double> flat;
  for (const auto& basis : tangents)
    for (const Tensor<1, dim>& tangent : basis)
      for (unsigned int d = 0; d < dim; ++d)
        flat.push_back(tangent[d]);
  return flat;
}

template <int dim>
void CoulombFriction<dim>::set_bases(const std::vector<double>& flat)
{
  AssertThrow(flat.size() % ((dim - 1) * dim + (dim == 1)) == 0,
              ExcMessage("CoulombFriction::set_bases: not a whole number of bases"));
  tangents.assign(dim > 1 ? flat.size() / ((dim - 1) * dim) : 0, {});
  auto value = flat.begin();
  for (auto& basis : tangents)
    for (Tensor<1, dim>& tangent : basis)
      for (unsigned int d = 0; d < dim; ++d)
        tangent[d] = *value++;
}

template <int dim>
std::vector<Tensor<1, dim>> CoulombFriction<dim>::friction_directions(const unsigned int pair) const
{
  std::vector<Tensor<1, dim>> directions;
  if (pair < tangents.size() && coefficients[pair] > 0.)
    for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
      if (free_direction[pair][alpha])
        directions.push_back(tangents[pair][alpha]);
  return directions;
}

template <int dim>
Tensor<1, dim> CoulombFriction<dim>::tangential_force(const unsigned int pair,
                                                      const Vector<double>& multipliers,
                                                      const MultiplierBlock& block) const
{
  Tensor<1, dim> force;
  if (block.n_components(pair) > 1)
    for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
      force += multipliers[block.index(pair, alpha + 1)] * tangents[pair][alpha];
  return force;
}

template <int dim>
double CoulombFriction<dim>::slip(const unsigned int pair,
                                  const unsigned int alpha,
                                  const Vector<double>& u) const
{
  double s = 0.;
  for_each_slip_coefficient(pair,
                            alpha,
                            [&](const unsigned int dof, const double g)
                            { s += g * (u[dof] - start_displacement[dof]); });
  return s;
}

template <int dim>
void CoulombFriction<dim>::add_forces(const std::vector<bool>& active,
                                      const Vector<double>& multipliers,
                                      const MultiplierBlock& block,
                                      Vector<double>& force) const
{
  for (unsigned int k = 0; k < start_pairs.size(); ++k)
    if (active[k] && block.n_components(k) > 1)
      for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
        for_each_slip_coefficient(k,
                                  alpha,
                                  [&](const unsigned int dof, const double g)
                                  { force[dof] += g * multipliers[block.index(k, alpha + 1)]; });
}

template <int dim>
std::array<double, dim - 1> CoulombFriction<dim>::trial(const unsigned int pair,
                                                        const Vector<double>& u,
                                                        const Vector<double>& multipliers,
                                                        const MultiplierBlock& block,
                                                        const ContactFormulation formulation) const
{
  std::array<double, dim - 1> z{};
  for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
    if (free_direction[pair][alpha])
    {
      const unsigned int m = block.index(pair, alpha + 1);
      z[alpha] =
          (formulation == ContactFormulation::penalty ? start_multipliers[m] : multipliers[m]) -
          stiffness[pair] * slip(pair, alpha, u);
    }
  return z;
}

namespace
{
template <std::size_t n>
double norm(const std::array<double, n>& z)
{
  double squared = 0.;
  for (const double component : z)
    squared += component * component;
  return std::sqrt(squared);
}
} // namespace

template <int dim>
void CoulombFriction<dim>::assemble_rows(const Vector<double>& u,
                                         const std::vector<bool>& active,
                                         const Vector<double>& multipliers,
                                         const MultiplierBlock& block,
                                         const ContactFormulation formulation,
                                         const double inactive_diagonal,
                                         const ContactBorder<dim>& border,
                                         MultiplierRows* rows,
                                         Vector<double>& residual) const
{
  for (unsigned int k = 0; k < coefficients.size(); ++k)
  {
    if (block.n_components(k) == 1)
      continue;
    const double c = stiffness[k];
    // The slip branch's direction tau = z / |z|, bound b = mu max(lambda_n, 0), P = I - tau tau^T.
    const std::array<double, dim - 1> z = trial(k, u, multipliers, block, formulation);
    const double z_norm                 = norm(z);
    const double bound = coefficients[k] * std::max(multipliers[block.index(k)], 0.);
    const bool sliding = slip_states[k] != 0;
    for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
    {
      const unsigned int m = block.index(k, alpha + 1);
      if (!active[k] || !free_direction[k][alpha])
      {
        if (rows != nullptr)
          rows->add_diagonal(m, inactive_diagonal);
        residual[m] = inactive_diagonal * multipliers[m];
        continue;
      }
      if (!sliding) // stick: s = 0 (penalty: an elastic spring from lambda_t^n)
      {
        residual[m] = -slip(k, alpha, u);
        if (rows != nullptr)
          for_each_slip_coefficient(k,
                                    alpha,
                                    [&](const unsigned int dof, const double g)
                                    { rows->add_coupling(m, border.volume_dof(dof), -g); });
        if (formulation == ContactFormulation::penalty)
        {
          residual[m] -= (multipliers[m] - start_multipliers[m]) / c;
          if (rows != nullptr)
            rows->add_diagonal(m, -1. / c);
        }
        continue;
      }
      // Slip: (lambda_t - b tau) / c = 0, linearized in lambda_t, lambda_n and u through tau.
      const double tau = z_norm > 0. ? z[alpha] / z_norm : 0.;
      residual[m]      = (multipliers[m] - bound * tau) / c;
      if (rows == nullptr)
        continue;
      const bool bounded = bound > 0. && z_norm > 0.;
      // theta = b / |z| in d tau = P / |z| dz: the exact derivative, except near the onset of
      // slip, where |z| -> b makes I - theta P (the lambda_t block, Lagrange) singular across tau
      // and a Newton update there unbounded (measured: a tangential multiplier 1e4 times the slip
      // bound after one update, on the oblique spheres). Capped at max_slip_theta: the same
      // answer (the residual is exact), a bounded direction (cf. the modified slip Jacobian of
      // Hueber, Stadler & Wohlmuth 2008, section 3).
      const double theta    = bounded ? std::min(bound / z_norm, max_slip_theta) : 0.;
      const double lagrange = formulation == ContactFormulation::penalty ? 0. : 1.;
      for (unsigned int beta = 0; beta + 1 < dim; ++beta)
      {
        const double projection =
            (alpha == beta ? 1. : 0.) - (z_norm > 0. ? z[alpha] * z[beta] / (z_norm * z_norm) : 0.);
        const double entry = ((alpha == beta ? 1. : 0.) - lagrange * theta * projection) / c;
        if (free_direction[k][beta])
          rows->add_multiplier_coupling(m, block.index(k, beta + 1), entry);
        if (bounded)
          for_each_slip_coefficient(
              k,
              beta,
              [&](const unsigned int dof, const double g)
              { rows->add_row_coupling(m, border.volume_dof(dof), theta * projection * g); });
      }
      if (bounded)
        rows->add_multiplier_coupling(m, block.index(k), -coefficients[k] * tau / c);
      // The force's column, -G_t^T, in the displacement rows.
      for_each_slip_coefficient(k,
                                alpha,
                                [&](const unsigned int dof, const double g)
                                { rows->add_column_coupling(m, border.volume_dof(dof), -g); });
    }
  }
}

template <int dim>
bool CoulombFriction<dim>::update_states(const Vector<double>& u,
                                         const std::vector<bool>& active,
                                         const Vector<double>& multipliers,
                                         const MultiplierBlock& block,
                                         const ContactFormulation formulation,
                                         const double force_tolerance)
{
  bool changed = false;
  for (unsigned int k = 0; k < coefficients.size(); ++k)
  {
    if (block.n_components(k) == 1)
      continue;
    if (!active[k])
    {
      // A pair enters sliding, its tangential force mu lambda_n = 0 at first: stick is taken
      // once its normal force is there to hold it (entering stuck, a pair closing at the release
      // of a sliding contact pulled its normal force tensile and left again, over and over, on
      // the oblique spheres).
      slip_states[k] = 1;
      continue;
    }
    const std::array<double, dim - 1> z = trial(k, u, multipliers, block, formulation);
    const double excess = norm(z) - coefficients[k] * std::max(multipliers[block.index(k)], 0.);
    // A sliding pair whose trial points against its force reverses: the answer lies between
    // the two directions, where it sticks (without this the iterates of a stuck block alternate
    // between sliding either way: the friction of one overshoots into the other).
    double along_force = 0.;
    for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
      along_force += z[alpha] * multipliers[block.index(k, alpha + 1)];
    signed char state = slip_states[k];
    if (state != 0 && along_force < 0.)
      state = 0;
    else if (excess > force_tolerance)
      state = dim == 2 ? (z[0] > 0. ? 1 : -1) : 1;
    else if (excess < -force_tolerance)
      state = 0;
    changed        = changed || state != slip_states[k];
    slip_states[k] = state;
  }
  return changed;
}

template <int dim>
double CoulombFriction<dim>::dissipation(const Vector<double>& u,
                                         const std::vector<bool>& active,
                                         const Vector<double>& multipliers,
                                         const MultiplierBlock& block,
                                         const double force_factor,
                                         const double new_weight,
                                         const ContactFormulation formulation) const
{
  double dissipated = 0.;
  for (unsigned int k = 0; k < coefficients.size(); ++k)
  {
    if (block.n_components(k) == 1)
      continue;
    Tensor<1, dim> force = (1. - new_weight) * force_factor * start_forces[k];
    if (active[k])
      for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
        force +=
            new_weight * force_factor * multipliers[block.index(k, alpha + 1)] * tangents[k][alpha];
    start_pairs[k].for_each_node(
        [&](const Node<dim>& node, const double coefficient)
        {
          for (unsigned int d = 0; d < dim; ++d)
            dissipated -=
                force[d] * coefficient * (u[node.dofs[d]] - start_displacement[node.dofs[d]]);
        });
    // A penalty's stick is an elastic spring: the energy it stores, f |lambda_t|^2 / (2 c) with
    // c = eps / f, is not dissipated.
    if (formulation == ContactFormulation::penalty)
    {
      double squared = 0.;
      if (active[k])
        for (unsigned int alpha = 0; alpha + 1 < dim; ++alpha)
          squared += std::pow(multipliers[block.index(k, alpha + 1)], 2);
      dissipated -= force_factor * (squared - start_forces[k].norm_square()) / (2. * stiffness[k]);
    }
  }
  return dissipated;
}

DYNCONTACT_INSTANTIATE_CLASS(CoulombFriction)
} // namespace dyncontact
