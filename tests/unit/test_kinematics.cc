// Unit tests of the kinematics of kinematics.h, fed the way the assembler feeds them: from a
// vector-valued Q2 finite element field on one cell, evaluated at Gauss points. A homogeneous
// deformation must give the exact F (axisymmetric: diag(a, b, a) including the hoop stretch), the
// variation of F must be the derivative of F with respect to each nodal value, and the measure
// factor must integrate to the reference volume.
#include <dyncontact/discretization/kinematics.h>

#include <deal.II/base/function.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <gtest/gtest.h>
#include <iostream>
#include <random>
#include <vector>

using dealii::DoFHandler;
using dealii::FE_Q;
using dealii::FESystem;
using dealii::FEValues;
using dealii::Function;
using dealii::Point;
using dealii::QGauss;
using dealii::Tensor;
using dealii::Triangulation;
using dealii::Vector;
using dyncontact::AxisymmetricKinematics;
using dyncontact::Kinematics;
using dyncontact::PlaneStrainKinematics;
using dyncontact::SolidKinematics;

namespace
{
// Every check below is exact in exact arithmetic. F is a sum over 9 (2D) or 27 (3D) nodes of
// nodal values O(1) times shape function gradients O(1), so it carries round-off of about 1e-15;
// the tolerance leaves a factor 100 over that.
constexpr double round_off_tolerance = 1e-13;

/// The displacement u(X) = G X of a homogeneous deformation.
template <int dim>
class LinearDisplacement : public Function<dim>
{
public:
  explicit LinearDisplacement(const Tensor<2, dim>& displacement_gradient)
      : Function<dim>(dim), displacement_gradient(displacement_gradient)
  {
  }

  double value(const Point<dim>& X, const unsigned int component) const override
  {
    return (displacement_gradient * X)[component];
  }

private:
  Tensor<2, dim> displacement_gradient;
};

/// One cell [lower, upper] carrying a vector-valued Q2 field (the elements of the continuum
/// roadmap), with FEValues at the 3^dim Gauss points.
template <int dim>
class OneCellField
{
public:
  OneCellField(const Point<dim>& lower, const Point<dim>& upper)
      : fe(FE_Q<dim>(2), dim), dof_handler(triangulation), quadrature(3),
        fe_values(fe,
                  quadrature,
                  dealii::update_values | dealii::update_gradients |
                      dealii::update_quadrature_points | dealii::update_JxW_values)
  {
    dealii::GridGenerator::hyper_rectangle(triangulation, lower, upper);
    dof_handler.distribute_dofs(fe);
    fe_values.reinit(dof_handler.begin_active());
  }

  /// The nodal values of u(X) = G X (Q2 reproduces a linear field exactly).
  Vector<double> linear_displacement(const Tensor<2, dim>& displacement_gradient) const
  {
    Vector<double> nodal_values(dof_handler.n_dofs());
    dealii::VectorTools::interpolate(
        dof_handler, LinearDisplacement<dim>(displacement_gradient), nodal_values);
    return nodal_values;
  }

  /// F at every Gauss point of the field with the given nodal values.
  std::vector<Tensor<2, 3>> deformation_gradients(const Kinematics<dim>& kinematics,
                                                  const Vector<double>& nodal_values) const
  {
    const dealii::FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, dim>> values(quadrature.size());
    std::vector<Tensor<2, dim>> gradients(quadrature.size());
    fe_values[displacement].get_function_values(nodal_values, values);
    fe_values[displacement].get_function_gradients(nodal_values, gradients);
    std::vector<Tensor<2, 3>> F(quadrature.size());
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      F[q] =
          kinematics.deformation_gradient(gradients[q], values[q], fe_values.quadrature_point(q));
    return F;
  }

  /// Largest |F - expected_F| over the Gauss points, for u = G X.
  double homogeneous_deformation_error(const Kinematics<dim>& kinematics,
                                       const Tensor<2, dim>& displacement_gradient,
                                       const Tensor<2, 3>& expected_F) const
  {
    double error = 0.;
    for (const Tensor<2, 3>& F :
         deformation_gradients(kinematics, linear_displacement(displacement_gradient)))
      error = std::max(error, (F - expected_F).norm());
    return error;
  }

