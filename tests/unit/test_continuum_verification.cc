// Verification of the continuum assembly of elastic_bodies.h, together with the kinematics of
// kinematics.h and the materials of material.h, on vector-valued Q2 elements (9 nodes in 2D, 27 in
// 3D) with a quadratic mapping, run serially on plain triangulations:
//  - consistent tangent: dQ/du equals central differences of the internal force Q(u), for every
//    material, axisymmetric and plane strain, on distorted meshes (one touching the axis) at a
//    finite displacement;
//  - patch tests: a static Newton solve reproduces a homogeneous finite deformation to round-off on
//    distorted patches, axisymmetric with the axis inside the patch, and 3D;
//  - convergence: a manufactured axisymmetric linear elastic solution converges at the optimal Q2
//    rates, h^3 in L2 and h^2 in the H1 seminorm, both weighted with 2 pi r.
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/material/material.h>

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/lac/vector_operation.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "simpson.h"

using dealii::ComponentMask;
using dealii::DoFHandler;
using dealii::DynamicSparsityPattern;
using dealii::FE_Q;
using dealii::FESystem;
using dealii::FEValues;
using dealii::Function;
using dealii::MappingQ;
using dealii::Point;
using dealii::QGauss;
using dealii::ScalarFunctionFromFunctionObject;
using dealii::SolverControl;
using dealii::Tensor;
using dealii::Triangulation;
using dealii::Vector;
using dealii::VectorOperation;
using dealii::types::boundary_id;
using dealii::types::global_dof_index;
using dyncontact::AxisymmetricKinematics;
using dyncontact::create_material;
using dyncontact::ElasticBodies;
using dyncontact::Kinematics;
using dyncontact::PlaneStrainKinematics;
using dyncontact::SolidKinematics;

namespace dof_tools      = dealii::DoFTools;
namespace functions      = dealii::Functions;
namespace grid_generator = dealii::GridGenerator;
namespace grid_tools     = dealii::GridTools;
namespace trilinos       = dealii::TrilinosWrappers;
namespace vector_tools   = dealii::VectorTools;

namespace
{
constexpr double pi = dealii::numbers::PI;

// Every test uses E = 1 (the stress scale) and nu = 0.3.
constexpr double youngs_modulus = 1.;
constexpr double poissons_ratio = 0.3;

const std::vector<std::string> all_materials = {
    "linear elastic", "st venant-kirchhoff", "neo-hookean"};

/// Boundary ids of GridGenerator::subdivided_hyper_rectangle with colorize = true, in (r, z).
constexpr boundary_id axis_side  = 0; // r = r_min, the symmetry axis when r_min = 0
constexpr boundary_id outer_side = 1; // r = r_max
constexpr boundary_id bottom     = 2; // z = z_min
constexpr boundary_id top        = 3; // z = z_max

/// A mesh with the vector-valued Q2 element, the quadratic mapping and the DoFs on it.
template <int dim>
struct Q2Model
{
  explicit Q2Model(const Triangulation<dim>& mesh) : fe(FE_Q<dim>(2), dim), mapping(2)
  {
    triangulation.copy_triangulation(mesh);
    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
  }

  global_dof_index n_dofs() const { return dof_handler.n_dofs(); }

  /// A zero serial Trilinos matrix with the element couplings, as ElasticBodies expects it.
  trilinos::SparseMatrix make_matrix() const
  {
    DynamicSparsityPattern pattern(n_dofs());
    dof_tools::make_sparsity_pattern(dof_handler, pattern);
    trilinos::SparseMatrix matrix;
    matrix.reinit(pattern);
    return matrix;
  }

