#include <dyncontact/discretization/elastic_bodies.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <cmath>

namespace dyncontact
{
namespace
{
/** Displacement value and gradient of a vector field at one quadrature point. */
template <int dim>
struct PointDisplacement
{
  Tensor<1, dim> value;
  Tensor<2, dim> gradient;
};

template <int dim>
PointDisplacement<dim>
interpolate_displacement(const FEValues<dim>& fe_values,
                         const std::vector<types::global_dof_index>& local_dofs,
                         const Vector<double>& displacement,
                         const unsigned int q)
{
  const FiniteElement<dim>& fe = fe_values.get_fe();
  PointDisplacement<dim> result;
  for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
  {
    const unsigned int component = fe.system_to_component_index(i).first;
    const double nodal           = displacement[local_dofs[i]];
    result.value[component] += nodal * fe_values.shape_value(i, q);
    result.gradient[component] += nodal * fe_values.shape_grad(i, q);
  }
  return result;
}

/** One cell's force vector and tangent matrix, with the work arrays of their integration. */
struct CellContribution
{
  explicit CellContribution(const unsigned int n_local)
      : force(n_local), tangent(n_local, n_local), variations(n_local),
        tangent_times_variation(n_local)
  {
  }

  Vector<double> force;
  FullMatrix<double> tangent;
  std::vector<Tensor<2, 3>> variations;
  std::vector<Tensor<2, 3>> tangent_times_variation;
};

/**
 * Adds one quadrature point's share to a cell's internal force, P : delta F_i dV, and, if
 * `with_tangent`, to its tangent, delta F_i : dP/dF : delta F_j dV; F is the deformation gradient
 * at the point, X its reference position.
 */
template <int dim>
void add_point_contribution(const Kinematics<dim>& kinematics,
                            const Material& material,
                            const FEValues<dim>& fe_values,
                            const unsigned int q,
                            const Tensor<2, 3>& F,
                            const double dV,
                            const bool with_tangent,
                            CellContribution& cell)
{
  const FiniteElement<dim>& fe = fe_values.get_fe();
  const unsigned int n_local   = fe.n_dofs_per_cell();
  const Point<dim>& X          = fe_values.quadrature_point(q);
  const Tensor<2, 3> P         = material.first_piola_kirchhoff_stress(F);
  for (unsigned int i = 0; i < n_local; ++i)
    cell.variations[i] =
        kinematics.deformation_gradient_variation(fe.system_to_component_index(i).first,
                                                  fe_values.shape_value(i, q),
                                                  fe_values.shape_grad(i, q),
                                                  X);
  for (unsigned int i = 0; i < n_local; ++i)
    cell.force[i] += scalar_product(P, cell.variations[i]) * dV;
  if (!with_tangent)
    return;
  const Tensor<4, 3> dP_dF = material.stress_tangent(F);
  for (unsigned int j = 0; j < n_local; ++j)
    cell.tangent_times_variation[j] = double_contract<2, 0, 3, 1>(dP_dF, cell.variations[j]);
  for (unsigned int i = 0; i < n_local; ++i)
    for (unsigned int j = 0; j < n_local; ++j)
      cell.tangent(i, j) +=
          scalar_product(cell.variations[i], cell.tangent_times_variation[j]) * dV;
}
} // namespace

template <int dim>
ElasticBodies<dim>::ElasticBodies(const DoFHandler<dim>& dof_handler,
                                  const Mapping<dim>& mapping,
                                  const Kinematics<dim>& kinematics,
                                  std::vector<BodyMaterial> bodies)
    : dof_handler(dof_handler), mapping(mapping), kinematics(kinematics), bodies(std::move(bodies))
{
  for (const auto& cell : dof_handler.active_cell_iterators())
    AssertThrow(cell->material_id() < this->bodies.size(),
                ExcMessage("A cell has material id " + std::to_string(cell->material_id()) +
                           " but only " + std::to_string(this->bodies.size()) +
                           " bodies are defined."));
}

template <int dim>
Vector<double> ElasticBodies<dim>::lumped_mass() const
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  // Exact for rho phi_i^2 times the (at most linear) measure factor on affine cells.
  const QGauss<dim> quadrature(fe.degree + 2);
  FEValues<dim> fe_values(
      mapping, fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
  const unsigned int n_local = fe.n_dofs_per_cell();
  Vector<double> mass(dof_handler.n_dofs());
  std::vector<types::global_dof_index> local_dofs(n_local);
  std::vector<double> consistent_diagonal(n_local);
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned())
      continue;
    fe_values.reinit(cell);
    cell->get_dof_indices(local_dofs);
    const double density = bodies[cell->material_id()].density;
    double cell_mass     = 0.;
    std::fill(consistent_diagonal.begin(), consistent_diagonal.end(), 0.);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const double weight =
          density * fe_values.JxW(q) *
          kinematics.measure_factor(fe_values.quadrature_point(q), cell->material_id());
      cell_mass += weight;
      for (unsigned int i = 0; i < n_local; ++i)
        consistent_diagonal[i] += weight * std::pow(fe_values.shape_value(i, q), 2);
    }
    // Every component carries the whole cell mass: scale its diagonal entries to sum to it.
    std::vector<double> diagonal_sum(fe.n_components(), 0.);
    for (unsigned int i = 0; i < n_local; ++i)
      diagonal_sum[fe.system_to_component_index(i).first] += consistent_diagonal[i];
    for (unsigned int i = 0; i < n_local; ++i)
      mass[local_dofs[i]] +=
          consistent_diagonal[i] * cell_mass / diagonal_sum[fe.system_to_component_index(i).first];
  }
  sum_over_ranks(mass);
  return mass;
}

