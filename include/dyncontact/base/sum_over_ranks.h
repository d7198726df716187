#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace dyncontact
{
/**
 * Adds `values` (the same length on every rank) over all ranks of `communicator`, in place: each
 * rank holds the whole sum afterwards. Collective. deal.II allows the input and output views to be
 * the same memory (MPI_IN_PLACE).
 */
inline void sum_over_ranks(Vector<double>& values, const MPI_Comm communicator)
{
  Utilities::MPI::sum(ArrayView<const double>(values.begin(), values.size()),
                      communicator,
                      ArrayView<double>(values.begin(), values.size()));
}

/** The same for a std::vector. */
inline void sum_over_ranks(std::vector<double>& values, const MPI_Comm communicator)
{
  Utilities::MPI::sum(ArrayView<const double>(values.data(), values.size()),
                      communicator,
                      ArrayView<double>(values.data(), values.size()));
}
} // namespace dyncontact
