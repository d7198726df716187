#include <dyncontact/base/dimensions.h>
#include <dyncontact/contact/contact_geometry_set.h>

#include <algorithm>
#include <iterator>

namespace dyncontact
{
template <int dim>
ContactGeometrySet<dim>::ContactGeometrySet(
    std::vector<std::unique_ptr<ContactGeometry<dim>>> members)
    : members(std::move(members))
{
  Assert(!this->members.empty(), ExcMessage("a contact geometry set needs a member"));
  for (const auto& member : this->members)
  {
    first_pair.push_back(all_pairs.size());
    all_pairs.insert(all_pairs.end(), member->pairs().begin(), member->pairs().end());
  }
  first_pair.push_back(all_pairs.size());
}

template <int dim>
template <typename Update>
void ContactGeometrySet<dim>::update_members(std::vector<ContactPair<dim>>& pairs,
                                             const Update& update) const
{
  AssertDimension(pairs.size(), all_pairs.size());
  for (unsigned int m = 0; m < members.size(); ++m)
  {
    std::vector<ContactPair<dim>> own(pairs.begin() + first_pair[m],
                                      pairs.begin() + first_pair[m + 1]);
    update(*members[m], own);
    std::copy(own.begin(), own.end(), pairs.begin() + first_pair[m]);
  }
}

template <int dim>
void ContactGeometrySet<dim>::update_pairs(const BorderDisplacement<dim>& displacement,
                                           std::vector<ContactPair<dim>>& pairs) const
{
  update_members(pairs,
                 [&](const ContactGeometry<dim>& member, std::vector<ContactPair<dim>>& own)
                 { member.update_pairs(displacement, own); });
}

template <int dim>
void ContactGeometrySet<dim>::update_master_points(const BorderDisplacement<dim>& displacement,
                                                   std::vector<ContactPair<dim>>& pairs,
                                                   const bool move_normals) const
{
  update_members(pairs,
                 [&](const ContactGeometry<dim>& member, std::vector<ContactPair<dim>>& own)
                 { member.update_master_points(displacement, own, move_normals); });
}

template <int dim>
bool ContactGeometrySet<dim>::moves_normals() const
{
  return std::any_of(
      members.begin(), members.end(), [](const auto& member) { return member->moves_normals(); });
}

template <int dim>
std::vector<Node<dim>> ContactGeometrySet<dim>::coupled_nodes(const unsigned int k) const
{
  const unsigned int m =
      std::distance(first_pair.begin(), std::upper_bound(first_pair.begin(), first_pair.end(), k)) -
      1;
  return members[m]->coupled_nodes(k - first_pair[m]);
}

template <int dim>
std::vector<Node<dim>> ContactGeometrySet<dim>::surface_nodes() const
{
  std::vector<Node<dim>> nodes;
  for (const auto& member : members)
  {
    const std::vector<Node<dim>> own = member->surface_nodes();
    nodes.insert(nodes.end(), own.begin(), own.end());
  }
  return nodes;
}

template <int dim>
std::vector<double>
ContactGeometrySet<dim>::contact_pressures(const BorderDisplacement<dim>& displacement,
                                           const std::vector<double>& multipliers) const
{
  AssertDimension(multipliers.size(), all_pairs.size());
  std::vector<double> pressures;
  for (unsigned int m = 0; m < members.size(); ++m)
  {
    const std::vector<double> own =
        members[m]->contact_pressures(displacement,
                                      std::vector<double>(multipliers.begin() + first_pair[m],
                                                          multipliers.begin() + first_pair[m + 1]));
    pressures.insert(pressures.end(), own.begin(), own.end());
  }
  return pressures;
}

DYNCONTACT_INSTANTIATE_CLASS(ContactGeometrySet)
} // namespace dyncontact
