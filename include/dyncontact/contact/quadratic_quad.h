#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/quadratic_face.h>

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
 * A Q2 face of a 3D mesh as the surface it is: x(p) = sum_j N_j(p) x_j, p = (xi, eta) in
 * [0, 1]^2, through its nine support points in the order of the unit face support points of
 * deal.II's FE_Q<2>(2), that of ContactSurface::face_nodes(): the vertices (0, 0), (1, 0), (0, 1),
 * (1, 1), the mid-sides (0, 1/2), (1, 1/2), (1/2, 0), (1/2, 1), the centre (1/2, 1/2). N_j are the
 * biquadratic Lagrange functions through them (products of QuadraticFace's 1D quadratics); they
 * sum to one. The face the isoparametric Q2 mapping makes. The 3D face patch of node-to-surface
 * contact (NodeToSegmentContact<3>), with QuadraticFace's interface: closest_point() and
 * ray_point() (Wriggers, Computational Contact Mechanics, 2nd ed., ch. 4).
 */
struct QuadraticQuad
{
  /** The face parameter (xi, eta). */
  using Parameter                       = Point<2>;
  static constexpr unsigned int n_nodes = 9;

  /** The support points, current positions, in the order above. */
  std::array<Point<3>, n_nodes> points;

  /** N_j(p), j = 0..8. */
  static std::array<double, n_nodes> shape_values(const Parameter& p)
  {
    const auto a = QuadraticFace<3>::shape_values(p[0]), b = QuadraticFace<3>::shape_values(p[1]);
    std::array<double, n_nodes> values;
    for (unsigned int j = 0; j < n_nodes; ++j)
      values[j] = a[xi_index[j]] * b[eta_index[j]];
    return values;
  }

  /** x(p). */
  Point<3> point(const Parameter& p) const { return combination(shape_values(p)); }

  /** The normal x_,xi x x_,eta at p (not normalized; area per unit parameter area). */
  Tensor<1, 3> normal(const Parameter& p) const
  {
    const Derivatives d = derivatives(p);
    return cross_product_3d(d.first[0], d.first[1]);
  }

  /** A closest point of the face to a point: its parameter, position and distance. */
  struct Projection
  {
    Parameter xi;
    Point<3> point;
    double distance;
  };

  /**
   * The point of the face nearest to `x_s`: Newton's method on (x(p) - x_s) . x_,k(p) = 0,
   * k = xi, eta, its Jacobian x_,k . x_,l + (x - x_s) . x_,kl, from the face's centre, each
   * iterate clamped into [0, 1]^2, until a step below 1e-14; stopped where the Jacobian is not
   * positive definite (x_s beyond a centre of curvature). The nearest corner wins if it is nearer.
   * A point whose projection falls outside the face is thereby clamped to its boundary.
   */
  Projection closest_point(const Point<3>& x_s) const
  {
    Parameter p(0.5, 0.5);
    for (unsigned int iteration = 0; iteration < 50; ++iteration)
    {
      const Derivatives d       = derivatives(p);
      const Tensor<1, 3> offset = point(p) - x_s;
      const double f0           = offset * d.first[0];
      const double f1           = offset * d.first[1];
      const double j00          = d.first[0] * d.first[0] + offset * d.second[0][0];
      const double j01          = d.first[0] * d.first[1] + offset * d.second[0][1];
      const double j11          = d.first[1] * d.first[1] + offset * d.second[1][1];
      const double determinant  = j00 * j11 - j01 * j01;
      if (!(j00 > 0. && determinant > 0.))
        break;
      const Parameter next(std::clamp(p[0] - (j11 * f0 - j01 * f1) / determinant, 0., 1.),
                           std::clamp(p[1] - (j00 * f1 - j01 * f0) / determinant, 0., 1.));
      const bool converged = next.distance(p) <= 1e-14;
      p                    = next;
      if (converged)
        break;
    }
    Projection nearest{p, point(p), point(p).distance(x_s)};
    for (unsigned int corner = 0; corner < 4; ++corner)
    {
      const Parameter c(corner % 2, corner / 2);
      if (point(c).distance(x_s) < nearest.distance)
        nearest = {c, point(c), point(c).distance(x_s)};
    }
    return nearest;
  }

  /**
   * The point of the face on the ray from `x_s` along the averaged normal nbar(p) = n_s -
   * sum_j N_j(p) normals[j] (`normals` the face's nodal normals in the order of `points`; all zero
   * for the ray along n_s alone): the root (p, s) of x(p) - x_s - s nbar(p) = 0 by Newton's method
   * from `p` (s = 0), returning p. Empty if Newton does not converge to a step below 1e-14 in 20
   * iterations or the root lies outside the face (beyond 1e-12); a root within that tolerance of
   * the boundary is clamped onto it.
   */
  std::optional<Parameter> ray_point(const Point<3>& x_s,
                                     const Tensor<1, 3>& n_s,
                                     const std::array<Tensor<1, 3>, n_nodes>& normals,
                                     Parameter p) const
  {
    double s = 0.;
    for (unsigned int iteration = 0; iteration < 20; ++iteration)
    {
      const auto N      = shape_values(p);
      const auto dN     = shape_derivatives(p);
      Tensor<1, 3> nbar = n_s;
      std::array<Tensor<1, 3>, 2> dnbar;
      for (unsigned int j = 0; j < n_nodes; ++j)
      {
        nbar -= N[j] * normals[j];
        for (unsigned int k = 0; k < 2; ++k)
          dnbar[k] -= dN[j][k] * normals[j];
      }
      const Derivatives d         = derivatives(p);
      const Tensor<1, 3> residual = point(p) - x_s - s * nbar;
      Tensor<2, 3> jacobian;
      for (unsigned int i = 0; i < 3; ++i)
      {
        jacobian[i][0] = d.first[0][i] - s * dnbar[0][i];
        jacobian[i][1] = d.first[1][i] - s * dnbar[1][i];
        jacobian[i][2] = -nbar[i];
      }
      if (determinant(jacobian) == 0.)
        return std::nullopt;
      const Tensor<1, 3> step = invert(jacobian) * residual;
      p[0] -= step[0];
      p[1] -= step[1];
      s -= step[2];
      if (std::hypot(step[0], step[1]) <= 1e-14)
      {
        const bool inside =
            p[0] >= -1e-12 && p[0] <= 1. + 1e-12 && p[1] >= -1e-12 && p[1] <= 1. + 1e-12;
        return inside ? std::optional<Parameter>(
                            Parameter(std::clamp(p[0], 0., 1.), std::clamp(p[1], 0., 1.)))
                      : std::nullopt;
      }
    }
    return std::nullopt;
  }

private:
  /** Per node, the index (0: 0, 1: 1, 2: 1/2) of its xi and eta among QuadraticFace's points. */
  static constexpr std::array<unsigned int, n_nodes> xi_index  = {{0, 1, 0, 1, 0, 1, 2, 2, 2}};
  static constexpr std::array<unsigned int, n_nodes> eta_index = {{0, 0, 1, 1, 2, 2, 0, 1, 2}};

  /** (dN_j/dxi, dN_j/deta), j = 0..8. */
  static std::array<std::array<double, 2>, n_nodes> shape_derivatives(const Parameter& p)
  {
    const auto a = QuadraticFace<3>::shape_values(p[0]), b = QuadraticFace<3>::shape_values(p[1]);
    const auto da = QuadraticFace<3>::shape_derivatives(p[0]),
               db = QuadraticFace<3>::shape_derivatives(p[1]);
    std::array<std::array<double, 2>, n_nodes> derivatives;
    for (unsigned int j = 0; j < n_nodes; ++j)
      derivatives[j] = {{da[xi_index[j]] * b[eta_index[j]], a[xi_index[j]] * db[eta_index[j]]}};
    return derivatives;
  }

  /** The tangents x_,k and the second derivatives x_,kl at p. */
  struct Derivatives
  {
    std::array<Tensor<1, 3>, 2> first;
    std::array<std::array<Tensor<1, 3>, 2>, 2> second;
  };
  Derivatives derivatives(const Parameter& p) const
  {
    // The 1D quadratics' second derivatives: 4, 4, -8 (QuadraticFace's order).
    constexpr std::array<double, 3> second_1d = {{4., 4., -8.}};
    const auto a = QuadraticFace<3>::shape_values(p[0]), b = QuadraticFace<3>::shape_values(p[1]);
    const auto da = QuadraticFace<3>::shape_derivatives(p[0]),
               db = QuadraticFace<3>::shape_derivatives(p[1]);
    Derivatives d;
    for (unsigned int j = 0; j < n_nodes; ++j)
    {
      const unsigned int i = xi_index[j], k = eta_index[j];
      const Tensor<1, 3> x = points[j] - Point<3>();
      d.first[0] += da[i] * b[k] * x;
      d.first[1] += a[i] * db[k] * x;
      d.second[0][0] += second_1d[i] * b[k] * x;
      d.second[0][1] += da[i] * db[k] * x;
      d.second[1][1] += a[i] * second_1d[k] * x;
    }
    d.second[1][0] = d.second[0][1];
    return d;
  }

  /** sum_j c_j x_j. */
  Point<3> combination(const std::array<double, n_nodes>& coefficients) const
  {
    Point<3> sum;
    for (unsigned int j = 0; j < n_nodes; ++j)
      sum += coefficients[j] * points[j];
    return sum;
  }
};
} // namespace dyncontact
