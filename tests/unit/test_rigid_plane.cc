// Contact with a rigid plane (Contact/Pair k/rigid plane, RigidPlaneContact): a sphere striking
// the plane is the lower half of two identical spheres striking each other, whose symmetry plane
// is rigid and frictionless; the two runs must agree to round-off.
#include <dyncontact/base/global.h>
#include <dyncontact/models/mesh_model.h>
#include <dyncontact/simulation/parameter_reader.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "case_run.h"

namespace dyncontact::testing
{
TEST(RigidPlane, SphereOnPlaneEqualsItsMirroredPair)
{
  // The coarse member of the graded family, body 1 of two_spheres.geo and sphere.geo alike.
  const std::string coarse = "Refinement: 0, PoleGrading: 10, CoreOffset: 0.3";
  const MeshRun pair       = run_mesh_case("prm/spheres_rho0.001.prm", paper_coarse_spheres());
  const MeshRun plane      = run_mesh_case("prm/sphere_on_rigid_plane.prm",
                                      {"Mesh/geo parameters=CentreZ: -10, " + coarse});
  ASSERT_EQ(plane.history().n_rows(), pair.history().n_rows());
  // The same equations on the same nodes: the pair's node-to-node constraint n . (u_B - u_A) with
  // u_B the mirror image of u_A is the plane's constraint with twice the gap, and the joint rate
  // correction moves both nodes by the same amount, the plane's moves the sphere's node alone.
  // What differs is round-off, amplified by Newton's iterations (measured: contact force 1.9e-13
  // of its peak, pole velocity 1e-11 of its range, accelerations 3e-11).
  for (const std::string column :
       {"contact_force", "u_tip_1", "v_tip_1", "a_tip_1", "momentum_1", "centre_pressure"})
  {
    const auto expected = pair.history().column(column);
    const auto actual   = plane.history().column(column);
    double scale = 0., difference = 0.;
    for (unsigned int row = 0; row < expected.size(); ++row)
    {
      scale      = std::max(scale, std::abs(expected[row]));
      difference = std::max(difference, std::abs(actual[row] - expected[row]));
    }
    std::cout << column << ": largest difference " << difference / scale << " of its range\n";
    EXPECT_LT(difference, 1e-9 * scale) << column;
  }
  EXPECT_EQ(plane.history().column("active_constraints"),
            pair.history().column("active_constraints"));
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
// Bad rigid planes: one line naming Contact/Pair 1 and what is wrong, as an InputError (exit 2).
TEST(RigidPlane, MisplacedPlanesAreInputErrors)
{
  const auto message_of = [](const std::string& plane)
  {
    try
    {
      run_mesh_case("prm/sphere_on_rigid_plane.prm", {"Contact/Pair 1/rigid plane=" + plane});
    }
    catch (const InputError& error)
    {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  const std::string zero_normal = message_of("0, 0; 0, 0");
  EXPECT_NE(zero_normal.find("Contact/Pair 1/rigid plane = '0, 0; 0, 0' is not allowed: it must "
                             "be 'r, z; n_r, n_z', a point and a nonzero normal"),
            std::string::npos)
      << zero_normal;
  // The contact pole is at z = -2: a plane at z = -2.5 cuts 0.5 into the sphere.
  const std::string overlap = message_of("0, -2.5; 0, -1");
  EXPECT_NE(overlap.find("Contact/Pair 1"), std::string::npos) << overlap;
  EXPECT_NE(overlap.find("body 1 and the rigid plane overlap at t = 0: the node 0 -2 of body 1 "
                         "lies 0.5 behind the rigid plane"),
            std::string::npos)
      << overlap;
  // A normal pointing away from the body puts the whole sphere behind the plane.
  const std::string away = message_of("0, 0; 0, 1");
  EXPECT_NE(away.find("lies 18 behind the rigid plane"), std::string::npos) << away;
  EXPECT_NE(away.find("which must point toward the body"), std::string::npos) << away;
}
} // namespace dyncontact::testing

namespace dyncontact::testing
{
// The references of the sphere on the rigid plane are those of its mirrored pair: Hertz's sphere
// on a rigid flat (E and mass infinite: R* = R, E* = E / (1 - nu^2), m* = m) has the two spheres'
// force history (R* = R / 2, E* = E / (2 (1 - nu^2)), m* = m / 2 at twice the speed), and so has
// the finite-sphere law, whose approach is the pair's halved.
TEST(RigidPlane, ReferencesAreThoseOfTheMirroredPair)
{
  const std::string coarse  = "Refinement: 0, PoleGrading: 10, CoreOffset: 0.3";
  const RunParameters plane = ParameterReader(source_path("prm/sphere_on_rigid_plane.prm"),
                                              {"Mesh/geo parameters=CentreZ: -10, " + coarse})
                                  .parameters();
  const RunParameters pair =
      ParameterReader(source_path("prm/spheres_rho0.001.prm"), paper_coarse_spheres()).parameters();
  MeshModel plane_model(plane.mesh, plane.bodies, plane.contact.pairs);
  MeshModel pair_model(pair.mesh, pair.bodies, pair.contact.pairs);
  Triangulation<2> plane_mesh, pair_mesh;
  plane_model.create_triangulation(plane_mesh);
  pair_model.create_triangulation(pair_mesh);
  const auto plane_hertz = plane_model.hertz_reference(), pair_hertz = pair_model.hertz_reference();
  const auto plane_law = plane_model.finite_sphere_reference();
  const auto pair_law  = pair_model.finite_sphere_reference();
  ASSERT_TRUE(plane_hertz && pair_hertz && plane_law && pair_law);
  std::cout << "  Hertz peak " << plane_hertz->maximum_force() << " vs "
            << pair_hertz->maximum_force() << ", law peak " << plane_law->maximum_force() << " vs "
            << pair_law->maximum_force() << std::endl;
  // Round-off of the different effective quantities: 1e-12.
  EXPECT_NEAR(plane_hertz->maximum_force(),
              pair_hertz->maximum_force(),
              1e-12 * pair_hertz->maximum_force());
  EXPECT_NEAR(plane_hertz->contact_duration(),
              pair_hertz->contact_duration(),
              1e-12 * pair_hertz->contact_duration());
  EXPECT_NEAR(plane_hertz->first_touch_time(), 2., 1e-12);
  EXPECT_NEAR(
      plane_law->maximum_force(), pair_law->maximum_force(), 1e-12 * pair_law->maximum_force());
  EXPECT_NEAR(plane_law->contact_duration(),
              pair_law->contact_duration(),
              1e-12 * pair_law->contact_duration());
}
} // namespace dyncontact::testing
