#include <dyncontact/base/parameter_entries.h>
#include <dyncontact/contact/contact_parameters.h>

#include <cmath>
#include <sstream>

namespace dyncontact
{
namespace
{
/** The numbers of "a, b, ..." (comma-separated); empty if one is not a number. */
std::vector<double> parse_numbers(const std::string& text)
{
  std::vector<double> numbers;
  std::istringstream fields(text);
  for (std::string field; std::getline(fields, field, ',');)
  {
    std::istringstream stream(field);
    double value;
    if (!(stream >> value) || !(stream >> std::ws).eof() || !std::isfinite(value))
      return {};
    numbers.push_back(value);
  }
  return numbers;
}

/** The friction coefficient `text` of the entry `entry`: a number >= 0; InputError otherwise. */
double parse_friction_coefficient(const std::string& text, const std::string& entry)
{
  const std::vector<double> numbers = parse_numbers(text);
  if (numbers.size() != 1 || !(numbers[0] >= 0.))
    throw InputError(entry + " = '" + text +
                     "' is not allowed: it must be a number >= 0 (Coulomb's mu; 0: "
                     "frictionless).");
  return numbers[0];
}
} // namespace

const NameTable<ContactFormulation>& contact_formulation_names()
{
  static const NameTable<ContactFormulation> names{
      {"lagrange multiplier", ContactFormulation::lagrange_multiplier},
      {"penalty", ContactFormulation::penalty}};
  return names;
}

void ContactPairParameters::declare_parameters(ParameterHandler& prm)
{
  prm.declare_entry("slave boundary",
                    "0",
                    Patterns::Integer(0),
                    "The slave surface of this pair: a boundary id, i.e. the tag of a gmsh "
                    "physical curve of the mesh (3D: physical surface) (>= 1; not the symmetry "
                    "axis 1 of an axisymmetric mesh). Its nodes carry the pair's multipliers.");
  prm.declare_entry("master boundary",
                    "0",
                    Patterns::Integer(0),
                    "The master surface: a boundary id (>= 1) of another body, or 0 for the rigid "
                    "plane below. The slave nodes are projected onto it (node-to-segment) or "
                    "paired with its facing nodes (node-to-node).");
  prm.declare_entry("rigid plane",
                    "",
                    Patterns::Anything(),
                    "With master boundary = 0: a fixed rigid plane (a line in the r-z plane) as "
                    "'r, z; n_r, n_z': a point on it [length] and its normal pointing toward the "
                    "body (normalized here), e.g. '0, 0; 0, 1' for the plane z = 0 below a body; "
                    "in 3D 'x, y, z; n_x, n_y, n_z', e.g. '0, 0, 0; 0, 0, 1'. Empty otherwise.");
  prm.declare_entry("friction coefficient",
                    "",
                    Patterns::Anything(),
                    "Coulomb's friction coefficient mu of this pair [-], a number >= 0; empty: "
                    "Contact/friction coefficient.");
}

void ContactPairParameters::parse_parameters(ParameterHandler& prm,
                                             const std::string& source,
                                             const unsigned int dim)
{
  this->source               = source;
  const auto slave           = prm.get_integer("slave boundary");
  const auto master          = prm.get_integer("master boundary");
  const std::string text     = prm.get("rigid plane");
  const bool has_plane       = text.find_first_not_of(" \t") != std::string::npos;
  const std::string friction = prm.get("friction coefficient");
  friction_coefficient.reset();
  if (friction.find_first_not_of(" \t") != std::string::npos)
    friction_coefficient = parse_friction_coefficient(friction, source + "/friction coefficient");
  if (slave < 1)
    throw InputError(source + "/slave boundary = " + std::to_string(slave) +
                     " is not allowed: it must be a boundary id >= 1 (a gmsh physical curve "
                     "tag).");
  if (master < 0 || master == slave)
    throw InputError(source + "/master boundary = " + std::to_string(master) +
                     " is not allowed: it must be a boundary id >= 1 other than the slave "
                     "boundary, or 0 for a rigid plane.");
  if ((master != 0) == has_plane)
    throw InputError(source +
                     ": give either master boundary (>= 1) or rigid plane ('r, z; "
                     "n_r, n_z' with master boundary = 0), not " +
                     std::string(has_plane ? "both." : "neither."));
  slave_boundary = slave;
  if (master != 0)
  {
    master_boundary = master;
    return;
  }
  const auto separator = text.find(';');
  const std::vector<double> point =
      parse_numbers(separator == std::string::npos ? text : text.substr(0, separator));
  const std::vector<double> normal = separator == std::string::npos
                                         ? std::vector<double>()
                                         : parse_numbers(text.substr(separator + 1));
  // hypot in 2D: the same bits as before 3D existed (histories identical version to version).
  const double length = normal.size() == 2   ? std::hypot(normal[0], normal[1])
                        : normal.size() == 3 ? std::hypot(normal[0], normal[1], normal[2])
                                             : 0.;
  if (point.size() != dim || normal.size() != dim || !(length > 0.))
    throw InputError(source + "/rigid plane = '" + text + "' is not allowed: it must be " +
                     (dim == 3 ? "'x, y, z; n_x, n_y, n_z'" : "'r, z; n_r, n_z'") +
                     ", a point and a nonzero normal.");
  rigid_plane = RigidPlane{point, normal};
  for (double& component : rigid_plane->normal)
    component /= length;
}

void ContactParameters::declare_parameters(ParameterHandler& prm, const unsigned int n_pairs)
{
  prm.enter_subsection("Contact");
  prm.declare_entry("number of pairs",
                    "0",
                    Patterns::Integer(0, 100),
                    "Mesh problems: how many contact pairs are declared, as subsections "
                    "'Pair 1', 'Pair 2', ... 0: in 2D with two bodies, their surfaces of the "
                    "sphere meshes (physical curves 2 and 3, body 1 the slave side); with one "
                    "body, no contact; more bodies (3D: two or more) need declared pairs. Bars: "
                    "0.");
  for_each_numbered_subsection(prm,
                               "Pair",
                               n_pairs,
                               [&prm](unsigned int, const std::string&)
                               { ContactPairParameters::declare_parameters(prm); });
  prm.declare_entry("dynamics",
                    contact_dynamics_names().name(ContactParameters::default_dynamics),
                    Patterns::Selection(contact_dynamics_names().selection()),
                    contact_dynamics_documentation(ContactParameters::default_dynamics));
  prm.declare_entry("formulation",
                    "lagrange multiplier",
                    Patterns::Selection(contact_formulation_names().selection()),
                    "Enforcement of the non-penetration condition g >= 0. lagrange multiplier: "
                    "exact, one multiplier unknown per candidate pair (saddle-point solve). "
                    "penalty: force eps <-g> along the normal (allows small penetration).");
  prm.declare_entry(
      "discretization",
      "node-to-node",
      Patterns::Selection(contact_discretization_names().selection()),
      "How the two bodies' contact surfaces meet. node-to-node: each facing node of "
      "the slave body against the node of the master body across from it; the facing surfaces "
      "must have matching nodes (mirrored meshes). node-to-segment: each slave surface node "
      "against its projection on the curved quadratic faces of the master body, for any meshes "
      "(in 3D node-to-surface, on 9-node faces); the paper's rate correction (Contact/dynamics) "
      "acts on the slave node and the master face's nodes. mortar (2D only): each slave node's gap "
      "weighted over its faces by its dual shape "
      "function, against the master surface under them (dual Lagrange multipliers, "
      "segment-based integration); passes the patch test on non-matching meshes, where "
      "node-to-segment's pressure oscillates between vertex and mid-side nodes; the rate "
      "correction acts on the slave node and every master node of its weights; not yet for long "
      "sliding between flat faces at strains far beyond small strain (a mode grows from "
      "round-off and stops the run, doc/method.md 4.2). All three are the same on matching flat "
      "faces.");
  prm.declare_entry(
      "friction coefficient",
      "0",
      Patterns::Anything(),
      "Coulomb's friction coefficient mu [-] of every contact pair that does not give its own "
      "(Pair k/friction coefficient), a number >= 0; 0: frictionless. With friction a pair's "
      "tangential force lambda_t obeys |lambda_t| <= mu lambda_n, opposite to the slip when it "
      "slides; stick and slip are decided inside Newton (a semismooth Newton on the NCP function "
      "of Hueber, Stadler & Wohlmuth 2008; doc/method.md, section 7). Meshes only (2D: in the "
      "r-z or x-y plane; 3D: both tangential directions): rigid planes, node-to-node, "
      "node-to-segment and mortar pairs; with Contact/dynamics = none, "
      "mass-redistribution or taylor-papadopoulos (whose rate constraints hold a stuck pair's "
      "whole relative velocity and acceleration). history.csv then has the columns "
      "sliding_pairs, frictional_dissipation, stick_velocity_jump and stick_acceleration_jump "
      "(and, in plane strain, each body's momentum components).");
  prm.declare_entry("penalty factor",
                    "auto",
                    Patterns::Anything(),
                    "Penalty only: stiffness eps of a pair [force/length] = this factor [-] times "
                    "E A / h of the stiffer side; a number > 0, or auto. Bars: A the "
                    "cross-section, h the element length at the contact node; meshes: A the "
                    "pair's contact area (2 pi r weighted), h the shortest cell edge. "
                    "auto: 100 where the time step does not resolve the bodies' highest mode "
                    "(omega dt > 2, the quasi-static contact of the spheres: penetration about "
                    "1e-3 of the Hertz approach), else the largest factor <= 100 whose stiffest "
                    "spring has omega dt <= 1 (wave problems such as the bars: an unresolved "
                    "spring chatters, forces several times the exact ones). The run prints the "
                    "factor it chose. "
                    "With the classical scheme and beta < gamma/2 a large penalty needs a small "
                    "time step (a run refuses one above the stability limit).");
  prm.leave_subsection();
}

void ContactParameters::parse_parameters(ParameterHandler& prm, const unsigned int dim)
{
  prm.enter_subsection("Contact");
  formulation = contact_formulation_names().parse(prm.get("formulation"), "Contact/formulation");
  dynamics    = contact_dynamics_names().parse(prm.get("dynamics"), "Contact/dynamics");
  discretization =
      contact_discretization_names().parse(prm.get("discretization"), "Contact/discretization");
  friction_coefficient =
      parse_friction_coefficient(prm.get("friction coefficient"), "Contact/friction coefficient");
  const std::string factor = prm.get("penalty factor");
  automatic_penalty        = factor == "auto";
  penalty_factor           = quasi_static_penalty_factor;
  if (!automatic_penalty)
  {
    std::istringstream stream(factor);
    if (!(stream >> penalty_factor) || !(stream >> std::ws).eof() || !(penalty_factor > 0.))
      throw InputError("Contact/penalty factor = " + factor +
                       " is not allowed: it must be a number > 0 or auto.");
  }
  pairs.resize(prm.get_integer("number of pairs"));
  for_each_numbered_subsection(prm,
                               "Pair",
                               pairs.size(),
                               [&](const unsigned int k, const std::string& name)
                               { pairs[k].parse_parameters(prm, "Contact/" + name, dim); });
  prm.leave_subsection();
}
} // namespace dyncontact