  Triangulation<dim> triangulation;
  FESystem<dim> fe;
  MappingQ<dim> mapping;
  DoFHandler<dim> dof_handler;
};

/**
 * A box of subdivisions^dim cells from `lower` to `upper`, colorized (boundary id 2d at the lower
 * and 2d+1 at the upper side of direction d) and of material id 0, whose interior vertices are
 * moved in random directions by `distortion` times their shortest adjacent edge. The seed is fixed,
 * so every run sees the same mesh; boundary vertices stay, so the sides stay planar.
 */
template <int dim>
Triangulation<dim> distorted_box(const Point<dim>& lower,
                                 const Point<dim>& upper,
                                 const unsigned int subdivisions,
                                 const double distortion = 0.2)
{
  Triangulation<dim> mesh;
  grid_generator::subdivided_hyper_rectangle(
      mesh, std::vector<unsigned int>(dim, subdivisions), lower, upper, /*colorize=*/true);
  grid_tools::distort_random(distortion, mesh, /*keep_boundary=*/true, /*seed=*/20240611);
  // colorize also numbers the cells by position; all of them form the one body 0.
  for (const auto& cell : mesh.active_cell_iterators())
    cell->set_material_id(0);
  return mesh;
}

/// The bodies of a model: one body of the named material (E = 1, nu = 0.3) with unit density.
template <int dim>
ElasticBodies<dim> make_bodies(const Q2Model<dim>& model,
                               const Kinematics<dim>& kinematics,
                               const std::string& material_name)
{
  return ElasticBodies<dim>(model.dof_handler,
                            model.mapping,
                            kinematics,
                            {{create_material(material_name, youngs_modulus, poissons_ratio), 1.}});
}

std::unique_ptr<Kinematics<2>> make_plane_kinematics(const std::string& name)
{
  if (name == "axisymmetric")
    return std::make_unique<AxisymmetricKinematics>();
  return std::make_unique<PlaneStrainKinematics>();
}

/// `whole` as the owned vector of a run on one rank.
dyncontact::DistributedVector on_one_rank(const Vector<double>& whole)
{
  dyncontact::DistributedVector owned(whole.size());
  std::copy(whole.begin(), whole.end(), owned.begin());
  return owned;
}

/// Q(u) and, freshly zeroed and compressed, the tangent dQ/du at u.
template <int dim>
Vector<double> internal_force_and_tangent(const ElasticBodies<dim>& bodies,
                                          const Vector<double>& displacement,
                                          trilinos::SparseMatrix& tangent)
{
  dyncontact::DistributedVector internal_force;
  tangent = 0.;
  bodies.assemble_internal_force(on_one_rank(displacement), internal_force, &tangent);
  tangent.compress(VectorOperation::add);
  return dyncontact::gather_whole(internal_force);
}

template <int dim>
Vector<double> internal_force(const ElasticBodies<dim>& bodies, const Vector<double>& displacement)
{
  dyncontact::DistributedVector force;
  bodies.assemble_internal_force(on_one_rank(displacement), force, nullptr);
  return dyncontact::gather_whole(force);
}

/// Independent entries uniform in [-amplitude, amplitude].
Vector<double>
random_vector(const global_dof_index size, const double amplitude, std::mt19937& generator)
{
  std::uniform_real_distribution<double> distribution(-amplitude, amplitude);
  Vector<double> values(size);
  for (auto& value : values)
    value = distribution(generator);
  return values;
}

/// Entries uniform in [-amplitude, amplitude] on the DoFs that are not keys of `fixed`, else 0.
Vector<double> random_vector_on_free_dofs(const global_dof_index size,
                                          const std::map<global_dof_index, double>& fixed,
                                          const double amplitude,
                                          std::mt19937& generator)
{
  Vector<double> values = random_vector(size, amplitude, generator);
  for (const auto& [dof, value] : fixed)
    values[dof] = 0.;
  return values;
}

/// The smallest det F and the largest |F - I| (Frobenius) at the Gauss points of the assembly.
struct DeformationRange
{
  double min_jacobian;
  double max_strain;
};

template <int dim>
DeformationRange deformation_range(const Q2Model<dim>& model,
                                   const Kinematics<dim>& kinematics,
                                   const Vector<double>& displacement)
{
  const QGauss<dim> quadrature(model.fe.degree + 1);
  FEValues<dim> fe_values(model.mapping,
                          model.fe,
                          quadrature,
                          dealii::update_values | dealii::update_gradients |
                              dealii::update_quadrature_points);
  const dealii::FEValuesExtractors::Vector displacements(0);
  std::vector<Tensor<1, dim>> values(quadrature.size());
  std::vector<Tensor<2, dim>> gradients(quadrature.size());
  DeformationRange range{std::numeric_limits<double>::max(), 0.};
  for (const auto& cell : model.dof_handler.active_cell_iterators())
  {
    fe_values.reinit(cell);
    fe_values[displacements].get_function_values(displacement, values);
    fe_values[displacements].get_function_gradients(displacement, gradients);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const Tensor<2, 3> F =
          kinematics.deformation_gradient(gradients[q], values[q], fe_values.quadrature_point(q));
      range.min_jacobian = std::min(range.min_jacobian, determinant(F));
      range.max_strain =
          std::max(range.max_strain, (F - dealii::unit_symmetric_tensor<3>()).norm());
    }
  }
  return range;
}

/// The radial DoFs on the axis r = 0 (boundary axis_side of a box with r_min = 0).
dealii::IndexSet radial_dofs_on_axis(const Q2Model<2>& model)
{
  return dof_tools::extract_boundary_dofs(
      model.dof_handler, ComponentMask(std::vector<bool>{true, false}), {axis_side});
}

/**
 * Solves the linear system with the rows of the prescribed DoFs replaced by x_i = value (row
 * elimination; the columns stay, so the system is unsymmetric, which KLU does not mind). The new
 * diagonal is the mean of the old one, which keeps the matrix well scaled.
 */
Vector<double> solve_with_prescribed_values(trilinos::SparseMatrix& matrix,
                                            Vector<double> right_hand_side,
                                            const std::map<global_dof_index, double>& prescribed)
{
  double diagonal = 0.;
  for (global_dof_index i = 0; i < matrix.m(); ++i)
    diagonal += std::abs(matrix.diag_element(i));
  diagonal /= matrix.m();
  std::vector<trilinos::SparseMatrix::size_type> rows;
  for (const auto& [dof, value] : prescribed)
  {
    rows.push_back(dof);
    right_hand_side[dof] = diagonal * value;
  }
  matrix.clear_rows(rows, diagonal);
  Vector<double> solution(right_hand_side.size());
  SolverControl control;
  trilinos::SolverDirect solver(control,
                                trilinos::SolverDirect::AdditionalData(false, "Amesos_Klu"));
  solver.solve(matrix, solution, right_hand_side);
  return solution;
}

