#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/contact/contact_border.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>

#include <Eigen/SparseCore>
#include <array>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * The part of one body's boundary that may touch another body (all faces with one boundary id),
 * seen as the set of its nodes: the support points of its faces, so vertices and, for Q2 faces,
 * mid-side nodes. For the current positions x = X + u of its nodes it gives
 *  - the outward unit normal at every node: the normals of the faces sharing the node, evaluated
 *    at the node on the deformed (isoparametric) faces, averaged and normalized;
 *  - the consistent surface mass matrix, the integrals over the deformed faces of products of face
 *    shape functions times the kinematics' measure factor (2 pi r for axisymmetry), which turns
 *    nodal forces into a pressure field;
 *  - a positive lumped area of every node, the mass matrix's diagonal scaled to the surface's
 *    area, which sizes penalty springs.
 *
 * The geometry is the isoparametric one: a face is x(s) = sum_i N_i(s) x_i over its nodes, N_i
 * the element's shape functions on the face, so the faces are the curves (surfaces) through their
 * current nodes, as the volume element's own mapping of X + u makes them. (deal.II's
 * MappingQEulerian adds the displacement to the straight-sided Q1 geometry instead: on the
 * spheres that tilted the pole's normal by 0.016 and put the surface mass matrix 0.8 % off.) The
 * shape functions and their derivatives along the face at the quadrature points are tabulated
 * once per face number of the reference cell; after construction the surface reads nothing but
 * the positions of its own nodes, so a rank that holds only the contact nodes' displacement
 * (BorderDisplacement) evaluates it. It holds no solution data and knows nothing about contact
 * pairs or multipliers.
 */
template <int dim>
class ContactSurface
{
public:
  /**
   * The faces with boundary id `boundary` of the cells of every rank, in the order of the ranks
   * and of each rank's cells: each rank finds those of its own cells (their nodes in `nodes`, this
   * rank's NodeIndex) and sends them to all (collective). Throws InputError if no face has that
   * id.
   */
  ContactSurface(const DoFHandler<dim>& dof_handler,
                 const Kinematics<dim>& kinematics,
                 const NodeIndex<dim>& nodes,
                 types::boundary_id boundary);

  /** The surface nodes, ordered as in NodeIndex (by body, then position). */
  const std::vector<Node<dim>>& nodes() const { return surface_nodes; }

  /** The reference positions X of nodes(), in their order. */
  std::vector<Point<dim>> reference_positions() const;

  /**
   * The current positions X + u of nodes(), in their order, for the displacement of the contact
   * nodes `displacement`, which must hold every node of the surface (else std::out_of_range).
   */
  std::vector<Point<dim>> current_positions(const BorderDisplacement<dim>& displacement) const;

  /**
   * Outward unit normals, one per node of nodes(), with the nodes at `positions` (one per node of
   * nodes(): reference_positions() or current_positions()).
   */
  std::vector<Tensor<1, dim>> normals(const std::vector<Point<dim>>& positions) const;

  /**
   * Lumped nodal areas with the nodes at `positions`, one per node of nodes(): the diagonal of
   * mass_matrix() scaled by one global factor so that they sum to the surface's area. Positive at
   * every node, unlike the consistent areas (the integrals of the shape functions), which vanish
   * at the Q2 vertex on the axis of an axisymmetric surface (the integral of its shape function
   * times 2 pi r). On straight faces in plane (not axisymmetric) kinematics the two coincide.
   */
  std::vector<double> lumped_areas(const std::vector<Point<dim>>& positions) const;

  /**
   * The consistent surface mass matrix M_ij = integral of N_i N_j times the measure factor over
   * the faces with the nodes at `positions`, i, j indices into nodes(): symmetric positive
   * definite. Solving M p = f turns nodal forces f into the pressure field p they are consistent
   * with, also at nodes whose tributary area vanishes (a Q2 vertex on the axis of an axisymmetric
   * model has area zero: the integral of N_i 2 pi r over its face is zero for a straight face).
   * Sparse: a node couples only to the nodes of its faces, so the storage grows with the number
   * of surface nodes, not with its square (a dense matrix of a 3D contact surface would need GBs).
   */
  Eigen::SparseMatrix<double> mass_matrix(const std::vector<Point<dim>>& positions) const;

