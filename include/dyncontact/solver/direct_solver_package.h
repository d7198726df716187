#pragma once

#include <dyncontact/base/name_table.h>

namespace dyncontact
{
/** The sparse direct solver package of the Newton iterations (Newton/direct solver). */
enum class DirectSolverPackage
{
  klu,     ///< Amesos KLU (Trilinos): any number of ranks, the matrix gathered to one
  umfpack, ///< UMFPACK (SuiteSparse, through deal.II): one rank only
  mumps    ///< MUMPS: symmetric LDL^T, distributed (MumpsSolver)
};

/** The names of Newton/direct solver (defined beside DirectSolver). */
const NameTable<DirectSolverPackage>& direct_solver_names();
} // namespace dyncontact