struct NewtonResult
{
  Vector<double> displacement;
  /// Max norm of every Newton correction, in order.
  std::vector<double> corrections;
  bool converged;
  /// max |f - Q(u)| over the free DoFs at the final u, divided by max |Q(u)| over all DoFs.
  double relative_free_residual;
};

/**
 * Newton for the static equilibrium Q(u) = f with u = `dirichlet` values on those DoFs, from
 * `initial_guess` (the first correction also brings the Dirichlet DoFs to their values). It stops
 * after a correction below 1e-11 |u|_max: convergence is quadratic, so the error left after it is
 * of the order of its square, far below round-off. A linear problem stops after the second solve.
 */
template <int dim>
NewtonResult solve_static_equilibrium(const Q2Model<dim>& model,
                                      const ElasticBodies<dim>& bodies,
                                      const std::map<global_dof_index, double>& dirichlet,
                                      const Vector<double>& external_force,
                                      const Vector<double>& initial_guess)
{
  constexpr unsigned int max_iterations = 20;
  NewtonResult result{initial_guess, {}, false, 0.};
  trilinos::SparseMatrix tangent = model.make_matrix();
  for (unsigned int iteration = 0; iteration < max_iterations && !result.converged; ++iteration)
  {
    Vector<double> residual = external_force;
    residual -= internal_force_and_tangent(bodies, result.displacement, tangent);
    std::map<global_dof_index, double> increments;
    for (const auto& [dof, value] : dirichlet)
      increments[dof] = value - result.displacement[dof];
    const Vector<double> correction = solve_with_prescribed_values(tangent, residual, increments);
    result.displacement += correction;
    result.corrections.push_back(correction.linfty_norm());
    result.converged = correction.linfty_norm() <= 1e-11 * result.displacement.linfty_norm();
  }
  const Vector<double> force = internal_force(bodies, result.displacement);
  for (global_dof_index i = 0; i < force.size(); ++i)
    if (dirichlet.count(i) == 0)
      result.relative_free_residual =
          std::max(result.relative_free_residual, std::abs(external_force[i] - force[i]));
  result.relative_free_residual /= force.linfty_norm();
  return result;
}

/// The exact values of `exact` on the given sides, all components.
template <int dim>
std::map<global_dof_index, double> boundary_values(const Q2Model<dim>& model,
                                                   const Function<dim>& exact,
                                                   const std::vector<boundary_id>& sides)
{
  std::map<global_dof_index, double> values;
  for (const boundary_id side : sides)
    vector_tools::interpolate_boundary_values(
        model.mapping, model.dof_handler, side, exact, values);
  return values;
}

/**
 * The Dirichlet values of an axisymmetric box with the axis r = 0 as side axis_side: `exact` on
 * the other three sides, and only u_r = 0 on the axis, where u_z stays free.
 */
std::map<global_dof_index, double> axisymmetric_dirichlet_values(const Q2Model<2>& model,
                                                                 const Function<2>& exact)
{
  std::map<global_dof_index, double> values =
      boundary_values(model, exact, {outer_side, bottom, top});
  vector_tools::interpolate_boundary_values(model.mapping,
                                            model.dof_handler,
                                            axis_side,
                                            functions::ZeroFunction<2>(2),
                                            values,
                                            ComponentMask(std::vector<bool>{true, false}));
  return values;
}

/// max over all DoFs of |u - exact interpolated at the nodes|.
template <int dim>
double max_nodal_error(const Q2Model<dim>& model,
                       const Vector<double>& displacement,
                       const Function<dim>& exact)
{
  Vector<double> error(model.n_dofs());
  vector_tools::interpolate(model.mapping, model.dof_handler, exact, error);
  error -= displacement;
  return error.linfty_norm();
}

/// The values in %.1e format, separated by blanks.
std::string format_list(const std::vector<double>& values)
{
  std::ostringstream text;
  text << std::scientific << std::setprecision(1);
  for (unsigned int i = 0; i < values.size(); ++i)
    text << (i == 0 ? "" : " ") << values[i];
  return text.str();
}

// ------------------------------------------------------------------------------------------------
// A. Consistent tangent.

struct TangentCase
{
  std::string material;
  std::string kinematics; // "axisymmetric" or "plane strain"
  double r_min;           // the mesh spans [r_min, r_max] x [0, 1] in (r, z) or (x, y)
  double r_max;
  std::string name;
};

std::vector<TangentCase> tangent_cases()
{
  const std::vector<std::string> material_labels = {
      "LinearElastic", "StVenantKirchhoff", "NeoHookean"};
  std::vector<TangentCase> cases;
  for (unsigned int m = 0; m < all_materials.size(); ++m)
  {
    cases.push_back(
        {all_materials[m], "axisymmetric", 0.5, 2., material_labels[m] + "_Axisymmetric"});
    cases.push_back(
        {all_materials[m], "axisymmetric", 0., 1., material_labels[m] + "_AxisymmetricOnAxis"});
    cases.push_back(
        {all_materials[m], "plane strain", 0.5, 2., material_labels[m] + "_PlaneStrain"});
  }
  return cases;
}

