#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/models/mesh_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace dyncontact
{
/**
 * A symmetry plane of a mesh problem: a straight boundary (a line in 2D) whose normal displacement
 * is held at zero, the boundary's tangential motion free. Subsection `Boundary/Symmetry k`. The
 * boundary's normal must lie along a coordinate axis (MeshModel checks it against the mesh).
 */
struct SymmetryParameters
{
  types::boundary_id boundary; ///< the gmsh physical curve (3D: surface) tag, >= 1

  static void declare_parameters(ParameterHandler& prm);
  /** `section` names the subsection in errors, e.g. "Boundary/Symmetry 1". */
  void parse_parameters(ParameterHandler& prm, const std::string& section);
};

/**
 * A fixed support of a mesh problem: the chosen displacement components held at zero for all
 * time on a boundary (a clamp, a roller). Subsection `Boundary/Support k`. Its reaction counts as
 * an external impulse (the momentum guard) and does no work.
 */
struct SupportParameters
{
  types::boundary_id boundary; ///< the gmsh physical curve (3D: surface) tag, >= 1
  /// 0 = x (r), 1 = y (z), 2 = z (3D); sorted, not empty
  std::vector<unsigned int> components;

  static void declare_parameters(ParameterHandler& prm);
  /** Throws InputError (naming `section`) for a component z when `dim` is 2. */
  void parse_parameters(ParameterHandler& prm, const std::string& section, unsigned int dim);
};

/**
 * A prescribed displacement of a mesh problem: the chosen displacement components of a boundary
 * follow u_i = g_i(x, t) for all time, x the reference position (a pushing plate, a clamp moved
 * slowly for a quasi-static load). Subsection `Boundary/Dirichlet k`: the entries of a support and
 * the subsection `Displacement`, a function of x, y (, z) and t with dim components, of which the
 * chosen ones apply. The bodies start undeformed, so g(x, 0) must be zero (PrescribedDisplacements
 * checks it); the velocity and acceleration of the boundary start at dg/dt and d2g/dt2 at t = 0,
 * and then follow the integrator's rates of u. Its reaction counts as an external impulse and does
 * work; a contact pair whose force would act on it is refused when it closes
 * (ContactConstraints::first_prescribed_active_pair()).
 */
struct DirichletParameters
{
  SupportParameters where; ///< the boundary and components
  FunctionExpression displacement;

  static void declare_parameters(ParameterHandler& prm, unsigned int dim);
  /** Throws InputError (naming `section`) for a bad component or expression. */
  void parse_parameters(ParameterHandler& prm, const std::string& section, unsigned int dim);
};

/**
 * A boundary with displacement components held: a support (zero) or a Dirichlet boundary
 * (prescribed), as the models read them.
 */
struct HeldBoundary
{
  std::string section; ///< "Boundary/Support k" or "Boundary/Dirichlet k", for errors
  SupportParameters where;
  FunctionExpression displacement; ///< empty expression: held at zero
};

/** The boundary conditions of a mesh problem besides contact and tractions. Subsection `Boundary`.
 */
struct BoundaryParameters
{
  std::vector<SymmetryParameters> symmetry_planes;
  std::vector<SupportParameters> supports;
  std::vector<DirichletParameters> dirichlet_boundaries;

  /** The counts of the numbered subsections; `dim` is 2 or 3 (the Displacement's components). */
  static void declare_parameters(ParameterHandler& prm,
                                 unsigned int n_symmetry_planes,
                                 unsigned int n_supports,
                                 unsigned int n_dirichlet_boundaries,
                                 unsigned int dim);

  /** The supports, then the Dirichlet boundaries, each with its section name. */
  std::vector<HeldBoundary> held_boundaries() const;
  /** Reads the entries of a `dim`-dimensional mesh problem (2 or 3). */
  void parse_parameters(ParameterHandler& prm, unsigned int dim);
};
} // namespace dyncontact
