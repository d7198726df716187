#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/name_table.h>
#include <dyncontact/solver/direct_solver_package.h>

#include <deal.II/base/parameter_handler.h>

namespace dyncontact
{
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
  /**
   * Reads the entries; `direct solver = auto` becomes klu for `dim` = 1, 2 and mumps for 3, and
   * the entry is set to the solver used (so that the run's record names it).
   */
  void parse_parameters(ParameterHandler& prm, unsigned int dim);
};
} // namespace dyncontact