/// Lets GoogleTest print a case by its name rather than as bytes.
void PrintTo(const TangentCase& test_case, std::ostream* stream)
{
  *stream << test_case.name;
}

class ConsistentTangent : public ::testing::TestWithParam<TangentCase>
{
};
} // namespace

// Checks that the tangent of assemble_internal_force is the derivative of its internal force: for
// four random directions w, K(u) w against the central difference (Q(u + e w) - Q(u - e w)) / 2e,
// on a distorted 3x3 Q2 mesh at a random finite displacement u (nodal values up to 5% of the
// smallest cell diameter, u_r = 0 on the axis; this gives |F - I| up to 0.45 and det F down to
// 0.63 at the Gauss points, det F > 0 is asserted).
// w is scaled to |w|_max = 1 and e = 1e-6 |u|_max. The truncation error of the central difference
// is O(e^2 |Q'''|), about 1e-12 relative; round-off gives about 1e-16 |Q| / (e |Kw|), roughly
// 1e-10 since |Q| ~ |K u| and |u| ~ |w|. A wrong term of the tangent (a missing geometric
// stiffness, a wrong hoop term) gives O(strain) = 1e-2..1e-1. So 1e-6 separates the two by four
// decades either way. For the linear elastic material the difference is exact up to round-off.
TEST_P(ConsistentTangent, MatchesCentralDifferenceOfInternalForce)
{
  const TangentCase& test_case = GetParam();
  const Q2Model<2> model(
      distorted_box(Point<2>(test_case.r_min, 0.), Point<2>(test_case.r_max, 1.), 3));
  const std::unique_ptr<Kinematics<2>> kinematics = make_plane_kinematics(test_case.kinematics);
  const ElasticBodies<2> bodies = make_bodies(model, *kinematics, test_case.material);

  std::mt19937 generator(12345);
  Vector<double> displacement = random_vector(
      model.n_dofs(), 0.05 * grid_tools::minimal_cell_diameter(model.triangulation), generator);
  if (test_case.r_min == 0.)
    for (const global_dof_index dof : radial_dofs_on_axis(model))
      displacement[dof] = 0.;
  const DeformationRange range = deformation_range(model, *kinematics, displacement);
  ASSERT_GT(range.min_jacobian, 0.);

  trilinos::SparseMatrix tangent = model.make_matrix();
  internal_force_and_tangent(bodies, displacement, tangent);
  const double step = 1e-6 * displacement.linfty_norm();

  std::vector<double> relative_errors;
  for (unsigned int direction = 0; direction < 4; ++direction)
  {
    Vector<double> w = random_vector(model.n_dofs(), 1., generator);
    w /= w.linfty_norm();
    Vector<double> plus = displacement, minus = displacement;
    plus.add(step, w);
    minus.add(-step, w);
    Vector<double> difference = internal_force(bodies, plus);
    difference -= internal_force(bodies, minus);
    difference /= 2. * step;
    Vector<double> tangent_times_w(model.n_dofs());
    tangent.vmult(tangent_times_w, w);
    difference -= tangent_times_w;
    relative_errors.push_back(difference.l2_norm() / tangent_times_w.l2_norm());
    EXPECT_LE(relative_errors.back(), 1e-6) << "direction " << direction;
  }
  std::cout << "  " << test_case.material << ", " << test_case.kinematics << ", r in ["
            << test_case.r_min << ", " << test_case.r_max << "]: " << model.n_dofs()
            << " DoFs, min det F " << range.min_jacobian << ", max |F - I| " << range.max_strain
            << "; |Kw - FD| / |Kw| = " << format_list(relative_errors) << "\n";
}

INSTANTIATE_TEST_SUITE_P(AllMaterialsAndKinematics,
                         ConsistentTangent,
                         ::testing::ValuesIn(tangent_cases()),
                         [](const ::testing::TestParamInfo<TangentCase>& info)
                         { return info.param.name; });

// ------------------------------------------------------------------------------------------------
// B. Patch tests.

namespace
{
/// u(X) = (F - I) X, the displacement of the homogeneous deformation x = F X.
template <int dim>
class HomogeneousDisplacement : public Function<dim>
{
public:
  explicit HomogeneousDisplacement(const Tensor<2, dim>& F)
      : Function<dim>(dim), displacement_gradient(F - dealii::unit_symmetric_tensor<dim>())
  {
  }

