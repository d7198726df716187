// Unit tests of the hyperelastic laws of material.h, each at the level of one material point:
// P is the derivative of W and dP/dF that of P (central finite differences at random finite
// deformations), every law reduces to the same linear elasticity at F = I, the finite-strain laws
// are objective, and the factory and constructors reject bad input with messages that name the
// entry and the allowed range.
#include <dyncontact/material/material.h>

#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

using dealii::Tensor;
using dyncontact::create_material;
using dyncontact::InputError;
using dyncontact::Material;
using dyncontact::material_names;

namespace
{
// Not 1 and not round, so that a lost factor E or a swapped lambda/mu shows.
constexpr double youngs_modulus = 210.;
constexpr double poissons_ratio = 0.3;
constexpr double lame_lambda =
    youngs_modulus * poissons_ratio / ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
constexpr double shear_modulus = youngs_modulus / (2. * (1. + poissons_ratio));

/// Random deformations checked per material; the reported error is the largest over all of them.
constexpr unsigned int n_random_deformations = 10;

std::vector<std::string> all_material_names()
{
  return dealii::Utilities::split_string_list(material_names(), '|');
}

/// GoogleTest parameter names may only hold letters, digits and underscores.
std::string test_name(const testing::TestParamInfo<std::string>& info)
{
  std::string name = info.param;
  std::replace_if(
      name.begin(), name.end(), [](const unsigned char c) { return !std::isalnum(c); }, '_');
  return name;
}

Tensor<2, 3> identity()
{
  Tensor<2, 3> I;
  for (unsigned int i = 0; i < 3; ++i)
    I[i][i] = 1.;
  return I;
}

/// F = I + 0.2 * (entries uniform in [-1, 1]). The perturbation has Frobenius norm <= 0.6 < 1,
/// so every singular value of F exceeds 0.4 and det F > 0.
Tensor<2, 3> random_deformation_gradient(std::mt19937& generator)
{
  std::uniform_real_distribution<double> entry(-1., 1.);
  Tensor<2, 3> F = identity();
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      F[i][j] += 0.2 * entry(generator);
  return F;
}

/// A proper rotation, by Rodrigues' formula, about a skew axis by a large angle.
Tensor<2, 3> rotation()
{
  const double angle = 2.1;
  Tensor<1, 3> axis;
  axis[0] = 1.;
  axis[1] = -2.;
  axis[2] = 3.;
  axis /= axis.norm();
  Tensor<2, 3> cross_product_matrix;
  cross_product_matrix[0][1] = -axis[2];
  cross_product_matrix[0][2] = axis[1];
  cross_product_matrix[1][0] = axis[2];
  cross_product_matrix[1][2] = -axis[0];
  cross_product_matrix[2][0] = -axis[1];
  cross_product_matrix[2][1] = axis[0];
  return std::cos(angle) * identity() + std::sin(angle) * cross_product_matrix +
         (1. - std::cos(angle)) * dealii::outer_product(axis, axis);
}

/// The tangent of linear elasticity with the constants above:
/// lambda delta_ij delta_kl + mu (delta_ik delta_jl + delta_il delta_jk).
Tensor<4, 3> linear_elastic_tangent()
{
  Tensor<4, 3> C;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          C[i][j][k][l] = lame_lambda * (i == j) * (k == l) +
                          shear_modulus * ((i == k) * (j == l) + (i == l) * (j == k));
  return C;
}

// Central differences with step h have truncation error h^2/6 |third derivative|, about 1e-12 of
// the stress scale here, and round-off about 1e-16 |W| / h, about 1e-10 of it.
constexpr double finite_difference_step = 1e-6;

/// dW/dF_kl by central differences.
Tensor<2, 3> finite_difference_stress(const Material& material, const Tensor<2, 3>& F)
{
  Tensor<2, 3> stress;
  for (unsigned int k = 0; k < 3; ++k)
    for (unsigned int l = 0; l < 3; ++l)
    {
      Tensor<2, 3> F_plus = F, F_minus = F;
      F_plus[k][l] += finite_difference_step;
      F_minus[k][l] -= finite_difference_step;
      stress[k][l] =
          (material.strain_energy_density(F_plus) - material.strain_energy_density(F_minus)) /
          (2. * finite_difference_step);
    }
  return stress;
}

/// dP_ij/dF_kl by central differences.
Tensor<4, 3> finite_difference_tangent(const Material& material, const Tensor<2, 3>& F)
{
  Tensor<4, 3> tangent;
  for (unsigned int k = 0; k < 3; ++k)
    for (unsigned int l = 0; l < 3; ++l)
    {
      Tensor<2, 3> F_plus = F, F_minus = F;
      F_plus[k][l] += finite_difference_step;
      F_minus[k][l] -= finite_difference_step;
      const Tensor<2, 3> stress_difference = material.first_piola_kirchhoff_stress(F_plus) -
                                             material.first_piola_kirchhoff_stress(F_minus);
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          tangent[i][j][k][l] = stress_difference[i][j] / (2. * finite_difference_step);
    }
  return tangent;
}

/// Expect that create_material(name, E, nu) throws InputError whose message contains every one
/// of expected_texts.
void expect_input_error(const std::string& name,
                        const double E,
                        const double nu,
                        const std::vector<std::string>& expected_texts)
{
  try
  {
    create_material(name, E, nu);
    ADD_FAILURE() << "no InputError for '" << name << "', E = " << E << ", nu = " << nu;
  }
  catch (const InputError& error)
  {
    for (const std::string& text : expected_texts)
      EXPECT_NE(std::string(error.what()).find(text), std::string::npos)
          << "'" << error.what() << "' does not mention '" << text << "'";
  }
}

/// Every test below runs once for each name in material_names().
class MaterialLaw : public testing::TestWithParam<std::string>
{
protected:
  MaterialLaw() : material(create_material(GetParam(), youngs_modulus, poissons_ratio)) {}

