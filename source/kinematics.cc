#include <dyncontact/kinematics.h>

#include <deal.II/base/symmetric_tensor.h>

namespace dyncontact
{
BarKinematics::BarKinematics(std::vector<double> areas) : areas(std::move(areas)) {}

Tensor<2, 3> BarKinematics::deformation_gradient(const Tensor<2, 1>& displacement_gradient,
                                                 const Tensor<1, 1>&,
                                                 const Point<1>&) const
{
  Tensor<2, 3> F = unit_symmetric_tensor<3>();
  F[0][0] += displacement_gradient[0][0];
  return F;
}

Tensor<2, 3> BarKinematics::deformation_gradient_variation(const unsigned int,
                                                           const double,
                                                           const Tensor<1, 1>& shape_gradient,
                                                           const Point<1>&) const
{
  Tensor<2, 3> variation;
  variation[0][0] = shape_gradient[0];
  return variation;
}

double BarKinematics::measure_factor(const Point<1>&, const types::material_id body) const
{
  AssertIndexRange(body, areas.size());
  return areas[body];
}
} // namespace dyncontact
