#include <dyncontact/discretization/kinematics.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/symmetric_tensor.h>

namespace dyncontact
{
namespace
{
/** I + the displacement gradient, embedded in the upper-left dim x dim block of a 3x3 tensor. */
template <int dim>
Tensor<2, 3> identity_plus_embedded(const Tensor<2, dim>& displacement_gradient)
{
  Tensor<2, 3> F = unit_symmetric_tensor<3>();
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      F[i][j] += displacement_gradient[i][j];
  return F;
}

/** The variation of I + grad u caused by a shape function of one vector component: its gradient
 * in row `component`, zero elsewhere. */
template <int dim>
Tensor<2, 3> embedded_gradient_variation(const unsigned int component,
                                         const Tensor<1, dim>& shape_gradient)
{
  AssertIndexRange(component, dim);
  Tensor<2, 3> variation;
  for (unsigned int j = 0; j < dim; ++j)
    variation[component][j] = shape_gradient[j];
  return variation;
}
} // namespace

BarKinematics::BarKinematics(std::vector<double> areas) : areas(std::move(areas)) {}

Tensor<2, 3> BarKinematics::deformation_gradient(const Tensor<2, 1>& displacement_gradient,
                                                 const Tensor<1, 1>&,
                                                 const Point<1>&) const
{
  return identity_plus_embedded(displacement_gradient);
}

Tensor<2, 3> BarKinematics::deformation_gradient_variation(const unsigned int component,
                                                           const double,
                                                           const Tensor<1, 1>& shape_gradient,
                                                           const Point<1>&) const
{
  return embedded_gradient_variation(component, shape_gradient);
}

double BarKinematics::measure_factor(const Point<1>&, const types::material_id body) const
{
  AssertIndexRange(body, areas.size());
  return areas[body];
}

Tensor<2, 3> AxisymmetricKinematics::deformation_gradient(const Tensor<2, 2>& displacement_gradient,
                                                          const Tensor<1, 2>& displacement,
                                                          const Point<2>& X) const
{
  Assert(X[0] >= 0., ExcMessage("An axisymmetric point lies at r < 0."));
  Tensor<2, 3> F = identity_plus_embedded(displacement_gradient);
  // On the axis u_r = 0 by symmetry, and u_r / r tends to du_r / dr.
  F[2][2] += X[0] > 0. ? displacement[0] / X[0] : displacement_gradient[0][0];
  return F;
}

Tensor<2, 3>
AxisymmetricKinematics::deformation_gradient_variation(const unsigned int component,
                                                       const double shape_value,
                                                       const Tensor<1, 2>& shape_gradient,
                                                       const Point<2>& X) const
{
  Assert(X[0] > 0., ExcMessage("The hoop strain u_r/r is undefined on the axis r = 0."));
  Tensor<2, 3> variation = embedded_gradient_variation(component, shape_gradient);
  if (component == 0)
    variation[2][2] = shape_value / X[0];
  return variation;
}

double AxisymmetricKinematics::measure_factor(const Point<2>& X, const types::material_id) const
{
  return 2. * numbers::PI * X[0];
}

Tensor<2, 3> PlaneStrainKinematics::deformation_gradient(const Tensor<2, 2>& displacement_gradient,
                                                         const Tensor<1, 2>&,
                                                         const Point<2>&) const
{
  return identity_plus_embedded(displacement_gradient);
}

Tensor<2, 3>
PlaneStrainKinematics::deformation_gradient_variation(const unsigned int component,
                                                      const double,
                                                      const Tensor<1, 2>& shape_gradient,
                                                      const Point<2>&) const
{
  return embedded_gradient_variation(component, shape_gradient);
}

double PlaneStrainKinematics::measure_factor(const Point<2>&, const types::material_id) const
{
  return 1.;
}

Tensor<2, 3> SolidKinematics::deformation_gradient(const Tensor<2, 3>& displacement_gradient,
                                                   const Tensor<1, 3>&,
                                                   const Point<3>&) const
{
  return identity_plus_embedded(displacement_gradient);
}

Tensor<2, 3> SolidKinematics::deformation_gradient_variation(const unsigned int component,
                                                             const double,
                                                             const Tensor<1, 3>& shape_gradient,
                                                             const Point<3>&) const
{
  return embedded_gradient_variation(component, shape_gradient);
}

double SolidKinematics::measure_factor(const Point<3>&, const types::material_id) const
{
  return 1.;
}
} // namespace dyncontact
