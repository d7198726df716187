#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dyncontact
{
/** The mesh of a mesh-based problem. Subsection `Mesh`. */
struct MeshParameters
{
  std::string file; ///< resolved: relative paths are taken relative to the parameter file
  std::map<std::string, double> geo_parameters;

  static void declare_parameters(ParameterHandler& prm);
  /** `parameter_file_directory` resolves a relative mesh file name. */
  void parse_parameters(ParameterHandler& prm, const std::string& parameter_file_directory);
};

/**
 * A vector function of position and time as a parameter file gives it (a deal.II ParsedFunction
 * subsection: variable names, expression, constants), kept as text so that it is tied to no
 * dimension until a model builds it.
 */
struct FunctionExpression
{
  std::string variables;
  std::string expression;
  std::string constants;

  /**
   * The ParsedFunction<dim> of these texts with `n_components` components. Throws deal.II's
   * exception for a malformed expression (BodyParameters::parse_parameters() has checked them).
   */
  template <int dim>
  std::shared_ptr<Functions::ParsedFunction<dim>> create(unsigned int n_components) const;

  /** Whether every component of the expression is the number 0 (e.g. "0; 0"). */
  bool is_zero() const;
};

/** Declares a `dim`-component ParsedFunction of x, y (, z) and t in subsection `name`. */
void declare_function_subsection(ParameterHandler& prm, const std::string& name, unsigned int dim);

/**
 * Reads the `dim`-component ParsedFunction in subsection `name` and evaluates each component once,
 * at the origin and t = 0: muParser compiles an expression only when it is first evaluated, so an
 * unknown function or a syntax error shows here and not in the middle of a run. Any problem
 * becomes an InputError naming `section`/`name`, the entry and the expression.
 */
FunctionExpression parse_function_subsection(ParameterHandler& prm,
                                             const std::string& name,
                                             const std::string& section,
                                             unsigned int dim);

/** One body of a mesh-based problem. Subsection `Bodies/Body <b>`. */
struct BodyParameters
{
  std::string material;
  double youngs_modulus;
  double poissons_ratio;
  double density;
  /// the coordinates (r, z), or (x, y) in plane strain, or (x, y, z) in 3D, of the point whose
  /// nearest node is reported as u_tip_<b> etc.; empty: the body's centroid ((0, z_c) in
  /// axisymmetry)
  std::vector<double> monitor_point;
  /// the initial velocity (v_r; v_z) [length/time] of x = r, y = z, t; in 3D (v_x; v_y; v_z) of
  /// x, y, z, t
  FunctionExpression initial_velocity;
  /// the dead surface traction [force/reference area], components as the initial velocity's
  FunctionExpression surface_traction;
  /// the dead body force [force/reference volume], components as the initial velocity's: rho g
  /// for gravity g
  FunctionExpression body_force;

  /** Declares the entries of a body of a `dim`-dimensional mesh (2 or 3). */
  static void declare_parameters(ParameterHandler& prm, unsigned int dim);
  /** Reads them; errors (InputError) name `section`. */
  void parse_parameters(ParameterHandler& prm, const std::string& section, unsigned int dim);
};

/** The bodies of a mesh-based problem, body b = material id b - 1. Subsection `Bodies`. */
struct BodiesParameters
{
  std::vector<BodyParameters> bodies;

  /** Declares the subsections Body 1 to Body n_bodies of a `dim`-dimensional mesh (2 or 3). */
  static void declare_parameters(ParameterHandler& prm, unsigned int n_bodies, unsigned int dim);
  void parse_parameters(ParameterHandler& prm, unsigned int dim);
};
} // namespace dyncontact
