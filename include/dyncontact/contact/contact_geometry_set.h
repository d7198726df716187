#pragma once

#include <dyncontact/contact/contact_geometry.h>

#include <memory>
#include <vector>

namespace dyncontact
{
/**
 * Several contact geometries (one per declared contact pair of surfaces, Contact/Pair k) seen as
 * one: its pairs are theirs, concatenated in the order given, and every query is passed to the
 * member that owns the pair. The constraint set then enforces all of them in one saddle-point
 * system, and the paper's modified Newmark corrects all their active pairs jointly.
 */
template <int dim>
class ContactGeometrySet : public ContactGeometry<dim>
{
public:
  /** Takes the members (at least one, none null). */
  explicit ContactGeometrySet(std::vector<std::unique_ptr<ContactGeometry<dim>>> members);

  const std::vector<ContactPair<dim>>& pairs() const override { return all_pairs; }
  void update_pairs(const BorderDisplacement<dim>& displacement,
                    std::vector<ContactPair<dim>>& pairs) const override;
  void update_master_points(const BorderDisplacement<dim>& displacement,
                            std::vector<ContactPair<dim>>& pairs,
                            bool move_normals) const override;
  /** Whether any member's does. */
  bool moves_normals() const override;
  std::vector<Node<dim>> coupled_nodes(unsigned int k) const override;
  std::vector<Node<dim>> surface_nodes() const override;
  std::vector<double> contact_pressures(const BorderDisplacement<dim>& displacement,
                                        const std::vector<double>& multipliers) const override;

private:
  std::vector<std::unique_ptr<ContactGeometry<dim>>> members;
  std::vector<ContactPair<dim>> all_pairs;
  /** first_pair[m]: index in all_pairs of member m's first pair; last entry: all_pairs.size(). */
  std::vector<unsigned int> first_pair;

  /** Calls update(member, own pairs) for every member with its part of `pairs`, written back. */
  template <typename Update>
  void update_members(std::vector<ContactPair<dim>>& pairs, const Update& update) const;
};
} // namespace dyncontact
