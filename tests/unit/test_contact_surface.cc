// Unit test of ContactSurface's geometry from its nodes' positions alone, in 1D, 2D and 3D: the
// boundary of a box meshed with Q2 cells of unequal sizes, under a homogeneous deformation
// x = F X + c, against Nanson's formula n da = det(F) F^-T N dA: the nodal normal of every node
// inside one face of the box is n = F^-T N / |F^-T N|, and the surface mass matrices sum to the
// deformed box's surface area, the sum of det(F) |F^-T N| A over its faces. Every face number of
// the reference cell occurs (the outward sign of each), and in 3D also faces that a cell sees in
// non-standard orientation.
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
#include <set>
#include <string>

namespace dyncontact::testing
{
namespace
{
/** A deformation gradient with det F > 0 that stretches and shears every axis. */
template <int dim>
Tensor<2, dim> deformation_gradient()
{
  Tensor<2, dim> F;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      F[i][j] =
          (i == j ? 1.1 + 0.2 * i : 0.) + (j == (i + 1) % dim && dim > 1 ? 0.15 * (i + 1) : 0.);
  return F;
}

/** The largest normal error and relative area error; see the file's comment. */
struct NansonErrors
{
  double normal = 0.;
  double area   = 0.;
  /** The nodes whose normal was checked (those inside one face of the box). */
  unsigned int checked_nodes = 0;
};

/**
 * The errors on the box `triangulation` (any boundary ids: each id is one surface), with its
 * cells made unequal by a monotone map of every coordinate that keeps each box face a face.
 */
template <int dim>
NansonErrors nanson_errors(Triangulation<dim>& triangulation, const Kinematics<dim>& kinematics)
{
  const BoundingBox<dim> reference_box = GridTools::compute_bounding_box(triangulation);
  const Point<dim> low                 = reference_box.get_boundary_points().first,
                   high                = reference_box.get_boundary_points().second;
  GridTools::transform(
      [&](const Point<dim>& X)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = low[d] + (high[d] - low[d]) * std::pow((X[d] - low[d]) / (high[d] - low[d]), 1.5);
        return x;
      },
      triangulation);
  DoFHandler<dim> dof_handler(triangulation);
  dof_handler.distribute_dofs(FESystem<dim>(FE_Q<dim>(2), dim));
  const MappingQ<dim> mapping(1);
  const NodeIndex<dim> nodes(dof_handler, mapping);
  const Tensor<2, dim> F                = deformation_gradient<dim>();
  const Tensor<2, dim> F_inverse_transp = transpose(invert(F));
  const auto deformed_normal            = [&](const unsigned int d, const double sign)
  { return F_inverse_transp * (sign * Point<dim>::unit_vector(d)); };

  std::set<types::boundary_id> ids;
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        ids.insert(cell->face(f)->boundary_id());
  NansonErrors errors;
  double area = 0., deformed_area = 0.;
  for (const types::boundary_id id : ids)
  {
    const ContactSurface<dim> surface(dof_handler, kinematics, nodes, id);
    std::vector<Point<dim>> positions;
    for (const Node<dim>& node : surface.nodes())
      positions.push_back(Point<dim>(F * node.position) + 0.3 * Point<dim>::unit_vector(0));
    const std::vector<Tensor<1, dim>> normals = surface.normals(positions);
    for (unsigned int i = 0; i < normals.size(); ++i)
    {
      const Point<dim>& X = surface.nodes()[i].position;
      std::vector<Tensor<1, dim>> box_faces; // the deformed normals of the box faces X lies on
      for (unsigned int d = 0; d < dim; ++d)
        for (const double sign : {-1., 1.})
          if (std::abs(X[d] - (sign < 0. ? low[d] : high[d])) < 1e-12)
            box_faces.push_back(deformed_normal(d, sign));
      if (box_faces.size() == 1)
      {
        errors.normal =
            std::max(errors.normal, (normals[i] - box_faces[0] / box_faces[0].norm()).norm());
        ++errors.checked_nodes;
      }
    }
    area += surface.mass_matrix(positions).sum();
  }
  for (unsigned int d = 0; d < dim; ++d)
  {
    double face_area = 1.; // of the reference box faces normal to axis d
    for (unsigned int e = 0; e < dim; ++e)
      face_area *= e == d ? 1. : high[e] - low[e];
    deformed_area += 2. * determinant(F) * deformed_normal(d, 1.).norm() * face_area;
  }
  errors.area = std::abs(area - deformed_area) / deformed_area;
  return errors;
}

/** The errors on [0, 1]^dim, colorized (a surface per face), refined `refinements` times. */
template <int dim>
NansonErrors errors_on_unit_cube(const unsigned int refinements, const Kinematics<dim>& kinematics)
{
  Triangulation<dim> triangulation;
  GridGenerator::hyper_cube(triangulation, 0., 1., /*colorize=*/true);
  triangulation.refine_global(refinements);
  return nanson_errors(triangulation, kinematics);
}

/**
 * Bound 1e-13: the faces are flat after an affine map, so normals and areas are exact up to the
 * round-off of sums over a few nodes (measured below 1e-15); a normal with the wrong sign, or the
 * tangents of another face number, is off by O(1), a wrong weight or measure by O(0.1).
 */
void expect_exact(const NansonErrors& errors, const std::string& mesh)
{
  EXPECT_LE(errors.normal, 1e-13) << mesh;
  EXPECT_LE(errors.area, 1e-13) << mesh;
  EXPECT_GT(errors.checked_nodes, 0u) << mesh;
}
} // namespace

TEST(ContactSurface, EndsOfABarFollowNanson)
{
  expect_exact(errors_on_unit_cube(2, BarKinematics({1.})), "bar");
}

TEST(ContactSurface, FacesOfASquareFollowNanson)
{
  expect_exact(errors_on_unit_cube(1, PlaneStrainKinematics()), "square");
}

TEST(ContactSurface, FacesOfACubeFollowNanson)
{
  expect_exact(errors_on_unit_cube(1, SolidKinematics()), "cube");
}

// Two cubes side by side whose common face one of them sees flipped and rotated: the cells'
// other faces then lie in the box's faces in orientations other than the hyper_cube's.
TEST(ContactSurface, FacesOfCubesInNonStandardOrientationFollowNanson)
{
  for (const bool manipulate_left_cube : {false, true})
  {
    Triangulation<3> triangulation;
    GridGenerator::non_standard_orientation_mesh(
        triangulation, false, true, true, manipulate_left_cube);
    triangulation.refine_global(1);
    expect_exact(nanson_errors(triangulation, SolidKinematics()),
                 manipulate_left_cube ? "left cube turned" : "right cube turned");
  }
}
} // namespace dyncontact::testing
