#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/sum_over_ranks.h>
#include <dyncontact/discretization/elastic_bodies.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <Eigen/Dense>
#include <algorithm>
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

/** The displacement and its gradient at quadrature point q of a cell (n_local DoFs). */
template <int dim>
PointDisplacement<dim> interpolate_displacement(const std::vector<unsigned int>& local_component,
                                                const double* shape_values,
                                                const Tensor<1, dim>* shape_gradients,
                                                const double* nodal_values)
{
  PointDisplacement<dim> result;
  for (unsigned int i = 0; i < local_component.size(); ++i)
  {
    const unsigned int component = local_component[i];
    result.value[component] += nodal_values[i] * shape_values[i];
    result.gradient[component] += nodal_values[i] * shape_gradients[i];
  }
  return result;
}

/** One cell's force vector, tangent matrix and energy, with the work arrays of their integration.
 */
struct CellContribution
{
  explicit CellContribution(const unsigned int n_local)
      : nodal_values(n_local), force(n_local), tangent(n_local, n_local),
        tangent_times_variation(n_local)
  {
  }

  std::vector<double> nodal_values;
  Vector<double> force;
  FullMatrix<double> tangent;
  /** W(F) dV at each quadrature point, added to the total one by one in the copier (the same sum
   *  as a single loop over all points). */
  std::vector<double> energies;
  std::vector<Tensor<2, 3>> tangent_times_variation;
  /** The message of a failed material point (an inverted element), empty if none. */
  std::string failure;
  /** The index of the cell integrated (in ElasticBodies' list). */
  std::size_t cell_index = 0;
};

/** WorkStream's scratch data: none, the work arrays are part of each cell's CellContribution. */
struct NoScratch
{
};

/**
 * Adds one quadrature point's share to a cell's internal force, P : delta F_i dV, and, if
 * `with_tangent`, to its tangent, delta F_i : dP/dF : delta F_j dV; F is the deformation gradient
 * at the point and `variations` the delta F_i of its n_local DoFs. Only their nonzero entries enter
 * the products, in the order of deal.II's full tensor products, so the sums are the same to the
 * last bit at a small fraction of the work (the tangent's 18 x 729 products per point become
 * about 18 x 27).
 */
void add_point_contribution(const Material& material,
                            const SparseVariation* variations,
                            const unsigned int n_local,
                            const Tensor<2, 3>& F,
                            const double dV,
                            const bool with_tangent,
                            CellContribution& cell)
{
  const Tensor<2, 3> P = material.first_piola_kirchhoff_stress(F);
  for (unsigned int i = 0; i < n_local; ++i)
    cell.force[i] += variations[i].contract(P) * dV;
  if (!with_tangent)
    return;
  const Tensor<4, 3> dP_dF = material.stress_tangent(F);
  for (unsigned int j = 0; j < n_local; ++j)
  {
    // (dP/dF : delta F_j)_kl = sum_ab dP_klab delta F_j,ab, as deal.II's double_contract<2, 0, 3,
    // 1>.
    Tensor<2, 3>& product = cell.tangent_times_variation[j];
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = 0; l < 3; ++l)
        product[k][l] = variations[j].contract(dP_dF[k][l]);
  }
  for (unsigned int i = 0; i < n_local; ++i)
    for (unsigned int j = 0; j < n_local; ++j)
      cell.tangent(i, j) += variations[i].contract(cell.tangent_times_variation[j]) * dV;
}
/**
 * The contributions of one cell (ElasticBodies' CellData: its DoFs, quadrature points, volumes,
 * shape values, gradients and variations) at `displacement` into `copy`: the internal force if
 * `with_force`, the tangent if `with_tangent`, the strain energy of each point if `with_energy`.
 * A failing material point (an inverted element) leaves its message in copy.failure.
 */
template <int dim, typename CellData>
void integrate_one_cell(const CellData& cell,
                        const Material& material,
                        const Kinematics<dim>& kinematics,
                        const std::vector<unsigned int>& local_component,
                        const DistributedVector& displacement,
                        const bool with_force,
                        const bool with_tangent,
                        const bool with_energy,
                        CellContribution& copy)
{
  const unsigned int n_local = local_component.size();
  copy.force                 = 0.;
  copy.tangent               = 0.;
  copy.energies.resize(cell.volumes.size());
  copy.failure.clear();
  for (unsigned int i = 0; i < n_local; ++i)
    copy.nodal_values[i] = displacement.local_element(cell.local_dofs[i]);
  try
  {
    for (unsigned int q = 0; q < cell.volumes.size(); ++q)
    {
      const double* values            = &cell.shape_values[q * n_local];
      const Tensor<1, dim>* gradients = &cell.shape_gradients[q * n_local];
      const Point<dim>& X             = cell.points[q];
      const PointDisplacement<dim> u =
          interpolate_displacement(local_component, values, gradients, copy.nodal_values.data());
      const Tensor<2, 3> F = kinematics.deformation_gradient(u.gradient, u.value, X);
      const double dV      = cell.volumes[q];
      if (with_energy)
        copy.energies[q] = material.strain_energy_density(F) * dV;
      if (with_force)
        add_point_contribution(
            material, &cell.variations[q * n_local], n_local, F, dV, with_tangent, copy);
    }
  }
  catch (const SolverFailure& error)
  {
    copy.failure = error.what();
  }
}
} // namespace

