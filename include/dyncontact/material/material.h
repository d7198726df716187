#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

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

  /**
   * Whether P is linear in the displacement gradient: P(F) = C : (F - I) with a constant C, so
   * that W is quadratic in it. A body of such a material has the internal force K u with a
   * constant stiffness matrix K (ElasticBodies uses it). False unless a law says otherwise.
   */
  virtual bool is_linear() const { return false; }
};

/**
 * The common part of the isotropic laws: their Lame constants lambda and mu, computed from
 * Young's modulus and Poisson's ratio with the checks E > 0 and -1 < nu < 0.5 (InputError
 * otherwise). It is not a material law by itself.
 */
class IsotropicMaterial : public Material
{
protected:
  IsotropicMaterial(double youngs_modulus, double poissons_ratio);

  const double lame_lambda;
  const double shear_modulus;
};

/**
 * Small-strain isotropic linear elasticity, W = lambda/2 (tr eps)^2 + mu eps:eps with
 * eps = sym(F - I), so that P = lambda tr(eps) I + 2 mu eps. Not objective under large rotations;
 * it is the model of the paper's 1D bars. With Poisson's ratio 0 a bar in uniaxial strain is also
 * in uniaxial stress, P_11 = E (F_11 - 1).
 */
class LinearElasticMaterial : public IsotropicMaterial
{
public:
  /** Throws InputError unless E > 0 and -1 < nu < 0.5. */
  LinearElasticMaterial(double youngs_modulus, double poissons_ratio);

  double strain_energy_density(const Tensor<2, 3>& F) const override;
  Tensor<2, 3> first_piola_kirchhoff_stress(const Tensor<2, 3>& F) const override;
  /** True: P = lambda tr(eps) I + 2 mu eps with eps = sym(F - I). */
  bool is_linear() const override { return true; }
  Tensor<4, 3> stress_tangent(const Tensor<2, 3>& F) const override;

private:
  Tensor<4, 3> elasticity_tensor;
};

/**
 * The St. Venant-Kirchhoff law: linear elasticity written in the Green-Lagrange strain
 * E = (F^T F - I)/2, W = lambda/2 (tr E)^2 + mu E:E, with the second Piola-Kirchhoff stress
 * S = lambda tr(E) I + 2 mu E and P = F S. The Lame constants come from Young's modulus and
 * Poisson's ratio as in linear elasticity, to which it reduces at small strain. It is objective, so
 * large rotations are exact, but it is only meant for moderate strains: it softens without bound
 * in compression and gives W a finite value even for an inverted element (det F <= 0), which it
 * therefore does not detect.
 */
class StVenantKirchhoffMaterial : public IsotropicMaterial
{
public:
  /** Throws InputError unless E > 0 and -1 < nu < 0.5. */
  StVenantKirchhoffMaterial(double youngs_modulus, double poissons_ratio);

  double strain_energy_density(const Tensor<2, 3>& F) const override;
  Tensor<2, 3> first_piola_kirchhoff_stress(const Tensor<2, 3>& F) const override;
  Tensor<4, 3> stress_tangent(const Tensor<2, 3>& F) const override;
};

/**
 * A compressible neo-Hookean law with the strain energy density
 *
 *   W(F) = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,   I1 = tr(F^T F),  J = det F,
 *
 * so that P = mu F + (lambda ln J - mu) F^{-T}. lambda and mu are the Lame constants of the given
 * Young's modulus and Poisson's ratio, and at small strain the law reduces to linear elasticity
 * with exactly these constants. W grows without bound as J -> 0 and is undefined for J <= 0; an
 * inverted element is a failed solve (SolverFailure), not a user error. It is not a
 * nearly-incompressible formulation: as nu -> 0.5 a displacement-only discretization locks.
 */
class CompressibleNeoHookeanMaterial : public IsotropicMaterial
{
public:
  /** Throws InputError unless E > 0 and -1 < nu < 0.5. */
  CompressibleNeoHookeanMaterial(double youngs_modulus, double poissons_ratio);

  /** Each of the three throws SolverFailure if det F <= 0 (an inverted element). */
  double strain_energy_density(const Tensor<2, 3>& F) const override;
  Tensor<2, 3> first_piola_kirchhoff_stress(const Tensor<2, 3>& F) const override;
  Tensor<4, 3> stress_tangent(const Tensor<2, 3>& F) const override;
};

/**
 * The names create_material() accepts, separated by '|' as Patterns::Selection expects:
 * "linear elastic|st venant-kirchhoff|neo-hookean".
 */
std::string material_names();

/**
 * The material of the given name (one of material_names()) with Young's modulus E and Poisson's
 * ratio nu. Throws InputError for an unknown name or for E, nu out of range.
 */
std::shared_ptr<const Material>
create_material(const std::string& name, double youngs_modulus, double poissons_ratio);
} // namespace dyncontact