  double value(const Point<dim>& X, const unsigned int component) const override
  {
    double result = 0.;
    for (unsigned int j = 0; j < dim; ++j)
      result += displacement_gradient[component][j] * X[j];
    return result;
  }

private:
  Tensor<2, dim> displacement_gradient;
};

/**
 * Solves the patch problem with Newton for every material and checks the nodal values against the
 * exact field to `tolerance` times the displacement scale. Newton starts from random nodal values
 * of up to 20 % of that scale at the free DoFs (zero on the Dirichlet DoFs): started from u = 0,
 * its first step, the linear elastic patch problem, would already land on the homogeneous field,
 * and no finite-strain iteration would be tested.
 */
template <int dim>
void check_patch_reproduces_homogeneous_deformation(
    const Q2Model<dim>& model,
    const Kinematics<dim>& kinematics,
    const HomogeneousDisplacement<dim>& exact,
    const std::map<global_dof_index, double>& dirichlet,
    const double tolerance)
{
  const Vector<double> no_external_force(model.n_dofs());
  Vector<double> exact_nodal(model.n_dofs());
  vector_tools::interpolate(model.mapping, model.dof_handler, exact, exact_nodal);
  const double displacement_scale = exact_nodal.linfty_norm();
  std::mt19937 generator(777);
  const Vector<double> initial_guess =
      random_vector_on_free_dofs(model.n_dofs(), dirichlet, 0.2 * displacement_scale, generator);
  for (const std::string& material : all_materials)
  {
    const ElasticBodies<dim> bodies = make_bodies(model, kinematics, material);
    const NewtonResult newton =
        solve_static_equilibrium(model, bodies, dirichlet, no_external_force, initial_guess);
    ASSERT_TRUE(newton.converged) << material << ": corrections "
                                  << format_list(newton.corrections);
    const double error = max_nodal_error(model, newton.displacement, exact) / displacement_scale;
    EXPECT_LE(error, tolerance) << material;
    std::cout << "  " << material << ": " << model.n_dofs() << " DoFs, " << dirichlet.size()
              << " prescribed; Newton corrections (max norm) " << format_list(newton.corrections)
              << "; free-DoF residual / max |Q| " << newton.relative_free_residual
              << "; max nodal error / max |u| " << error << "\n";
  }
}
} // namespace

// Checks that the homogeneous finite deformation u_r = (a - 1) r, u_z = (b - 1) z (a = 1.1,
// b = 0.95) solves the static axisymmetric problem exactly on a distorted 3x3 patch of Q2 cells
// in (r, z) in [0, 1]^2 whose left column touches the axis: the exact field is imposed on r = 1,
// z = 0 and z = 1, only u_r = 0 on the axis (its u_z is free), and Newton solves Q(u) = 0.
// Why it is exact: F = diag(a, b, a) is constant, including the hoop stretch 1 + u_r/r = a. As
// F_rr = F_thetatheta, isotropy gives P_rr = P_thetatheta (and P_rz = 0), so the hoop term
// (P_rr - P_thetatheta)/r of the radial equilibrium vanishes and the constant P is in equilibrium
// without body force. Discretely, the r-row of a node i is 2 pi times the integral over the mesh
// of P_rr (r dphi_i/dr + phi_i) = P_rr d(r phi_i)/dr, its z-row that of P_zz d(r phi_i)/dz:
// integrals of derivatives, zero for every free node (phi_i vanishes on the Dirichlet sides and
// r phi_i on the axis). On the reference cell the integrands, times det J, are polynomials of
// degree <= 3 per direction (the map of a straight-sided cell is bilinear), which the 3-point
// Gauss rule integrates exactly; and the linear field lies in the Q2 space. So the discrete
// solution is the exact field up to round-off (measured: a few 1e-16). The bound 1e-10 leaves
// room for the conditioning of the system; a wrong hoop term or measure misses it by far more.
TEST(PatchTest, AxisymmetricHomogeneousStretchWithAxisIsExact)
{
  const Q2Model<2> model(distorted_box(Point<2>(0., 0.), Point<2>(1., 1.), 3));
  const AxisymmetricKinematics kinematics;
  Tensor<2, 2> F;
  F[0][0] = 1.1;
  F[1][1] = 0.95;
  const HomogeneousDisplacement<2> exact(F);
  check_patch_reproduces_homogeneous_deformation(
      model, kinematics, exact, axisymmetric_dirichlet_values(model, exact), 1e-10);
}

// The same patch test in 3D (SolidKinematics): u = (F - I) X with a general, unsymmetric constant
// F (det F = 1.098, stretches of 5-10 % and shears of 2-5 %), imposed on all boundary nodes of a
// distorted 3x3x3 patch of Q2 hexahedra (planar sides, 8 interior vertices moved). A constant P is
// divergence-free, and the discrete residual of a free node, the integral of P : grad phi_i, is
// the integral of a derivative of a function vanishing on the boundary; with a trilinear geometry
// its integrand times det J is a polynomial of degree <= 3 per direction on the reference cell,
// which 3-point Gauss integrates exactly. So again only round-off remains; the tolerance is that
// of the axisymmetric patch.
TEST(PatchTest, SolidGeneralHomogeneousDeformationIsExact)
{
  const Q2Model<3> model(distorted_box(Point<3>(0., 0., 0.), Point<3>(1., 1., 1.), 3));
  const SolidKinematics kinematics;
  const Tensor<2, 3> F({{1.1, 0.05, -0.03}, {0.02, 0.95, 0.04}, {-0.05, 0.03, 1.05}});
  ASSERT_GT(determinant(F), 0.);
  const HomogeneousDisplacement<3> exact(F);
  check_patch_reproduces_homogeneous_deformation(
      model, kinematics, exact, boundary_values(model, exact, {0, 1, 2, 3, 4, 5}), 1e-10);
}