  std::shared_ptr<const Material> material;
};
} // namespace

INSTANTIATE_TEST_SUITE_P(AllMaterials,
                         MaterialLaw,
                         testing::ValuesIn(all_material_names()),
                         test_name);

// P must be dW/dF. Relative error in the Frobenius norm <= 1e-6: the central-difference error
// estimated above is about 1e-10 (measured values are printed), so 1e-6 leaves four orders of
// margin while any wrong term in P, which would be of relative size 1e-2 or more, still fails.
TEST_P(MaterialLaw, StressIsDerivativeOfStrainEnergy)
{
  std::mt19937 generator(20230917);
  double max_relative_error = 0.;
  for (unsigned int sample = 0; sample < n_random_deformations; ++sample)
  {
    const Tensor<2, 3> F = random_deformation_gradient(generator);
    ASSERT_GT(determinant(F), 0.);
    const Tensor<2, 3> P = material->first_piola_kirchhoff_stress(F);
    max_relative_error   = std::max(max_relative_error,
                                  (finite_difference_stress(*material, F) - P).norm() / P.norm());
  }
  std::cout << "  " << GetParam() << ": max relative FD error of P against dW/dF "
            << max_relative_error << " over " << n_random_deformations << " random F\n";
  EXPECT_LE(max_relative_error, 1e-6);
}

// dP/dF must be the derivative of P, the consistency Newton's quadratic convergence relies on.
// Same step, error estimate and tolerance as for P against W.
TEST_P(MaterialLaw, TangentIsDerivativeOfStress)
{
  std::mt19937 generator(20230918);
  double max_relative_error = 0.;
  for (unsigned int sample = 0; sample < n_random_deformations; ++sample)
  {
    const Tensor<2, 3> F = random_deformation_gradient(generator);
    ASSERT_GT(determinant(F), 0.);
    const Tensor<4, 3> tangent = material->stress_tangent(F);
    max_relative_error =
        std::max(max_relative_error,
                 (finite_difference_tangent(*material, F) - tangent).norm() / tangent.norm());
  }
  std::cout << "  " << GetParam() << ": max relative FD error of dP/dF against P "
            << max_relative_error << " over " << n_random_deformations << " random F\n";
  EXPECT_LE(max_relative_error, 1e-6);
}