  /// Largest difference, over all nodal values i and Gauss points, between the variation of F
  /// for shape function i and the central difference (F(U + h e_i) - F(U - h e_i)) / 2h at a
  /// random U. F is affine in U, so the difference quotient is exact for any h up to round-off,
  /// about 1e-16 |F| / h; h = 1 keeps that smallest.
  double variation_error(const Kinematics<dim>& kinematics) const
  {
    std::mt19937 generator(20230920);
    std::uniform_real_distribution<double> nodal_value(-0.1, 0.1);
    Vector<double> U(dof_handler.n_dofs());
    for (double& value : U)
      value = nodal_value(generator);

    const double step = 1.;
    double error      = 0.;
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
    {
      Vector<double> U_plus = U, U_minus = U;
      U_plus[i] += step;
      U_minus[i] -= step;
      const std::vector<Tensor<2, 3>> F_plus  = deformation_gradients(kinematics, U_plus);
      const std::vector<Tensor<2, 3>> F_minus = deformation_gradients(kinematics, U_minus);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const Tensor<2, 3> variation =
            kinematics.deformation_gradient_variation(fe.system_to_component_index(i).first,
                                                      fe_values.shape_value(i, q),
                                                      fe_values.shape_grad(i, q),
                                                      fe_values.quadrature_point(q));
        error = std::max(error, ((F_plus[q] - F_minus[q]) / (2. * step) - variation).norm());
      }
    }
    return error;
  }

  /// The integral of the measure factor over the cell: the reference volume of the model.
  double reference_volume(const Kinematics<dim>& kinematics) const
  {
    double volume = 0.;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      volume += fe_values.JxW(q) * kinematics.measure_factor(fe_values.quadrature_point(q), 0);
    return volume;
  }

private:
  Triangulation<dim> triangulation;
  FESystem<dim> fe;
  DoFHandler<dim> dof_handler;
  QGauss<dim> quadrature;
  FEValues<dim> fe_values;
};

} // namespace

// u_r = (a - 1) r, u_z = (b - 1) z stretches radius and hoop circles by a and heights by b, so
// F = diag(a, b, a). Checked once at a point where every operation is exact in binary (so F must
// be exact), then on a Q2 field off the axis (to round_off_tolerance).
TEST(AxisymmetricKinematics, HomogeneousDeformationGivesDiagonalF)
{
  const double a = 1.25, b = 0.75;
  const AxisymmetricKinematics kinematics;

  const Point<2> X(0.5, 2.);
  const Tensor<2, 2> displacement_gradient({{a - 1., 0.}, {0., b - 1.}});
  const Tensor<1, 2> displacement({(a - 1.) * X[0], (b - 1.) * X[1]});
  const Tensor<2, 3> expected_F({{a, 0., 0.}, {0., b, 0.}, {0., 0., a}});
  EXPECT_EQ(kinematics.deformation_gradient(displacement_gradient, displacement, X), expected_F);

  const OneCellField<2> field(Point<2>(0.3, -1.), Point<2>(1.7, 0.5));
  const double error =
      field.homogeneous_deformation_error(kinematics, displacement_gradient, expected_F);
  std::cout << "  axisymmetric: homogeneous F error on Q2 " << error << "\n";
  EXPECT_LE(error, round_off_tolerance);
}

// The hoop term makes the variation of u_r depend on the shape value (shape_value / r); the
// difference quotient of F over each nodal value checks it along with the gradient terms, to
// round_off_tolerance (see variation_error() for why the quotient is exact).
TEST(AxisymmetricKinematics, VariationIsDerivativeOfF)
{
  const OneCellField<2> field(Point<2>(0.3, -1.), Point<2>(1.7, 0.5));
  const double error = field.variation_error(AxisymmetricKinematics());
  std::cout << "  axisymmetric: variation vs difference quotient " << error << "\n";
  EXPECT_LE(error, round_off_tolerance);
}

