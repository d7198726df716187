#include <dyncontact/solver/direct_solver.h>
#include <dyncontact/solver/epetra_entries.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>
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

DirectSolver::DirectSolver(const DirectSolverPackage package,
                           const MPI_Comm communicator,
                           const bool symmetric)
    : package(package), communicator(communicator), symmetric(symmetric)
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
    mumps = std::make_unique<MumpsSolver>(communicator, symmetric);
    mumps->analyse(epetra);
  }
  else
  {
    const char* name = "Amesos_Klu";
    problem          = std::make_unique<Epetra_LinearProblem>();
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

DistributedVector DirectSolver::solve(const DistributedVector& right_hand_side)
{
  return std::move(solve(std::vector<DistributedVector>{right_hand_side}).front());
}

std::string DirectSolver::last_factorization_statistics() const
{
  return mumps ? mumps->last_factorization_statistics() : "";
}

std::vector<DistributedVector>
DirectSolver::solve(const std::vector<DistributedVector>& right_hand_sides)
{
  if (package == DirectSolverPackage::mumps)
    return mumps->solve(right_hand_sides);
  std::vector<DistributedVector> solutions(right_hand_sides.size());
  for (std::size_t j = 0; j < right_hand_sides.size(); ++j)
  {
    const DistributedVector& right_hand_side = right_hand_sides[j];
    DistributedVector& solution              = solutions[j];
    solution.reinit(right_hand_side, /*omit_zeroing_entries=*/true);
    if (package == DirectSolverPackage::umfpack) // one rank: the vectors are whole
    {
      Vector<double> serial(right_hand_side.begin(), right_hand_side.end());
      umfpack.solve(serial);
      std::copy(serial.begin(), serial.end(), solution.begin());
      continue;
    }
    // Amesos reads and writes Epetra views of the vectors' own rows (the matrix's row map).
    const Epetra_Map& rows = problem->GetMatrix()->RowMatrixRowMap();
    AssertThrow(right_hand_side.locally_owned_size() ==
                    static_cast<unsigned int>(rows.NumMyElements()),
                ExcMessage("DirectSolver::solve: the right-hand side must be distributed like "
                           "the matrix's rows"));
    Epetra_Vector rhs(View, rows, const_cast<double*>(right_hand_side.begin()));
    Epetra_Vector lhs(View, rows, solution.begin());
    problem->SetRHS(&rhs);
    problem->SetLHS(&lhs);
    check(amesos->Solve(), "Amesos_Klu", "solve");
  }
  return solutions;
}
} // namespace dyncontact
