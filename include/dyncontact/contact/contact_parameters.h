#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/name_table.h>
#include <dyncontact/contact/contact_discretization.h>
#include <dyncontact/contact_dynamics/contact_dynamics_kind.h>

#include <deal.II/base/parameter_handler.h>

#include <optional>
#include <string>
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
  /// A rigid plane: the coordinates of a point on it [length] and of its unit normal, which points
  /// toward the body.
  struct RigidPlane
  {
    std::vector<double> point;
    std::vector<double> normal;
  };
  /// the rigid plane the slave boundary meets; empty: it meets the master boundary
  std::optional<RigidPlane> rigid_plane;
  /// what errors name: "Contact/Pair k"
  std::string source;
  /// Coulomb friction coefficient of this pair [-], >= 0; empty: Contact/friction coefficient
  std::optional<double> friction_coefficient;

  static void declare_parameters(ParameterHandler& prm);
  /** Throws InputError (naming `source`) for ids below 2, equal ids, or not exactly one of
   * master boundary and rigid plane, a malformed plane (not `dim` coordinates each), or a
   * friction coefficient that is not a number >= 0. */
  void parse_parameters(ParameterHandler& prm, const std::string& source, unsigned int dim);
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
  /// Contact/dynamics when not given: mass redistribution, on the trapezoidal rule with its contact
  /// events resolved (doc/schemes.md, "The default")
  static constexpr ContactDynamicsKind default_dynamics = ContactDynamicsKind::mass_redistribution;
  /// Coulomb friction coefficient [-] of every pair that does not give its own, >= 0 (0:
  /// frictionless)
  double friction_coefficient = 0.;
  /// Contact/Pair 1, 2, ... (mesh problems); empty: the model's default pairing
  std::vector<ContactPairParameters> pairs;

  /** Declares the subsections Pair 1 to Pair n_pairs too. */
  static void declare_parameters(ParameterHandler& prm, unsigned int n_pairs);
  /** Reads the entries; `dim` is the space dimension the rigid planes are given in (1 to 3). */
  void parse_parameters(ParameterHandler& prm, unsigned int dim);
};
} // namespace dyncontact
