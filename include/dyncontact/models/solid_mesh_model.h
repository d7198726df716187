#pragma once

#include <dyncontact/contact/contact_parameters.h>
#include <dyncontact/models/boundary_parameters.h>
#include <dyncontact/models/gmsh_mesh.h>
#include <dyncontact/models/mesh_parameters.h>
#include <dyncontact/models/problem_model.h>

#include <deal.II/base/parsed_function.h>

#include <memory>
#include <vector>

namespace dyncontact
{
/**
 * Bodies from a 3D gmsh mesh of hexahedra (Problem/geometry = 3d mesh), 27-node cells (FE_Q<3>(2))
 * whose boundary surfaces are planes or parts of spheres (read_gmsh_solid_mesh(); the Q2 mapping
 * follows the spheres' manifolds). Each body has its own hyperelastic law, density, initial
 * velocity, surface traction and body force (parsed functions of x, y, z, t with three components)
 * and monitor node; symmetry planes and supports on boundary surfaces hold displacement components
 * at zero. Bodies touch through the declared contact pairs: a rigid plane, or another body's
 * surface with matching facing nodes (node-to-node). Momentum and tip motion are reported along z.
 */
class SolidMeshModel : public ProblemModel<3>
{
public:
  SolidMeshModel(const MeshParameters& mesh,
                 const BodiesParameters& bodies,
                 const std::vector<ContactPairParameters>& pairs,
                 const BoundaryParameters& boundary);

  unsigned int element_degree() const override { return 2; }
  unsigned int n_bodies() const override { return bodies.bodies.size(); }
  /**
   * Reads the mesh (read_gmsh_solid_mesh()); throws InputError if its physical volumes are not the
   * bodies 1 .. Bodies/number of bodies.
   */
  void create_triangulation(Triangulation<3>& triangulation) override;
  /** The spheres' manifolds (attach_manifolds() of gmsh_mesh.h); after create_triangulation(). */
  void attach_manifolds(Triangulation<3>& triangulation) const override;
  std::vector<BodyMaterial> body_materials() const override;
  std::unique_ptr<Kinematics<3>> create_kinematics() const override;
  /** Body b's `Initial velocity` at X; throws InputError if it is not finite there. */
  Tensor<1, 3> initial_velocity(types::material_id body, const Point<3>& X) const override;
  /**
   * The declared pairs (Contact/Pair k): a slave surface against a rigid plane, or against a
   * master surface of another body with matching facing nodes (Contact/discretization =
   * node-to-node; the others are 2D only). No declared pairs: no contact. Throws InputError for a
   * boundary id the mesh does not have and for two surfaces of one body. The penalty stiffness
   * per unit contact area is E / h_min (E of the stiffest body, h_min the shortest cell edge).
   */
  ContactDescription<3> contact_description(const NodeIndex<3>& nodes) const override;
  /**
   * The Boundary section's symmetry planes (the normal component on a plane boundary surface
   * whose normal lies along x, y or z) and supports. Throws InputError naming the subsection for
   * a boundary id the mesh does not have and for a symmetry surface that is a sphere or a plane
   * with an oblique normal.
   */
  std::vector<FixedBoundary> fixed_boundaries() const override;
  /**
   * The node of each body nearest to its `monitor point` (by default its centroid). Throws
   * InputError for a given point farther from that node than the body's largest cell diameter.
   */
  std::vector<Node<3>> monitor_nodes(const NodeIndex<3>& nodes) const override;
  /** Body b's `Surface traction` on every boundary surface of body b. */
  std::vector<SurfaceTraction<3>> surface_tractions() const override;
  /** Body b's `Body force` on its cells, for every body whose force is not zero. */
  std::vector<BodyForce<3>> body_forces() const override;
  /** z. */
  Tensor<1, 3> impact_direction() const override;
  void print_summary(std::ostream& out, double time_step) const override;

private:
  /** The surface with boundary id `id`; throws InputError naming `entry` if there is none. */
  const BoundarySurface& find_surface(types::boundary_id id, const std::string& entry) const;
  /**
   * How close surfaces count as touching at t = 0: 1e-9 of the shortest cell edge, and at least
   * the round-off of the positions (as MeshModel).
   */
  double touching_tolerance() const;

  MeshParameters mesh;
  BodiesParameters bodies;
  BoundaryParameters boundary;
  std::vector<ContactPairParameters> pairs;
  /// per body: its initial velocity, surface traction and body force
  std::vector<std::shared_ptr<Functions::ParsedFunction<3>>> initial_velocities, tractions, forces;
  SolidMeshGeometry geometry;
  unsigned int n_cells;
  double shortest_edge;
  double largest_coordinate;
  std::vector<double> largest_cell_diameter; ///< per body
  std::vector<Point<3>> body_centroids;      ///< per body
};
} // namespace dyncontact