// ------------------------------------------------------------------------------------------------
// C. Convergence to a manufactured axisymmetric solution.

namespace
{
constexpr double manufactured_amplitude = 0.01;

// The Lame constants of E and nu, computed here independently of material.cc.
constexpr double lame_lambda =
    youngs_modulus * poissons_ratio / ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
constexpr double lame_mu = youngs_modulus / (2. * (1. + poissons_ratio));

/// u_r = A sin r cos z, u_z = A cos r sin z: u_r is odd and u_z even in r, so u is smooth on the
/// axis and u_r vanishes there.
Tensor<1, 2> manufactured_displacement(const Point<2>& p)
{
  const double r = p[0], z = p[1];
  return Tensor<1, 2>({manufactured_amplitude * std::sin(r) * std::cos(z),
                       manufactured_amplitude * std::cos(r) * std::sin(z)});
}

/// [i][j] = d u_i / d x_j with x = (r, z).
Tensor<2, 2> manufactured_displacement_gradient(const Point<2>& p)
{
  const double r = p[0], z = p[1], A = manufactured_amplitude;
  return Tensor<2, 2>({{A * std::cos(r) * std::cos(z), -A * std::sin(r) * std::sin(z)},
                       {-A * std::sin(r) * std::sin(z), A * std::cos(r) * std::cos(z)}});
}

/// The cylindrical stress components of linear elasticity, sigma = lambda tr(e) I + 2 mu e.
struct CylindricalStress
{
  double rr, zz, tt, rz;
};

CylindricalStress manufactured_stress(const Point<2>& p)
{
  const Tensor<2, 2> grad = manufactured_displacement_gradient(p);
  const double e_rr = grad[0][0], e_zz = grad[1][1];
  const double e_tt  = manufactured_displacement(p)[0] / p[0];
  const double e_rz  = 0.5 * (grad[0][1] + grad[1][0]);
  const double trace = e_rr + e_zz + e_tt;
  return {lame_lambda * trace + 2. * lame_mu * e_rr,
          lame_lambda * trace + 2. * lame_mu * e_zz,
          lame_lambda * trace + 2. * lame_mu * e_tt,
          2. * lame_mu * e_rz};
}

/**
 * The body force b = -div sigma in cylindrical coordinates, derived by hand. With
 * s(r) = sin(r)/r and s'(r) = (r cos r - sin r)/r^2:
 *   b_r = A (lambda + 2 mu) (2 sin r - s'(r)) cos z,
 *   b_z = A (lambda + 2 mu) (2 cos r + s(r)) sin z.
 * s'(r) loses about 3e-16/r^2 (relative) to cancellation: 1e-11 at the Gauss point nearest the
 * axis on the finest mesh, far below the discretization errors.
 */
Tensor<1, 2> manufactured_body_force(const Point<2>& p)
{
  const double r = p[0], z = p[1];
  const double factor = manufactured_amplitude * (lame_lambda + 2. * lame_mu);
  const double s      = std::sin(r) / r;
  const double ds_dr  = (r * std::cos(r) - std::sin(r)) / (r * r);
  return Tensor<1, 2>({factor * (2. * std::sin(r) - ds_dr) * std::cos(z),
                       factor * (2. * std::cos(r) + s) * std::sin(z)});
}

/// b = -(d s_rr/dr + d s_rz/dz + (s_rr - s_tt)/r, d s_rz/dr + d s_zz/dz + s_rz/r), the
/// derivatives by central differences of step h.
Tensor<1, 2> body_force_by_finite_differences(const Point<2>& p, const double h)
{
  const Tensor<1, 2> dr({h, 0.}), dz({0., h});
  const CylindricalStress s       = manufactured_stress(p);
  const CylindricalStress r_plus  = manufactured_stress(p + dr),
                          r_minus = manufactured_stress(p - dr);
  const CylindricalStress z_plus  = manufactured_stress(p + dz),
                          z_minus = manufactured_stress(p - dz);
  const double radial = (r_plus.rr - r_minus.rr) / (2. * h) + (z_plus.rz - z_minus.rz) / (2. * h) +
                        (s.rr - s.tt) / p[0];
  const double axial =
      (r_plus.rz - r_minus.rz) / (2. * h) + (z_plus.zz - z_minus.zz) / (2. * h) + s.rz / p[0];
  return Tensor<1, 2>({-radial, -axial});
}

/// The manufactured displacement as a deal.II function with gradients (for the H1 error).
class ManufacturedDisplacement : public Function<2>
{
public:
  ManufacturedDisplacement() : Function<2>(2) {}

  double value(const Point<2>& p, const unsigned int component) const override
  {
    return manufactured_displacement(p)[component];
  }

