#include <dyncontact/base/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <numeric>

namespace dyncontact
{
Vector<double> gather_whole(const DistributedVector& vector)
{
  const MPI_Comm communicator = vector.get_mpi_communicator();
  const IndexSet& owned       = vector.locally_owned_elements();
  // Every rank's owned rows (a few intervals each) and their values, in rank order.
  const std::vector<IndexSet> owned_by_rank = Utilities::MPI::all_gather(communicator, owned);
  std::vector<int> counts(owned_by_rank.size()), offsets(owned_by_rank.size());
  for (std::size_t rank = 0; rank < owned_by_rank.size(); ++rank)
    counts[rank] = static_cast<int>(owned_by_rank[rank].n_elements());
  std::exclusive_scan(counts.begin(), counts.end(), offsets.begin(), 0);
  std::vector<double> values(vector.size());
  const int rc = MPI_Allgatherv(vector.begin(),
                                static_cast<int>(vector.locally_owned_size()),
                                MPI_DOUBLE,
                                values.data(),
                                counts.data(),
                                offsets.data(),
                                MPI_DOUBLE,
                                communicator);
  AssertThrowMPI(rc);
  Vector<double> whole(vector.size());
  auto value = values.begin();
  for (const IndexSet& rows : owned_by_rank)
    for (const auto row : rows)
      whole[row] = *value++;
  return whole;
}

void copy_owned_entries(const Vector<double>& whole, DistributedVector& vector)
{
  AssertDimension(whole.size(), vector.size());
  for (unsigned int i = 0; i < vector.locally_owned_size(); ++i)
    vector.local_element(i) = whole[vector.get_partitioner()->local_to_global(i)];
}
} // namespace dyncontact
