// The 9-node face patch of node-to-surface contact in 3D (QuadraticQuad): on the curved face
// x(xi, eta) = (xi, eta, xi^2 + xi eta), which its biquadratic interpolation represents exactly,
// the closest point of a point off the face along its normal and the ray point along a given
// direction are the exact parameters, and the shape functions are Lagrange's.
#include <dyncontact/contact/quadratic_quad.h>

#include <cmath>
#include <gtest/gtest.h>

namespace dyncontact::testing
{
namespace
{
/** The unit support points of FE_Q<2>(2), the order of QuadraticQuad::points. */
const std::array<Point<2>, 9> support = {{{0., 0.},
                                          {1., 0.},
                                          {0., 1.},
                                          {1., 1.},
                                          {0., 0.5},
                                          {1., 0.5},
                                          {0.5, 0.},
                                          {0.5, 1.},
                                          {0.5, 0.5}}};

/** The exact surface. */
Point<3> surface(const double xi, const double eta)
{
  return Point<3>(xi, eta, xi * xi + xi * eta);
}

/** The patch through the surface's points at the unit support points of FE_Q<2>(2). */
QuadraticQuad patch()
{
  QuadraticQuad face;
  for (unsigned int j = 0; j < 9; ++j)
    face.points[j] = surface(support[j][0], support[j][1]);
  return face;
}
} // namespace

// N_j is one at its own support point and zero at the others, the N_j sum to one anywhere, and
// the patch reproduces the biquadratic surface between its nodes (round-off: 1e-15).
TEST(QuadraticQuad, ShapeFunctionsAreTheLagrangeBiquadratics)
{
  for (unsigned int i = 0; i < 9; ++i)
  {
    const auto values = QuadraticQuad::shape_values(support[i]);
    for (unsigned int j = 0; j < 9; ++j)
      EXPECT_NEAR(values[j], i == j ? 1. : 0., 1e-15) << "N_" << j << " at support point " << i;
  }
  double sum = 0.;
  for (const double value : QuadraticQuad::shape_values({0.21, 0.83}))
    sum += value;
  EXPECT_NEAR(sum, 1., 1e-15);
  EXPECT_LT(patch().point({0.3, 0.7}).distance(surface(0.3, 0.7)), 1e-15);
}

// A point 0.1 off the face along its unit normal at (0.3, 0.6) projects back onto (0.3, 0.6):
// Newton converges to round-off (1e-12 in the parameter, far above it, far below any mesh size);
// a point beyond the face's edge xi = 1 is clamped onto that edge.
TEST(QuadraticQuad, ClosestPointIsTheFootOfTheNormal)
{
  const QuadraticQuad face = patch();
  const double xi = 0.3, eta = 0.6;
  // x_xi = (1, 0, 2 xi + eta), x_eta = (0, 1, xi): normal x_xi x x_eta = (-(2 xi + eta), -xi, 1).
  Tensor<1, 3> normal({-(2. * xi + eta), -xi, 1.});
  normal /= normal.norm();
  const auto projection = face.closest_point(surface(xi, eta) + 0.1 * normal);
  EXPECT_NEAR(projection.xi[0], xi, 1e-12);
  EXPECT_NEAR(projection.xi[1], eta, 1e-12);
  EXPECT_NEAR(projection.distance, 0.1, 1e-12);
  const auto outside = face.closest_point(Point<3>(1.5, 0.5, 1.5));
  EXPECT_NEAR(outside.xi[0], 1., 1e-12);
}

// The ray from (0.3, 0.6, 5) along -z meets the face at (0.3, 0.6); one whose foot lies outside
// the face has no ray point.
TEST(QuadraticQuad, RayPointIsWhereTheRayMeetsTheFace)
{
  const QuadraticQuad face = patch();
  const std::array<Tensor<1, 3>, 9> no_normals{};
  const Tensor<1, 3> down({0., 0., -1.});
  const auto hit = face.ray_point(Point<3>(0.3, 0.6, 5.), down, no_normals, {0.5, 0.5});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR((*hit)[0], 0.3, 1e-12);
  EXPECT_NEAR((*hit)[1], 0.6, 1e-12);
  EXPECT_FALSE(face.ray_point(Point<3>(1.3, 0.6, 5.), down, no_normals, {0.5, 0.5}).has_value());
}

// The face's normal x_xi x x_eta at (0.3, 0.6) is (-(2 xi + eta), -xi, 1) = (-1.2, -0.3, 1)
// exactly: the patch is the biquadratic surface itself (1e-14: round-off of 9-term sums).
TEST(QuadraticQuad, NormalIsTheCrossProductOfTheTangents)
{
  const Tensor<1, 3> normal = patch().normal({0.3, 0.6});
  EXPECT_NEAR(normal[0], -1.2, 1e-14);
  EXPECT_NEAR(normal[1], -0.3, 1e-14);
  EXPECT_NEAR(normal[2], 1., 1e-14);
}
} // namespace dyncontact::testing
