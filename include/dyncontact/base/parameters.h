#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/name_table.h>
#include <dyncontact/contact/contact_discretization.h>
#include <dyncontact/contact_dynamics/contact_dynamics_kind.h>
#include <dyncontact/solver/direct_solver_package.h>
#include <dyncontact/time_integration/integrator_family.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{

/** How the contact constraint g >= 0 is enforced. */
enum class ContactFormulation
{
  lagrange_multiplier, ///< exact enforcement, one multiplier unknown per candidate pair
  penalty              ///< force eps <-g> along the normal
};

/** The names of Contact/formulation. */
const NameTable<ContactFormulation>& contact_formulation_names();

/** Newmark parameters and the time window of a run. Subsection `Time integration`. */
struct TimeIntegrationParameters
{
  /// the deprecated Time integration/scheme (classical | modified), "" if not given; it sets
  /// Contact/dynamics (ParameterReader resolves it)
  std::string deprecated_scheme;
  /// the member of the generalized-alpha family (Time integration/integrator)
  IntegratorFamily integrator;
  /// rho_inf of a dissipative member (Time integration/spectral radius); unused by newmark
  double spectral_radius;
  /// Newmark beta and gamma: for newmark as given, an entry left empty taking its default (see
  /// resolve_newmark_coefficients()); else the member's, set from rho_inf when read
  double beta;
  double gamma;
  /// Time integration/beta and gamma as given; empty when the entry is left empty
  std::optional<double> given_beta;
  std::optional<double> given_gamma;

  /**
   * gamma of newmark when neither beta nor gamma is given: 0.502, with beta = (gamma + 1/2)^2 / 4
   * = 0.251001, the unconditionally stable member that damps the highest frequencies most for its
   * gamma (rho_inf = (3/2 - gamma) / (gamma + 1/2) = 0.996), first order with the error constant
   * gamma - 1/2. Chosen over the whole kind of issue 25, item 7: with the default Contact/dynamics
   * = mass-redistribution no impact of the sweep gains energy at any step from gamma = 0.501 on,
   * where the trapezoidal rule gains up to 1e-4 of it; 0.502 doubles that smallest damping
   * (doc/schemes.md, "The default").
   */
  static constexpr double default_newmark_gamma = 0.502;
  /// beta of newmark when neither is given: (default_newmark_gamma + 1/2)^2 / 4, written out so
  /// that the record names it in its 6 digits
  static constexpr double default_newmark_beta = 0.251001;
  double time_step;
  double end_time;
  /// a failing step is halved at most this many times (minimum step dt / 2^max_step_cuts)
  unsigned int max_step_cuts;

  /**
   * Number of steps: end time / time step, rounded up (the last step may end past end time), at
   * least 1.
   */
  unsigned int n_steps() const;

  /**
   * Newmark's beta and gamma when not both given: gamma left empty is 1/2 if beta is given, else
   * default_newmark_gamma; beta left empty is (gamma + 1/2)^2 / 4. With
   * `trapezoidal_rule_required` (a contact treatment built on the trapezoidal rule) and neither
   * given, they are 1/4 and 1/2. Does nothing for the other members.
   */
  void resolve_newmark_coefficients(bool trapezoidal_rule_required);

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm);
};

/**
 * One declared contact pair of a mesh problem, subsection `Contact/Pair k`: a slave boundary
 * against a master boundary (both gmsh physical curve tags, i.e. boundary ids), or against a rigid
 * plane.
 */
struct ContactPairParameters
{
  types::boundary_id slave_boundary;
  /// empty: the slave boundary meets the rigid plane instead
  std::optional<types::boundary_id> master_boundary;
  /// the rigid plane: a point on it [length] and its unit normal pointing toward the body
  std::optional<std::pair<Point<2>, Tensor<1, 2>>> rigid_plane;
  /// what errors name: "Contact/Pair k"
  std::string source;

  static void declare_parameters(ParameterHandler& prm);
  /** Throws InputError (naming `source`) for ids below 2, equal ids, or not exactly one of
   * master boundary and rigid plane, or a malformed plane. */
  void parse_parameters(ParameterHandler& prm, const std::string& source);
};

