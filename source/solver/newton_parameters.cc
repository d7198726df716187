#include <dyncontact/base/parameter_entries.h>
#include <dyncontact/solver/newton_parameters.h>

namespace dyncontact
{
const NameTable<NewtonMethod>& newton_method_names()
{
  static const NameTable<NewtonMethod> names{{"full", NewtonMethod::full},
                                             {"modified", NewtonMethod::modified}};
  return names;
}

void NewtonParameters::declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Newton");
  prm.declare_entry("maximum iterations",
                    "25",
                    Patterns::Integer(2, 1000),
                    "Maximum number of linear solves per time step, including the re-solves "
                    "after active-set changes [-], 2..1000 (an active-set change needs two). "
                    "Exceeding it stops the run with a "
                    "message; the output written so far is kept.");
  prm.declare_entry(
      "residual tolerance",
      "1e-10",
      Patterns::Double(),
      "Newton converges when the residual norm is below this fraction of the "
      "reference force |Q(u)| + |W| + |G^T lambda| (elastic, external and contact "
      "forces; not the inertia) plus a round-off floor, every active pair is closed to "
      "this fraction of the smallest cell diameter and compressive, every inactive "
      "pair open to it, and, with active pairs, after at least one linear solve "
      "[-], 1e-16..1e-6. Looser values are rejected: they leave residuals at the "
      "contact nodes that break the momentum balance (1e-6 relative) of a step.");
  prm.declare_entry(
      "direct solver",
      "auto",
      Patterns::Selection("auto|" + direct_solver_names().selection()),
      "Sparse direct solver of the Newton iterations; a factorization is reused while the "
      "matrix does not change. klu: Amesos KLU, any number of MPI ranks (the matrix is gathered "
      "to one), results identical run to run. umfpack: UMFPACK, one rank only. mumps: MUMPS's "
      "symmetric LDL^T (half the flops and memory of LU), distributed over the ranks, the "
      "fastest on large meshes; on several ranks its results may differ in the last digits from "
      "run to run. auto: klu for bars and 2D meshes, mumps for 3D meshes (measured on the "
      "coarse quarter sphere of prm/sphere_on_rigid_plane_3d.prm, 11,637 DoFs: 16 s with mumps, "
      "33 s with umfpack, 227 s with klu, whose factorizations of 27-node hexahedra fill in); the "
      "run's parameters.prm names the one used.");
  prm.declare_entry(
      "method",
      "full",
      Patterns::Selection(newton_method_names().selection()),
      "full: a fresh tangent (assembly and factorization) for every Newton update. modified: the "
      "tangent of a step's first update also serves its later updates while the active set stays "
      "the same and each update reduces the residual at least 10 times, else a fresh one is "
      "taken, and when pairs enter or leave the active set (at most 4 at a time) the factors are "
      "updated (low-rank) instead of recomputed; the same convergence test, fewer "
      "factorizations (the converged steps differ within the Newton tolerance).");
  prm.leave_subsection();
}

void NewtonParameters::parse_parameters(ParameterHandler& prm, const unsigned int dim)
{
  prm.enter_subsection("Newton");
  max_iterations     = prm.get_integer("maximum iterations");
  residual_tolerance = get_in_range(prm, "residual tolerance", "Newton", 1e-16, 1e-6);
  if (prm.get("direct solver") == "auto")
    prm.set("direct solver",
            direct_solver_names().name(dim == 3 ? DirectSolverPackage::mumps
                                                : DirectSolverPackage::klu));
  direct_solver = direct_solver_names().parse(prm.get("direct solver"), "Newton/direct solver");
  method        = newton_method_names().parse(prm.get("method"), "Newton/method");
  prm.leave_subsection();
}
} // namespace dyncontact
