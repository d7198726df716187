#include <dyncontact/solver/mumps_solver.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>
#include <string>

// MUMPS's documentation numbers its control and information arrays from 1.
#define ICNTL(i) icntl[(i)-1]
#define INFOG(i) infog[(i)-1]

namespace dyncontact
{
struct MumpsSolver::Instance : DMUMPS_STRUC_C
{
};

namespace
{
constexpr int host = 0;
}

MumpsSolver::MumpsSolver(const MPI_Comm communicator)
    : communicator(communicator), instance(std::make_unique<Instance>())
{
  instance->comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
  instance->par          = 1; // the host works too
  instance->sym          = 2; // symmetric, possibly indefinite: LDL^T with 2x2 pivots
  run(-1, "initialization");
  // No output from MUMPS: errors are reported as SolverFailure.
  instance->ICNTL(1)  = -1;
  instance->ICNTL(2)  = -1;
  instance->ICNTL(3)  = -1;
  instance->ICNTL(4)  = 0;
  instance->ICNTL(5)  = 0; // assembled matrix
  instance->ICNTL(18) = 3; // distributed entries (each rank its rows)
  instance->ICNTL(28) = 1; // sequential analysis, with:
  // METIS: 13 % (56k DoFs) and 18 % (223k) less factorization time than MUMPS's automatic
  // choice, measured back to back with Amesos_Mumps (SCOTCH as METIS, PORD 24 % more).
  instance->ICNTL(7)  = 5;
  instance->ICNTL(20) = 0; // centralized dense right-hand side, on the host
  instance->ICNTL(21) = 0; // centralized solution, on the host
}

MumpsSolver::~MumpsSolver()
{
  instance->job = -2;
  dmumps_c(instance.get());
}

void MumpsSolver::run(const int job, const char* phase)
{
  instance->job = job;
  dmumps_c(instance.get());
  if (instance->INFOG(1) < 0)
    throw SolverFailure(std::string("the direct solver (MUMPS) failed in the ") + phase +
                        " (INFOG(1) = " + std::to_string(instance->INFOG(1)) +
                        ", INFOG(2) = " + std::to_string(instance->INFOG(2)) +
                        (instance->INFOG(1) == -10 ? "; a singular matrix" : "") + ")");
}

void MumpsSolver::factorize(const Epetra_CrsMatrix& matrix)
{
  const bool first = !analysed;
  values.clear();
  for (int row = 0; row < matrix.NumMyRows(); ++row)
  {
    int n_entries;
    double* row_values;
    int* row_columns;
    matrix.ExtractMyRowView(row, n_entries, row_values, row_columns);
    const long long global_row = matrix.GRID64(row);
    for (int k = 0; k < n_entries; ++k)
    {
      const long long global_column = matrix.GCID64(row_columns[k]);
      if (global_column < global_row)
        continue;
      if (first)
      {
        rows.push_back(static_cast<int>(global_row + 1));
        columns.push_back(static_cast<int>(global_column + 1));
      }
      values.push_back(row_values[k]);
    }
  }
  AssertDimension(values.size(), rows.size());
  instance->a_loc = values.data();
  if (first)
  {
    instance->n       = static_cast<MUMPS_INT>(matrix.NumGlobalRows64());
    instance->nnz_loc = static_cast<MUMPS_INT8>(rows.size());
    instance->irn_loc = rows.data();
    instance->jcn_loc = columns.data();
    run(1, "analysis");
    analysed = true;
  }
  for (unsigned int attempt = 0;; ++attempt)
    try
    {
      run(2, "numeric factorization");
      return;
    }
    catch (const SolverFailure&)
    {
      // Pivoting needed more workspace than the analysis estimated: relax it and retry.
      const bool workspace_too_small = instance->INFOG(1) == -8 || instance->INFOG(1) == -9;
      if (!workspace_too_small || attempt == 3)
        throw;
      instance->ICNTL(14) = 2 * std::max(instance->ICNTL(14), 20);
    }
}

Vector<double> MumpsSolver::solve(const Vector<double>& right_hand_side)
{
  AssertDimension(right_hand_side.size(), static_cast<std::size_t>(instance->n));
  const bool is_host = Utilities::MPI::this_mpi_process(communicator) == host;
  if (is_host)
  {
    host_vector.assign(right_hand_side.begin(), right_hand_side.end());
    instance->rhs  = host_vector.data();
    instance->nrhs = 1;
    instance->lrhs = instance->n;
  }
  run(3, "solve");
  Vector<double> solution(right_hand_side.size());
  if (is_host)
    std::copy(host_vector.begin(), host_vector.end(), solution.begin());
  const int n = static_cast<int>(solution.size());
  MPI_Bcast(solution.data(), n, MPI_DOUBLE, host, communicator);
  return solution;
}
} // namespace dyncontact