template <int dim>
void ElasticBodies<dim>::sum_over_ranks(Vector<double>& values) const
{
  const MPI_Comm communicator = dof_handler.get_triangulation().get_communicator();
  // deal.II allows the input and output views to be the same memory (MPI_IN_PLACE).
  Utilities::MPI::sum(ArrayView<const double>(values.begin(), values.size()),
                      communicator,
                      ArrayView<double>(values.begin(), values.size()));
}

template <int dim>
void ElasticBodies<dim>::assemble_internal_force(const Vector<double>& displacement,
                                                 Vector<double>& internal_force,
                                                 TrilinosWrappers::SparseMatrix* tangent,
                                                 double* strain_energy) const
{
  integrate(displacement, &internal_force, tangent, strain_energy);
}

template <int dim>
double ElasticBodies<dim>::strain_energy(const Vector<double>& displacement) const
{
  double energy = 0.;
  integrate(displacement, nullptr, nullptr, &energy);
  return energy;
}

template <int dim>
void ElasticBodies<dim>::integrate(const Vector<double>& displacement,
                                   Vector<double>* internal_force,
                                   TrilinosWrappers::SparseMatrix* tangent,
                                   double* strain_energy) const
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const QGauss<dim> quadrature(fe.degree + 1);
  FEValues<dim> fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
  const unsigned int n_local = fe.n_dofs_per_cell();
  std::vector<types::global_dof_index> local_dofs(n_local);
  CellContribution cell_contribution(n_local);

  if (internal_force != nullptr)
    internal_force->reinit(dof_handler.n_dofs());
  if (strain_energy != nullptr)
    *strain_energy = 0.;
  // A failing material point (an inverted element) must not leave this rank out of the
  // collective sums below: remember the failure, finish the collectives, then fail on all ranks.
  std::string failure;
  try
  {
    for (const auto& cell : dof_handler.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      fe_values.reinit(cell);
      cell->get_dof_indices(local_dofs);
      cell_contribution.force   = 0.;
      cell_contribution.tangent = 0.;
      const Material& material  = *bodies[cell->material_id()].material;
      for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const Point<dim>& X = fe_values.quadrature_point(q);
        const PointDisplacement<dim> u =
            interpolate_displacement(fe_values, local_dofs, displacement, q);
        const Tensor<2, 3> F = kinematics.deformation_gradient(u.gradient, u.value, X);
        const double dV      = fe_values.JxW(q) * kinematics.measure_factor(X, cell->material_id());
        if (strain_energy != nullptr)
          *strain_energy += material.strain_energy_density(F) * dV;
        if (internal_force != nullptr || tangent != nullptr)
          add_point_contribution(
              kinematics, material, fe_values, q, F, dV, tangent != nullptr, cell_contribution);
      }
      if (internal_force != nullptr)
        for (unsigned int i = 0; i < n_local; ++i)
          (*internal_force)[local_dofs[i]] += cell_contribution.force[i];
      if (tangent != nullptr)
        tangent->add(local_dofs, cell_contribution.tangent);
    }
  }
  catch (const SolverFailure& error)
  {
    failure = error.what();
  }
  if (internal_force != nullptr)
    sum_over_ranks(*internal_force);
  if (strain_energy != nullptr)
    *strain_energy =
        Utilities::MPI::sum(*strain_energy, dof_handler.get_triangulation().get_communicator());
  const MPI_Comm communicator = dof_handler.get_triangulation().get_communicator();
  if (Utilities::MPI::max(failure.empty() ? 0 : 1, communicator) > 0)
    throw SolverFailure(failure.empty() ? "a material point failed on another MPI rank." : failure);
}

template class ElasticBodies<1>;
template class ElasticBodies<2>;
template class ElasticBodies<3>;
} // namespace dyncontact