// dV = 2 pi r dr dz, so the cell [r0, r1] x [z0, z1] integrates to pi (r1^2 - r0^2)(z1 - z0);
// 3-point Gauss integrates the linear integrand exactly, so the tolerance is round-off, 1e-14
// relative. The body id does not matter.
TEST(AxisymmetricKinematics, MeasureFactorGivesVolumeOfRevolution)
{
  const AxisymmetricKinematics kinematics;
  const OneCellField<2> field(Point<2>(0.3, -1.), Point<2>(1.7, 0.5));
  const double exact_volume = dealii::numbers::PI * (1.7 * 1.7 - 0.3 * 0.3) * 1.5;
  EXPECT_NEAR(field.reference_volume(kinematics), exact_volume, 1e-14 * exact_volume);
  EXPECT_EQ(kinematics.measure_factor(Point<2>(0.8, 3.), 0),
            kinematics.measure_factor(Point<2>(0.8, 3.), 7));
  EXPECT_DOUBLE_EQ(kinematics.measure_factor(Point<2>(0.8, 3.), 0), 2. * dealii::numbers::PI * 0.8);
}

// u = G X with a general (shearing, non-symmetric) G gives F = I + G in the plane and F_33 = 1,
// to round_off_tolerance.
TEST(PlaneStrainKinematics, HomogeneousDeformationGivesEmbeddedF)
{
  const Tensor<2, 2> G({{0.1, 0.3}, {-0.2, 0.05}});
  const Tensor<2, 3> expected_F({{1.1, 0.3, 0.}, {-0.2, 1.05, 0.}, {0., 0., 1.}});
  const OneCellField<2> field(Point<2>(-1., 0.), Point<2>(2., 0.5));
  const double error = field.homogeneous_deformation_error(PlaneStrainKinematics(), G, expected_F);
  std::cout << "  plane strain: homogeneous F error on Q2 " << error << "\n";
  EXPECT_LE(error, round_off_tolerance);
}

// The variation is the derivative of F with respect to each nodal value, to round_off_tolerance.
TEST(PlaneStrainKinematics, VariationIsDerivativeOfF)
{
  const OneCellField<2> field(Point<2>(-1., 0.), Point<2>(2., 0.5));
  const double error = field.variation_error(PlaneStrainKinematics());
  std::cout << "  plane strain: variation vs difference quotient " << error << "\n";
  EXPECT_LE(error, round_off_tolerance);
}

// Unit thickness: the cell integrates to its area, exactly up to round-off (1e-14 relative), for
// any body id.
TEST(PlaneStrainKinematics, MeasureFactorIsUnitThickness)
{
  const OneCellField<2> field(Point<2>(-1., 0.), Point<2>(2., 0.5));
  EXPECT_NEAR(field.reference_volume(PlaneStrainKinematics()), 1.5, 1e-14);
  EXPECT_EQ(PlaneStrainKinematics().measure_factor(Point<2>(0.3, 0.2), 7), 1.);
}

// u = G X with a general G gives F = I + G, to round_off_tolerance.
TEST(SolidKinematics, HomogeneousDeformationGivesF)
{
  const Tensor<2, 3> G({{0.1, 0.3, -0.05}, {-0.2, 0.05, 0.15}, {0.25, -0.1, -0.3}});
  const OneCellField<3> field(Point<3>(-1., 0., 0.5), Point<3>(0.5, 2., 1.));
  const Tensor<2, 3> expected_F({{1.1, 0.3, -0.05}, {-0.2, 1.05, 0.15}, {0.25, -0.1, 0.7}});
  const double error = field.homogeneous_deformation_error(SolidKinematics(), G, expected_F);
  std::cout << "  solid: homogeneous F error on Q2 " << error << "\n";
  EXPECT_LE(error, round_off_tolerance);
}

// The variation is the derivative of F with respect to each nodal value, to round_off_tolerance.
TEST(SolidKinematics, VariationIsDerivativeOfF)
{
  const OneCellField<3> field(Point<3>(-1., 0., 0.5), Point<3>(0.5, 2., 1.));
  const double error = field.variation_error(SolidKinematics());
  std::cout << "  solid: variation vs difference quotient " << error << "\n";
  EXPECT_LE(error, round_off_tolerance);
}

// dV = dX: the cell integrates to its volume, exactly up to round-off (1e-14 relative), for any
// body id.
TEST(SolidKinematics, MeasureFactorIsOne)
{
  const OneCellField<3> field(Point<3>(-1., 0., 0.5), Point<3>(0.5, 2., 1.));
  EXPECT_NEAR(field.reference_volume(SolidKinematics()), 1.5, 1e-14);
  EXPECT_EQ(SolidKinematics().measure_factor(Point<3>(0.3, 0.2, 0.1), 7), 1.);
}