// At F = I every law is stress-free and its tangent is that of linear elasticity with the same
// lambda and mu, so the models agree at small strain. The values are a handful of products of
// O(E) numbers: round-off is about 1e-16 E, and 1e-13 E is the tolerance.
TEST_P(MaterialLaw, ReferenceStateIsStressFreeWithLinearElasticTangent)
{
  EXPECT_LE(material->first_piola_kirchhoff_stress(identity()).norm(), 1e-13 * youngs_modulus);
  EXPECT_LE((material->stress_tangent(identity()) - linear_elastic_tangent()).norm(),
            1e-13 * youngs_modulus);
  EXPECT_LE(std::abs(material->strain_energy_density(identity())), 1e-13 * youngs_modulus);
}

// A uniaxial stress test at axial strain eps = 1e-6: the lateral stretch is solved so that the
// lateral stress vanishes, then P_11 / eps must be E and -(lateral strain) / eps must be nu. Both
// differ from their small-strain limits by O(eps) relative (the next term of W is cubic). Stresses
// are computed from F - I, whose entries carry round-off of about 1e-16, so the lateral stress
// cannot be driven below about 1e-16 E (1e-13 E is asked for, 1e-9 of the axial stress) and
// P_11 / eps carries a relative round-off of about 1e-16 / eps = 1e-10. The tolerance 1e-5 leaves a
// factor 10 over the O(eps) term with coefficients of order one.
TEST_P(MaterialLaw, UniaxialSmallStrainGivesYoungsModulusAndPoissonsRatio)
{
  const double axial_strain   = 1e-6;
  double lateral_strain       = 0.;
  const auto uniaxial_stretch = [&]()
  {
    Tensor<2, 3> F = identity();
    F[0][0] += axial_strain;
    F[1][1] += lateral_strain;
    F[2][2] += lateral_strain;
    return F;
  };
  // Newton on P_22(lateral strain) = 0; by isotropy P_33 = P_22.
  const double lateral_stress_tolerance = 1e-13 * youngs_modulus;
  for (unsigned int iteration = 0; iteration < 20; ++iteration)
  {
    const double lateral_stress = material->first_piola_kirchhoff_stress(uniaxial_stretch())[1][1];
    if (std::abs(lateral_stress) <= lateral_stress_tolerance)
      break;
    const Tensor<4, 3> tangent = material->stress_tangent(uniaxial_stretch());
    lateral_strain -= lateral_stress / (tangent[1][1][1][1] + tangent[1][1][2][2]);
  }
  const Tensor<2, 3> P = material->first_piola_kirchhoff_stress(uniaxial_stretch());
  EXPECT_LE(std::abs(P[1][1]), lateral_stress_tolerance);
  EXPECT_LE(std::abs(P[2][2]), lateral_stress_tolerance);
  const double modulus_error = P[0][0] / axial_strain / youngs_modulus - 1.;
  const double ratio_error   = -lateral_strain / axial_strain - poissons_ratio;
  std::cout << "  " << GetParam() << ": uniaxial strain 1e-6, relative error of E " << modulus_error
            << ", error of nu " << ratio_error << "\n";
  EXPECT_LE(std::abs(modulus_error), 1e-5);
  EXPECT_LE(std::abs(ratio_error), 1e-5);
}

