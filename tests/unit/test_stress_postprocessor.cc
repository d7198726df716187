// StressPostprocessor (the VTU's stress and strain fields) against closed forms: a homogeneous
// axisymmetric deformation u = (a r, b z) has F = diag(1 + a, 1 + b, 1 + a) everywhere, including
// on the axis r = 0 where the hoop stretch is the limit 1 + du_r/dr. Its Cauchy stress follows from
// each law in closed form; two cells carry two bodies of different laws, so the cell-to-body lookup
// is checked too. The values go through DataOut as a run writes them, at the 9 points of each Q2
// cell (the axis included).
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/material/material.h>
#include <dyncontact/postprocess/stress_postprocessor.h>

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
constexpr double a = 0.02, b = -0.05; // u_r = a r, u_z = b z
constexpr double youngs_modulus = 200., poissons_ratio = 0.3;

class HomogeneousDisplacement : public Function<2>
{
public:
  HomogeneousDisplacement() : Function<2>(2) {}
  double value(const Point<2>& X, const unsigned int component) const override
  {
    return component == 0 ? a * X[0] : b * X[1];
  }
};

struct Expected
{
  double sigma_rr, sigma_zz, sigma_hoop;
};

/// The Cauchy stress of F = diag(1 + a, 1 + b, 1 + a) for St. Venant-Kirchhoff (body 0) and the
/// compressible neo-Hookean law (body 1), from their definitions in material.h.
Expected expected_stress(const unsigned int body)
{
  const double lambda =
      youngs_modulus * poissons_ratio / ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
  const double mu = youngs_modulus / (2. * (1. + poissons_ratio));
  const double fr = 1. + a, fz = 1. + b, J = fr * fr * fz;
  if (body == 0)
  {
    // S = lambda tr(E) I + 2 mu E, sigma = F S F^T / J.
    const double Er = 0.5 * (fr * fr - 1.), Ez = 0.5 * (fz * fz - 1.);
    const double trace = 2. * Er + Ez;
    const double Sr = lambda * trace + 2. * mu * Er, Sz = lambda * trace + 2. * mu * Ez;
    return {fr * fr * Sr / J, fz * fz * Sz / J, fr * fr * Sr / J};
  }
  // sigma = (mu (F F^T - I) + lambda ln J I) / J.
  const double sr = (mu * (fr * fr - 1.) + lambda * std::log(J)) / J;
  const double sz = (mu * (fz * fz - 1.) + lambda * std::log(J)) / J;
  return {sr, sz, sr};
}
} // namespace

TEST(StressPostprocessor, HomogeneousAxisymmetricDeformationGivesTheClosedFormStresses)
{
  Triangulation<2> triangulation;
  GridGenerator::subdivided_hyper_rectangle(
      triangulation, {2, 1}, Point<2>(0., 1.), Point<2>(2., 2.));
  for (const auto& cell : triangulation.active_cell_iterators())
    cell->set_material_id(cell->center()[0] < 1. ? 0 : 1);
  const FESystem<2> fe(FE_Q<2>(2), 2);
  DoFHandler<2> dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  const MappingQ<2> mapping(2);
  Vector<double> displacement(dof_handler.n_dofs());
  VectorTools::interpolate(mapping, dof_handler, HomogeneousDisplacement(), displacement);

  const dyncontact::AxisymmetricKinematics kinematics;
  const dyncontact::StressPostprocessor<2> stresses(
      kinematics,
      {dyncontact::create_material("st venant-kirchhoff", youngs_modulus, poissons_ratio),
       dyncontact::create_material("neo-hookean", youngs_modulus, poissons_ratio)});
  DataOut<2> data_out;
  data_out.attach_dof_handler(dof_handler);
  data_out.add_data_vector(displacement, stresses);
  data_out.build_patches(mapping, 2, DataOut<2>::curved_inner_cells);

  const std::vector<std::string> names = stresses.get_names();
  const auto row                       = [&](const std::string& name) {
    return static_cast<unsigned int>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  ASSERT_EQ(names.size(), 9u);
  // The patches store float values: 1e-6 of the stress scale (|sigma| ~ 10 here) is their
  // round-off with a margin of 10.
  const double tolerance     = 1e-5;
  unsigned int n_axis_points = 0;
  for (const auto& patch : data_out.get_patches())
  {
    const unsigned int body =
        patch.vertices[0][0] < 0.5 ? 0 : 1; // the cells span r in [0, 1], [1, 2]
    const Expected expected = expected_stress(body);
    for (unsigned int q = 0; q < patch.data.n_cols(); ++q)
    {
      const double r = patch.data(names.size(), q); // the points follow the data sets
      n_axis_points += r == 0. ? 1 : 0;
      EXPECT_NEAR(patch.data(row("cauchy_stress_rr"), q), expected.sigma_rr, tolerance) << r;
      EXPECT_NEAR(patch.data(row("cauchy_stress_zz"), q), expected.sigma_zz, tolerance) << r;
      EXPECT_NEAR(patch.data(row("cauchy_stress_thetatheta"), q), expected.sigma_hoop, tolerance)
          << r;
      EXPECT_NEAR(patch.data(row("cauchy_stress_rz"), q), 0., tolerance);
      EXPECT_NEAR(patch.data(row("green_lagrange_strain_rr"), q), a + 0.5 * a * a, 1e-7);
      EXPECT_NEAR(patch.data(row("green_lagrange_strain_zz"), q), b + 0.5 * b * b, 1e-7);
      EXPECT_NEAR(patch.data(row("green_lagrange_strain_thetatheta"), q), a + 0.5 * a * a, 1e-7);
      // von Mises of diag(s1, s2, s1) is |s1 - s2|.
      EXPECT_NEAR(patch.data(row("von_mises_stress"), q),
                  std::abs(expected.sigma_rr - expected.sigma_zz),
                  tolerance);
    }
  }
  EXPECT_EQ(n_axis_points, 3u); // the left cell's 3 points on r = 0
}
