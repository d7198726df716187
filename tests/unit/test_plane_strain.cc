// Plane strain meshes (Problem/geometry = plane strain mesh) and body forces (Bodies/Body b/Body
// force), on GetFEM's dynamic-contact demo (prm/disc_gravity_plane_strain.prm: a disc of radius 20,
// E = 50, nu = 0.25, rho = 1, 5 above a rigid plane, gravity 0.1, Newmark beta = 1/4):
//  - read_gmsh_mesh() in plane strain: a circle of any centre is fitted as one, the same disc is
//    refused as an axisymmetric mesh (a vertex at r < 0);
//  - free fall before the first touch at t = sqrt(2 * 5 / 0.1) = 10 is exact: a uniform body force
//    on a free body gives every node the same acceleration (the load is lumped as the mass is),
//    Newmark integrates a constant acceleration exactly, and the body falls rigidly;
//  - the bounce, on the default treatment and the paper's: momentum = impulse, the energy
//    guard's balance E - E_0 - W_ext, one contact episode starting right after t = 10;
//  - Boundary/Symmetry k and Boundary/Support k on meshes/block.geo: the half block on its
//    symmetry plane x = 0 reproduces the whole block's impact on the rigid plane; a roller support
//    lets the block slide rigidly along it, a clamp does not; bad boundaries are one-line errors.
#include <dyncontact/models/gmsh_mesh.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <string>
#include <vector>

#include "case_run.h"
#include "mesh_checks.h"