  Tensor<1, 2> gradient(const Point<2>& p, const unsigned int component) const override
  {
    return manufactured_displacement_gradient(p)[component];
  }
};

/**
 * The load vector f_i = integral of b . phi_i 2 pi r dA. b is smooth but not polynomial, so the
 * Gauss rule is two points richer than the element's; its error is far below the h^3 of interest.
 */
Vector<double>
axisymmetric_load_vector(const Q2Model<2>& model,
                         const std::function<Tensor<1, 2>(const Point<2>&)>& body_force)
{
  const QGauss<2> quadrature(model.fe.degree + 3);
  FEValues<2> fe_values(model.mapping,
                        model.fe,
                        quadrature,
                        dealii::update_values | dealii::update_quadrature_points |
                            dealii::update_JxW_values);
  std::vector<global_dof_index> local_dofs(model.fe.n_dofs_per_cell());
  Vector<double> load(model.n_dofs());
  for (const auto& cell : model.dof_handler.active_cell_iterators())
  {
    fe_values.reinit(cell);
    cell->get_dof_indices(local_dofs);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const Point<2>& X    = fe_values.quadrature_point(q);
      const Tensor<1, 2> b = body_force(X);
      const double measure = 2. * pi * X[0] * fe_values.JxW(q);
      for (unsigned int i = 0; i < local_dofs.size(); ++i)
        load[local_dofs[i]] +=
            b[model.fe.system_to_component_index(i).first] * fe_values.shape_value(i, q) * measure;
    }
  }
  return load;
}

/// log2 of the error ratio between levels level - 1 and level, whose h differ by a factor 2.
double convergence_rate(const std::vector<double>& errors, const unsigned int level)
{
  return std::log(errors[level - 1] / errors[level]) / std::log(2.);
}

/// The error of one level and its rate ("-" on the first level), as two table columns.
std::string error_and_rate(const std::vector<double>& errors, const unsigned int level)
{
  std::ostringstream text;
  text << std::scientific << std::setprecision(3) << std::setw(13) << errors[level] << std::fixed
       << std::setprecision(2) << std::setw(6);
  if (level == 0)
    text << "-";
  else
    text << convergence_rate(errors, level);
  return text.str();
}

struct WeightedErrors
{
  double l2;
  double h1_seminorm;
};

/// sqrt(integral |u_h - u|^2 2 pi r dA) and sqrt(integral |grad (u_h - u)|^2 2 pi r dA).
WeightedErrors axisymmetric_errors(const Q2Model<2>& model,
                                   const Vector<double>& displacement,
                                   const Function<2>& exact)
{
  const ScalarFunctionFromFunctionObject<2> weight([](const Point<2>& p)
                                                   { return 2. * pi * p[0]; });
  const QGauss<2> quadrature(model.fe.degree + 3);
  const auto global_error = [&](const vector_tools::NormType norm)
  {
    Vector<double> cellwise(model.triangulation.n_active_cells());
    vector_tools::integrate_difference(
        model.mapping, model.dof_handler, displacement, exact, cellwise, quadrature, norm, &weight);
    return vector_tools::compute_global_error(model.triangulation, cellwise, norm);
  };
  return {global_error(vector_tools::L2_norm), global_error(vector_tools::H1_seminorm)};
}
} // namespace

// Checks the hand-derived body force of the manufactured solution against minus the divergence of
// its stress by central differences (step h = 1e-5) at points across the domain, including near
// the axis. The truncation error is h^2/6 |sigma'''| ~ 1e-11 A and the round-off ~ 1e-16 |sigma|/h
// ~ 1e-13, both relative to |b| ~ A; 1e-8 leaves room for both while any error in the
// derivation (a wrong sign or factor) would be O(1).
TEST(ManufacturedAxisymmetricSolution, BodyForceIsMinusDivergenceOfStress)
{
  double max_error = 0.;
  for (const Point<2>& p : {Point<2>(0.01, 0.3),
                            Point<2>(0.2, 0.9),
                            Point<2>(0.5, 0.5),
                            Point<2>(0.77, 0.13),
                            Point<2>(1., 1.)})
  {
    const Tensor<1, 2> difference =
        manufactured_body_force(p) - body_force_by_finite_differences(p, 1e-5);
    max_error = std::max(max_error, difference.norm() / manufactured_body_force(p).norm());
  }
  std::cout << "  max |b - b_FD| / |b| = " << max_error << "\n";
  EXPECT_LE(max_error, 1e-8);
}

