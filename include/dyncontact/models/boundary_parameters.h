#pragma once

#include <dyncontact/base/global.h>

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

/** The boundary conditions of a mesh problem besides contact and tractions. Subsection `Boundary`.
 */
struct BoundaryParameters
{
  std::vector<SymmetryParameters> symmetry_planes;
  std::vector<SupportParameters> supports;

  static void declare_parameters(ParameterHandler& prm,
                                 unsigned int n_symmetry_planes,
                                 unsigned int n_supports);
  /** Reads the entries of a `dim`-dimensional mesh problem (2 or 3). */
  void parse_parameters(ParameterHandler& prm, unsigned int dim);
};
} // namespace dyncontact
