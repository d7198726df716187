// Several bodies and contact pairs (Contact/Pair k): three spheres, the outer two striking the
// middle one from both sides at once (prm/three_spheres.prm, a mesh that is its own mirror image).
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>

#include "case_run.h"

namespace dyncontact::testing
{
TEST(ThreeBodies, SymmetricDoubleImpactKeepsTheMiddleSphereAtRestAndConservesMomentum)
{
  // The paper's scheme: its rate constraints, corrected jointly over both pairs, and the elastic
  // rebound of the energy-conserving trapezoidal rule are part of what is tested.
  const MeshRun run       = run_mesh_case("prm/three_spheres.prm",
                                    {"Contact/dynamics=taylor-papadopoulos",
                                           "Time integration/integrator=newmark",
                                           "Time integration/beta=0.25",
                                           "Time integration/gamma=0.5"});
  const History& history  = run.history();
  const double momentum_1 = history.value(0, "momentum_1");
  double total = 0., middle = 0., imbalance = 0., velocity_jump = 0., peak = 0.;
  for (unsigned int row = 0; row < history.n_rows(); ++row)
  {
    total         = std::max(total,
                     std::abs(history.value(row, "momentum_1") + history.value(row, "momentum_2") +
                              history.value(row, "momentum_3")));
    middle        = std::max(middle, std::abs(history.value(row, "momentum_2")));
    imbalance     = std::max(imbalance, std::abs(history.value(row, "force_imbalance")));
    velocity_jump = std::max(velocity_jump, history.value(row, "velocity_jump"));
    peak          = std::max(peak, history.value(row, "contact_force"));
  }
  const double rebound = history.value(history.n_rows() - 1, "momentum_1");
  std::cout << "  total momentum " << total / momentum_1 << ", middle sphere "
            << middle / momentum_1 << " of the striker's momentum, force imbalance "
            << imbalance / peak << " of the peak, velocity jump " << velocity_jump << ", rebound "
            << rebound / momentum_1 << "\n";
  // Both pairs are enforced in one saddle-point system and corrected jointly: total momentum is
  // conserved to round-off (measured 2.5e-13), forces balance (4e-13 of the peak) and the rate
  // constraints hold (8e-13, impact speed 1).
  EXPECT_LT(total, 1e-10 * momentum_1);
  EXPECT_LT(imbalance, 1e-10 * peak);
  EXPECT_LT(velocity_jump, 1e-10);
  // By symmetry the middle sphere stays at rest: what moves it is round-off amplified by Newton
  // (measured 1.8e-9 of the striker's momentum), far below the 1e-4 of an unbalanced pair.
  EXPECT_LT(middle, 1e-7 * momentum_1);
  // The strikers rebound: as off a rigid wall up to the energy left in vibration (measured
  // 0.99995 of the initial momentum, reversed).
  EXPECT_LT(rebound, -0.999 * momentum_1);
  EXPECT_EQ(history.value(history.n_rows() - 1, "active_constraints"), 0.);
}
} // namespace dyncontact::testing