// Checks optimal convergence of the axisymmetric Q2 discretization of static linear elasticity
// (E = 1, nu = 0.3) to the manufactured solution u_r = A sin r cos z, u_z = A cos r sin z on
// (r, z) in [0, 1]^2: exact Dirichlet values on r = 1, z = 0, z = 1, u_r = 0 on the axis, the
// body force from the cylindrical equilibrium equations, and K from assemble_internal_force (a
// Newton solve of the linear problem). The meshes are a 2x2 mesh with its centre vertex moved,
// refined 0-3 times (2, 4, 8, 16 cells per side), so every level has the same distortion
// pattern. Theory gives rates 3 (L2) and 2 (H1 seminorm) in the 2 pi r weighted norms, for a
// solution this smooth also on the axis. The bounds 2.8 and 1.8 on the last rates leave room for
// pre-asymptotic effects; a wrong hoop term or axis treatment costs at least a full order.
TEST(ManufacturedAxisymmetricSolution, ConvergesAtOptimalRates)
{
  const AxisymmetricKinematics kinematics;
  const ManufacturedDisplacement exact;
  std::cout << "  cells/side       h     L2 error  rate     H1 error  rate\n";
  std::vector<double> l2_errors, h1_errors;
  for (unsigned int refinement = 0; refinement < 4; ++refinement)
  {
    Triangulation<2> mesh = distorted_box(Point<2>(0., 0.), Point<2>(1., 1.), 2);
    mesh.refine_global(refinement);
    const Q2Model<2> model(mesh);
    const ElasticBodies<2> bodies = make_bodies(model, kinematics, "linear elastic");
    const NewtonResult solution =
        solve_static_equilibrium(model,
                                 bodies,
                                 axisymmetric_dirichlet_values(model, exact),
                                 axisymmetric_load_vector(model, manufactured_body_force),
                                 Vector<double>(model.n_dofs()));
    ASSERT_TRUE(solution.converged);
    const WeightedErrors errors = axisymmetric_errors(model, solution.displacement, exact);
    l2_errors.push_back(errors.l2);
    h1_errors.push_back(errors.h1_seminorm);
    const unsigned int cells_per_side = 2 << refinement;
    std::cout << "  " << std::setw(10) << cells_per_side << std::setw(8) << 1. / cells_per_side
              << error_and_rate(l2_errors, refinement) << error_and_rate(h1_errors, refinement)
              << "\n";
  }
  const unsigned int last = l2_errors.size() - 1;
  const double l2_rate    = convergence_rate(l2_errors, last);
  const double h1_rate    = convergence_rate(h1_errors, last);
  EXPECT_GE(l2_rate, 2.8);
  EXPECT_GE(h1_rate, 1.8);
}

// The HRZ lumped mass of one off-axis axisymmetric Q2 cell, node by node: m_i = M_ii * m / sum_j
// M_jj with the consistent diagonal M_ii = rho * integral of N_i^2 2 pi r dA and the cell's mass
// m = rho * integral of 2 pi r dA (Hinton, Rock & Zienkiewicz 1976). On the rectangle [1, 1.5] x
// [0.5, 0.9] N_i = L_a(r) L_b(z), so M_ii = 2 pi (integral of L_a^2 r dr)(integral of L_b^2 dz),
// integrated here by Simpson's rule on 400 intervals (its error, of order h^4 on degree-5
// integrands, is below 1e-12 relative). Keeping only the cell total right is not enough: moving
// mass among the nodes (e.g. dropping the 2 pi r weight inside the shares, which makes the two
// radial columns equal) misses these values by several percent. Bound 1e-10 relative.
TEST(LumpedMass, OffAxisQ2CellHasTheHrzNodalMasses)
{
  const double r0 = 1., r1 = 1.5, z0 = 0.5, z1 = 0.9;
  const Q2Model<2> model(distorted_box(Point<2>(r0, z0), Point<2>(r1, z1), 1));
  const AxisymmetricKinematics kinematics;
  const Vector<double> mass = make_bodies(model, kinematics, "linear elastic").lumped_mass();

  // Quadratic Lagrange polynomials on [a, b] with nodes a, (a + b) / 2, b, as functions of the
  // coordinate; `node` is the node's coordinate.
  const auto lagrange = [](const double a, const double b, const double node, const double x)
  {
    const double m = 0.5 * (a + b);
    if (std::abs(node - a) < 1e-12)
      return (x - m) * (x - b) / ((a - m) * (a - b));
    if (std::abs(node - m) < 1e-12)
      return (x - a) * (x - b) / ((m - a) * (m - b));
    return (x - a) * (x - m) / ((b - a) * (b - m));
  };
  const auto diagonal = [&](const Point<2>& node)
  {
    const double radial = dyncontact::testing::simpson(
        r1 - r0,
        400,
        [&](const double s) { return std::pow(lagrange(r0, r1, node[0], r0 + s), 2) * (r0 + s); });
    const double axial = dyncontact::testing::simpson(
        z1 - z0,
        400,
        [&](const double s) { return std::pow(lagrange(z0, z1, node[1], z0 + s), 2); });
    return 2. * pi * radial * axial;
  };
  std::vector<Point<2>> support_points(model.n_dofs());
  dof_tools::map_dofs_to_support_points(model.mapping, model.dof_handler, support_points);
  double diagonal_sum = 0.;
  for (const auto& point : support_points)
    diagonal_sum += diagonal(point) / 2.;                        // each node has two DoFs
  const double cell_mass = pi * (r1 * r1 - r0 * r0) * (z1 - z0); // density 1
  for (global_dof_index dof = 0; dof < model.n_dofs(); ++dof)
  {
    const double expected = diagonal(support_points[dof]) * cell_mass / diagonal_sum;
    EXPECT_NEAR(mass[dof], expected, 1e-10 * expected) << "node " << support_points[dof];
  }
}
