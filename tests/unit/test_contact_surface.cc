// Unit test of ContactSurface's geometry from its nodes' positions alone, in 2D and 3D: every
// face of a distorted square (cube) under a homogeneous deformation x = F X + c against Nanson's
// formula, n da = det(F) F^-T N dA: the nodal normals n = F^-T N / |F^-T N| and the total of the
// surface mass matrix, which is the deformed face's area det(F) |F^-T N| A, for each of the faces
// of the reference cell (the outward sign of every face number).
#include <dyncontact/contact/contact_surface.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <gtest/gtest.h>

namespace dyncontact::testing
{
namespace
{
/** A deformation gradient with det F > 0 that shears, stretches and rotates every axis. */
template <int dim>
Tensor<2, dim> deformation_gradient()
{
  Tensor<2, dim> F;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      F[i][j] = (i == j ? 1.1 + 0.2 * i : 0.) + 0.15 * (i + 1.) * (j == (i + 1) % dim);
  return F;
}

/**
 * For each of the 2 dim faces of [0, 1]^dim (boundary id = face number, colorized), meshed with
 * 2^dim Q2 cells of unequal sizes: the surface's normals and mass total at x = F X + c against
 * Nanson's formula. Returns the largest normal error and the largest relative area error.
 */
template <int dim, typename KinematicsType>
std::pair<double, double> worst_nanson_errors()
{
  Triangulation<dim> triangulation;
  GridGenerator::hyper_cube(triangulation, 0., 1., /*colorize=*/true);
  triangulation.refine_global(1);
  // Cells of unequal sizes; each face of the cube stays a face, flat.
  GridTools::transform(
      [](const Point<dim>& X)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = std::pow(X[d], 1.5);
        return x;
      },
      triangulation);
  DoFHandler<dim> dof_handler(triangulation);
  dof_handler.distribute_dofs(FESystem<dim>(FE_Q<dim>(2), dim));
  const MappingQ<dim> mapping(1);
  const NodeIndex<dim> nodes(dof_handler, mapping);
  const KinematicsType kinematics;
  const Tensor<2, dim> F                = deformation_gradient<dim>();
  const Tensor<2, dim> F_inverse_transp = transpose(invert(F));
  Tensor<1, dim> shift;
  shift[0] = 0.3;

  double normal_error = 0., area_error = 0.;
  for (unsigned int face = 0; face < 2 * dim; ++face)
  {
    const ContactSurface<dim> surface(dof_handler, kinematics, nodes, face);
    std::vector<Point<dim>> positions;
    for (const Node<dim>& node : surface.nodes())
      positions.push_back(Point<dim>(F * node.position + shift));
    const Tensor<1, dim> N = GeometryInfo<dim>::unit_normal_vector[face];
    const Tensor<1, dim> n = F_inverse_transp * N;
    for (const Tensor<1, dim>& normal : surface.normals(positions))
      normal_error = std::max(normal_error, (normal - n / n.norm()).norm());
    const double area = determinant(F) * n.norm(); // the reference face has area 1
    area_error = std::max(area_error, std::abs(surface.mass_matrix(positions).sum() - area) / area);
  }
  return {normal_error, area_error};
}
} // namespace

// Bound 1e-13: the faces are straight (flat) after an affine map, so normals and areas are exact
// up to round-off of sums over a few nodes (measured below 1e-15); a normal with the wrong sign,
// or the tangents of another face number, is off by O(1).
TEST(ContactSurface, FacesOfAPlaneSquareFollowNanson)
{
  const auto [normal_error, area_error] = worst_nanson_errors<2, PlaneStrainKinematics>();
  EXPECT_LE(normal_error, 1e-13);
  EXPECT_LE(area_error, 1e-13);
}

TEST(ContactSurface, FacesOfACubeFollowNanson)
{
  const auto [normal_error, area_error] = worst_nanson_errors<3, SolidKinematics>();
  EXPECT_LE(normal_error, 1e-13);
  EXPECT_LE(area_error, 1e-13);
}
} // namespace dyncontact::testing