template <int dim>
ElasticBodies<dim>::ElasticBodies(const DoFHandler<dim>& dof_handler,
                                  const Mapping<dim>& mapping,
                                  const Kinematics<dim>& kinematics,
                                  std::vector<BodyMaterial> bodies,
                                  const AffineConstraints<double>* constraints)
    : dof_handler(dof_handler), mapping(mapping), kinematics(kinematics), bodies(std::move(bodies)),
      constraints(constraints)
{
  for (const auto& cell : dof_handler.active_cell_iterators())
    AssertThrow(cell->material_id() < this->bodies.size(),
                ExcMessage("A cell has material id " + std::to_string(cell->material_id()) +
                           " but only " + std::to_string(this->bodies.size()) +
                           " bodies are defined."));

  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const QGauss<dim> quadrature(fe.degree + 1);
  FEValues<dim> fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
  const unsigned int n_local = fe.n_dofs_per_cell();
  const unsigned int n_q     = quadrature.size();
  for (unsigned int i = 0; i < n_local; ++i)
    local_component.push_back(fe.system_to_component_index(i).first);
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned())
      continue;
    fe_values.reinit(cell);
    CellData data{cell->material_id(),
                  std::vector<types::global_dof_index>(n_local),
                  {},
                  std::vector<Point<dim>>(n_q),
                  std::vector<double>(n_q),
                  std::vector<double>(n_q * n_local),
                  std::vector<Tensor<1, dim>>(n_q * n_local),
                  std::vector<SparseVariation>(n_q * n_local)};
    cell->get_dof_indices(data.dofs);
    for (unsigned int q = 0; q < n_q; ++q)
    {
      data.points[q]  = fe_values.quadrature_point(q);
      data.volumes[q] = fe_values.JxW(q) * kinematics.measure_factor(data.points[q], data.body);
      for (unsigned int i = 0; i < n_local; ++i)
      {
        data.shape_values[q * n_local + i]    = fe_values.shape_value(i, q);
        data.shape_gradients[q * n_local + i] = fe_values.shape_grad(i, q);
        data.variations[q * n_local + i] =
            SparseVariation(kinematics.deformation_gradient_variation(local_component[i],
                                                                      fe_values.shape_value(i, q),
                                                                      fe_values.shape_grad(i, q),
                                                                      data.points[q]));
      }
    }
    cells.push_back(std::move(data));
  }
  IndexSet cell_dofs(dof_handler.n_dofs());
  for (const CellData& data : cells)
  {
    std::vector<types::global_dof_index> sorted = data.dofs;
    std::sort(sorted.begin(), sorted.end());
    cell_dofs.add_indices(sorted.begin(), sorted.end());
  }
  force_layout = std::make_shared<Utilities::MPI::Partitioner>(
      dof_handler.locally_owned_dofs(),
      cell_dofs,
      dof_handler.get_triangulation().get_communicator());
  for (CellData& data : cells)
    for (const types::global_dof_index dof : data.dofs)
      data.local_dofs.push_back(force_layout->global_to_local(dof));

  constant_tangent =
      std::all_of(this->bodies.begin(),
                  this->bodies.end(),
                  [](const BodyMaterial& body) { return body.material->is_linear(); });
}

