#include <dyncontact/material/material.h>

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace dyncontact
{
namespace
{
const std::string linear_elastic_name      = "linear elastic";
const std::string st_venant_kirchhoff_name = "st venant-kirchhoff";
const std::string neo_hookean_name         = "neo-hookean";

Tensor<2, 3> identity()
{
  return unit_symmetric_tensor<3>();
}

Tensor<2, 3> small_strain(const Tensor<2, 3>& F)
{
  const Tensor<2, 3> displacement_gradient = F - identity();
  return 0.5 * (displacement_gradient + transpose(displacement_gradient));
}

Tensor<2, 3> green_lagrange_strain(const Tensor<2, 3>& F)
{
  return 0.5 * (transpose(F) * F - identity());
}

/** det F, or SolverFailure if the element is inverted (det F <= 0 or not a number). */
double positive_jacobian(const Tensor<2, 3>& F)
{
  const double J = determinant(F);
  if (!(J > 0.))
    throw SolverFailure("Neo-Hookean material: inverted element (J = " + format_number(J) + ").");
  return J;
}
} // namespace

namespace
{
/** Young's modulus after checking E > 0 and -1 < nu < 0.5 (InputError otherwise). */
double checked_youngs_modulus(const double youngs_modulus, const double poissons_ratio)
{
  if (!(youngs_modulus > 0.))
    throw InputError("Young's modulus must be > 0 (got " + format_number(youngs_modulus) + ").");
  if (!(poissons_ratio > -1. && poissons_ratio < 0.5))
    throw InputError("Poisson's ratio must lie in (-1, 0.5) (got " + format_number(poissons_ratio) +
                     ").");
  return youngs_modulus;
}
} // namespace

IsotropicMaterial::IsotropicMaterial(const double youngs_modulus, const double poissons_ratio)
    : lame_lambda(checked_youngs_modulus(youngs_modulus, poissons_ratio) * poissons_ratio /
                  ((1. + poissons_ratio) * (1. - 2. * poissons_ratio))),
      shear_modulus(youngs_modulus / (2. * (1. + poissons_ratio)))
{
}

LinearElasticMaterial::LinearElasticMaterial(const double youngs_modulus,
                                             const double poissons_ratio)
    : IsotropicMaterial(youngs_modulus, poissons_ratio)
{
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
  return lame_lambda * trace(eps) * identity() + 2. * shear_modulus * eps;
}

Tensor<4, 3> LinearElasticMaterial::stress_tangent(const Tensor<2, 3>&) const
{
  return elasticity_tensor;
}

StVenantKirchhoffMaterial::StVenantKirchhoffMaterial(const double youngs_modulus,
                                                     const double poissons_ratio)
    : IsotropicMaterial(youngs_modulus, poissons_ratio)
{
}

double StVenantKirchhoffMaterial::strain_energy_density(const Tensor<2, 3>& F) const
{
  const Tensor<2, 3> E = green_lagrange_strain(F);
  return 0.5 * lame_lambda * trace(E) * trace(E) + shear_modulus * scalar_product(E, E);
}

Tensor<2, 3> StVenantKirchhoffMaterial::first_piola_kirchhoff_stress(const Tensor<2, 3>& F) const
{
  const Tensor<2, 3> E = green_lagrange_strain(F);
  return F * (lame_lambda * trace(E) * identity() + 2. * shear_modulus * E);
}

Tensor<4, 3> StVenantKirchhoffMaterial::stress_tangent(const Tensor<2, 3>& F) const
{
  // d(F S) = dF S + F (lambda tr(dE) I + 2 mu dE) with dE = sym(F^T dF); for dF = e_k (x) e_l:
  // dP_ij/dF_kl = delta_ik S_lj + lambda F_ij F_kl + mu ((F F^T)_ik delta_jl + F_il F_kj).
  const Tensor<2, 3> E    = green_lagrange_strain(F);
  const Tensor<2, 3> S    = lame_lambda * trace(E) * identity() + 2. * shear_modulus * E;
  const Tensor<2, 3> FF_T = F * transpose(F);
  Tensor<4, 3> tangent;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          tangent[i][j][k][l] = (i == k) * S[l][j] + lame_lambda * F[i][j] * F[k][l] +
                                shear_modulus * (FF_T[i][k] * (j == l) + F[i][l] * F[k][j]);
  return tangent;
}

CompressibleNeoHookeanMaterial::CompressibleNeoHookeanMaterial(const double youngs_modulus,
                                                               const double poissons_ratio)
    : IsotropicMaterial(youngs_modulus, poissons_ratio)
{
}

double CompressibleNeoHookeanMaterial::strain_energy_density(const Tensor<2, 3>& F) const
{
  const double log_J = std::log(positive_jacobian(F));
  return 0.5 * shear_modulus * (scalar_product(F, F) - 3.) - shear_modulus * log_J +
         0.5 * lame_lambda * log_J * log_J;
}

Tensor<2, 3>
CompressibleNeoHookeanMaterial::first_piola_kirchhoff_stress(const Tensor<2, 3>& F) const
{
  const double log_J = std::log(positive_jacobian(F));
  return shear_modulus * F + (lame_lambda * log_J - shear_modulus) * transpose(invert(F));
}

Tensor<4, 3> CompressibleNeoHookeanMaterial::stress_tangent(const Tensor<2, 3>& F) const
{
  // With d(ln J)/dF = F^{-T} and d(F^{-T})_ij/dF_kl = -F^{-T}_il F^{-T}_kj:
  // dP_ij/dF_kl = mu delta_ik delta_jl + lambda F^{-T}_ij F^{-T}_kl
  //               - (lambda ln J - mu) F^{-T}_il F^{-T}_kj.
  const double log_J          = std::log(positive_jacobian(F));
  const Tensor<2, 3> F_inv_T  = transpose(invert(F));
  const double inverse_weight = lame_lambda * log_J - shear_modulus;
  Tensor<4, 3> tangent;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          tangent[i][j][k][l] = shear_modulus * (i == k) * (j == l) +
                                lame_lambda * F_inv_T[i][j] * F_inv_T[k][l] -
                                inverse_weight * F_inv_T[i][l] * F_inv_T[k][j];
  return tangent;
}

std::string material_names()
{
  return linear_elastic_name + "|" + st_venant_kirchhoff_name + "|" + neo_hookean_name;
}

std::shared_ptr<const Material>
create_material(const std::string& name, const double youngs_modulus, const double poissons_ratio)
{
  if (name == linear_elastic_name)
    return std::make_shared<LinearElasticMaterial>(youngs_modulus, poissons_ratio);
  if (name == st_venant_kirchhoff_name)
    return std::make_shared<StVenantKirchhoffMaterial>(youngs_modulus, poissons_ratio);
  if (name == neo_hookean_name)
    return std::make_shared<CompressibleNeoHookeanMaterial>(youngs_modulus, poissons_ratio);
  throw InputError("Unknown material '" + name + "': the material must be one of '" +
                   linear_elastic_name + "', '" + st_venant_kirchhoff_name + "', '" +
                   neo_hookean_name + "'.");
}
} // namespace dyncontact
