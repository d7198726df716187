#pragma once

#include <dyncontact/contact/contact_parameters.h>
#include <dyncontact/models/boundary_parameters.h>
#include <dyncontact/models/gmsh_mesh.h>
#include <dyncontact/models/mesh_parameters.h>
#include <dyncontact/models/problem_model.h>
#include <dyncontact/reference/finite_sphere_impact.h>
#include <dyncontact/reference/hertz_impact.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parsed_function.h>

#include <memory>
#include <optional>
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
   * master surface of another body, node-to-node (matching facing nodes) or node-to-surface
   * (node-to-segment, within search_radius()); mortar is 2D only. No declared pairs: no contact
   * for one body; InputError for more (they would pass through each other).
   * Throws InputError for a boundary id the mesh does not have and for two surfaces of one body.
   * The penalty stiffness per unit contact area is E / h_min (E of the stiffest body, h_min the
   * shortest cell edge).
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
  /** x, y and z. */
  std::vector<Tensor<1, 3>> momentum_directions() const override;
  /**
   * Writes hertz.csv and, where the finite-sphere law applies, finite_sphere.csv
   * (write_impact_references()) if the problem is a sphere dropped on a rigid plane, see
   * hertz_reference().
   */
  void write_reference(const std::string& directory,
                       const std::vector<double>& times,
                       const std::vector<Node<3>>& monitors) const override;
  /**
   * For a sphere dropped on a rigid plane: impact_summary.csv (write_impact_summary()) of the
   * whole sphere, the model's force and impulse times whole_body_factor().
   */
  void summarize_run(const std::string& directory,
                     const History& history,
                     const std::vector<double>& contact_impulses,
                     const std::string& status,
                     std::ostream& log) const override;
  /**
   * Hertz's theory of a sphere dropped on a rigid plane, if the problem is one: one contact pair,
   * a spherical slave surface against a rigid plane perpendicular to z, the sphere approaching it
   * (its initial velocity at the centre), not overlapping it, its pole (the point nearest the
   * plane) the body's extreme point toward the plane and on no other boundary of the body but
   * symmetry planes; the model may be a symmetric part of the sphere, cut by symmetry planes
   * through its centre that contain the plane's normal (a quarter on x = 0 and y = 0). Its mass:
   * the whole sphere's rho 4/3 pi R^3 if the body's boundary is the sphere and those planes, else
   * rho V times whole_body_factor(). Empty otherwise. Valid after create_triangulation().
   */
  std::optional<HertzImpact> hertz_reference() const;
  /**
   * The finite-sphere law of hertz_reference()'s impact for a whole sphere (the mirrored pair:
   * the sphere twice at twice the speed), where it applies (nu = 0.3, see FiniteSphereImpact).
   */
  std::optional<FiniteSphereImpact> finite_sphere_reference() const;
  /**
   * How many copies of the model make the whole body: 2 per distinct symmetry plane (4 for a
   * quarter; boundaries of several bodies on one plane, as the two half balls of
   * prm/oblique_spheres_3d.prm on y = 0, count once), the factor by which impact_summary.csv
   * scales the model's force and impulse. The history's columns are the model's.
   */
  double whole_body_factor() const;
  void print_summary(std::ostream& out, double time_step) const override;

private:
  /** A sphere dropped on a rigid plane (hertz_reference()). */
  struct SphereOnPlane
  {
    unsigned int body;
    SurfaceSphere sphere;
    double approach_speed; ///< toward the plane [length/time]
    double gap;            ///< at t = 0, 0 if touching [length]
    double plane_normal_z; ///< +1 or -1: the plane's normal (toward the body) along z
    bool whole_sphere;     ///< the body's boundary is the sphere and symmetry planes
  };
  std::optional<SphereOnPlane> sphere_on_plane() const;
  /** The surface with boundary id `id`; throws InputError naming `entry` if there is none. */
  const BoundarySurface& find_surface(types::boundary_id id, const std::string& entry) const;
  /**
   * How close surfaces count as touching at t = 0: 1e-9 of the shortest cell edge, and at least
   * the round-off of the positions (as MeshModel).
   */
  double touching_tolerance() const;
  /**
   * Node-to-surface search radius [length] between bodies a and b: the smallest distance between
   * a boundary vertex of a and one of b at t = 0 plus a quarter of the smallest bounding-box side
   * of the two bodies.
   */
  double search_radius(unsigned int body_a, unsigned int body_b) const;

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
  std::vector<double> largest_cell_diameter;            ///< per body
  std::vector<Point<3>> body_centroids;                 ///< per body
  std::vector<double> body_volumes;                     ///< per body, the model's [length^3]
  std::vector<std::vector<Point<3>>> boundary_vertices; ///< per body, at t = 0
  std::vector<BoundingBox<3>> body_boxes;               ///< per body, of its vertices
};
} // namespace dyncontact
