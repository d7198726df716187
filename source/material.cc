#include <dyncontact/material.h>

#include <deal.II/base/symmetric_tensor.h>

namespace dyncontact
{
namespace
{
Tensor<2, 3> small_strain(const Tensor<2, 3>& F)
{
  const Tensor<2, 3> displacement_gradient = F - unit_symmetric_tensor<3>();
  return 0.5 * (displacement_gradient + transpose(displacement_gradient));
}
} // namespace

LinearElasticMaterial::LinearElasticMaterial(const double youngs_modulus,
                                             const double poissons_ratio)
{
  if (!(youngs_modulus > 0.))
    throw InputError("Young's modulus must be > 0 (got " + format_number(youngs_modulus) + ").");
  if (!(poissons_ratio > -1. && poissons_ratio < 0.5))
    throw InputError("Poisson's ratio must lie in (-1, 0.5) (got " + format_number(poissons_ratio) +
                     ").");
  lame_lambda =
      youngs_modulus * poissons_ratio / ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
  shear_modulus = youngs_modulus / (2. * (1. + poissons_ratio));
  // dP/dF of P = lambda tr(sym grad u) I + 2 mu sym(grad u): minor symmetrization included.
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          elasticity_tensor[i][j][k][l] =
              lame_lambda * (i == j) * (k == l) +
              shear_modulus * ((i == k) * (j == l) + (i == l) * (j == k));
}

double LinearElasticMaterial::strain_energy_density(const Tensor<2, 3>& F) const
{
  const Tensor<2, 3> eps = small_strain(F);
  return 0.5 * lame_lambda * trace(eps) * trace(eps) + shear_modulus * scalar_product(eps, eps);
}

Tensor<2, 3> LinearElasticMaterial::first_piola_kirchhoff_stress(const Tensor<2, 3>& F) const
{
  const Tensor<2, 3> eps = small_strain(F);
  return lame_lambda * trace(eps) * Tensor<2, 3>(unit_symmetric_tensor<3>()) +
         2. * shear_modulus * eps;
}

Tensor<4, 3> LinearElasticMaterial::stress_tangent(const Tensor<2, 3>&) const
{
  return elasticity_tensor;
}
} // namespace dyncontact
