#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <optional>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * What a problem model says about its contact, without building anything: candidate pairs with
 * fixed normals (bars, a rigid wall), or any number of pairs of contact surfaces by boundary id
 * and of surfaces against rigid planes, each with the elastic stiffness scale a penalty is sized
 * from. create_contact() builds the
 * geometry and the constraint set from it and applies Contact/formulation and Contact/penalty
 * factor; models never see those.
 */
template <int dim>
struct ContactDescription
{
  /** A node of body A against a node of body B, or against a rigid wall, along a fixed normal. */
  struct FixedPair
  {
    Node<dim> node_a;
    std::optional<Node<dim>> node_b; ///< empty: a rigid wall through `wall_point`
    Point<dim> wall_point;
    Tensor<1, dim> normal;  ///< unit normal from A toward B (or the wall)
    double stiffness_scale; ///< E A / h of the stiffer side [force/length]; penalty = factor x this
  };

  /**
   * Contact between two boundaries (surface_a: the slave side, body A; surface_b: the master
   * side), discretized as Contact/discretization says (NodeToNodeContact for mirrored meshes,
   * NodeToSegmentContact for any); the pairs follow the deformation.
   */
  struct SurfacePair
  {
    types::boundary_id surface_a;
    types::boundary_id surface_b;
    /// the penalty per unit contact area is factor x stiffness_modulus / stiffness_length
    double stiffness_modulus;  ///< [force/area], the stiffer body's Young's modulus
    double stiffness_length;   ///< [length], e.g. the shortest cell edge
    double matching_tolerance; ///< [length], node-to-node: facing nodes coincide across to this
    /// [length], node-to-segment: how far from the master surface (at t = 0) a slave node and its
    /// candidate faces may lie, the approach plus the sliding a run can follow
    double search_radius;
    double touching_tolerance; ///< [length], a gap above -this at t = 0 is touching, not overlap
    std::string source;        ///< what errors name, e.g. "Mesh/file = 'two_spheres.geo'"
    /// the pair's own Coulomb friction coefficient [-]; empty: Contact/friction coefficient
    std::optional<double> friction_coefficient = {};
  };

  /** A boundary against a rigid, fixed plane (RigidPlaneContact). */
  struct PlanePair
  {
    types::boundary_id surface;
    Point<dim> point;      ///< [length], on the plane
    Tensor<1, dim> normal; ///< unit, pointing out of the plane toward the body
    /// the penalty per unit contact area is factor x stiffness_modulus / stiffness_length
    double stiffness_modulus;  ///< [force/area], the body's Young's modulus
    double stiffness_length;   ///< [length], e.g. the shortest cell edge
    double touching_tolerance; ///< [length], a gap above -this at t = 0 is touching, not overlap
    std::string source;        ///< what errors name, e.g. "Contact/Pair 2"
    /// the pair's own Coulomb friction coefficient [-]; empty: Contact/friction coefficient
    std::optional<double> friction_coefficient = {};
  };

  std::vector<FixedPair> fixed_pairs;
  std::vector<SurfacePair> surface_pairs;
  std::vector<PlanePair> plane_pairs;
};
} // namespace dyncontact