template <int dim>
std::vector<double> ElasticBodies<dim>::cell_lumped_mass(const FEValues<dim>& fe_values,
                                                         const types::material_id body,
                                                         const std::vector<bool>& massless) const
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const unsigned int n_local   = fe.n_dofs_per_cell();
  const double density         = bodies[body].density;
  double cell_mass             = 0.;
  std::vector<double> consistent_diagonal(n_local, 0.);
  for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
  {
    const double weight =
        density * fe_values.JxW(q) * kinematics.measure_factor(fe_values.quadrature_point(q), body);
    cell_mass += weight;
    for (unsigned int i = 0; i < n_local; ++i)
      consistent_diagonal[i] += weight * std::pow(fe_values.shape_value(i, q), 2);
  }
  // Every component carries the whole cell mass: scale its diagonal entries to sum to it.
  std::vector<double> diagonal_sum(fe.n_components(), 0.);
  for (unsigned int i = 0; i < n_local; ++i)
    diagonal_sum[fe.system_to_component_index(i).first] += consistent_diagonal[i];
  // Mass redistribution: the massless DoFs' share goes to the others of the same component.
  std::vector<double> lumped(n_local);
  std::vector<double> moved(fe.n_components(), 0.), kept(fe.n_components(), 0.);
  for (unsigned int i = 0; i < n_local; ++i)
  {
    const unsigned int component = fe.system_to_component_index(i).first;
    lumped[i]                    = consistent_diagonal[i] * cell_mass / diagonal_sum[component];
    (massless[i] ? moved : kept)[component] += lumped[i];
  }
  for (unsigned int component = 0; component < fe.n_components(); ++component)
    if (moved[component] > 0. && kept[component] == 0.)
      throw InputError("Contact/dynamics = mass-redistribution: a cell of body " +
                       std::to_string(body + 1) +
                       " has all its nodes on the contact surfaces, so its mass has nowhere to "
                       "go; refine the mesh (bars: at least 2 elements).");
  for (unsigned int i = 0; i < n_local; ++i)
  {
    const unsigned int component = fe.system_to_component_index(i).first;
    lumped[i]                    = massless[i] ? 0.
                                   : moved[component] > 0. ? lumped[i] * (1. + moved[component] / kept[component])
                                                           : lumped[i];
  }
  return lumped;
}

template <int dim>
Vector<double> ElasticBodies<dim>::lumped_mass(const std::vector<bool>& massless_dofs) const
{
  AssertThrow(massless_dofs.empty() || massless_dofs.size() == dof_handler.n_dofs(),
              ExcMessage("ElasticBodies::lumped_mass: massless_dofs must be empty or have n_dofs "
                         "entries"));
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  // Exact for rho phi_i^2 times the (at most linear) measure factor on affine cells.
  const QGauss<dim> quadrature(fe.degree + 2);
  FEValues<dim> fe_values(
      mapping, fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
  const unsigned int n_local = fe.n_dofs_per_cell();
  Vector<double> mass(dof_handler.n_dofs());
  std::vector<types::global_dof_index> local_dofs(n_local);
  std::vector<bool> local_massless(n_local);
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned())
      continue;
    fe_values.reinit(cell);
    cell->get_dof_indices(local_dofs);
    for (unsigned int i = 0; i < n_local; ++i)
      local_massless[i] = !massless_dofs.empty() && massless_dofs[local_dofs[i]];
    const std::vector<double> lumped =
        cell_lumped_mass(fe_values, cell->material_id(), local_massless);
    for (unsigned int i = 0; i < n_local; ++i)
      mass[local_dofs[i]] += lumped[i];
  }
  sum_over_ranks(mass, dof_handler.get_triangulation().get_communicator());
  return mass;
}

template <int dim>
double ElasticBodies<dim>::highest_frequency_bound(const std::vector<bool>& fixed_dofs,
                                                   const std::vector<bool>& massless_dofs) const
{
  AssertDimension(fixed_dofs.size(), dof_handler.n_dofs());
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const QGauss<dim> quadrature(fe.degree + 2); // the masses of lumped_mass()
  FEValues<dim> fe_values(
      mapping, fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
  const unsigned int n_local = fe.n_dofs_per_cell();
  std::vector<bool> local_massless(n_local);
  CellContribution stiffness(n_local);
  double largest_eigenvalue = 0.;
  auto data                 = cells.cbegin(); // the locally owned cells, in this order
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned())
      continue;
    fe_values.reinit(cell);
    for (unsigned int i = 0; i < n_local; ++i)
      local_massless[i] = !massless_dofs.empty() && massless_dofs[data->dofs[i]];
    const std::vector<double> lumped =
        cell_lumped_mass(fe_values, cell->material_id(), local_massless);
    // K_e at u = 0, from the cell's reference data.
    stiffness.tangent        = 0.;
    const Material& material = *bodies[data->body].material;
    for (unsigned int q = 0; q < data->volumes.size(); ++q)
    {
      const Tensor<2, 3> F =
          kinematics.deformation_gradient(Tensor<2, dim>(), Tensor<1, dim>(), data->points[q]);
      add_point_contribution(
          material, &data->variations[q * n_local], n_local, F, data->volumes[q], true, stiffness);
    }
    // lambda_max of M_e^{-1/2} K_e M_e^{-1/2} on the free DoFs.
    std::vector<unsigned int> free;
    for (unsigned int i = 0; i < n_local; ++i)
      if (!fixed_dofs[data->dofs[i]] && lumped[i] > 0.)
        free.push_back(i);
    Eigen::MatrixXd scaled(free.size(), free.size());
    for (unsigned int a = 0; a < free.size(); ++a)
      for (unsigned int b = 0; b < free.size(); ++b)
        scaled(a, b) =
            stiffness.tangent(free[a], free[b]) / std::sqrt(lumped[free[a]] * lumped[free[b]]);
    if (!free.empty())
      largest_eigenvalue =
          std::max(largest_eigenvalue,
                   Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scaled, Eigen::EigenvaluesOnly)
                       .eigenvalues()
                       .maxCoeff());
    ++data;
  }
  return std::sqrt(
      Utilities::MPI::max(largest_eigenvalue, dof_handler.get_triangulation().get_communicator()));
}

