// Unit tests of the solver units on the smallest contact problem: two 1D bars of one linear element
// each, their outer ends fixed, the inner ends a (body 1, at X = 1) and b (body 2, at X = 1.5)
// facing each other over the gap g0 = 0.5, with one contact pair enforcing g = g0 + b - a >= 0.
//
// Data: E = 3, A = 1, L = 1, rho = 2, nu = 0, so each bar is the spring k = E A / L = 3 between its
// fixed end and its free end, and the lumped (HRZ = nodal) mass of every node is m = rho A L / 2
// = 1. Inertia factor c = 1, no external force, predictor u~_a = p, u~_b = -p (the bars
// approaching), last converged configuration u_n = 0. The step's equations (G^T lambda = -lambda on
// a, +lambda on b) are, with K' = c m + k = 4,
//   K' a - c m p + lambda = 0,   K' b + c m p - lambda = 0,
// and, if the pair is active, g0 + b - a = 0. By hand:
//   active:   a = g0/2 = 0.25, b = -0.25, lambda = c m p - K' g0/2 = p - 1 (active iff p > 1);
//   inactive: lambda = 0, a = c m p / K' = p/4, b = -p/4, open iff g0 - p/2 > 0 (p < 1).
// The problem is linear (linear elasticity in uniaxial strain is exactly linear), so one Newton
// update from any point with the right active set is the answer up to the round-off of one direct
// solve: the entries and answers are O(1) numbers and the 5 x 5 matrices have condition numbers
// near 10, so LU's forward error is below kappa n eps ~ 1e-14. The tolerance 1e-13 is ten times
// that, while every wrong term (a sign, a missing mass or spring, a wrong multiplier row) changes
// an answer by at least 0.05.
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/material/material.h>
#include <dyncontact/simulation/parameter_reader.h>
#include <dyncontact/solver/contact_newton_solver.h>
#include <dyncontact/solver/saddle_point_system.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace dyncontact::testing
{
namespace
{
constexpr double tolerance = 1e-13; // see the file comment
using Update               = SaddlePointSystem<1>::Update;
/** Every direct solver package, each test's systems solved by each. */
constexpr DirectSolverPackage all_packages[] = {
    DirectSolverPackage::klu, DirectSolverPackage::umfpack, DirectSolverPackage::mumps};
constexpr double gap0 = 0.5;

/** The variations of the problem of the file comment. */
struct Variant
{
  unsigned int max_iterations = 10;
  bool neo_hookean            = false; ///< else linear elastic (E = 3, nu = 0 for both)
  double gap                  = gap0;  ///< g0, the reference gap of the pair
};

/** Values at the two free ends a and b. */
struct AtEnds
{
  double a;
  double b;
};

/** The two bars, their DoFs, the contact pair and a Newton solver. */
struct TwoSprings
{
  explicit TwoSprings(const Variant& variant = Variant())
  {
    triangulation.create_triangulation(
        {Point<1>(0.), Point<1>(1.), Point<1>(1. + variant.gap), Point<1>(2. + variant.gap)},
        {cell(0, 1, 0), cell(2, 3, 1)},
        SubCellData());
    dof_handler.distribute_dofs(fe);
    const NodeIndex<1> nodes(dof_handler, mapping);
    const Node<1>& node_a = nodes.closest_node(0, Point<1>(1.));
    const Node<1>& node_b = nodes.closest_node(1, Point<1>(1. + variant.gap));
    a                     = node_a.dofs[0];
    b                     = node_b.dofs[0];
    fixed                 = {nodes.closest_node(0, Point<1>(0.)).dofs[0],
                             nodes.closest_node(1, Point<1>(2. + variant.gap)).dofs[0]};
    for (const auto dof : fixed)
      constraints.add_line(dof);
    constraints.close();
    const std::shared_ptr<const Material> spring =
        variant.neo_hookean ? std::shared_ptr<const Material>(
                                  std::make_shared<CompressibleNeoHookeanMaterial>(3., 0.))
                            : std::make_shared<LinearElasticMaterial>(3., 0.);
    bodies =
        std::make_unique<ElasticBodies<1>>(dof_handler,
                                           mapping,
                                           kinematics,
                                           std::vector<BodyMaterial>{{spring, 2.}, {spring, 2.}},
                                           &constraints);
    mass = bodies->lumped_mass();
    Tensor<1, 1> normal; // from A toward B
    normal[0] = 1.;
    contact   = std::make_unique<ContactConstraints<1>>(
        std::vector<ContactPair<1>>{{node_a, {{node_b, 1.}}, Point<1>(), normal, 1., {}}},
        ContactFormulation::lagrange_multiplier);
    solver = std::make_unique<ContactNewtonSolver<1>>(
        dof_handler,
        *bodies,
        *contact,
        mass,
        constraints,
        NewtonParameters{
            variant.max_iterations, 1e-12, DirectSolverPackage::klu, NewtonMethod::full},
        1.,
        timer);
  }

  static CellData<1> cell(const unsigned int v0, const unsigned int v1, const unsigned int body)
  {
    CellData<1> data;
    data.vertices    = {v0, v1};
    data.material_id = body;
    return data;
  }

  /** The nodal vector with `values` at a and b, zero at the fixed ends. */
  DistributedVector nodal(const AtEnds& values) const
  {
    DistributedVector vector(solver->dof_layout());
    vector[a] = values.a;
    vector[b] = values.b;
    return vector;
  }

  /**
   * Solves the step (c = 1) of `predictor` u~ with the external force `external` from the last
   * converged configuration `last` u_n, with the initial guess u = `guess` (the increment
   * guess - u~); returns u = u~ + increment and the number of linear solves in `linear_solves`.
   */
  Vector<double> solve_step(const AtEnds& predictor,
                            const AtEnds& last,
                            const AtEnds& external,
                            const AtEnds& guess,
                            unsigned int& linear_solves)
  {
    const DistributedVector u_tilde = nodal(predictor);
    DistributedVector increment     = nodal(guess);
    increment -= u_tilde;
    linear_solves = solver->solve(u_tilde, 1., nodal(external), nodal(last), nodal(last), increment)
                        .linear_solves;
    increment += u_tilde;
    return gather_whole(increment);
  }

  /** The same from the initial guess u~ (the increment zero, as a time step starts). */
  Vector<double> solve_step(const AtEnds& predictor,
                            const AtEnds& last,
                            const AtEnds& external,
                            unsigned int& linear_solves)
  {
    return solve_step(predictor, last, external, predictor, linear_solves);
  }

  /**
   * The step of the file comment: predictor (p, -p), no external force, u_n = 0, from the initial
   * guess `guess` (default: the predictor).
   */
  Vector<double> solve_step(const double p,
                            unsigned int& linear_solves,
                            const std::optional<AtEnds>& guess = std::nullopt)
  {
    return solve_step({p, -p}, {0., 0.}, {0., 0.}, guess.value_or(AtEnds{p, -p}), linear_solves);
  }

  Triangulation<1> triangulation;
  FESystem<1> fe{FE_Q<1>(1), 1};
  DoFHandler<1> dof_handler{triangulation};
  MappingQ<1> mapping{1};
  BarKinematics kinematics{{1., 1.}};
  types::global_dof_index a = 0, b = 0;
  std::vector<types::global_dof_index> fixed;
  AffineConstraints<double> constraints; ///< the fixed ends held at zero
  std::unique_ptr<ElasticBodies<1>> bodies;
  Vector<double> mass;
  std::unique_ptr<ContactConstraints<1>> contact;
  std::ostringstream timer_log;
  TimerOutput timer{timer_log, TimerOutput::never, TimerOutput::wall_times};
  std::unique_ptr<ContactNewtonSolver<1>> solver;
};

/** What a solved step must give: u at a and b, the number of linear solves, the pair's state. */
struct Expected
{
  AtEnds u;
  unsigned int linear_solves;
  bool active;
};

/** Checks the answer `u` of a step that took `linear_solves`; the fixed ends must stay at zero. */
void expect_answer(const TwoSprings& springs,
                   const Vector<double>& u,
                   const unsigned int linear_solves,
                   const Expected& expected)
{
  EXPECT_EQ(linear_solves, expected.linear_solves);
  EXPECT_NEAR(u[springs.a], expected.u.a, tolerance);
  EXPECT_NEAR(u[springs.b], expected.u.b, tolerance);
  for (const auto dof : springs.fixed)
    EXPECT_EQ(u[dof], 0.);
  EXPECT_EQ(springs.contact->is_active(0), expected.active);
}

/** The message of the SolverFailure `run` throws; "" (and a test failure) if it throws none. */
std::string solver_failure(const std::function<void()>& run)
{
  try
  {
    run();
  }
  catch (const SolverFailure& failure)
  {
    return failure.what();
  }
  ADD_FAILURE() << "no SolverFailure";
  return "";
}
/**
 * The saddle-point matrix of SystemSolvesAKnownSaddlePoint times `scale`, with
 * the constraint row and column (+1 at a, -1 at b) times `constraint_scale`, into `system`.
 */
void assemble_known_system(const TwoSprings& springs,
                           const double scale,
                           const double constraint_scale,
                           SaddlePointSystem<1>& system)
{
  const types::global_dof_index a = springs.a, b = springs.b;
  system.start_assembly();
  auto& matrix = system.matrix();
  for (const auto& [free, fixed] : {std::pair{a, springs.fixed[0]}, std::pair{b, springs.fixed[1]}})
  {
    matrix.add(free, free, 4. * scale);
    matrix.add(fixed, fixed, 2. * scale); // the diagonal of an eliminated (constrained) DoF
    // The coupling to the constrained DoF is dropped, as the contact layer's are.
    system.multiplier_rows()->add_coupling(0, fixed, 5.);
  }
  for (const auto& [dof, sign] : {std::pair{a, 1.}, std::pair{b, -1.}})
    system.multiplier_rows()->add_coupling(0, dof, sign * scale * constraint_scale);
  system.finish_assembly();
}

/**
 * `whole` (the displacement rows, then the one multiplier row of this file's systems) as
 * `system`'s distributed vector.
 */
template <int dim>
DistributedVector rows(const SaddlePointSystem<dim>& system, const Vector<double>& whole)
{
  const unsigned int n_multipliers = 1;
  DistributedVector displacement_rows(whole.size() - n_multipliers); // one rank: all owned
  Vector<double> multiplier_rows(n_multipliers);
  std::copy_n(whole.begin(), displacement_rows.size(), displacement_rows.begin());
  std::copy(whole.begin() + displacement_rows.size(), whole.end(), multiplier_rows.begin());
  return system.stack(displacement_rows, multiplier_rows);
}
} // namespace

TEST(SaddlePointNewton, LumpedMassIsTheHandValue)
{
  const TwoSprings springs;
  for (unsigned int i = 0; i < springs.mass.size(); ++i)
    EXPECT_NEAR(springs.mass[i], 1., tolerance) << "DoF " << i;
}

// The saddle-point system alone: [K' at a and b, constraint row (+1 at a, -1 at b)] with the fixed
// ends eliminated, their rows and columns empty but for the diagonal 2 (a coupling of the
// constraint row to them is dropped). Chosen answer a = 0.25, b = -0.25, lambda = 1, fixed ends
// 0.15 (right-hand side 0.3 over the diagonal 2); the right-hand side is the matrix times it, by
// hand: row a: 4 (0.25) + 1 = 2, row b: 4 (-0.25) - 1 = -2, constraint row: 0.25 + 0.25 = 0.5.
//
// Each direct solver package (KLU, UMFPACK, MUMPS) on the same system; the factorization is kept
// while the matrix stays the same: assembling the same entries again does not refactorize and
// solves the same, and the whole matrix assembled with twice its entries (fixed rows 4) is
// refactorized, giving half the solution (a stale factorization would give the old one).
TEST(SaddlePointNewton, SystemSolvesAKnownSaddlePoint)
{
  const TwoSprings springs;
  for (const auto package : all_packages)
  {
    SCOPED_TRACE(direct_solver_names().name(package));
    SaddlePointSystem<1> system(
        springs.dof_handler, *springs.contact, springs.constraints, package);
    ASSERT_NE(system.multiplier_rows(), nullptr);
    const types::global_dof_index a = springs.a, b = springs.b,
                                  lambda  = springs.dof_handler.n_dofs();
    const types::global_dof_index fixed_a = springs.fixed[0], fixed_b = springs.fixed[1];
    const auto assemble = [&](const double scale)
    { assemble_known_system(springs, scale, 1., system); };
    assemble(1.);
    // Rows a and b: 4 on the diagonal and the coupling 1 to the multiplier; the fixed rows: 2.
    EXPECT_EQ(system.displacement_scales().largest_diagonal, 4.);
    EXPECT_EQ(system.displacement_scales().largest_row_sum, 5.);

    Vector<double> right_hand_side(lambda + 1);
    right_hand_side[a]       = 2.;
    right_hand_side[b]       = -2.;
    right_hand_side[fixed_a] = 0.3;
    right_hand_side[fixed_b] = 0.3;
    right_hand_side[lambda]  = 0.5;
    EXPECT_EQ(system.update_factorization(true), Update::factorization);
    const DistributedVector solution = system.solve(rows(system, right_hand_side));
    EXPECT_NEAR(solution[a], 0.25, tolerance);
    EXPECT_NEAR(solution[b], -0.25, tolerance);
    EXPECT_NEAR(solution[lambda], 1., tolerance);
    EXPECT_NEAR(solution[fixed_a], 0.15, tolerance);
    EXPECT_NEAR(solution[fixed_b], 0.15, tolerance);
    DistributedVector displacement_part(lambda); // one rank: every DoF owned
    Vector<double> multiplier_part;
    system.split(solution, displacement_part, multiplier_part);
    ASSERT_EQ(multiplier_part.size(), 1u);
    EXPECT_EQ(multiplier_part[0], solution[lambda]);
    EXPECT_EQ(displacement_part[b], solution[b]);
    const DistributedVector stacked = system.stack(displacement_part, multiplier_part);
    for (unsigned int i = 0; i < solution.size(); ++i)
      EXPECT_EQ(stacked[i], solution[i]);

    assemble(1.);
    EXPECT_EQ(system.update_factorization(true), Update::none);
    const DistributedVector again = system.solve(rows(system, right_hand_side));
    for (unsigned int i = 0; i < solution.size(); ++i)
      EXPECT_EQ(again[i], solution[i]);
    EXPECT_EQ(system.n_factorizations(), 1u);

    assemble(2.);
    EXPECT_EQ(system.update_factorization(true), Update::factorization);
    const DistributedVector half = system.solve(rows(system, right_hand_side));
    for (unsigned int i = 0; i < solution.size(); ++i)
      EXPECT_NEAR(half[i], 0.5 * solution[i], tolerance);
    EXPECT_EQ(system.n_factorizations(), 2u);
  }
}

// The constant part and the diagonal: the known system's displacement block (4 at a and b, 2 at
// the fixed ends) kept as the constant part; each assembly then starts from it and adds c M on the
// diagonal (add_to_diagonal(); M = 1 at every DoF) and the constraint row. A second system gets
// the same entries one by one (matrix().add()), in the same order, so the two matrices, their
// scales and their solutions agree to the bit; the largest diagonal is 4 + c exactly. The second
// c shows that start_assembly() restores the constant part, not the last assembly.
TEST(SaddlePointNewton, ConstantPartAndDiagonalMatchAnEntryByEntryAssembly)
{
  const TwoSprings springs;
  const types::global_dof_index a = springs.a, b = springs.b;
  SaddlePointSystem<1> kept(
      springs.dof_handler, *springs.contact, springs.constraints, DirectSolverPackage::klu);
  SaddlePointSystem<1> plain(
      springs.dof_handler, *springs.contact, springs.constraints, DirectSolverPackage::klu);
  const auto add_stiffness = [&](SaddlePointSystem<1>& system)
  {
    for (const auto dof : {a, b})
      system.matrix().add(dof, dof, 4.);
    for (const auto dof : springs.fixed)
      system.matrix().add(dof, dof, 2.);
  };
  const auto add_constraint_row = [&](SaddlePointSystem<1>& system)
  {
    system.multiplier_rows()->add_coupling(0, a, 1.);
    system.multiplier_rows()->add_coupling(0, b, -1.);
    system.finish_assembly();
  };
  EXPECT_FALSE(kept.has_constant_part());
  kept.start_assembly();
  add_stiffness(kept);
  kept.finish_assembly();
  kept.keep_as_constant_part();
  EXPECT_TRUE(kept.has_constant_part());
  Vector<double> right_hand_side(springs.dof_handler.n_dofs() + 1);
  for (unsigned int i = 0; i < right_hand_side.size(); ++i)
    right_hand_side[i] = std::cos(1. + i);
  for (const double c : {0.5, 3.})
  {
    SCOPED_TRACE("c = " + std::to_string(c));
    kept.start_assembly();
    kept.add_to_diagonal(springs.mass, c);
    add_constraint_row(kept);
    plain.start_assembly();
    add_stiffness(plain);
    for (types::global_dof_index i = 0; i < springs.dof_handler.n_dofs(); ++i)
      plain.matrix().add(i, i, c * springs.mass[i]);
    add_constraint_row(plain);
    EXPECT_EQ(kept.displacement_scales().largest_diagonal, 4. + c);
    EXPECT_EQ(plain.displacement_scales().largest_diagonal, 4. + c);
    EXPECT_EQ(kept.displacement_scales().largest_row_sum,
              plain.displacement_scales().largest_row_sum);
    kept.update_factorization(false);
    plain.update_factorization(false);
    const DistributedVector from_kept  = kept.solve(rows(kept, right_hand_side));
    const DistributedVector from_plain = plain.solve(rows(plain, right_hand_side));
    for (unsigned int i = 0; i < right_hand_side.size(); ++i)
      EXPECT_EQ(from_kept[i], from_plain[i]) << "row " << i;
  }
}

// A change in the constraint row and column only (the multiplier's coefficients tripled, as when
// a pair's normal or active set changes) is served by a low-rank update of the factors, which
// solves the changed system as a fresh factorization does: to the LU round-off of the file
// comment (the Woodbury correction adds a 2 x 2 solve of O(1) numbers), while the stale factors
// would be off by more than 0.1 in a, b and lambda. Assembling the factorized matrix again returns
// to the factors as they are; a change of the leading block needs a factorization.
TEST(SaddlePointNewton, ConstraintRowChangeIsALowRankUpdateOfTheFactors)
{
  const TwoSprings springs;
  for (const auto package : all_packages)
  {
    SCOPED_TRACE(direct_solver_names().name(package));
    SaddlePointSystem<1> system(
        springs.dof_handler, *springs.contact, springs.constraints, package);
    SaddlePointSystem<1> fresh(springs.dof_handler, *springs.contact, springs.constraints, package);
    Vector<double> right_hand_side(springs.dof_handler.n_dofs() + 1);
    right_hand_side[springs.a]                    = 1.55;
    right_hand_side[springs.b]                    = -2.45;
    right_hand_side[springs.fixed[0]]             = 0.3;
    right_hand_side[springs.fixed[1]]             = 0.3;
    right_hand_side[springs.dof_handler.n_dofs()] = 0.5;

    assemble_known_system(springs, 1., 1., system);
    EXPECT_EQ(system.update_factorization(true), Update::factorization);
    const DistributedVector stale = system.solve(rows(system, right_hand_side));

    assemble_known_system(springs, 1., 3., system);
    EXPECT_EQ(system.update_factorization(true), Update::low_rank);
    assemble_known_system(springs, 1., 3., fresh);
    EXPECT_EQ(fresh.update_factorization(true), Update::factorization);
    const DistributedVector updated  = system.solve(rows(system, right_hand_side));
    const DistributedVector expected = fresh.solve(rows(fresh, right_hand_side));
    for (unsigned int i = 0; i < expected.size(); ++i)
      EXPECT_NEAR(updated[i], expected[i], tolerance) << "unknown " << i;
    for (const auto i : {springs.a, springs.b, springs.dof_handler.n_dofs()})
      EXPECT_GT(std::abs(stale[i] - expected[i]), 0.1) << "unknown " << i;
    EXPECT_EQ(system.n_factorizations(), 1u);
    EXPECT_EQ(system.n_low_rank_updates(), 1u);

    assemble_known_system(springs, 1., 1., system);
    EXPECT_EQ(system.update_factorization(true), Update::none);
    const DistributedVector back = system.solve(rows(system, right_hand_side));
    for (unsigned int i = 0; i < back.size(); ++i)
      EXPECT_EQ(back[i], stale[i]);

    assemble_known_system(springs, 2., 1., system);
    EXPECT_EQ(system.update_factorization(true), Update::factorization);
    EXPECT_EQ(system.n_factorizations(), 2u);
  }
}

TEST(SaddlePointNewton, SingularSystemIsASolverFailure)
{
  const TwoSprings springs;
  for (const auto package : all_packages)
  {
    SaddlePointSystem<1> system(
        springs.dof_handler, *springs.contact, springs.constraints, package);
    system.start_assembly();
    system.finish_assembly(); // all zero
    const std::string message = solver_failure([&] { system.update_factorization(true); });
    EXPECT_EQ(message.rfind("the direct solver (", 0), 0u) << message;
  }
}

// p = 2: the predictor penetrates (g = 0.5 - 4), the pair enters, Newton restarts from u_n = 0
// and one update of the linear problem is the answer. Converged Q(u), strain energy and tangent
// scale: Q_a = k a, Q_b = k b, k a^2 / 2 + k b^2 / 2, max diag(K_eff) = K' = 4.
TEST(SaddlePointNewton, ActiveConstraintInOneLinearSolve)
{
  TwoSprings springs;
  unsigned int linear_solves = 0;
  const Vector<double> u     = springs.solve_step(2., linear_solves);
  expect_answer(springs, u, linear_solves, {{0.25, -0.25}, 1, true});
  EXPECT_NEAR(springs.contact->pair_force(0), 2. - 1., tolerance);
  EXPECT_NEAR(springs.solver->internal_force()[springs.a], 3. * 0.25, tolerance);
  EXPECT_NEAR(springs.solver->internal_force()[springs.b], 3. * -0.25, tolerance);
  EXPECT_NEAR(springs.solver->strain_energy(), 3. * 0.0625, tolerance);
  // K_eff at a and b: stiffness 3 plus c m = 1 on the diagonal, and the pair's coupling 1.
  EXPECT_NEAR(springs.solver->tangent_scales().largest_diagonal, 4., tolerance);
  EXPECT_NEAR(springs.solver->tangent_scales().largest_row_sum, 5., tolerance);

  // From its own answer the step still makes one linear solve: an active pair's residual can look
  // converged only because the multiplier of the last solve still balances it.
  const Vector<double> again =
      springs.solve_step(2., linear_solves, AtEnds{u[springs.a], u[springs.b]});
  expect_answer(springs, again, linear_solves, {{0.25, -0.25}, 1, true});
}

// p = 0.1: the predicted gap 0.5 - 0.2 stays open; one solve from u_n = 0. Solving the same step
// again from its answer costs no linear solve (the free-flight case: the initial guess is
// evaluated without a tangent and accepted).
TEST(SaddlePointNewton, InactiveConstraintInOneLinearSolveThenNone)
{
  TwoSprings springs;
  unsigned int linear_solves = 0;
  const Vector<double> u     = springs.solve_step(0.1, linear_solves);
  expect_answer(springs, u, linear_solves, {{0.025, -0.025}, 1, false});
  EXPECT_EQ(springs.contact->pair_force(0), 0.);

  const Vector<double> again =
      springs.solve_step(0.1, linear_solves, AtEnds{u[springs.a], u[springs.b]});
  expect_answer(springs, again, linear_solves, {{0.025, -0.025}, 0, false});
  for (unsigned int i = 0; i < u.size(); ++i)
    EXPECT_EQ(again[i], u[i]) << "DoF " << i;
}

// p = 0.4: the predictor penetrates (g = 0.5 - 0.8), so the pair enters; the constrained answer
// has the tensile multiplier p - 1 = -0.6, the pair leaves, and a second solve gives the open
// answer a = 0.1 (gap 0.3): the semi-smooth Newton's active-set update.
TEST(SaddlePointNewton, TensileMultiplierReleasesThePairInTwoLinearSolves)
{
  TwoSprings springs;
  unsigned int linear_solves = 0;
  const Vector<double> u     = springs.solve_step(0.4, linear_solves);
  expect_answer(springs, u, linear_solves, {{0.1, -0.1}, 2, false});
}

// The same step with one linear solve allowed: the active set is still changing when the limit
// is reached, and the message says so in the documented words.
TEST(SaddlePointNewton, IterationLimitIsASolverFailureWithItsMessage)
{
  TwoSprings springs(Variant{1});
  unsigned int linear_solves = 0;
  const std::string message  = solver_failure([&] { springs.solve_step(0.4, linear_solves); });
  EXPECT_EQ(message.rfind("Newton did not converge in 1 linear solves (Newton/maximum "
                          "iterations): residual ",
                          0),
            0u)
      << message;
  EXPECT_NE(message.find(", active pairs 0, active set still changing."), std::string::npos)
      << message;
}

// Newton starts from u_n, not from the predictor. p = 0.1 (the predicted gap 0.3 is open and the
// inactive answer a = 0.025 of the file comment), but u_n = (0.5, -0.5) penetrates (g = -0.5):
// from u_n the pair enters, the constrained update gives the tensile multiplier
// c m p - K' g0/2 = 0.1 - 1 = -0.9, the pair leaves and a second solve gives the answer. From the
// predictor the active set would have been right at once: one solve.
TEST(SaddlePointNewton, NewtonRestartsFromTheLastConvergedConfiguration)
{
  TwoSprings springs;
  unsigned int linear_solves = 0;
  const Vector<double> u = springs.solve_step({0.1, -0.1}, {0.5, -0.5}, {0., 0.}, linear_solves);
  expect_answer(springs, u, linear_solves, {{0.025, -0.025}, 2, false});
}

// An inverted element at u_n (neo-Hookean, a_n = -1.5: F = 1 + a_n = -0.5) surfaces as the
// material's SolverFailure with the solver's note where it happened.
TEST(SaddlePointNewton, InvertedElementAtTheLastConfigurationIsASolverFailure)
{
  Variant variant;
  variant.neo_hookean = true;
  TwoSprings springs(variant);
  unsigned int linear_solves = 0;
  EXPECT_EQ(solver_failure(
                [&] {
                  springs.solve_step({0.1, -0.1}, {-1.5, 0.}, {0., 0.}, linear_solves);
                }),
            "Neo-Hookean material: inverted element (J = -0.5). (at the last converged "
            "configuration)");
}

// The line search. Neo-Hookean bars with nu = 0 in uniaxial strain: P = mu (F - 1/F), mu = E/2 =
// 1.5, tangent mu (1 + 1/F^2); F = 1 + a in bar 1 and 1 - b in bar 2. Gap g0 = 5, so the pair
// never enters (the largest closure below is 4). The answer is chosen, a = -0.5 and b = 0.5
// (both bars at F = 0.5, P = -2.25), and the external force made to balance it with the
// predictor 0: W_a = c m (a - 0) + P = -0.5 - 2.25 = -2.75, W_b = +2.75. From u_n = (2, -2)
// (F = 3) the full Newton update is -r/K with r = c m (2 - 0) + mu (3 - 1/3) + 2.75 = 8.75 and
// K = c m + mu (1 + 1/9) = 8/3: a = 2 - 3.28 = -1.28, F = -0.28, an inverted element. Only the
// halving of that update lets Newton reach the answer. The convergence test leaves a residual of at
// most 1e-12 (|Q| + |W|) = 1e-12 (4.5 + 3.9), over the tangent c m + mu (1 + 1/0.25) = 8.5 at the
// answer an error below 1e-12: the tolerance 1e-11 covers it, and a missed answer is off by far
// more.
TEST(SaddlePointNewton, LineSearchHalvesAnUpdateThatInvertsAnElement)
{
  Variant variant;
  variant.neo_hookean = true;
  variant.gap         = 5.;
  TwoSprings springs(variant);
  unsigned int linear_solves = 0;
  const Vector<double> u = springs.solve_step({0., 0.}, {2., -2.}, {-2.75, 2.75}, linear_solves);
  EXPECT_GT(linear_solves, 1u);
  EXPECT_NEAR(u[springs.a], -0.5, 1e-11);
  EXPECT_NEAR(u[springs.b], 0.5, 1e-11);
  EXPECT_FALSE(springs.contact->is_active(0));
}
} // namespace dyncontact::testing
