#include <dyncontact/base/dimensions.h>
#include <dyncontact/postprocess/pairs_across_ranks.h>

#include <algorithm>

namespace dyncontact
{
template <int dim>
unsigned int pairs_across_ranks(const ContactConstraints<dim>& contact,
                                const IndexSet& owned_dofs,
                                const MPI_Comm communicator)
{
  // The pairs' nodes carry border DoFs; the border maps them back to the volume's.
  const auto owned = [&](const Node<dim>& node)
  { return owned_dofs.is_element(contact.border().volume_dof(node.dofs[0])); };
  unsigned int count = 0;
  for (unsigned int k = 0; k < contact.n_pairs(); ++k)
  {
    const ContactPair<dim>& pair = contact.candidate_pairs()[k];
    if (contact.is_active(k) && !pair.against_wall() && owned(pair.slave) &&
        std::none_of(pair.masters.begin(),
                     pair.masters.end(),
                     [&](const MasterNode<dim>& master) { return owned(master.node); }))
      ++count;
  }
  return Utilities::MPI::sum(count, communicator);
}

#define DYNCONTACT_INSTANTIATE(dim)                                                                \
  template unsigned int pairs_across_ranks<dim>(                                                   \
      const ContactConstraints<dim>&, const IndexSet&, MPI_Comm);
DYNCONTACT_FOR_EACH_DIMENSION(DYNCONTACT_INSTANTIATE)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