/** Contact enforcement. Subsection `Contact`. */
struct ContactParameters
{
  ContactFormulation formulation;
  ContactDynamicsKind dynamics;
  ContactDiscretization discretization;
  /// penalty stiffness of a pair = this factor times E A / h of the stiffer side (dimensionless);
  /// with `automatic_penalty` the factor the models start from (quasi_static_penalty_factor),
  /// which create_contact() lowers for wave problems (size_automatic_penalty())
  double penalty_factor;
  /// Contact/penalty factor = auto: chosen per run by the time-step resolution, see the prm help
  bool automatic_penalty;
  /// the automatic factor where the bodies' highest mode is not resolved by the time step
  static constexpr double quasi_static_penalty_factor = 100.;
  /// Contact/Pair 1, 2, ... (mesh problems); empty: the model's default pairing
  std::vector<ContactPairParameters> pairs;

  /** Declares the subsections Pair 1 to Pair n_pairs too. */
  static void declare_parameters(ParameterHandler& prm, unsigned int n_pairs);
  void parse_parameters(ParameterHandler& prm);
};

/** Convergence control of the per-step Newton / active-set loop. Subsection `Newton`. */
/** Newton/method: a fresh tangent for every update, or the step's tangent reused. */
enum class NewtonMethod
{
  full,    ///< the tangent at every iterate (quadratic convergence)
  modified ///< the tangent of the step's first update while the active set stays (linear rate),
           ///< low-rank updates of the factors for active-set changes
};

/** The names of Newton/method. */
const NameTable<NewtonMethod>& newton_method_names();

struct NewtonParameters
{
  unsigned int max_iterations;
  double residual_tolerance;
  DirectSolverPackage direct_solver;
  NewtonMethod method;

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm);
};

/**
 * The physical checks of every step (StepGuards): each on by default, with a tolerance relative to
 * the run's own scale. Subsection `Guards`.
 */
struct GuardParameters
{
  bool energy;
  double energy_tolerance;
  double plain_energy_tolerance;
  bool tensile_force;
  double tensile_force_tolerance;
  bool momentum;
  double momentum_tolerance;
  /// massless contact nodes: the largest contact event work of a step per unit of energy (0..1)
  double contact_event_tolerance;

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm);
};

/** One straight linear elastic bar on the x axis. Subsection `Geometry/Bar <b>`. */
struct BarParameters
{
  double left_end;
  double length;
  unsigned int n_elements;
  double youngs_modulus;
  double density;
  double area;
  double initial_velocity;

  double right_end() const { return left_end + length; }
  double wave_speed() const;
  double element_length() const { return length / n_elements; }

  static void declare_parameters(ParameterHandler& prm);
  /// `section` is the subsection path used in error messages, e.g. "Geometry/Bar 2".
  void parse_parameters(ParameterHandler& prm, const std::string& section);
};

/**
 * The bodies of a bar problem: bars in prm order (body b = bar b) and an optional rigid wall at
 * x = wall position that faces -x (all bars lie to its left). Subsection `Geometry`.
 */
struct GeometryParameters
{
  std::vector<BarParameters> bars;
  bool wall_enabled;
  double wall_position;
  /// the left end of the leftmost bar is clamped (u = 0 there)
  bool clamped_left_end;

  static void declare_parameters(ParameterHandler& prm, unsigned int n_bars);
  void parse_parameters(ParameterHandler& prm);
};

/** What a run writes and where. Subsection `Output`. */
struct OutputParameters
{
  std::string directory;
  std::vector<double> profile_times;
  unsigned int vtu_interval;
  std::vector<double> vtu_times;
  /// with VTU output on, also a frame at every step (cut steps included) with active pairs
  bool vtu_during_contact;
  /// write checkpoint.bin every this many nominal steps (0: only when interrupted)
  unsigned int checkpoint_interval;
  bool write_exact_solution;

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm);
};

/** Which kind of problem a run solves; decides the dimension and the sections that apply. */
enum class GeometryKind
{
  bars,             ///< 1D bars built in code, subsection `Geometry`
  axisymmetric_mesh ///< bodies of revolution from a gmsh mesh, subsections `Mesh` and `Bodies`
};

/** The names of Problem/geometry. */
const NameTable<GeometryKind>& geometry_names();

