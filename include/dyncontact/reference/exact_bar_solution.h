#pragma once

#include <functional>
#include <optional>
#include <queue>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * Data of one straight, linearly elastic bar lying on the x axis, as input to
 * ExactBarSolution. The bar is stress-free at t = 0 and moves with a uniform initial velocity.
 */
struct ExactBar
{
  /// Reference x coordinate of the left end.
  double left_end;
  /// Reference length (> 0).
  double length;
  /// Young's modulus E (> 0).
  double youngs_modulus;
  /// Mass density rho (> 0).
  double density;
  /// Cross-section area A (> 0).
  double area;
  /// Uniform initial velocity along x.
  double initial_velocity;
};

namespace internal
{
/**
 * A right-continuous, piecewise-constant function of time: `initial_value` before the first
 * breakpoint, `values_from_breakpoints()[k]` on `[breakpoints()[k], breakpoints()[k+1])`.
 * Breakpoints are only ever appended, in increasing time.
 */
class StepFunction
{
public:
  /// A constant function with the given value (until the first breakpoint is appended).
  explicit StepFunction(double initial_value);

  /**
   * The value at time @p t. A breakpoint at most @p tolerance after @p t counts as passed, so that
   * instants that differ by round-off only are treated as one.
   */
  double value(double t, double tolerance) const;

  /**
   * Make the function take the value @p new_value from time @p t on, by appending a breakpoint,
   * unless it differs from the current last value by no more than @p threshold. Returns whether a
   * breakpoint was appended.
   */
  bool update(double t, double new_value, double threshold);

  /**
   * The integral of the function over [@p lower, @p upper] (lower <= upper), in O(log n) from
   * the running integral kept at the breakpoints.
   */
  double integral(double lower, double upper) const;

  /// The times at which the value changes, increasing.
  const std::vector<double>& breakpoints() const { return times; }

  /// The value taken from each breakpoint on.
  const std::vector<double>& values_from_breakpoints() const { return values; }

private:
  /// The integral from the first breakpoint (t = 0 without breakpoints) to @p t.
  double antiderivative(double t) const;

  double initial_value;
  std::vector<double> times;
  std::vector<double> values;
  /// The integral from the first breakpoint to each breakpoint.
  std::vector<double> running_integral;
};
} // namespace internal

/**
 * The exact solution of linear one-dimensional elastic waves in straight bars on the x axis that
 * come into frictionless contact with each other (facing ends of bars that are consecutive in x)
 * and, optionally, with a fixed rigid wall to the right of all bars. Each bar starts stress-free
 * with its own uniform velocity; initial gaps, separation and renewed contact are all allowed.
 *
 * The solution is computed by wave tracking along characteristics: in each bar, with wave speed
 * c = sqrt(E/rho), impedance z = rho c A, velocity v and axial force N, the Riemann invariants
 * R = v - N/z and L = v + N/z travel unchanged with speeds +c and -c. Both are piecewise constant;
 * the whole solution is stored as the history of R emitted at each left end and of L emitted at
 * each right end. These histories are built in the constructor by processing events (arrivals of
 * jumps at bar ends, closure of gaps) in time order up to `end_time`; each event applies the end
 * conditions (free end, contact with the neighbour or the wall with release when the contact force
 * would turn tensile). Fields and their integrals (displacement in time, momentum and energies in
 * space) are then evaluated exactly, up to round-off.
 *
 * At an instant where a quantity jumps, the value returned is the one just after that instant
 * (right-continuous in time); this also fixes the value on a moving wave front. Instants that
 * differ by round-off only (relative 1e-14) are treated as the same instant. Queries need a valid
 * bar or interface index, 0 <= t <= end_time and X on the bar, else std::out_of_range is thrown.
 *
 * This is what it is NOT: not a discretization (there is no mesh and no time step), not
 * geometrically or materially nonlinear (small strain, linear elasticity, reference and current
 * configuration are only distinguished in the contact gaps), and not coupled to the finite-element
 * code, which it serves as an independent reference for. Nor is it cheap in every case: each wave
 * front that meets a contact between unequal impedances splits in two, so with several bars of
 * incommensurable travel times the number of fronts, and with it the cost of the constructor and
 * of the queries, grows quickly with end_time.
 */
class ExactBarSolution
{
public:
  /**
   * Track the waves in @p bars (indices in this order are used in all queries) from t = 0 to
   * @p end_time. An empty @p wall_position means that there is no wall; @p clamped_left_end
   * holds the left end of the leftmost bar at rest (v = 0 there from t = 0 on, so a wave leaves it
   * at once if that bar moves: the incoming L is reflected as R = -L). Throws
   * std::invalid_argument for non-positive length, Young's modulus, density or area, for
   * overlapping bars, for a wall left of a bar's right end and for a negative end time (0: the
   * solution at t = 0 alone, the reference of a run that failed its first step).
   */
  ExactBarSolution(const std::vector<ExactBar>& bars,
                   std::optional<double> wall_position,
                   double end_time,
                   bool clamped_left_end = false);

  /// The number of bars.
  unsigned int n_bars() const;

