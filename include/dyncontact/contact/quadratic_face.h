#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace dyncontact
{
/**
 * A Q2 face of a 2D mesh as the curve it is: x(xi) = sum_i N_i(xi) x_i, xi in [0, 1], through
 * its three support points x_0 (xi = 0), x_1 (xi = 1) and the mid-side node x_2 (xi = 1/2), the
 * order of ContactSurface::face_nodes(). N_i are the Lagrange quadratics through those points;
 * they sum to one. This is the face the isoparametric Q2 mapping makes, not its chord.
 *
 * closest_point() is the closest-point projection of node-to-segment contact (Wriggers,
 * Computational Contact Mechanics, 2nd ed., ch. 4; Laursen, Computational Contact and Impact
 * Mechanics, ch. 5): the parameter xi at which x(xi) - x_s is orthogonal to the tangent x'(xi).
 */
template <int dim>
struct QuadraticFace
{
  /** The face parameter xi. */
  using Parameter                       = double;
  static constexpr unsigned int n_nodes = 3;

  /** The support points x_0 (xi = 0), x_1 (xi = 1), x_2 (xi = 1/2), current positions. */
  std::array<Point<dim>, 3> points;

  /** N_i(xi), i = 0, 1, 2 (the order of `points`). */
  static std::array<double, 3> shape_values(const double xi)
  {
    return {{(1. - xi) * (1. - 2. * xi), xi * (2. * xi - 1.), 4. * xi * (1. - xi)}};
  }

  /** dN_i/dxi, i = 0, 1, 2. */
  static std::array<double, 3> shape_derivatives(const double xi)
  {
    return {{4. * xi - 3., 4. * xi - 1., 4. - 8. * xi}};
  }

  /** x(xi). */
  Point<dim> point(const double xi) const { return combination(shape_values(xi)); }

  /** The tangent x'(xi) (not normalized; length per unit xi). */
  Tensor<1, dim> tangent(const double xi) const
  {
    return combination(shape_derivatives(xi)) - Point<dim>();
  }

  /**
   * The normal of a face of a 2D mesh at xi: the tangent x'(xi) turned by -90 degrees (not
   * normalized; length per unit xi).
   */
  Tensor<1, dim> normal(const double xi) const
  {
    static_assert(dim == 2, "a line in 3D has no normal");
    const Tensor<1, dim> t = tangent(xi);
    Tensor<1, dim> n;
    n[0] = t[1];
    n[1] = -t[0];
    return n;
  }

  /** A closest point of the face to a point: its parameter, position and distance. */
  struct Projection
  {
    double xi;
    Point<dim> point;
    double distance;
  };

  /**
   * The point of the face nearest to `x_s`: Newton's method on f(xi) = (x(xi) - x_s) . x'(xi) = 0,
   * f'(xi) = |x'|^2 + (x(xi) - x_s) . x'', started at the projection onto the chord and kept in
   * [0, 1], until a step below 1e-14 (Newton converges quadratically, so xi is then exact to
   * round-off); the nearer face end wins if it is nearer than Newton's point. A point whose
   * projection falls outside the face is thereby clamped to the nearest face end (xi = 0 or 1).
   * If f' <= 0 (x_s beyond the face's centre of curvature) Newton stops and the ends decide.
   */
  Projection closest_point(const Point<dim>& x_s) const
  {
    const Tensor<1, dim> chord = points[1] - points[0];
    double xi = std::clamp(((x_s - points[0]) * chord) / chord.norm_square(), 0., 1.);
    const Tensor<1, dim> second_derivative = combination({{4., 4., -8.}}) - Point<dim>();
    for (unsigned int iteration = 0; iteration < max_newton_iterations; ++iteration)
    {
      const Tensor<1, dim> offset  = point(xi) - x_s;
      const Tensor<1, dim> tangent = this->tangent(xi);
      const double slope           = tangent * tangent + offset * second_derivative;
      if (slope <= 0.)
        break;
      const double next    = std::clamp(xi - (offset * tangent) / slope, 0., 1.);
      const bool converged = std::abs(next - xi) <= 1e-14;
      xi                   = next;
      if (converged)
        break;
    }
    Projection nearest{xi, point(xi), point(xi).distance(x_s)};
    for (const double end : {0., 1.})
      if (point(end).distance(x_s) < nearest.distance)
        nearest = {end, point(end), point(end).distance(x_s)};
    return nearest;
  }

  /**
   * The point of the face on the ray from `x_s` along the averaged normal nbar(xi) = n_s -
   * sum_i N_i(xi) normals[i] (`normals` the face's nodal normals in the order of `points`; all
   * zero for the ray along n_s alone): the parameter xi of the root of (x(xi) - x_s) x nbar(xi) =
   * 0, by Newton's method from `xi`. 2D only. Empty if Newton does not converge to a step below
   * 1e-14 in 20 iterations or the root lies outside the face (beyond 1e-12); a root within that
   * tolerance of a face end is clamped onto it.
   */
  std::optional<double> ray_point(const Point<dim>& x_s,
                                  const Tensor<1, dim>& n_s,
                                  const std::array<Tensor<1, dim>, 3>& normals,
                                  double xi) const
  {
    for (unsigned int iteration = 0; iteration < 20; ++iteration)
    {
      const auto N        = shape_values(xi);
      const auto dN       = shape_derivatives(xi);
      Tensor<1, dim> nbar = n_s, dnbar;
      for (unsigned int i = 0; i < 3; ++i)
      {
        nbar -= N[i] * normals[i];
        dnbar -= dN[i] * normals[i];
      }
      const Tensor<1, dim> offset = point(xi) - x_s;
      const double slope = tangent(xi) * cross_product_2d(nbar) + offset * cross_product_2d(dnbar);
      if (slope == 0.)
        return std::nullopt;
      const double step = (offset * cross_product_2d(nbar)) / slope;
      xi -= step;
      if (std::abs(step) <= 1e-14)
        return xi >= -1e-12 && xi <= 1. + 1e-12 ? std::optional<double>(std::clamp(xi, 0., 1.))
                                                : std::nullopt;
    }
    return std::nullopt;
  }

private:
  static constexpr unsigned int max_newton_iterations = 50;

  /** sum_i c_i x_i. */
  Point<dim> combination(const std::array<double, 3>& coefficients) const
  {
    Point<dim> sum;
    for (unsigned int i = 0; i < 3; ++i)
      sum += coefficients[i] * points[i];
    return sum;
  }
};
} // namespace dyncontact
