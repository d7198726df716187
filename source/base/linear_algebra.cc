#include <dyncontact/base/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <numeric>

namespace dyncontact
{
Vector<double> gather_whole(const DistributedVector& vector)
{
  const MPI_Comm communicator = vector.get_mpi_communicator();
  // Every rank's owned rows (a few intervals each; one if contiguous).
  const std::vector<IndexSet> owned_by_rank =
      Utilities::MPI::all_gather(communicator, vector.locally_owned_elements());
  const bool one_range_each =
      std::all_of(owned_by_rank.begin(),
                  owned_by_rank.end(),
                  [](const IndexSet& rows) { return rows.is_contiguous(); });
  std::vector<int> counts(owned_by_rank.size()), offsets(owned_by_rank.size());
  for (std::size_t rank = 0; rank < owned_by_rank.size(); ++rank)
  {
    counts[rank]  = static_cast<int>(owned_by_rank[rank].n_elements());
    offsets[rank] = counts[rank] > 0 && one_range_each
                        ? static_cast<int>(owned_by_rank[rank].nth_index_in_set(0))
                        : 0;
  }
  if (!one_range_each)
    std::exclusive_scan(counts.begin(), counts.end(), offsets.begin(), 0);
  // One range each: straight into place; else in rank order, then placed row by row.
  Vector<double> whole(vector.size());
  std::vector<double> in_rank_order(one_range_each ? 0 : vector.size());
  double* const receive = one_range_each ? whole.begin() : in_rank_order.data();
  const int rc          = MPI_Allgatherv(vector.begin(),
                                static_cast<int>(vector.locally_owned_size()),
                                MPI_DOUBLE,
                                receive,
                                counts.data(),
                                offsets.data(),
                                MPI_DOUBLE,
                                communicator);
  AssertThrowMPI(rc);
  if (!one_range_each)
  {
    auto value = in_rank_order.begin();
    for (const IndexSet& rows : owned_by_rank)
      for (const auto row : rows)
        whole[row] = *value++;
  }
  return whole;
}

void copy_owned_entries(const Vector<double>& whole, DistributedVector& vector)
{
  AssertDimension(whole.size(), vector.size());
  for (unsigned int i = 0; i < vector.locally_owned_size(); ++i)
    vector.local_element(i) = whole[vector.get_partitioner()->local_to_global(i)];
}
} // namespace dyncontact