template <int dim>
DistributedVector ElasticBodies<dim>::with_cell_ghosts(const DistributedVector& displacement) const
{
  Assert(displacement.locally_owned_elements() == force_layout->locally_owned_range(),
         ExcMessage("the displacement must hold this rank's owned DoFs"));
  DistributedVector ghosted(force_layout);
  ghosted.copy_locally_owned_data_from(displacement);
  ghosted.update_ghost_values();
  return ghosted;
}

template <int dim>
void ElasticBodies<dim>::assemble_internal_force(const DistributedVector& displacement,
                                                 DistributedVector& internal_force,
                                                 TrilinosWrappers::SparseMatrix* tangent,
                                                 double* strain_energy) const
{
  integrate(with_cell_ghosts(displacement), &internal_force, tangent, strain_energy);
}

template <int dim>
double ElasticBodies<dim>::strain_energy(const DistributedVector& displacement) const
{
  double energy = 0.;
  integrate(with_cell_ghosts(displacement),
            nullptr,
            static_cast<SparseMatrix<double>*>(nullptr),
            &energy);
  return energy;
}

template <int dim>
void ElasticBodies<dim>::add_constant_tangent(TrilinosWrappers::SparseMatrix& tangent) const
{
  Assert(constant_tangent, ExcMessage("add_constant_tangent() is for linear bodies only"));
  integrate(with_cell_ghosts(DistributedVector(force_layout)), nullptr, &tangent, nullptr);
}

template <int dim>
template <typename MatrixType>
void ElasticBodies<dim>::integrate(const DistributedVector& displacement,
                                   DistributedVector* internal_force,
                                   MatrixType* tangent,
                                   double* strain_energy) const
{
  Assert(displacement.get_partitioner() == force_layout && displacement.has_ghost_elements(),
         ExcMessage("integrate() reads a displacement from with_cell_ghosts()"));
  const unsigned int n_local = local_component.size();
  if (internal_force != nullptr)
    internal_force->reinit(force_layout);
  if (strain_energy != nullptr)
    *strain_energy = 0.;
  // A failing material point (an inverted element) must not leave this rank out of the
  // collective sums below: remember the first failure (in cell order), finish the collectives,
  // then fail on all ranks.
  std::string failure;

  const auto integrate_cell = [&](const typename std::vector<CellData>::const_iterator& cell,
                                  NoScratch&,
                                  CellContribution& copy)
  {
    copy.cell_index = cell - cells.cbegin();
    integrate_one_cell(*cell,
                       *bodies[cell->body].material,
                       kinematics,
                       local_component,
                       displacement,
                       internal_force != nullptr || tangent != nullptr,
                       tangent != nullptr,
                       strain_energy != nullptr,
                       copy);
  };
  const auto add_cell = [&](const CellContribution& copy)
  {
    if (!copy.failure.empty())
    {
      if (failure.empty())
        failure = copy.failure;
      return;
    }
    const CellData& cell = cells[copy.cell_index];
    if (strain_energy != nullptr)
      for (const double energy : copy.energies)
        *strain_energy += energy;
    if (internal_force != nullptr)
      for (unsigned int i = 0; i < n_local; ++i)
        internal_force->local_element(cell.local_dofs[i]) += copy.force[i];
    if (tangent != nullptr)
    {
      if (constraints != nullptr)
        constraints->distribute_local_to_global(copy.tangent, cell.dofs, *tangent);
      else
        tangent->add(cell.dofs, copy.tangent);
    }
  };
  WorkStream::run(cells.cbegin(),
                  cells.cend(),
                  integrate_cell,
                  add_cell,
                  NoScratch(),
                  CellContribution(n_local));

  if (internal_force != nullptr)
    internal_force->compress(VectorOperation::add);
  if (strain_energy != nullptr)
    *strain_energy =
        Utilities::MPI::sum(*strain_energy, dof_handler.get_triangulation().get_communicator());
  const MPI_Comm communicator = dof_handler.get_triangulation().get_communicator();
  if (Utilities::MPI::max(failure.empty() ? 0 : 1, communicator) > 0)
    throw SolverFailure(failure.empty() ? "a material point failed on another MPI rank." : failure);
}

DYNCONTACT_INSTANTIATE_CLASS(ElasticBodies)
} // namespace dyncontact
