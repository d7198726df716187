#pragma once

#include <dyncontact/global.h>

#include <deal.II/base/tensor.h>

namespace dyncontact
{
/**
 * A hyperelastic law at one material point, written for the full 3x3 deformation gradient F (the
 * kinematics embed 1D, plane and axisymmetric problems into it): the strain energy density W(F)
 * per unit reference volume, the first Piola-Kirchhoff stress P = dW/dF and its derivative
 * dP/dF. It knows nothing about quadrature, meshes or the mass density.
 */
class Material
{
public:
  virtual ~Material() = default;

  /** W(F) per unit reference volume. */
  virtual double strain_energy_density(const Tensor<2, 3>& F) const = 0;

  /** P(F) = dW/dF. */
  virtual Tensor<2, 3> first_piola_kirchhoff_stress(const Tensor<2, 3>& F) const = 0;

  /** dP/dF, with (dP/dF)_{ijkl} = d P_ij / d F_kl. */
  virtual Tensor<4, 3> stress_tangent(const Tensor<2, 3>& F) const = 0;
};

/**
 * Small-strain isotropic linear elasticity, W = lambda/2 (tr eps)^2 + mu eps:eps with
 * eps = sym(F - I), so that P = lambda tr(eps) I + 2 mu eps. Not objective under large rotations;
 * it is the model of the paper's 1D bars. With Poisson's ratio 0 a bar in uniaxial strain is also
 * in uniaxial stress, P_11 = E (F_11 - 1).
 */
class LinearElasticMaterial : public Material
{
public:
  /** Throws InputError unless E > 0 and -1 < nu < 0.5. */
  LinearElasticMaterial(double youngs_modulus, double poissons_ratio);

  double strain_energy_density(const Tensor<2, 3>& F) const override;
  Tensor<2, 3> first_piola_kirchhoff_stress(const Tensor<2, 3>& F) const override;
  Tensor<4, 3> stress_tangent(const Tensor<2, 3>& F) const override;

private:
  double lame_lambda;
  double shear_modulus;
  Tensor<4, 3> elasticity_tensor;
};
} // namespace dyncontact
