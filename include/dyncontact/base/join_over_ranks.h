#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/mpi.h>

#include <boost/serialization/vector.hpp>
#include <vector>

namespace dyncontact
{
/**
 * Every rank's `local` entries joined in the order of the ranks, on every rank of `communicator`
 * (Utilities::MPI::all_gather; T must be serializable by boost). Collective. For the small sets
 * every rank needs whole: contact surfaces, fixed DoFs, matrix changes.
 */
template <class T>
std::vector<T> join_over_ranks(const MPI_Comm communicator, const std::vector<T>& local)
{
  std::vector<T> joined;
  for (const std::vector<T>& part : Utilities::MPI::all_gather(communicator, local))
    joined.insert(joined.end(), part.begin(), part.end());
  return joined;
}

/** The same on rank 0 of `communicator` only (Utilities::MPI::gather); empty elsewhere. */
template <class T>
std::vector<T> join_on_root(const MPI_Comm communicator, const std::vector<T>& local)
{
  std::vector<T> joined;
  for (const std::vector<T>& part : Utilities::MPI::gather(communicator, local))
    joined.insert(joined.end(), part.begin(), part.end());
  return joined;
}
} // namespace dyncontact
