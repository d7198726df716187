#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/simulation/guard_parameters.h>

#include <array>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * The physics a solved step must respect before it is accepted, checked on figures the
 * Simulation measures (a tripped guard makes the step fail, which cuts it):
 *
 * - energy: the algorithmic energy E_{n+1} (GeneralizedAlpha::algorithmic_energy; Simulation
 *   passes E_0 plus the changes of the accepted steps, each at its own step size) must not exceed
 *   the initial energy plus the work of the external forces by more than `energy tolerance` times
 *   the energy scale (the larger of |E_0| and |external work|; for E_0 = 0 the largest accepted
 *   energy instead). With 2 beta < gamma the plain energy (kinetic + strain) must in addition
 *   stay within `plain energy tolerance` of the same bound: the algorithmic energy weighs the
 *   strain energy of a mode at omega dt by 1 - (omega dt / limit)^2, nearly zero next to the
 *   stability limit, where a blow-up of the highest modes leaves it unchanged. Elastic bodies in
 *   frictionless contact cannot gain energy; trapezoidal Newmark conserves it for linear free
 *   systems, and the modified scheme dissipates some at impact. The check is cumulative, against
 *   the start, because per-step fluctuations of the nonlinear trapezoidal rule (up to 1e-3 of E
 *   per step on the coarse neo-Hookean spheres, measured) are not gains.
 * - tensile force: the recovered total contact force (compression positive) must not be below
 *   -`tensile force tolerance` times the force scale (the largest accepted |force| and the sum of
 *   this step's |multipliers|).
 * - momentum: for every body and every momentum direction (BodyImpulses: x, y and z in 3D and x,
 *   y in plane strain; the axis in axisymmetry), the momentum change since t = 0 must
 *   equal the accumulated impulse of the contact and external forces on it (see
 *   Simulation: Newmark-weighted recovered forces plus the modified scheme's velocity-correction
 *   impulses) to `momentum tolerance` times the momentum scale (the largest momentum magnitude
 *   seen, the sum of |m v| over every DoF: a scale that exists when the net momenta vanish, as
 *   in a free vibration).
 *   Equality is exact for a converged step; a gap means a residual left in the momentum balance.
 *
 * A non-finite figure always rejects the step. A zero scale (nothing moves yet) skips that check. A
 * guard switched off does not reject steps, but its first violation is kept for a warning at the
 * end of the run (warnings()), so that a run that gains energy (e.g. the paper's classical Newmark,
 * reproduced with `Guards/energy = false`) says so. It does not cut or solve anything.
 */
class StepGuards
{
public:
  /** What the guards read about one step (the state at its end). */
  struct Figures
  {
    double time;                        ///< t_{n+1}
    double energy;                      ///< algorithmic energy at t_{n+1}
    double external_work;               ///< work of the external forces since t = 0
    double contact_force;               ///< recovered total contact force, compression positive
    double multiplier_magnitude;        ///< sum of the active pairs' |force|
    std::vector<double> momenta;        ///< per track (BodyImpulses: a body along a direction)
    std::vector<double> impulses;       ///< per track, accumulated since t = 0
    double momentum_magnitude;          ///< sum of |m v| over every DoF (zero only at rest)
    double plain_energy;                ///< kinetic + strain energy at t_{n+1}
    double frictional_dissipation = 0.; ///< energy friction dissipated since t = 0
  };

  /**
   * `plain_energy_checked`: the integrator is conditionally stable (Newmark with 2 beta < gamma),
   * whose algorithmic energy underweights the highest modes; the energy guard then also bounds
   * the plain energy (Guards/plain energy tolerance). `track_names`: per entry of
   * Figures::momenta, what the momentum guard's message calls it (BodyImpulses::track_names()).
   */
  StepGuards(const GuardParameters& parameters,
             bool plain_energy_checked,
             std::vector<std::string> track_names);

  /** Takes the references (E_0, p_0) from the figures of the initial state. */
  void initialize(const Figures& initial);

  /**
   * The reason the step must be rejected, one line naming the guard and its prm entry, or an
   * empty string if every enabled guard holds.
   */
  std::string check(const Figures& step) const;

  /** Records an accepted step (updates the scales, notes violations of guards switched off). */
  void accept(const Figures& step);

  /** One line per guard switched off that was violated: where first, and its largest amount. */
  std::vector<std::string> warnings() const;

  /** Writes or reads the references and records (checkpoints). */
  template <class Archive>
  void serialize(Archive& archive, const unsigned int)
  {
    archive& initial_energy& initial_plain_energy& energy_scale& force_scale& momentum_scale&
        initial_momenta& accepted_dissipation;
    for (Record& record : disabled_violations)
      archive& record.first_reason& record.first_time& record.largest;
  }

private:
  enum Guard
  {
    energy,
    tensile_force,
    momentum,
    n_guards
  };
  bool enabled(Guard guard) const;
  /** The violation of `guard` by `step` as (reason, relative amount); amount 0: none. */
  std::pair<std::string, double> violation(Guard guard, const Figures& step) const;

  const GuardParameters parameters;
  const bool plain_energy_checked;
  double initial_energy       = 0.;
  double initial_plain_energy = 0.;
  double energy_scale         = 0.;
  double force_scale          = 0.;
  double momentum_scale       = 0.;
  double accepted_dissipation = 0.; ///< Figures::frictional_dissipation of the last accepted step
  std::vector<double> initial_momenta;
  std::vector<std::string> track_names;
  /** Per guard switched off: the first violation's text and time, and the largest amount. */
  struct Record
  {
    std::string first_reason;
    double first_time = 0.;
    double largest    = 0.;
  };
  std::array<Record, n_guards> disabled_violations;
};
} // namespace dyncontact