// The finite-strain laws must be objective: W(Q F) = W(F) and P(Q F) = Q P(F) for a rotation Q.
// (Linear elasticity is not, by design.) Both sides are a few dozen products of O(1) entries, so
// they agree to round-off, about 1e-15 relative; the tolerance is 1e-12.
TEST(MaterialFrameIndifference, FiniteStrainLawsAreObjective)
{
  const Tensor<2, 3> Q = rotation();
  ASSERT_NEAR((Q * transpose(Q) - identity()).norm(), 0., 1e-15);
  ASSERT_NEAR(determinant(Q), 1., 1e-15);
  std::mt19937 generator(20230919);
  for (const std::string name : {"st venant-kirchhoff", "neo-hookean"})
  {
    const auto material = create_material(name, youngs_modulus, poissons_ratio);
    for (unsigned int sample = 0; sample < n_random_deformations; ++sample)
    {
      const Tensor<2, 3> F = random_deformation_gradient(generator);
      const double W       = material->strain_energy_density(F);
      EXPECT_NEAR(material->strain_energy_density(Q * F), W, 1e-12 * std::abs(W)) << name;
      const Tensor<2, 3> P = material->first_piola_kirchhoff_stress(F);
      EXPECT_LE((material->first_piola_kirchhoff_stress(Q * F) - Q * P).norm(), 1e-12 * P.norm())
          << name;
    }
  }
}

// det F <= 0 means an inverted element, which the neo-Hookean energy cannot evaluate: a failed
// solve with a message that says so, for W, P and dP/dF alike.
TEST(MaterialInvertedElement, NeoHookeanThrowsSolverFailure)
{
  const auto material = create_material("neo-hookean", youngs_modulus, poissons_ratio);
  Tensor<2, 3> F      = identity();
  F[2][2]             = -0.5;
  for (const auto& evaluate :
       std::vector<std::function<void()>>{[&]() { material->strain_energy_density(F); },
                                          [&]() { material->first_piola_kirchhoff_stress(F); },
                                          [&]() { material->stress_tangent(F); }})
  {
    try
    {
      evaluate();
      ADD_FAILURE() << "no SolverFailure for det F = " << determinant(F);
    }
    catch (const dyncontact::SolverFailure& error)
    {
      EXPECT_NE(std::string(error.what()).find("inverted element (J = -0.5)"), std::string::npos)
          << error.what();
    }
  }
}

// The factory knows exactly the three documented names and builds the matching class.
TEST(MaterialFactory, CreatesTheNamedMaterial)
{
  EXPECT_EQ(material_names(), "linear elastic|st venant-kirchhoff|neo-hookean");
  EXPECT_NE(dynamic_cast<const dyncontact::LinearElasticMaterial*>(
                create_material("linear elastic", youngs_modulus, poissons_ratio).get()),
            nullptr);
  EXPECT_NE(dynamic_cast<const dyncontact::StVenantKirchhoffMaterial*>(
                create_material("st venant-kirchhoff", youngs_modulus, poissons_ratio).get()),
            nullptr);
  EXPECT_NE(dynamic_cast<const dyncontact::CompressibleNeoHookeanMaterial*>(
                create_material("neo-hookean", youngs_modulus, poissons_ratio).get()),
            nullptr);
}

// Bad input is the user's to fix: an InputError whose message names the entry, the offending
// value where it helps, and what is allowed.
TEST(MaterialFactory, RejectsBadInput)
{
  expect_input_error("foo",
                     youngs_modulus,
                     poissons_ratio,
                     {"material", "'foo'", "linear elastic", "st venant-kirchhoff", "neo-hookean"});
  for (const std::string& name : all_material_names())
  {
    expect_input_error(name, youngs_modulus, 0.5, {"Poisson's ratio", "(-1, 0.5)", "got 0.5"});
    expect_input_error(name, youngs_modulus, -1., {"Poisson's ratio", "(-1, 0.5)", "got -1"});
    expect_input_error(name, 0., poissons_ratio, {"Young's modulus", "> 0", "got 0"});
    expect_input_error(name, std::nan(""), poissons_ratio, {"Young's modulus", "> 0"});
  }
}
