#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/node_index.h>

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <Eigen/SparseCore>
#include <vector>

namespace dyncontact
{
/**
 * The part of one body's boundary that may touch another body (all faces with one boundary id),
 * seen as the set of its nodes: the support points of its faces, so vertices and, for Q2 faces,
 * mid-side nodes. For a displacement u it gives, in the current configuration x = X + u,
 *  - the outward unit normal at every node: the normals of the faces sharing the node, evaluated
 *    at the node on the deformed (isoparametric) faces, averaged and normalized;
 *  - the consistent surface mass matrix, the integrals over the deformed faces of products of face
 *    shape functions times the kinematics' measure factor (2 pi r for axisymmetry), which turns
 *    nodal forces into a pressure field;
 *  - a positive lumped area of every node, the mass matrix's diagonal scaled to the surface's
 *    area, which sizes penalty springs.
 *
 * The geometry is the isoparametric one: the element interpolates the nodes' current positions
 * X + u (MappingFEField), X the nodes' reference positions on the curved boundary, so the faces
 * are the curves (surfaces) through their current nodes. (deal.II's MappingQEulerian adds the
 * displacement to the straight-sided Q1 geometry instead: on the spheres that tilted the pole's
 * normal by 0.016 and put the surface mass matrix 0.8 % off.) The class holds no
 * solution data and knows nothing about contact pairs or multipliers. Every MPI rank of a shared
 * triangulation can evaluate it (it loops over all surface faces, owned or not).
 */
template <int dim>
class ContactSurface
{
public:
  /**
   * The faces of `dof_handler`'s cells with boundary id `boundary`; `nodes` indexes all nodes of
   * the mesh. Throws InputError if no face has that id.
   */
  ContactSurface(const DoFHandler<dim>& dof_handler,
                 const Kinematics<dim>& kinematics,
                 const NodeIndex<dim>& nodes,
                 types::boundary_id boundary);

  /** Size of the displacement vectors this surface is evaluated at. */
  types::global_dof_index n_dofs() const { return dof_handler.n_dofs(); }

  /** The surface nodes, ordered as in NodeIndex (by body, then position). */
  const std::vector<Node<dim>>& nodes() const { return surface_nodes; }

  /**
   * Outward unit normals at `displacement` (a whole vector in the DoFHandler's numbering), one per
   * node of nodes().
   */
  std::vector<Tensor<1, dim>> normals(const Vector<double>& displacement) const;

  /**
   * Lumped nodal areas at `displacement`, one per node of nodes(): the diagonal of mass_matrix()
   * scaled by one global factor so that they sum to the surface's area. Positive at every node,
   * unlike the consistent areas (the integrals of the shape functions), which vanish at the Q2
   * vertex on the axis of an axisymmetric surface (the integral of its shape function times 2 pi
   * r). On straight faces in plane (not axisymmetric) kinematics the two coincide.
   */
  std::vector<double> lumped_areas(const Vector<double>& displacement) const;

  /**
   * The consistent surface mass matrix M_ij = integral of N_i N_j times the measure factor over
   * the current faces, i, j indices into nodes(): symmetric positive definite. Solving M p = f
   * turns nodal forces f into the pressure field p they are consistent with, also at nodes whose
   * tributary area vanishes (a Q2 vertex on the axis of an axisymmetric model has area zero: the
   * integral of N_i 2 pi r over its face is zero for a straight face). Sparse: a node couples only
   * to the nodes of its faces, so the storage grows with the number of surface nodes, not with
   * its square (a dense matrix of a 3D contact surface would need GBs).
   */
  Eigen::SparseMatrix<double> mass_matrix(const Vector<double>& displacement) const;

  /**
   * The nodes of every face, as indices into nodes(), in the order of the scalar element's unit
   * face support points (FiniteElement::get_unit_face_support_points()): for a Q2 face in 2D the
   * vertex at xi = 0, the vertex at xi = 1, then the mid-side node at xi = 1/2. One entry per face
   * of the surface.
   */
  const std::vector<std::vector<unsigned int>>& face_nodes() const { return support_point_nodes; }

  /**
   * The consistent recovery of a contact pressure [force/area] from nodal forces: one pressure
   * per entry of `surface_nodes_of_pairs` (indices into nodes(), one per contact pair) from the
   * pairs' nodal forces `multipliers` (same length) at `displacement`. The contact zone is the
   * support of the multipliers, the nodes whose pair has a nonzero multiplier (each node at most
   * once). The pressure is p = sum over zone nodes j of p_j N_j and solves M_zz p_z = f_z, the
   * rows and columns of the zone in mass_matrix() at `displacement`: the work of p on every zone
   * node's shape function equals its nodal force. Pairs outside the zone get exactly 0. Exact for
   * a pressure the zone's shape functions represent; it also gives the pressure at the axis node
   * of an axisymmetric model, whose tributary area is zero. Throws SolverFailure if the zone's
   * mass matrix is not positive definite (a collapsed face).
   */
  std::vector<double> consistent_pressures(const Vector<double>& displacement,
                                           const std::vector<unsigned int>& surface_nodes_of_pairs,
                                           const std::vector<double>& multipliers) const;

private:
  const DoFHandler<dim>& dof_handler;
  const Kinematics<dim>& kinematics;
  const types::boundary_id boundary;
  std::vector<Node<dim>> surface_nodes;
  /** X at every DoF: the nodes' reference positions (on the curved, isoparametric faces). */
  Vector<double> reference_positions;
  /** (cell, face number) of every surface face. */
  std::vector<std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>> faces;
  /** Per face: (local DoF of component 0, index in surface_nodes) of each of its nodes. */
  std::vector<std::vector<std::pair<unsigned int, unsigned int>>> nodes_of_face;
  /** Per face: index in surface_nodes of each of its nodes, by unit face support point. */
  std::vector<std::vector<unsigned int>> support_point_nodes;

  /** X + u at every DoF, the field the current configuration's mapping interpolates. */
  Vector<double> current_positions(const Vector<double>& displacement) const;

  /**
   * Calls integrand(nodes_of_face[f], fe_values, q, measure) at every Gauss point q of every face f
   * in the configuration of `mapping`, with measure = measure factor times JxW.
   */
  template <typename Integrand>
  void integrate_over_faces(const Mapping<dim>& mapping, const Integrand& integrand) const;
};
} // namespace dyncontact