namespace dyncontact::testing
{
namespace
{
const std::string disc_case = "prm/disc_gravity_plane_strain.prm";
constexpr double gravity = 0.1, drop = 5., radius = 20., density = 1.;
} // namespace

TEST(PlaneStrain, CirclesOfAnyCentreAreFitted)
{
  Triangulation<2> triangulation;
  const MeshGeometry geometry = read_gmsh_mesh(mesh_path("disc.geo"),
                                               {{"R", 5.}, {"CentreX", 3.}, {"CentreY", -7.}},
                                               triangulation,
                                               MeshSection::plane_strain);
  EXPECT_EQ(geometry.n_bodies, 1u);
  ASSERT_EQ(geometry.curves.size(), 1u);
  ASSERT_TRUE(geometry.curves[0].circle.has_value());
  EXPECT_EQ(geometry.curves[0].id, 2u);
  // gmsh places the circle's vertices to round-off (16 digits), and the fit is exact for points
  // on a circle.
  const SphereGeometry& circle = *geometry.curves[0].circle;
  EXPECT_NEAR(circle.centre[0], 3., 1e-12 * 5.);
  EXPECT_NEAR(circle.centre[1], -7., 1e-12 * 5.);
  EXPECT_NEAR(circle.radius, 5., 1e-12 * 5.);
  EXPECT_TRUE(geometry.sphere(0).has_value());

  Triangulation<2> axisymmetric;
  EXPECT_THROW(read_gmsh_mesh(mesh_path("disc.geo"), {{"R", 5.}, {"CentreX", 3.}}, axisymmetric),
               InputError);
}

TEST(PlaneStrain, FreeFallUnderGravityIsRigidAndExact)
{
  const MeshRun run      = run_mesh_case(disc_case, {"Time integration/end time=9.9"});
  const History& history = run.history();
  const auto time = history.column("time"), u = history.column("u_tip_1"),
             v = history.column("v_tip_1"), a = history.column("a_tip_1"),
             momentum = history.column("momentum_1"), impulse = history.column("impulse_1"),
             kinetic = history.column("kinetic_energy"), strain = history.column("strain_energy"),
             work = history.column("external_work"), force = history.column("contact_force");
  ASSERT_EQ(time.size(), 991u);
  // The Q2 mapping of the circle (24 arcs of 15 degrees) gives the disc's area, and so its mass,
  // to about 1e-5 of pi R^2 (measured 9.8e-6 below).
  const double mass = momentum.back() / (-gravity * time.back());
  EXPECT_NEAR(mass, density * M_PI * radius * radius, 2e-5 * mass);
  for (unsigned int row = 0; row < time.size(); ++row)
  {
    const double t = time[row];
    // Constant acceleration: Newmark's update is exact, so every node (the monitor at the centre
    // too) follows u = -g t^2 / 2 to round-off of the steps' sums (1e-12 of the drop).
    EXPECT_NEAR(u[row], -0.5 * gravity * t * t, 1e-12 * drop) << "t = " << t;
    EXPECT_NEAR(v[row], -gravity * t, 1e-12 * gravity * 10.) << "t = " << t;
    // a = (u - predictor) / (beta dt^2): the round-off of u (1e-16 of 5) divided by
    // beta dt^2 = 2.5e-5 is 2e-11 (measured up to 4.6e-12 absolute, 4.6e-11 of g).
    EXPECT_NEAR(a[row], -gravity, 2e-10 * gravity) << "t = " << t;
    EXPECT_NEAR(momentum[row], -mass * gravity * t, 1e-12 * mass) << "t = " << t;
    EXPECT_NEAR(momentum[row], impulse[row], 1e-12 * mass) << "t = " << t;
    // Rigid motion: no strain beyond round-off of a displacement of order 5, and all the work of
    // gravity is kinetic energy.
    EXPECT_LT(strain[row], 1e-20 * mass) << "t = " << t;
    EXPECT_NEAR(kinetic[row], work[row], 1e-12 * mass * drop * gravity) << "t = " << t;
    EXPECT_EQ(force[row], 0.) << "t = " << t;
  }
}

TEST(PlaneStrain, DiscBouncesWithMomentumAndEnergyBalanced)
{
  for (const std::string dynamics : {"mass-redistribution", "taylor-papadopoulos"})
  {
    const MeshRun run =
        run_mesh_case(disc_case, {"Time integration/end time=30", "Contact/dynamics=" + dynamics});
    const History& history = run.history();
    const auto time = history.column("time"), force = history.column("contact_force"),
               momentum = history.column("momentum_1"), impulse = history.column("impulse_1"),
               energy = history.column("algorithmic_energy"),
               work   = history.column("external_work");
    ASSERT_DOUBLE_EQ(time.back(), 30.) << dynamics;
    // The touch: the lowest node reaches the plane at t = 10 exactly; the first force comes with
    // the step that ends after it (the pair closes as the gap reaches zero at 10).
    for (unsigned int row = 0; row < time.size() && time[row] < 10. - 1e-9; ++row)
      EXPECT_EQ(force[row], 0.) << dynamics << ", t = " << time[row];
    EXPECT_EQ(contact_episodes(history), 1u) << dynamics;
    const double mass = density * M_PI * radius * radius, peak_momentum = mass * gravity * 10.;
    double largest_imbalance = 0., largest_gain = 0., final_change = 0.;
    for (unsigned int row = 0; row < time.size(); ++row)
    {
      largest_imbalance = std::max(largest_imbalance, std::abs(momentum[row] - impulse[row]));
      largest_gain      = std::max(largest_gain, energy[row] - energy[0] - work[row]);
      final_change      = energy[row] - energy[0] - work[row];
      EXPECT_GE(force[row], 0.) << dynamics << ", t = " << time[row];
    }
    std::cout << dynamics << ": momentum - impulse " << largest_imbalance / peak_momentum
              << " of m g t_touch, largest energy gain " << largest_gain / (mass * gravity * drop)
              << ", energy change at t = 30 " << final_change / (mass * gravity * drop)
              << " of m g h\n";
    // The momentum guard's tolerance (1e-6 of the momentum scale) bounds the imbalance; measured
    // far below it: the contact impulse is accounted for exactly.
    EXPECT_LT(largest_imbalance, 1e-9 * peak_momentum) << dynamics;
    // Neither treatment creates energy beyond the guard's tolerance (1e-6 of the energy scale).
    EXPECT_LT(largest_gain, 1e-6 * mass * gravity * drop) << dynamics;
    // The disc has left the plane by t = 30 and flies up under gravity.
    EXPECT_EQ(force.back(), 0.) << dynamics;
    EXPECT_GT(momentum.back(), 0.) << dynamics;
  }
}

namespace
{
/**
 * The disc case turned into a block of meshes/block.geo (`geo` its parameters) with the given
 * initial velocity, no body force, the block's bottom (curve 2) 0.5 above the rigid plane y = 0,
 * monitored at `monitor`, dt = 0.01 to t = 1; then `more`.
 */
std::vector<std::string> block_case(const std::string& geo,
                                    const std::string& velocity,
                                    const std::string& monitor,
                                    const std::vector<std::string>& more = {})
{
  std::vector<std::string> overrides = {"Mesh/file=" + source_path("meshes/block.geo"),
                                        "Mesh/geo parameters=Y0: 0.5, Height: 1, NY: 4, " + geo,
                                        "Bodies/Body 1/Body force/Function expression=0; 0",
                                        "Bodies/Body 1/Initial velocity/Function expression=" +
                                            velocity,
                                        "Bodies/Body 1/monitor point=" + monitor,
                                        "Time integration/end time=1"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return overrides;
}
} // namespace

TEST(PlaneStrain, TractionOnTheContactSurfaceFromTheStartKeepsMomentumEqualToImpulse)
{
  // A dead traction (0, -0.05) on the disc's whole surface, from t = 0, on every treatment: with
  // mass redistribution (the default) the surface nodes are massless and start out of balance
  // with Q(u_0) = 0; that imbalance must count in the impulse, or the momentum guard stops the
  // first step. The total force is T times the perimeter 2 pi R (the Q2 circle's to about 1e-5,
  // as the area in FreeFallUnderGravityIsRigidAndExact), so the momentum is -0.05 * 2 pi R t;
  // with massless surface nodes the load reaches the body only as they move, so the momentum
  // lags by a constant part of one step's impulse F dt (measured F dt / 4, 0.0157): an O(dt)
  // start-up error, bounded here by F dt / 2.
  for (const std::string dynamics : {"mass-redistribution", "taylor-papadopoulos", "none"})
  {
    const MeshRun run =
        run_mesh_case(disc_case,
                      {"Time integration/end time=2",
                       "Contact/dynamics=" + dynamics,
                       "Bodies/Body 1/Body force/Function expression=0; 0",
                       "Bodies/Body 1/Surface traction/Function expression=0; -0.05"});
    const auto time = run.history().column("time"), momentum = run.history().column("momentum_1"),
               impulse = run.history().column("impulse_1");
    const double force = -0.05 * 2. * M_PI * radius;
    for (unsigned int row = 0; row < time.size(); ++row)
    {
      const double lag = dynamics == "mass-redistribution" ? 0.5 * std::abs(force) * 0.01 : 0.;
      EXPECT_NEAR(momentum[row], force * time[row], lag + 2e-5 * std::abs(force * 2.))
          << dynamics << ", t = " << time[row];
      EXPECT_NEAR(momentum[row], impulse[row], 1e-12 * std::abs(force * 2.))
          << dynamics << ", t = " << time[row];
    }
  }
}

TEST(PlaneStrain, HalfBlockOnItsSymmetryPlaneEqualsTheWholeBlock)
{
  // The block 4 x 1 at speed 1 onto the plane (touch at t = 0.5, a bounce of about 2 H / c_p =
  // 0.26), whole on 16 x 4 cells, and its right half on 8 x 4 cells with the same nodes.
  const MeshRun whole =
      run_mesh_case(disc_case, block_case("X0: -2, Width: 4, NX: 16", "0; -1", "0, 1"));
  const std::vector<std::string> half_block = block_case("X0: 0, Width: 2, NX: 8", "0; -1", "0, 1");
  std::vector<std::string> symmetric        = half_block;
  symmetric.insert(symmetric.end(),
                   {"Boundary/number of symmetry planes=1", "Boundary/Symmetry 1/boundary=1"});
  const MeshRun half = run_mesh_case(disc_case, symmetric);
  ASSERT_EQ(half.history().n_rows(), whole.history().n_rows());
  EXPECT_GT(max_force_deviation(whole.history(), 0., 0.5, 1.), 1.) << "the block never struck";
  // The same equations on the same nodes, halved: forces and momenta half the whole block's, the
  // motion of the node on x = 0 the same; round-off amplified by Newton (measured below).
  const auto compare = [&](const MeshRun& run, const std::string& column, const double factor)
  {
    const auto expected = whole.history().column(column);
    const auto actual   = run.history().column(column);
    double scale = 0., difference = 0.;
    for (unsigned int row = 0; row < expected.size(); ++row)
    {
      scale      = std::max(scale, std::abs(factor * expected[row]));
      difference = std::max(difference, std::abs(actual[row] - factor * expected[row]));
    }
    return difference / scale;
  };
  for (const auto& [column, factor] : std::vector<std::pair<std::string, double>>{
           {"contact_force", 0.5}, {"momentum_1", 0.5}, {"u_tip_1", 1.}, {"a_tip_1", 1.}})
  {
    const double difference = compare(half, column, factor);
    std::cout << column << ": half against whole " << difference << " of its range\n";
    EXPECT_LT(difference, 1e-9) << column;
  }
  // Without the symmetry plane the half block is a free block of its own: it spreads about its
  // own centre, and its impact differs (so the comparison above can fail).
  const MeshRun free_half   = run_mesh_case(disc_case, half_block);
  const double free_differs = compare(free_half, "a_tip_1", 1.);
  std::cout << "a_tip_1: free half block against whole " << free_differs << " of its range\n";
  EXPECT_GT(free_differs, 1e-3);
}

TEST(PlaneStrain, CurveOneIsAContactSurfaceLikeAnyOther)
{
  // In plane strain there is no axis: the block's left side (curve 1, x = 0.5) strikes the plane
  // x = 0 at speed 1 (touch at t = 0.5), as its bottom strikes y = 0 in the test above.
  const MeshRun run = run_mesh_case(
      disc_case,
      block_case("X0: 0.5, Width: 2, NX: 8",
                 "-1; 0",
                 "1.5, 1",
                 {"Contact/Pair 1/slave boundary=1", "Contact/Pair 1/rigid plane=0, 0; 1, 0"}));
  EXPECT_GT(max_force_deviation(run.history(), 0., 0.5, 1.), 1.) << "the block never struck";
  EXPECT_EQ(max_force_deviation(run.history(), 0., 0., 0.5 - 1e-9), 0.) << "a force before 0.5";
}

TEST(PlaneStrain, RollerSupportLetsTheBlockSlideAndAClampHoldsIt)
{
  // No contact: the block 2 x 1 far above the plane, at speed 1 along x.
  const auto run = [](const std::string& components)
  {
    return run_mesh_case(disc_case,
                         block_case("X0: 0, Width: 2, NX: 8",
                                    "1; 0",
                                    "1, 10.5",
                                    {"Mesh/geo parameters=Y0: 10, Height: 1, NY: 4, Width: 2",
                                     "Boundary/number of supports=1",
                                     "Boundary/Support 1/boundary=2",
                                     "Boundary/Support 1/components=" + components}));
  };
  // A roller (u_y = 0 on the bottom) leaves the rigid sliding along x free: no strain, and the
  // kinetic energy stays m v^2 / 2 = 1 (area 2, rho 1) to round-off.
  const MeshRun roller = run("y");
  for (const double strain : roller.history().column("strain_energy"))
    EXPECT_LT(strain, 1e-20);
  for (const double kinetic : roller.history().column("kinetic_energy"))
    EXPECT_NEAR(kinetic, 1., 1e-12);
  // A clamp (u_x = u_y = 0) stops the bottom at once: the block vibrates, exchanging kinetic and
  // strain energy; the support's reaction is an impulse, so the momentum guard still holds.
  const MeshRun clamp = run("x, y");
  const auto strain   = clamp.history().column("strain_energy");
  EXPECT_GT(*std::max_element(strain.begin(), strain.end()), 0.01);
}

TEST(PlaneStrain, BadSymmetryPlanesAndSupportsAreInputErrors)
{
  const auto message_of = [](const std::vector<std::string>& overrides)
  {
    try
    {
      run_mesh_case(disc_case, overrides);
    }
    catch (const InputError& error)
    {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  const std::string circle = message_of({"Time integration/end time=0.01",
                                         "Boundary/number of symmetry planes=1",
                                         "Boundary/Symmetry 1/boundary=2"});
  EXPECT_NE(circle.find("Boundary/Symmetry 1/boundary = 2 is not a straight line"),
            std::string::npos)
      << circle;
  const std::string unknown = message_of({"Time integration/end time=0.01",
                                          "Boundary/number of supports=1",
                                          "Boundary/Support 1/boundary=7"});
  EXPECT_NE(unknown.find("Boundary/Support 1/boundary = 7: Mesh/file"), std::string::npos)
      << unknown;
  const std::string unset = message_of({"Boundary/number of supports=1"});
  EXPECT_NE(unset.find("Boundary/Support 1/boundary = 0 is not set"), std::string::npos) << unset;
  for (const std::string& message : {circle, unknown, unset})
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}
} // namespace dyncontact::testing
