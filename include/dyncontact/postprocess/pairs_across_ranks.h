#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_constraints.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

namespace dyncontact
{
/**
 * The number of active contact pairs of `contact` that couple two ranks' data: the slave node's
 * DoFs are owned by one rank and every master node's (the whole master face's, in node-to-segment
 * and node-to-surface contact) by others. `owned_dofs` is this rank's locally owned volume DoFs.
 * Pairs against a rigid wall (no master node) are not counted. Each pair is counted by the rank
 * owning its slave node, and the counts are summed over `communicator` (collective). Zero on one
 * rank. What shows that a run on several ranks had pairs whose faces another rank holds (the
 * contact border gathers them to every rank).
 */
template <int dim>
unsigned int pairs_across_ranks(const ContactConstraints<dim>& contact,
                                const IndexSet& owned_dofs,
                                MPI_Comm communicator);
} // namespace dyncontact
