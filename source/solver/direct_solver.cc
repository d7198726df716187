#include <dyncontact/solver/direct_solver.h>
#include <dyncontact/solver/epetra_entries.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Teuchos_ParameterList.hpp>

namespace dyncontact
{
const NameTable<DirectSolverPackage>& direct_solver_names()
{
  static const NameTable<DirectSolverPackage> names{{"klu", DirectSolverPackage::klu},
                                                    {"umfpack", DirectSolverPackage::umfpack},
                                                    {"mumps", DirectSolverPackage::mumps}};
  return names;
}

namespace
{
/** Throws SolverFailure if an Amesos call returned an error code. */
void check(const int error_code, const char* package, const char* phase)
{
  if (error_code != 0)
    throw SolverFailure(std::string("the direct solver (") + package + ") failed in the " + phase +
                        " (error code " + std::to_string(error_code) + "; a singular matrix?)");
}
} // namespace

DirectSolver::DirectSolver(const DirectSolverPackage package, const MPI_Comm communicator)
    : package(package), communicator(communicator)
{
  if (package == DirectSolverPackage::umfpack &&
      dealii::Utilities::MPI::n_mpi_processes(communicator) > 1)
    throw InputError("Newton/direct solver = 'umfpack' runs on one MPI rank only: choose 'klu' or "
                     "'mumps' for " +
                     std::to_string(dealii::Utilities::MPI::n_mpi_processes(communicator)) +
                     " ranks.");
}

DirectSolver::~DirectSolver() = default;

void DirectSolver::analyse(const TrilinosWrappers::SparseMatrix& matrix)
{
  Assert(!analysed, ExcMessage("DirectSolver::analyse() is called once"));
  const Epetra_CrsMatrix& epetra = matrix.trilinos_matrix();
  if (package == DirectSolverPackage::umfpack)
  {
    DynamicSparsityPattern pattern(matrix.m(), matrix.n());
    for_each_entry(epetra,
                   [&](const auto row, const auto column, double) { pattern.add(row, column); });
    serial_pattern.copy_from(pattern);
    serial_matrix.reinit(serial_pattern);
  }
  else if (package == DirectSolverPackage::mumps)
  {
    mumps = std::make_unique<MumpsSolver>(communicator);
    mumps->analyse(epetra);
  }
  else
  {
    const char* name   = "Amesos_Klu";
    locally_owned_rows = matrix.locally_owned_range_indices();
    problem            = std::make_unique<Epetra_LinearProblem>();
    problem->SetOperator(const_cast<Epetra_CrsMatrix*>(&epetra));
    Amesos factory;
    amesos.reset(factory.Create(name, *problem));
    if (!amesos)
      throw SolverFailure(std::string("the direct solver ") + name + " is not available");
    Teuchos::ParameterList parameters;
    check(amesos->SetParameters(parameters), name, "setup");
    check(amesos->SymbolicFactorization(), name, "symbolic factorization");
  }
  analysed = true;
}

void DirectSolver::factorize(const TrilinosWrappers::SparseMatrix& matrix)
{
  if (!analysed)
    analyse(matrix);
  if (package == DirectSolverPackage::umfpack)
  {
    for_each_entry(matrix.trilinos_matrix(),
                   [&](const auto row, const auto column, const double value)
                   { serial_matrix.set(row, column, value); });
    try
    {
      umfpack.factorize(serial_matrix);
    }
    catch (const std::exception& error)
    {
      throw SolverFailure(std::string("the direct solver (UMFPACK) failed: ") + error.what());
    }
  }
  else if (package == DirectSolverPackage::mumps)
    mumps->factorize(matrix.trilinos_matrix());
  else
    check(amesos->NumericFactorization(), "Amesos_Klu", "numeric factorization");
  ++factorizations;
}

Vector<double> DirectSolver::solve(const Vector<double>& right_hand_side)
{
  if (package == DirectSolverPackage::umfpack)
  {
    Vector<double> solution = right_hand_side;
    umfpack.solve(solution);
    return solution;
  }
  if (package == DirectSolverPackage::mumps)
    return std::move(mumps->solve({right_hand_side}).front());
  TrilinosWrappers::MPI::Vector distributed_rhs(locally_owned_rows, communicator);
  TrilinosWrappers::MPI::Vector distributed_solution(locally_owned_rows, communicator);
  for (const auto row : locally_owned_rows)
    distributed_rhs[row] = right_hand_side[row];
  distributed_rhs.compress(VectorOperation::insert);
  problem->SetLHS(&distributed_solution.trilinos_vector());
  problem->SetRHS(&distributed_rhs.trilinos_vector());
  check(amesos->Solve(), "Amesos_Klu", "solve");
  // Every rank needs the whole solution: import all entries.
  TrilinosWrappers::MPI::Vector whole(
      locally_owned_rows, complete_index_set(right_hand_side.size()), communicator);
  whole = distributed_solution;
  Vector<double> solution(right_hand_side.size());
  for (types::global_dof_index i = 0; i < solution.size(); ++i)
    solution[i] = whole[i];
  return solution;
}

std::string DirectSolver::last_factorization_statistics() const
{
  return mumps ? mumps->last_factorization_statistics() : "";
}

std::vector<Vector<double>> DirectSolver::solve(const std::vector<Vector<double>>& right_hand_sides)
{
  if (package == DirectSolverPackage::mumps)
    return mumps->solve(right_hand_sides);
  std::vector<Vector<double>> solutions;
  solutions.reserve(right_hand_sides.size());
  for (const auto& right_hand_side : right_hand_sides)
    solutions.push_back(solve(right_hand_side));
  return solutions;
}
} // namespace dyncontact
