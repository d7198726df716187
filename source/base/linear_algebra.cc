#include <dyncontact/base/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <boost/serialization/utility.hpp>
#include <tuple>
#include <utility>

namespace dyncontact
{
Vector<double> gather_on_root(const DistributedVector& vector)
{
  const MPI_Comm communicator = vector.get_mpi_communicator();
  // A DistributedVector's owned rows are one range (Utilities::MPI::Partitioner): each rank's
  // entries go straight into place.
  const std::pair<int, int> range{static_cast<int>(vector.get_partitioner()->local_range().first),
                                  static_cast<int>(vector.locally_owned_size())};
  const std::vector<std::pair<int, int>> ranges = Utilities::MPI::all_gather(communicator, range);
  std::vector<int> offsets(ranges.size()), counts(ranges.size());
  for (std::size_t rank = 0; rank < ranges.size(); ++rank)
    std::tie(offsets[rank], counts[rank]) = ranges[rank];
  Vector<double> whole(Utilities::MPI::this_mpi_process(communicator) == 0 ? vector.size() : 0);
  const int rc = MPI_Gatherv(vector.begin(),
                             range.second,
                             MPI_DOUBLE,
                             whole.begin(),
                             counts.data(),
                             offsets.data(),
                             MPI_DOUBLE,
                             0,
                             communicator);
  AssertThrowMPI(rc);
  return whole;
}

Vector<double> gather_whole(const DistributedVector& vector)
{
  Vector<double> whole = gather_on_root(vector);
  if (whole.size() != vector.size()) // not rank 0: room for the broadcast
    whole.reinit(vector.size(), /*omit_zeroing_entries=*/true);
  const int rc = MPI_Bcast(
      whole.begin(), static_cast<int>(whole.size()), MPI_DOUBLE, 0, vector.get_mpi_communicator());
  AssertThrowMPI(rc);
  return whole;
}

void copy_owned_entries(const Vector<double>& whole, DistributedVector& vector)
{
  AssertDimension(whole.size(), vector.size());
  for (unsigned int i = 0; i < vector.locally_owned_size(); ++i)
    vector.local_element(i) = whole[vector.get_partitioner()->local_to_global(i)];
}
} // namespace dyncontact