  /**
   * The nodes of every face, as indices into nodes(), in the order of the scalar element's unit
   * face support points (FiniteElement::get_unit_face_support_points()) as the cell sees its face
   * (the face in standard orientation; in 3D a face may be oriented otherwise for the cell on its
   * other side): for a Q2 face in 2D the vertex at xi = 0, the vertex at xi = 1, then the mid-side
   * node at xi = 1/2. One entry per face of the surface.
   */
  const std::vector<std::vector<unsigned int>>& face_nodes() const { return support_point_nodes; }

  /**
   * The consistent recovery of a contact pressure [force/area] from nodal forces: one pressure
   * per entry of `surface_nodes_of_pairs` (indices into nodes(), one per contact pair) from the
   * pairs' nodal forces `multipliers` (same length) with the nodes at `positions`. The contact
   * zone is the support of the multipliers, the nodes whose pair has a nonzero multiplier (each
   * node at most once). The pressure is p = sum over zone nodes j of p_j N_j and solves
   * M_zz p_z = f_z, the rows and columns of the zone in mass_matrix(): the work of p on every
   * zone node's shape function equals its nodal force. Pairs outside the zone get exactly 0.
   * Exact for a pressure the zone's shape functions represent; it also gives the pressure at the
   * axis node of an axisymmetric model, whose tributary area is zero. Throws SolverFailure if the
   * zone's mass matrix is not positive definite (a collapsed face).
   */
  std::vector<double> consistent_pressures(const std::vector<Point<dim>>& positions,
                                           const std::vector<unsigned int>& surface_nodes_of_pairs,
                                           const std::vector<double>& multipliers) const;

private:
  /**
   * The shape functions of the nodes of a face of the reference cell at points of that face: per
   * point, each node's value and its derivatives along the face's dim - 1 unit tangential vectors
   * (GeometryInfo::unit_tangential_vectors), with the point's weight (a quadrature's; infinite
   * for the table at the support points, which is not integrated over).
   */
  struct FaceTable
  {
    std::vector<std::vector<double>> values;
    std::vector<std::vector<std::array<double, dim - 1>>> tangential_derivatives;
    std::vector<double> weights;
  };

  /** A face of the surface: its face number in the cell, the cell's body, its nodes. */
  struct Face
  {
    unsigned int face_number;
    types::material_id body;
    /** Index in surface_nodes of each node, in the order of the face number's tables. */
    std::vector<unsigned int> nodes;
  };

  const Kinematics<dim>& kinematics;
  std::vector<Node<dim>> surface_nodes;
  std::vector<Face> faces;
  /** Per face: index in surface_nodes of each of its nodes, by unit face support point. */
  std::vector<std::vector<unsigned int>> support_point_nodes;
  /** Per face number: the tables at the Gauss points and at the face's support points. */
  std::vector<FaceTable> at_gauss_points, at_nodes;
  /** Per face number: +1 or -1, the sign that turns the tangents' normal outward. */
  std::vector<double> outward_sign;

  /**
   * The table of the scalar element's DoFs `face_dofs` (those with support on face `face_number`)
   * at the points of `quadrature` on that face.
   */
  static FaceTable tabulate(const FiniteElement<dim>& scalar,
                            const std::vector<unsigned int>& face_dofs,
                            unsigned int face_number,
                            const Quadrature<dim - 1>& quadrature);

  /** The geometry of face `face` at point `q` of `table`: the point, the outward normal times
   * the face's measure (its length |n| is the area element per unit reference area). */
  std::pair<Point<dim>, Tensor<1, dim>> face_point(const Face& face,
                                                   const FaceTable& table,
                                                   unsigned int q,
                                                   const std::vector<Point<dim>>& positions) const;
};

/** The nodes of `a` followed by those of `b` (a two-surface geometry's surface_nodes()). */
template <int dim>
std::vector<Node<dim>> nodes_of_both(const ContactSurface<dim>& a, const ContactSurface<dim>& b)
{
  std::vector<Node<dim>> nodes = a.nodes();
  nodes.insert(nodes.end(), b.nodes().begin(), b.nodes().end());
  return nodes;
}
} // namespace dyncontact