  /**
   * The number of interfaces: one between each pair of bars that are consecutive in x (in x
   * order), then the one between the rightmost bar and the wall, if there is a wall.
   */
  unsigned int n_interfaces() const;

  /// The index of the bar on the left of interface @p interface.
  int left_bar(unsigned int interface) const;

  /// The index of the bar on the right of interface @p interface, or -1 for the wall.
  int right_bar(unsigned int interface) const;

  /// Displacement of the point with reference coordinate @p X of bar @p bar at time @p t.
  double displacement(unsigned int bar, double X, double t) const;

  /// Velocity of the point with reference coordinate @p X of bar @p bar at time @p t.
  double velocity(unsigned int bar, double X, double t) const;

  /// Axial force N = sigma A (tension positive) at reference coordinate @p X of bar @p bar.
  double axial_force(unsigned int bar, double X, double t) const;

  /// Contact force at interface @p interface at time @p t: compression positive, 0 when apart.
  double contact_force(unsigned int interface, double t) const;

  /// The time integral of contact_force() over [0, @p t].
  double contact_impulse(unsigned int interface, double t) const;

  /**
   * Whether the two sides of interface @p interface are in contact at time @p t. Ends that touch
   * with zero force and are not separating count as in contact.
   */
  bool in_contact(unsigned int interface, double t) const;

  /**
   * The contact periods [start, end) of interface @p interface, in time order; end = end_time
   * for a contact that lasts until the end time.
   */
  std::vector<std::pair<double, double>> contact_intervals(unsigned int interface) const;

  /// Momentum of bar @p bar at time @p t: the integral of rho A v over the bar.
  double momentum(unsigned int bar, double t) const;

  /// Kinetic energy of bar @p bar at time @p t: the integral of rho A v^2 / 2 over the bar.
  double kinetic_energy(unsigned int bar, double t) const;

  /// Strain energy of bar @p bar at time @p t: the integral of N^2 / (2 E A) over the bar.
  double strain_energy(unsigned int bar, double t) const;

private:
  /// One bar: its input data, derived constants and the histories of its outgoing waves.
  struct Bar
  {
    ExactBar data;
    double wave_speed;
    double impedance;
    /// Time a wave takes from one end to the other.
    double travel_time;
    /// R emitted at the left end, as a function of the emission time.
    internal::StepFunction right_going;
    /// L emitted at the right end, as a function of the emission time.
    internal::StepFunction left_going;
  };

  /// Two facing ends (or an end and the wall) and the history of their contact.
  struct Interface
  {
    int left_bar;
    int right_bar;
    internal::StepFunction force;
    internal::StepFunction contact;
  };

  /** Wave arrival times, earliest first. */
  using ArrivalQueue = std::priority_queue<double, std::vector<double>, std::greater<double>>;

  /**
   * The time of the next event after `t`: the earliest of the `arrivals` and of the closings of
   * the open interfaces (gap / closing speed, for `closing_speeds` > 0). If it lies within the end
   * time, drops the arrivals grouped with it and advances the `gaps` to it (an interface that
   * closes within the group to gap 0); else returns it and changes nothing.
   */
  double advance_to_next_event(double t,
                               ArrivalQueue& arrivals,
                               std::vector<double>& gaps,
                               const std::vector<double>& closing_speeds) const;

  /**
   * Build the wave histories from t = 0 to end_time, given the bars at both ends of the row, the
   * end conditions (wall, clamp) and the initial gap of every interface.
   */
  void track_events(unsigned int leftmost_bar,
                    unsigned int rightmost_bar,
                    bool has_wall,
                    bool clamped_left_end,
                    std::vector<double> gaps);

  /// The bar @p bar, after checking that it exists and that 0 <= @p t <= end_time.
  const Bar& checked_bar(unsigned int bar, double t) const;

  /// As checked_bar(), also checking that @p X lies on the bar (up to round-off).
  const Bar& checked_point(unsigned int bar, double X, double t) const;

  /// The interface @p interface, after checking that it exists.
  const Interface& checked_interface(unsigned int interface) const;

  /// The invariants (R, L) at reference coordinate @p X of @p bar at time @p t.
  std::pair<double, double> invariants(const Bar& bar, double X, double t, double tolerance) const;

  /**
   * Instants near @p t that are closer than this are treated as one: about 45 units of round-off
   * of t, enough for a jump always to be seen at the event of its own arrival, small enough to
   * keep distinct events apart. (Should events that coincide in exact arithmetic differ by more,
   * they are processed one after the other, which is equally correct.)
   */
  double time_tolerance(double t) const { return 1e-14 * (t + shortest_travel_time); }

  /// The exact integral over @p bar at time @p t of a function of the velocity and axial force.
  double integrate_over_bar(const Bar& bar,
                            double t,
                            const std::function<double(double, double)>& integrand) const;

  std::vector<Bar> bars;
  std::vector<Interface> interfaces;
  /// Events are tracked up to this time.
  double end_time;
  /// The shortest time a wave takes to cross a bar.
  double shortest_travel_time;
  /// Initial gaps and overlaps up to this size are round-off and count as touching.
  double length_tolerance;
  /// Changes of an outgoing wave up to this size are round-off and not emitted.
  double signal_tolerance;
};
} // namespace dyncontact
