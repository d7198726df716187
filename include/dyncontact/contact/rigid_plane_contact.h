#pragma once

#include <dyncontact/contact/contact_geometry.h>
#include <dyncontact/contact/contact_surface.h>

namespace dyncontact
{
/**
 * Contact of one body's surface with a rigid, fixed plane (a line in 2D): every surface node whose
 * outward normal faces the plane (n_node . n_plane < 0 at t = 0) is a slave node of a pair against
 * the wall, gap g = n . (p - x) with n = -n_plane the normal from the body toward the plane and p
 * a point of the plane. The plane never moves, so the pairs never change (update_pairs() leaves
 * them). Penalty stiffness of a pair = the stiffness per unit area times the node's lumped area.
 * In the paper's terms the plane is the master surface at rest: the modified Newmark sets the
 * slave node's normal velocity and acceleration to zero while it is in contact.
 */
template <int dim>
class RigidPlaneContact : public ContactGeometry<dim>
{
public:
  /**
   * `point` [length] on the plane and `normal` (unit) pointing out of the plane toward the body.
   * Throws InputError if no node of `surface` faces the plane, or (overlap_at_start()) if a node
   * lies behind the plane by more than `touching_tolerance` [length] at t = 0.
   */
  RigidPlaneContact(ContactSurface<dim> surface,
                    const Point<dim>& point,
                    const Tensor<1, dim>& normal,
                    double penalty_stiffness_per_area,
                    double touching_tolerance);

  const std::vector<ContactPair<dim>>& pairs() const override { return candidate_pairs; }
  /** Nothing moves: the plane is fixed and its normal is the pairs' normal. */
  void update_pairs(const BorderDisplacement<dim>&, std::vector<ContactPair<dim>>&) const override
  {
  }
  std::vector<Node<dim>> coupled_nodes(unsigned int k) const override;
  /** The surface's nodes. */
  std::vector<Node<dim>> surface_nodes() const override { return surface.nodes(); }
  std::vector<double> contact_pressures(const BorderDisplacement<dim>& displacement,
                                        const std::vector<double>& multipliers) const override;

private:
  ContactSurface<dim> surface;
  std::vector<ContactPair<dim>> candidate_pairs;
  std::vector<unsigned int> surface_node_of_pair; ///< index into surface.nodes()
};
} // namespace dyncontact
