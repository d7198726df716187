#include <dyncontact/solver/epetra_entries.h>
#include <dyncontact/solver/mumps_solver.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <dmumps_c.h>
#include <iomanip>
#include <metis.h>
#include <numeric>
#include <sstream>
#include <string>

// MUMPS's documentation numbers its control and information arrays from 1.
#define ICNTL(i) icntl[(i)-1]
#define INFOG(i) infog[(i)-1]
#define INFO(i) info[(i)-1]
#define RINFOG(i) rinfog[(i)-1]
#define RINFO(i) rinfo[(i)-1]

namespace dyncontact
{
struct MumpsSolver::Instance : DMUMPS_STRUC_C
{
};

namespace
{
constexpr int host = 0;

/**
 * METIS's nested-dissection ordering of the n x n symmetric matrix whose entries on and above the
 * diagonal are (rows[k], columns[k]) (1-based) over all ranks of `communicator`, as MUMPS's
 * PERM_IN (the pivot position of each variable, 1-based) on the host, empty elsewhere.
 * Collective; the host holds the whole graph while it orders.
 */
std::vector<int> nested_dissection_on_host(const std::vector<int>& rows,
                                           const std::vector<int>& columns,
                                           const int n,
                                           const MPI_Comm communicator)
{
  const bool is_host = Utilities::MPI::this_mpi_process(communicator) == host;
  const int n_ranks  = Utilities::MPI::n_mpi_processes(communicator);
  const int local    = static_cast<int>(rows.size());
  std::vector<int> counts(is_host ? n_ranks : 0), offsets(is_host ? n_ranks : 0);
  MPI_Gather(&local, 1, MPI_INT, counts.data(), 1, MPI_INT, host, communicator);
  if (is_host)
    std::exclusive_scan(counts.begin(), counts.end(), offsets.begin(), 0);
  const int total = is_host ? offsets.back() + counts.back() : 0;
  std::vector<int> all_rows(total), all_columns(total);
  for (auto [local_part, whole] : {std::pair{&rows, &all_rows}, std::pair{&columns, &all_columns}})
    MPI_Gatherv(local_part->data(),
                local,
                MPI_INT,
                whole->data(),
                counts.data(),
                offsets.data(),
                MPI_INT,
                host,
                communicator);
  if (!is_host)
    return {};
  // The graph of the matrix in METIS's CSR form: both directions of every off-diagonal entry.
  std::vector<idx_t> offsets_of_vertex(n + 1, 0);
  for (int k = 0; k < total; ++k)
    if (all_rows[k] != all_columns[k])
    {
      ++offsets_of_vertex[all_rows[k]];
      ++offsets_of_vertex[all_columns[k]];
    }
  std::partial_sum(offsets_of_vertex.begin(), offsets_of_vertex.end(), offsets_of_vertex.begin());
  std::vector<idx_t> neighbours(offsets_of_vertex.back());
  std::vector<idx_t> next(offsets_of_vertex.begin(), offsets_of_vertex.end() - 1);
  for (int k = 0; k < total; ++k)
    if (all_rows[k] != all_columns[k])
    {
      neighbours[next[all_rows[k] - 1]++]    = all_columns[k] - 1;
      neighbours[next[all_columns[k] - 1]++] = all_rows[k] - 1;
    }
  all_rows         = {};
  all_columns      = {};
  idx_t n_vertices = n;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  std::vector<idx_t> permutation(n), pivot_position(n);
  if (METIS_NodeND(&n_vertices,
                   offsets_of_vertex.data(),
                   neighbours.data(),
                   nullptr,
                   options,
                   permutation.data(),
                   pivot_position.data()) != METIS_OK)
    throw SolverFailure("METIS failed to order the matrix for the direct solver (MUMPS)");
  std::vector<int> perm_in(n);
  for (int i = 0; i < n; ++i)
    perm_in[i] = pivot_position[i] + 1;
  return perm_in;
}
} // namespace

MumpsSolver::MumpsSolver(const MPI_Comm communicator, const bool symmetric)
    : communicator(communicator), instance(std::make_unique<Instance>()), symmetric(symmetric)
{
  instance->comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
  instance->par          = 1; // the host works too
  // Symmetric, possibly indefinite: LDL^T with 2x2 pivots; else LU.
  instance->sym = symmetric ? 2 : 0;
  run(-1, "initialization");
  // No output from MUMPS: errors are reported as SolverFailure.
  instance->ICNTL(1)  = -1;
  instance->ICNTL(2)  = -1;
  instance->ICNTL(3)  = -1;
  instance->ICNTL(4)  = 0;
  instance->ICNTL(5)  = 0;  // assembled matrix
  instance->ICNTL(18) = 3;  // distributed entries (each rank its rows)
  instance->ICNTL(28) = 1;  // sequential analysis, with:
  instance->ICNTL(7)  = 1;  // the pivot order given: METIS's nested dissection (analyse())
  instance->ICNTL(20) = 10; // dense right-hand sides, distributed: each rank its matrix rows
  instance->ICNTL(21) = 1;  // distributed solution: each rank the rows of its factors
  // The root front without ScaLAPACK (a type-2 front, rows split over the ranks): ScaLAPACK has
  // no LDL^T and factorizes it as LU (6 % more flops at 1.09M DoFs), and its block-cyclic
  // triangular solves were the slowest part of a 2-rank step (doc/performance.md, "Contact
  // geometry on the border").
  instance->ICNTL(13) = 1;
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

void MumpsSolver::analyse(const Epetra_CrsMatrix& matrix)
{
  Assert(!analysed, ExcMessage("MumpsSolver::analyse() is called once"));
  for_each_entry(matrix,
                 [&](const long long row, const long long column, double)
                 {
                   if (column < row && symmetric)
                     return;
                   rows.push_back(static_cast<int>(row + 1));
                   columns.push_back(static_cast<int>(column + 1));
                 });
  instance->n = static_cast<MUMPS_INT>(matrix.NumGlobalRows64());
  for (int i = 0; i < matrix.RowMap().NumMyElements(); ++i)
    owned_rows.push_back(static_cast<MUMPS_INT>(matrix.RowMap().GID64(i) + 1));
  // The first row of each run of consecutive owned rows, with its rank, over all ranks.
  std::vector<int> run_starts;
  for (std::size_t i = 0; i < owned_rows.size(); ++i)
    if (i == 0 || owned_rows[i] != owned_rows[i - 1] + 1)
      run_starts.push_back(owned_rows[i]);
  const auto starts_by_rank = Utilities::MPI::all_gather(communicator, run_starts);
  for (std::size_t rank = 0; rank < starts_by_rank.size(); ++rank)
    for (const int start : starts_by_rank[rank])
      owner_runs.emplace_back(start, static_cast<int>(rank));
  std::sort(owner_runs.begin(), owner_runs.end());
  instance->nnz_loc = static_cast<MUMPS_INT8>(rows.size());
  instance->irn_loc = rows.data();
  instance->jcn_loc = columns.data();
  // Debian's MUMPS has no METIS or SCOTCH (ICNTL(7) = 3 or 5 silently fall back to AMF, as
  // INFOG(7) = 2 shows); deal.II's METIS orders instead. Nested dissection suits 2D and 3D
  // meshes: the factors and flops grow as n log n and n^1.5 in 2D.
  // The order from the entries on and above the diagonal (the pattern is structurally symmetric).
  std::vector<int> upper_rows, upper_columns;
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (columns[k] >= rows[k])
    {
      upper_rows.push_back(rows[k]);
      upper_columns.push_back(columns[k]);
    }
  const std::vector<int> perm_in =
      nested_dissection_on_host(upper_rows, upper_columns, instance->n, communicator);
  instance->perm_in = const_cast<int*>(perm_in.data());
  // Distributed input (ICNTL(18) = 3) with a given order: the analysis reads no values.
  instance->a_loc = nullptr;
  run(1, "analysis");
  instance->perm_in = nullptr; // read by the analysis only
  analysed          = true;
}

void MumpsSolver::factorize(const Epetra_CrsMatrix& matrix)
{
  if (!analysed)
    analyse(matrix);
  values.clear();
  for_each_entry(matrix,
                 [&](const long long row, const long long column, const double value)
                 {
                   if (column >= row || !symmetric)
                     values.push_back(value);
                 });
  AssertDimension(values.size(), rows.size());
  instance->a_loc = values.data();
  for (unsigned int attempt = 0;; ++attempt)
    try
    {
      run(2, "numeric factorization");
      busiest_rank_flops = Utilities::MPI::max(instance->RINFO(3), communicator);
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

std::string MumpsSolver::last_factorization_statistics() const
{
  if (busiest_rank_flops == 0)
    return "";
  const double flops = instance->RINFOG(3);
  std::ostringstream line;
  line << std::setprecision(3) << "MUMPS, last factorization: " << flops << " flops, " << std::fixed
       << std::setprecision(1) << 100 * busiest_rank_flops / flops
       << " % of them on the busiest of " << Utilities::MPI::n_mpi_processes(communicator)
       << " rank(s); " << std::defaultfloat << std::setprecision(3)
       << static_cast<double>(instance->INFOG(29)) << " entries in the factors; "
       << instance->INFOG(21) << " MB used on the largest rank, " << instance->INFOG(22)
       << " MB on all";
  return line.str();
}

std::vector<DistributedVector>
MumpsSolver::solve(const std::vector<DistributedVector>& right_hand_sides)
{
  const auto k = right_hand_sides.size();
  std::vector<DistributedVector> solutions(k);
  if (k == 0)
    return solutions;
  // Distributed right-hand sides (ICNTL(20) = 10): this rank's rows of each column.
  const auto n_rows = owned_rows.size();
  std::vector<double> local_rhs(std::max<std::size_t>(n_rows, 1) * k);
  for (std::size_t j = 0; j < k; ++j)
  {
    AssertThrow(right_hand_sides[j].size() == static_cast<std::size_t>(instance->n) &&
                    right_hand_sides[j].locally_owned_size() == n_rows &&
                    right_hand_sides[j].get_partitioner()->local_range() ==
                        right_hand_sides.front().get_partitioner()->local_range(),
                ExcMessage("MumpsSolver::solve: each right-hand side must be distributed like "
                           "the matrix's rows"));
    std::copy_n(right_hand_sides[j].begin(), n_rows, &local_rhs[j * n_rows]);
    solutions[j].reinit(right_hand_sides[j]);
  }
  instance->nrhs     = static_cast<MUMPS_INT>(k);
  instance->nloc_rhs = static_cast<MUMPS_INT>(n_rows);
  instance->lrhs_loc = static_cast<MUMPS_INT>(std::max<std::size_t>(n_rows, 1));
  instance->rhs_loc  = local_rhs.data();
  instance->irhs_loc = owned_rows.data();
  // Distributed solution (ICNTL(21) = 1): the rows MUMPS's factors put on this rank.
  const int n_solution_rows = instance->INFO(23);
  std::vector<double> local_solution(std::max(n_solution_rows, 1) * k);
  std::vector<MUMPS_INT> solution_rows(std::max(n_solution_rows, 1));
  instance->lsol_loc = std::max(n_solution_rows, 1);
  instance->sol_loc  = local_solution.data();
  instance->isol_loc = solution_rows.data();
  run(3, "solve");
  instance->rhs_loc  = nullptr; // the buffers end with this call
  instance->sol_loc  = nullptr;
  instance->isol_loc = nullptr;
  send_to_owners(solution_rows, local_solution, n_solution_rows, solutions);
  return solutions;
}

void MumpsSolver::send_to_owners(const std::vector<int>& solution_rows,
                                 const std::vector<double>& local_solution,
                                 const int n_solution_rows,
                                 std::vector<DistributedVector>& solutions) const
{
  const int k       = static_cast<int>(solutions.size());
  const int n_ranks = static_cast<int>(Utilities::MPI::n_mpi_processes(communicator));
  // The rank of each row: the run of owned rows that holds it (the runs partition 1..n).
  std::vector<int> destination(n_solution_rows), send_counts(n_ranks, 0);
  for (int p = 0; p < n_solution_rows; ++p)
  {
    const auto run = std::upper_bound(owner_runs.begin(),
                                      owner_runs.end(),
                                      std::pair{solution_rows[p], n_ranks}) -
                     1;
    destination[p] = run->second;
    ++send_counts[destination[p]];
  }
  std::vector<int> receive_counts(n_ranks);
  int rc =
      MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, communicator);
  AssertThrowMPI(rc);
  std::vector<int> send_offsets(n_ranks), receive_offsets(n_ranks);
  std::exclusive_scan(send_counts.begin(), send_counts.end(), send_offsets.begin(), 0);
  std::exclusive_scan(receive_counts.begin(), receive_counts.end(), receive_offsets.begin(), 0);
  // Rows, and the k values of each row (row by row), packed by destination.
  std::vector<int> send_rows(n_solution_rows), next = send_offsets;
  std::vector<double> send_values(static_cast<std::size_t>(n_solution_rows) * k);
  for (int p = 0; p < n_solution_rows; ++p)
  {
    const int slot  = next[destination[p]]++;
    send_rows[slot] = solution_rows[p];
    for (int j = 0; j < k; ++j)
      send_values[static_cast<std::size_t>(slot) * k + j] =
          local_solution[static_cast<std::size_t>(j) * instance->lsol_loc + p];
  }
  const int n_received = receive_offsets.back() + receive_counts.back();
  std::vector<int> received_rows(n_received);
  std::vector<double> received_values(static_cast<std::size_t>(n_received) * k);
  rc = MPI_Alltoallv(send_rows.data(),
                     send_counts.data(),
                     send_offsets.data(),
                     MPI_INT,
                     received_rows.data(),
                     receive_counts.data(),
                     receive_offsets.data(),
                     MPI_INT,
                     communicator);
  AssertThrowMPI(rc);
  for (auto* counts : {&send_counts, &send_offsets, &receive_counts, &receive_offsets})
    for (int& count : *counts)
      count *= k;
  rc = MPI_Alltoallv(send_values.data(),
                     send_counts.data(),
                     send_offsets.data(),
                     MPI_DOUBLE,
                     received_values.data(),
                     receive_counts.data(),
                     receive_offsets.data(),
                     MPI_DOUBLE,
                     communicator);
  AssertThrowMPI(rc);
  const Utilities::MPI::Partitioner& rows = *solutions.front().get_partitioner();
  for (int p = 0; p < n_received; ++p)
  {
    const unsigned int local = rows.global_to_local(received_rows[p] - 1);
    for (int j = 0; j < k; ++j)
      solutions[j].local_element(local) = received_values[static_cast<std::size_t>(p) * k + j];
  }
}
} // namespace dyncontact
