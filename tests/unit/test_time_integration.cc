// Unit tests of the generalized-alpha family (GeneralizedAlpha: Newmark, HHT-alpha, WBZ-alpha,
// Chung & Hulbert's generalized-alpha) on the one-DOF linear oscillator m = 1, k = omega^2
// (Q(u) = k u, W = 0). Every step goes through the class: predictor, mass factor c, effective
// force and rate update; only the step equation c (u - u~) + k u = W_eff is solved here, in closed
// form. The references are independent of the update formulas: the exact period 2 pi / omega, the
// requested spectral radius at infinite frequency, the stability limit of Newmark (Hughes, The
// Finite Element Method, 2000, sec. 9.1) and the energy balance of the algorithmic energy. The
// amplification matrix is built from one step of the class applied to unit initial states and
// its eigenvalues come from LAPACK.
#include <dyncontact/time_integration/generalized_alpha.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "case_run.h"

namespace dyncontact::testing
{
namespace
{
using Family = GeneralizedAlpha::Family;

/** Displacement [length], velocity [length/time] and acceleration [length/time^2] of the DOF. */
struct OscillatorState
{
  double u;
  double v;
  double a;
};

/** Newmark (beta, gamma) with step dt, built as the run builds it: from the parameters. */
GeneralizedAlpha newmark(const double beta, const double gamma, const double dt)
{
  TimeIntegrationParameters parameters{};
  parameters.beta      = beta;
  parameters.gamma     = gamma;
  parameters.time_step = dt;
  return GeneralizedAlpha(parameters);
}

/**
 * One step of `integrator` on m = 1, Q(u) = k u, W = 0 from `old`. The step equation
 * c (u_{n+1} - u~) + k u_{n+1} = W_eff, with W_eff from the class (M a_n = a_n, Q(u_n) = k u_n),
 * is linear: the increment d = u_{n+1} - u~ is (W_eff - k u~) / (c + k). The old acceleration is
 * taken as given, so any (u, v, a) is a valid start (no consistency with the equation of motion
 * is needed: the formulation carries a_n through W_eff and the predictor).
 */
OscillatorState step(const GeneralizedAlpha& integrator, const double k, const OscillatorState& old)
{
  DistributedVector u(1), v(1), a(1), predictor, zero(1), inertia(1), internal(1), effective;
  u[0]        = old.u;
  v[0]        = old.v;
  a[0]        = old.a;
  inertia[0]  = old.a;
  internal[0] = k * old.u;
  integrator.predict(u, v, a, predictor);
  integrator.effective_force(zero, inertia, internal, effective);
  DistributedVector increment(1), v_new, a_new;
  increment[0] = (effective[0] - k * predictor[0]) / (integrator.inertia_factor() + k);
  integrator.update_rates(increment, v, a, v_new, a_new);
  return {predictor[0] + increment[0], v_new[0], a_new[0]};
}

/**
 * Eigenvalues of the one-step amplification matrix of `integrator` (its own dt) at omega = 1, in
 * the dimensionless state z = (omega u, v, dt a) so that the matrix is well scaled at any
 * omega dt: column j is the step from z = e_j. 3 values, unordered;
 * NaN, and a test failure, when that step is not finite.
 */
std::vector<std::complex<double>> amplification_eigenvalues(const GeneralizedAlpha& integrator)
{
  const double omega = 1., dt = integrator.time_step();
  LAPACKFullMatrix<double> amplification(3, 3);
  for (unsigned int j = 0; j < 3; ++j)
  {
    const OscillatorState unit{j == 0 ? 1. / omega : 0., j == 1 ? 1. : 0., j == 2 ? 1. / dt : 0.};
    const OscillatorState next = step(integrator, omega * omega, unit);
    amplification(0, j)        = omega * next.u;
    amplification(1, j)        = next.v;
    amplification(2, j)        = dt * next.a;
  }
  std::vector<std::complex<double>> eigenvalues;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      if (!std::isfinite(amplification(i, j)))
      {
        ADD_FAILURE() << "the step from a unit state is not finite";
        return std::vector<std::complex<double>>(3, std::numeric_limits<double>::quiet_NaN());
      }
  amplification.compute_eigenvalues();
  for (unsigned int i = 0; i < 3; ++i)
    eigenvalues.push_back(amplification.eigenvalue(i));
  return eigenvalues;
}

double spectral_radius(const GeneralizedAlpha& integrator)
{
  double radius = 0.;
  for (const auto& lambda : amplification_eigenvalues(integrator))
    radius = std::isnan(std::abs(lambda)) ? std::abs(lambda) : std::max(radius, std::abs(lambda));
  return radius;
}

/**
 * Numerical period over the exact one, minus 1, at omega = 1: the principal roots are the
 * complex pair exp(+-i omega~ dt) (times a decay), so the numerical period is 2 pi / omega~.
 */
double relative_period_error(const GeneralizedAlpha& integrator)
{
  const auto eigenvalues = amplification_eigenvalues(integrator);
  const auto principal   = *std::max_element(eigenvalues.begin(),
                                           eigenvalues.end(),
                                           [](const auto& x, const auto& y)
                                           { return std::abs(x.imag()) < std::abs(y.imag()); });
  EXPECT_GT(std::abs(principal.imag()), 0.) << "no oscillating root";
  const double numerical_omega = std::abs(std::arg(principal)) / integrator.time_step();
  return 1. / numerical_omega - 1.;
}

/** The members of the tests with a name for the messages. */
struct Member
{
  std::string name;
  GeneralizedAlpha integrator;
};

Member dissipative(const Family family, const double rho)
{
  const std::string name = family == Family::hht      ? "HHT"
                           : family == Family::bossak ? "Bossak"
                                                      : "generalized-alpha";
  return {name + " rho_inf = " + format_number(rho), GeneralizedAlpha(family, rho, 1.)};
}

/**
 * Algorithmic energy of `state` of the oscillator (m = 1, k): 1/2 v^2, 1/2 k u^2, 1/2 a^2 and
 * the residual r = a + k u (W = 0) in 1/2 r^2 / k.
 */
double energy(const GeneralizedAlpha& integrator, const double k, const OscillatorState& state)
{
  const double residual = state.a + k * state.u;
  return integrator.algorithmic_energy(0.5 * state.v * state.v,
                                       0.5 * k * state.u * state.u,
                                       0.5 * state.a * state.a,
                                       0.5 * residual * residual / k);
}

/** Energies of `n_steps` steps from u = 1, v = 0 and the acceleration of the equation of motion. */
std::vector<double> energy_history(const GeneralizedAlpha& integrator,
                                   const double omega_dt,
                                   const unsigned int n_steps)
{
  const double k = std::pow(omega_dt / integrator.time_step(), 2);
  OscillatorState state{1., 0., -k};
  std::vector<double> energies{energy(integrator, k, state)};
  for (unsigned int n = 0; n < n_steps; ++n)
  {
    state = step(integrator, k, state);
    energies.push_back(energy(integrator, k, state));
  }
  return energies;
}
} // namespace

// The period error of a second-order member falls by 4 per halving of dt (Hughes 2000, sec. 9.3:
// period elongation of order (omega dt)^2); 4 +- 20 % at omega dt = 0.2, 0.1, 0.05.
TEST(TimeIntegration, PeriodErrorIsSecondOrder)
{
  std::vector<Member> members{{"Newmark (1/4, 1/2)", newmark(0.25, 0.5, 1.)},
                              dissipative(Family::hht, 0.8),
                              dissipative(Family::generalized_alpha, 0.5),
                              dissipative(Family::generalized_alpha, 0.8),
                              dissipative(Family::bossak, 0.5)};
  for (auto& [name, integrator] : members)
  {
    std::vector<double> errors;
    for (const double omega_dt : {0.2, 0.1, 0.05})
    {
      integrator.set_time_step(omega_dt);
      errors.push_back(relative_period_error(integrator));
    }
    std::cout << "  " << name << ": period error " << errors[0] << ", " << errors[1] << ", "
              << errors[2] << "; ratios " << errors[0] / errors[1] << ", " << errors[1] / errors[2]
              << "\n";
    for (unsigned int i = 0; i + 1 < errors.size(); ++i)
      EXPECT_NEAR(errors[i] / errors[i + 1], 4., 0.8) << name;
  }
}

// Chung & Hulbert's rho_inf is the spectral radius in the limit omega dt -> infinity. It is
// approached only as (omega dt)^(-2/3) where the three roots meet at -rho_inf (generalized-alpha,
// and rho_inf = 0): at omega dt = 1e6 generalized-alpha rho_inf = 0 has 1.00007e-4. Hence 1e7,
// where every member is within 2.2e-5.
TEST(TimeIntegration, SpectralRadiusAtInfiniteFrequency)
{
  std::vector<std::pair<Family, double>> members;
  for (const double rho : {0., 0.5, 0.8, 1.})
    members.emplace_back(Family::generalized_alpha, rho);
  for (const double rho : {0.5, 0.8, 1.})
    members.emplace_back(Family::hht, rho);
  for (const double rho : {0., 0.5, 1.})
    members.emplace_back(Family::bossak, rho);
  for (const auto& [family, rho] : members)
  {
    auto [name, integrator] = dissipative(family, rho);
    integrator.set_time_step(1e6);
    const double at_1e6 = spectral_radius(integrator);
    integrator.set_time_step(1e7);
    const double at_1e7 = spectral_radius(integrator);
    std::cout << "  " << name << ": spectral radius at omega dt = 1e6 " << at_1e6 << ", at 1e7 "
              << at_1e7 << "\n";
    EXPECT_NEAR(at_1e7, rho, 1e-4) << name;
    EXPECT_EQ(integrator.stability_limit(), std::numeric_limits<double>::infinity()) << name;
    for (const double omega_dt : {1e-2, 0.1, 1., 2., 10., 100.})
    {
      integrator.set_time_step(omega_dt);
      EXPECT_LE(spectral_radius(integrator), 1. + 1e-12) << name << ", omega dt = " << omega_dt;
    }
  }
  GeneralizedAlpha trapezoidal = newmark(0.25, 0.5, 1.);
  for (const double omega_dt : {1e-3, 1e-2, 0.1, 1., 2., 10., 100., 1e3, 1e6})
  {
    trapezoidal.set_time_step(omega_dt);
    EXPECT_NEAR(spectral_radius(trapezoidal), 1., 1e-12) << "omega dt = " << omega_dt;
  }
}

// The paper's Newmark (0.001, 1/2) is stable only up to omega dt = 1 / sqrt(gamma/2 - beta).
TEST(TimeIntegration, NewmarkStabilityLimit)
{
  GeneralizedAlpha paper = newmark(0.001, 0.5, 1.);
  const double limit     = 1. / std::sqrt(0.25 - 0.001);
  EXPECT_DOUBLE_EQ(paper.stability_limit(), limit);
  paper.set_time_step(1.001 * limit);
  const double above = spectral_radius(paper);
  paper.set_time_step(0.999 * limit);
  const double below = spectral_radius(paper);
  std::cout << "  Newmark (0.001, 1/2): spectral radius at 1.001 x limit " << above
            << ", at 0.999 x limit " << below << "\n";
  EXPECT_GT(above, 1. + 1e-3);
  EXPECT_LE(below, 1. + 1e-12);
}

// Hughes' energy method: the algorithmic energy of gamma = 1/2 Newmark is conserved for a linear
// free system (beta = 1/4, and the paper's 0.001 below its limit); that of generalized-alpha
// rho_inf = 0.5 never grows (see GeneralizedAlpha::algorithmic_energy()) and does decay.
TEST(TimeIntegration, AlgorithmicEnergy)
{
  const std::vector<std::pair<Member, double>> conserving{
      {{"Newmark (1/4, 1/2)", newmark(0.25, 0.5, 1.)}, 0.5},
      {{"Newmark (0.001, 1/2)", newmark(0.001, 0.5, 1.)}, 1.}};
  for (const auto& [member, omega_dt] : conserving)
  {
    const std::vector<double> energies = energy_history(member.integrator, omega_dt, 1000);
    double drift                       = 0.;
    for (const double energy : energies)
      drift = std::max(drift, std::abs(energy / energies[0] - 1.));
    std::cout << "  " << member.name << ": largest energy drift over 1000 steps " << drift << "\n";
    EXPECT_LE(drift, 1e-12) << member.name;
  }
  const Member dissipating = dissipative(Family::generalized_alpha, 0.5);
  for (const double omega_dt : {0.1, 1., 10.})
  {
    const std::vector<double> energies = energy_history(dissipating.integrator, omega_dt, 1000);
    double largest_growth              = -std::numeric_limits<double>::infinity();
    for (unsigned int n = 0; n + 1 < energies.size(); ++n)
      largest_growth = std::max(largest_growth, (energies[n + 1] - energies[n]) / energies[0]);
    std::cout << "  " << dissipating.name << ", omega dt = " << omega_dt << ": largest step growth "
              << largest_growth << ", E_1000 / E_0 " << energies.back() / energies[0] << "\n";
    EXPECT_LE(largest_growth, 1e-14) << "omega dt = " << omega_dt;
    EXPECT_LT(energies.back(), energies[0]) << "omega dt = " << omega_dt;
  }
}

// The run's Newmark is today's arithmetic: c = 1/(beta dt^2) and W_eff = W bit for bit; the
// dissipative members refuse a spectral radius outside their range.
TEST(TimeIntegration, NewmarkMemberAndRanges)
{
  const GeneralizedAlpha paper = newmark(0.001, 0.5, 0.0125);
  EXPECT_EQ(paper.inertia_factor(), 1. / (0.001 * 0.0125 * 0.0125));
  EXPECT_EQ(paper.load_time(2.), 2.);
  DistributedVector external(2), inertia(2), internal(2), effective;
  external[0] = 0.1;
  external[1] = -3.7;
  inertia[0]  = 5.;
  internal[1] = 7.;
  paper.effective_force(external, inertia, internal, effective);
  EXPECT_EQ(effective[0], 0.1);
  EXPECT_EQ(effective[1], -3.7);
  EXPECT_ANY_THROW(GeneralizedAlpha(Family::hht, 0.49, 1.));
  EXPECT_ANY_THROW(GeneralizedAlpha(Family::generalized_alpha, 1.01, 1.));
  EXPECT_ANY_THROW(GeneralizedAlpha(Family::bossak, -0.01, 1.));
  EXPECT_ANY_THROW(GeneralizedAlpha(Family::newmark, 0.5, 1.));
}

// The dissipative members in a finite-element run (Time integration/integrator): the breathing mode
// of the free sphere (prm/sphere_free_vibration.prm, analytic period 0.229452, the mode its initial
// velocity excites) at omega dt = 1 must decay per step by the modulus of the principal root of the
// member's own amplification matrix at that omega dt, computed above on the one-DOF oscillator.
// The rate is the least-squares slope of log E over steps 20 to 140 (about 19 periods; by step 20
// the faster-decaying higher modes and the spurious root are gone, and the fit averages the
// energy's oscillation within a period). A member whose balance point (alpha_m, alpha_f) or
// effective force were wired wrong into the finite-element step would decay at another rate; the
// trapezoidal rule is the control (no decay). Measured agreement 6e-6 (hht), 1.2e-5 (bossak),
// 5e-6 (generalized-alpha) on rates of 0.97-0.99 per step; bound 5e-5, which the mesh's period
// error (0.12 %, moving |lambda| by less than 1e-5) leaves room for.
TEST(TimeIntegration, DissipativeMembersDampTheSphereBreathingModeAsTheirAmplificationPredicts)
{
  const double omega = 2. * M_PI / 0.229452, dt = 1. / omega;
  const std::vector<std::pair<std::string, double>> members{
      {"newmark", 1.}, {"hht", 0.6}, {"bossak", 0.5}, {"generalized-alpha", 0.5}};
  for (const auto& [name, rho] : members)
  {
    const MeshRun run = run_mesh_case("prm/sphere_free_vibration.prm",
                                      {"Time integration/integrator=" + name,
                                       "Time integration/spectral radius=" + std::to_string(rho),
                                       "Time integration/time step=" + std::to_string(dt),
                                       "Time integration/end time=" + std::to_string(140.5 * dt),
                                       "Output/vtu interval=0"});
    const auto energy = run.history().column("total_energy");
    ASSERT_GE(energy.size(), 141u);
    // Least-squares slope of log E over steps 20..140: log |lambda| = slope / 2.
    double sum_n = 0., sum_e = 0., sum_nn = 0., sum_ne = 0.;
    for (unsigned int n = 20; n <= 140; ++n)
    {
      const double log_e = std::log(energy[n]);
      sum_n += n;
      sum_e += log_e;
      sum_nn += double(n) * n;
      sum_ne += n * log_e;
    }
    const double count    = 121.;
    const double slope    = (count * sum_ne - sum_n * sum_e) / (count * sum_nn - sum_n * sum_n);
    const double measured = std::exp(slope / 2.);
    double expected       = 1.;
    if (name != "newmark")
    {
      const Family family = integrator_family_names().parse(name, "test");
      // The principal root at omega dt = 1: the member at dt = 1 on the oscillator omega = 1.
      const auto eigenvalues = amplification_eigenvalues(GeneralizedAlpha(family, rho, 1.));
      expected               = 0.;
      for (const auto& lambda : eigenvalues)
        if (std::abs(lambda.imag()) > 0.)
          expected = std::max(expected, std::abs(lambda));
    }
    std::cout << "  " << name << " rho_inf " << rho << ": breathing-mode decay per step "
              << measured << ", amplification matrix " << expected << "\n";
    EXPECT_NEAR(measured, expected, 5e-5) << name;
  }
}
} // namespace dyncontact::testing
