#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * How a dim-dimensional displacement field becomes a 3x3 deformation gradient and how reference
 * volume is measured: the one place where 1D bars, plane strain, axisymmetry and 3D differ.
 * The assembler asks it for F, for the variation of F caused by one shape function, and for the
 * measure factor dV = factor * dX. It has no material law and no quadrature of its own.
 */
template <int dim>
class Kinematics
{
public:
  virtual ~Kinematics() = default;

  /**
   * F from the displacement gradient and value at reference point X: I plus a term linear in
   * them (every kinematics here), so that a linear material gives a force linear in u.
   */
  virtual Tensor<2, 3> deformation_gradient(const Tensor<2, dim>& displacement_gradient,
                                            const Tensor<1, dim>& displacement,
                                            const Point<dim>& X) const = 0;

  /** dF caused by a shape function of the given vector component, value and gradient at X. */
  virtual Tensor<2, 3> deformation_gradient_variation(unsigned int component,
                                                      double shape_value,
                                                      const Tensor<1, dim>& shape_gradient,
                                                      const Point<dim>& X) const = 0;

  /** Reference volume per unit dX of the dim-dimensional model (area, 2 pi r, thickness). */
  virtual double measure_factor(const Point<dim>& X, types::material_id body) const = 0;

  /**
   * The names of the three axes of F, as stress and strain components are named in the output:
   * {"x", "y", "z"}, or {"r", "z", "theta"} for axisymmetry.
   */
  virtual std::array<std::string, 3> axis_names() const { return {{"x", "y", "z"}}; }
};

/**
 * Straight bars in uniaxial strain: F = diag(1 + du/dx, 1, 1), dV = A_b dx with the
 * cross-section area of body b. Combined with a Poisson's ratio of zero this is the 1D bar of the
 * paper. It is not a beam and carries no bending.
 */
class BarKinematics : public Kinematics<1>
{
public:
  /** `areas[b]` is the cross-section area of body b (material id b). */
  explicit BarKinematics(std::vector<double> areas);

  Tensor<2, 3> deformation_gradient(const Tensor<2, 1>& displacement_gradient,
                                    const Tensor<1, 1>& displacement,
                                    const Point<1>& X) const override;
  Tensor<2, 3> deformation_gradient_variation(unsigned int component,
                                              double shape_value,
                                              const Tensor<1, 1>& shape_gradient,
                                              const Point<1>& X) const override;
  double measure_factor(const Point<1>& X, types::material_id body) const override;

private:
  std::vector<double> areas;
};

/**
 * Axisymmetric solids: the 2D model lives in the meridian half-plane with coordinates X = (r, z)
 * and displacement (u_r, u_z), and the third index of F is the hoop direction,
 *
 *   F = [[1 + du_r/dr, du_r/dz, 0], [du_z/dr, 1 + du_z/dz, 0], [0, 0, 1 + u_r/r]],
 *
 * with dV = 2 pi r dr dz. Torsion (a hoop displacement) is not represented. On the axis r = 0 the
 * hoop term u_r/r of F is 0/0; there u_r = 0 by symmetry, and F takes its limit
 * F_33 = 1 + du_r/dr (the field output evaluates stresses at nodes on the axis). The variation's
 * shape_value/r has no such limit for a single shape function; Gauss quadrature points lie inside
 * cells, never on the axis, so asking for the variation at r <= 0, or for F at r < 0, is a
 * programming error (Assert). The body argument of measure_factor() is ignored.
 */
class AxisymmetricKinematics : public Kinematics<2>
{
public:
  Tensor<2, 3> deformation_gradient(const Tensor<2, 2>& displacement_gradient,
                                    const Tensor<1, 2>& displacement,
                                    const Point<2>& X) const override;
  Tensor<2, 3> deformation_gradient_variation(unsigned int component,
                                              double shape_value,
                                              const Tensor<1, 2>& shape_gradient,
                                              const Point<2>& X) const override;
  double measure_factor(const Point<2>& X, types::material_id body) const override;
  std::array<std::string, 3> axis_names() const override { return {{"r", "z", "theta"}}; }
};

/**
 * Plane strain in the x-y plane: F = [[1 + du_x/dx, du_x/dy, 0], [du_y/dx, 1 + du_y/dy, 0],
 * [0, 0, 1]], dV = dx dy (unit thickness). The out-of-plane stress that keeps F_33 = 1 is implied,
 * not computed. It is not plane stress. The body argument of measure_factor() is ignored.
 */
class PlaneStrainKinematics : public Kinematics<2>
{
public:
  Tensor<2, 3> deformation_gradient(const Tensor<2, 2>& displacement_gradient,
                                    const Tensor<1, 2>& displacement,
                                    const Point<2>& X) const override;
  Tensor<2, 3> deformation_gradient_variation(unsigned int component,
                                              double shape_value,
                                              const Tensor<1, 2>& shape_gradient,
                                              const Point<2>& X) const override;
  double measure_factor(const Point<2>& X, types::material_id body) const override;
};

/**
 * Three-dimensional solids: F = I + grad u, dV = dx dy dz. No reduction of any kind. The body
 * argument of measure_factor() is ignored.
 */
class SolidKinematics : public Kinematics<3>
{
public:
  Tensor<2, 3> deformation_gradient(const Tensor<2, 3>& displacement_gradient,
                                    const Tensor<1, 3>& displacement,
                                    const Point<3>& X) const override;
  Tensor<2, 3> deformation_gradient_variation(unsigned int component,
                                              double shape_value,
                                              const Tensor<1, 3>& shape_gradient,
                                              const Point<3>& X) const override;
  double measure_factor(const Point<3>& X, types::material_id body) const override;
};
} // namespace dyncontact