/** Subsection `Problem`. */
struct ProblemParameters
{
  GeometryKind geometry;

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm);
};

/** The mesh of a mesh-based problem. Subsection `Mesh`. */
struct MeshParameters
{
  std::string file; ///< resolved: relative paths are taken relative to the parameter file
  std::map<std::string, double> geo_parameters;

  static void declare_parameters(ParameterHandler& prm);
  /** `parameter_file_directory` resolves a relative mesh file name. */
  void parse_parameters(ParameterHandler& prm, const std::string& parameter_file_directory);
};

/** One body of a mesh-based problem. Subsection `Bodies/Body <b>`. */
struct BodyParameters
{
  std::string material;
  double youngs_modulus;
  double poissons_ratio;
  double density;
  /// (r, z) whose nearest node is reported as u_tip_<b> etc.; empty: the body's centroid (0, z_c).
  std::optional<Point<2>> monitor_point;
  std::shared_ptr<Functions::ParsedFunction<2>> initial_velocity;
  std::shared_ptr<Functions::ParsedFunction<2>> surface_traction;

  static void declare_parameters(ParameterHandler& prm);
  void parse_parameters(ParameterHandler& prm, const std::string& section);
};

/** The bodies of a mesh-based problem, body b = material id b - 1. Subsection `Bodies`. */
struct BodiesParameters
{
  std::vector<BodyParameters> bodies;

  static void declare_parameters(ParameterHandler& prm, unsigned int n_bodies);
  void parse_parameters(ParameterHandler& prm);
};

/** Every setting of one run, grouped by prm subsection. */
struct RunParameters
{
  ProblemParameters problem;
  TimeIntegrationParameters time;
  ContactParameters contact;
  NewtonParameters newton;
  GuardParameters guards;
  GeometryParameters geometry; ///< bars only
  MeshParameters mesh;         ///< mesh-based problems only
  BodiesParameters bodies;     ///< mesh-based problems only
  OutputParameters output;
  /// one line each, for the user: deprecated entries and what replaces them
  std::vector<std::string> warnings;
  /**
   * "Section/entry" and value of every entry that defines the problem, in declaration order: all
   * but Output/... and Time integration/end time (a resumed run may write elsewhere and run
   * longer), Contact/dynamics as resolved from the deprecated Time integration/scheme, which is
   * left out. What a resumed run must repeat (ProblemFingerprint).
   */
  std::vector<std::pair<std::string, std::string>> problem_entries;
};

/**
 * Reads a parameter file, applies `Section/entry=value` overrides, checks every value and keeps
 * the ParameterHandler so that the run can record what it used. Every problem becomes an
 * InputError naming the file, the entry and the allowed range. It does not create any output.
 */
class ParameterReader
{
public:
  /**
   * Parses `filename` and then the overrides in order (each "Section/Subsection/entry=value").
   * Throws InputError on an unreadable file, an unknown entry, a value out of range, or
   * inconsistent geometry.
   */
  ParameterReader(const std::string& filename, const std::vector<std::string>& overrides);

  const RunParameters& parameters() const { return run_parameters; }

  /**
   * Writes `original.prm` (the input as given, followed by the overrides as comments) and
   * `parameters.prm` (every entry with the value in effect) into `directory`.
   */
  void write_records(const std::string& directory) const;

  /**
   * Prints a parameter file for problems of `kind` ("bars" or "mesh"): every entry such a problem
   * takes, with its documentation, default and allowed values. It runs as printed: bars, one bar
   * at rest; mesh, two spheres at rest in the shipped meshes/two_spheres.geo (named by its
   * absolute path in the source tree) with one contact pair.
   */
  static void print_template(std::ostream& out, const std::string& kind);

private:
  /**
   * Resolves the deprecated Time integration/scheme into Contact/dynamics (with a warning) and
   * checks across subsections (contact dynamics vs formulation).
   */
  void resolve_and_check();
  /** Fills RunParameters::problem_entries from the parsed entries. */
  void record_problem_entries();

  std::string input_filename;
  std::string input_text;
  std::vector<std::string> overrides;
  ParameterHandler prm;
  RunParameters run_parameters;
};
} // namespace dyncontact
