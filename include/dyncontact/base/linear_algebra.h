#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

namespace dyncontact
{
/**
 * A vector distributed over the ranks of a communicator like the rows of a matrix: each rank
 * stores the entries of its locally owned rows (deal.II's LinearAlgebra::distributed::Vector;
 * local_element(i) is the i-th owned row in ascending order). The unknowns of
 * SaddlePointSystem (displacement DoFs, then multipliers) travel through the direct solver in
 * this form (issue 27, move 5: owned vectors in place of whole ones on every rank).
 */
using DistributedVector = LinearAlgebra::distributed::Vector<double>;
// Assigning a DistributedVector to one with another partitioner object (an empty one included)
// reinitializes it, which in deal.II 9.4 is collective (Utilities::MPI::min): such copies must be
// reached by every rank.

/**
 * The whole of `vector` (all size() entries) on every rank: each rank's owned range gathered
 * to all (MPI_Gatherv to rank 0, MPI_Bcast). Collective. For the parts of the code that still work
 * on whole vectors.
 */
Vector<double> gather_whole(const DistributedVector& vector);

/**
 * The whole of `vector` on rank 0 of its communicator (MPI_Gatherv), an empty vector on the other
 * ranks. Collective. For what rank 0 alone writes (a checkpoint).
 */
Vector<double> gather_on_root(const DistributedVector& vector);

/**
 * Calls `f(i, j)` for each owned row of `vector` in ascending order: i its global index, j its
 * local one (local_element(j); the first locally_owned_size() local entries are the owned rows of
 * every DistributedVector, ghosts follow them). Vectors over the same owned rows share j.
 */
template <class Function>
void for_each_owned_row(const DistributedVector& vector, const Function& f)
{
  const types::global_dof_index first = vector.get_partitioner()->local_range().first;
  for (unsigned int j = 0; j < vector.locally_owned_size(); ++j)
    f(first + j, j);
}

/** Sets the owned entries of `vector` to those of the whole vector `whole` (same size). */
void copy_owned_entries(const Vector<double>& whole, DistributedVector& vector);
} // namespace dyncontact
