#pragma once

#include <vector>

namespace dyncontact
{
/**
 * Data of a homogeneous, isotropic, linearly elastic solid sphere, as input to the analytic
 * references SphereBreathingModes, HertzImpact and FiniteSphereImpact. It is plain data: nothing is
 * checked here (the classes that take it check what they need), and it says nothing about the
 * sphere's position or motion.
 */
struct ElasticSphere
{
  /// Radius R (> 0).
  double radius;
  /// Young's modulus E (> 0).
  double youngs_modulus;
  /// Poisson's ratio nu (-1 < nu < 0.5 for the breathing modes, -1 < nu <= 0.5 for Hertz).
  double poissons_ratio;
  /// Mass density rho (> 0).
  double density;
};

/**
 * The left-hand side of the frequency equation of the breathing modes of a free elastic sphere,
 * in dimensionless form:
 *
 *   f(xi) = a j0(xi) - 4 j1(xi) / xi,   a = (lambda + 2 mu) / mu = 2 (1 - nu) / (1 - 2 nu),
 *
 * with xi = k R, j0 and j1 the spherical Bessel functions of the first kind and nu =
 * @p poissons_ratio. f(xi) is the radial stress sigma_rr(R) of the mode u_r = A j1(k r), divided by
 * A k mu (see SphereBreathingModes for the derivation), so the breathing modes are exactly its
 * positive roots. It is evaluated without cancellation also for small xi (f(0) = a - 4/3).
 *
 * This is what it is NOT: not normalized to make round-off comparable across xi (its terms are of
 * size a |j0| + 4 |j1 / xi|, a bound on its round-off is a small multiple of that times machine
 * epsilon), and not checked: nu is expected in (-1, 0.5) and xi >= 0.
 */
double breathing_mode_frequency_function(double xi, double poissons_ratio);

/**
 * The first @p n_roots positive roots xi_1 < xi_2 < ... of the breathing-mode frequency equation
 * f(xi) = 0 (see breathing_mode_frequency_function()) for Poisson's ratio @p poissons_ratio, to
 * full double precision: the m-th root is the only root in ((m - 1) pi, m pi), and it is found by
 * bisection on that interval until its two ends are adjacent doubles.
 *
 * Why there is exactly one root per interval: f(xi) = (sin(xi) / xi) (a - 4 G(xi)) with
 * G(xi) = (1 - xi cot(xi)) / xi^2 = 2 sum_{n >= 1} 1 / (n^2 pi^2 - xi^2) (Mittag-Leffler expansion
 * of the cotangent), which increases strictly between its poles at n pi, from 1/3 at xi = 0 (a >
 * 4/3 for every nu > -1) and from -infinity after each pole, to +infinity. So a - 4 G changes sign
 * exactly once per interval, from + to -, and (-1)^(m - 1) f(xi) is positive left of the root and
 * negative right of it.
 *
 * This is what it is NOT: not a general root finder (it relies on the interlacing just shown), and
 * not well conditioned in the limits: as nu -> -1 the first root tends to 0, as nu -> 0.5 the m-th
 * root tends to m pi, and there the roots carry the relative round-off of a (that of nu, amplified
 * by 1 / (1 - 2 nu) or 1 / (1 + nu)). Throws std::invalid_argument unless -1 < nu < 0.5 and
 * @p n_roots >= 1.
 */
std::vector<double> breathing_mode_roots(double poissons_ratio, unsigned int n_roots);

/**
 * The purely radial ("breathing", spherical harmonic degree n = 0) free vibrations of a
 * homogeneous, isotropic, linearly elastic solid sphere with a traction-free surface: natural
 * angular frequencies, periods and mode shapes of the first few modes.
 *
 * Derivation. A radial displacement u_r(r) e^{i omega t} has strains eps_rr = u', eps_thth =
 * eps_phph = u / r and radial stress sigma_rr = (lambda + 2 mu) u' + 2 lambda u / r; the radial
 * Navier equation (lambda + 2 mu) d/dr (r^-2 d(r^2 u)/dr) + rho omega^2 u = 0 has the solution
 * regular at r = 0
 *
 *   u_r(r) = A j1(k r),   k = omega / c_p,   c_p = sqrt((lambda + 2 mu) / rho),
 *
 * with j1(x) = sin(x) / x^2 - cos(x) / x. With j1'(x) = j0(x) - 2 j1(x) / x and j0(x) = sin(x) / x,
 *
 *   sigma_rr(r) = A k [ (lambda + 2 mu) j0(k r) - 4 mu j1(k r) / (k r) ].
 *
 * The free surface sigma_rr(R) = 0 gives the frequency equation for xi = k R:
 *
 *   (lambda + 2 mu) j0(xi) = 4 mu j1(xi) / xi,
 *
 * or, multiplied by xi^3 / (4 mu sin(xi)),
 *
 *   xi cot(xi) = 1 - a xi^2 / 4,   a = (lambda + 2 mu) / mu = 2 (1 - nu) / (1 - 2 nu)
 *
 * (Lamb 1882, the n = 0 case; e.g. nu = 1/4: xi cot(xi) = 1 - 3 xi^2 / 4, xi_1 = 2.563434 =
 * 0.815966 pi). Its positive roots xi_m (one in each ((m - 1) pi, m pi), see
 * breathing_mode_roots()) give omega_m = xi_m c_p / R and the periods T_m = 2 pi / omega_m.
 *
 * Mode shapes are normalized to the value 1 at the surface: phi_m(r) = j1(xi_m r / R) / j1(xi_m)
 * (j1(xi_m) != 0, since j0 and j1 have no common zero). A sphere at rest and stress-free that is
 * given the initial radial velocity v_r(r) = epsilon phi_m(r) (Cartesian components epsilon
 * phi_m(|x|) x / |x|) vibrates in the pure mode m: u_r(r, t) = (epsilon / omega_m) sin(omega_m t)
 * phi_m(r).
 *
 * Modes are indexed from 0: mode 0 is the fundamental (xi_1), mode 1 the next, and so on.
 *
 * This is what it is NOT: not the non-radial (spheroidal n >= 1 or torsional) modes, not
 * geometrically or materially nonlinear (small strain, linear elasticity), not damped, and not
 * coupled to the finite-element code, for which it is an independent reference only.
 */
class SphereBreathingModes
{
public:
  /**
   * Compute the first @p n_modes breathing modes of @p sphere. Throws std::invalid_argument for a
   * non-positive radius, Young's modulus or density, for nu outside (-1, 0.5) and for
   * @p n_modes = 0.
   */
  SphereBreathingModes(const ElasticSphere& sphere, unsigned int n_modes);

  /// The number of modes computed.
  unsigned int n_modes() const;

  /// The dilatational (P) wave speed c_p = sqrt((lambda + 2 mu) / rho).
  double dilatational_wave_speed() const;

  /// The root xi = k R of the frequency equation belonging to mode @p mode (0: fundamental).
  double dimensionless_wavenumber(unsigned int mode) const;

  /// The natural angular frequency omega = xi c_p / R of mode @p mode.
  double angular_frequency(unsigned int mode) const;

  /// The period 2 pi / omega of mode @p mode.
  double period(unsigned int mode) const;

  /**
   * The radial displacement of mode @p mode at radius @p r in [0, R], normalized to 1 at r = R:
   * j1(xi r / R) / j1(xi). Throws std::out_of_range for a bad mode or r outside [0, R] (beyond
   * round-off).
   */
  double mode_shape(unsigned int mode, double r) const;

  /// The derivative d/dr of mode_shape(), with the same arguments and checks.
  double mode_shape_derivative(unsigned int mode, double r) const;

private:
  /// The root of mode @p mode, after checking the mode index and that 0 <= @p r <= R.
  double checked_root(unsigned int mode, double r) const;

  double radius;
  double wave_speed;
  std::vector<double> roots;
};
} // namespace dyncontact
