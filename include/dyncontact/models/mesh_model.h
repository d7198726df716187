#pragma once

#include <dyncontact/contact/contact_parameters.h>
#include <dyncontact/models/boundary_parameters.h>
#include <dyncontact/models/gmsh_mesh.h>
#include <dyncontact/models/mesh_parameters.h>
#include <dyncontact/models/mesh_section.h>
#include <dyncontact/models/problem_model.h>
#include <dyncontact/reference/finite_sphere_impact.h>
#include <dyncontact/reference/hertz_impact.h>

#include <optional>

namespace dyncontact
{
/**
 * Bodies from a 2D gmsh mesh, 9-node quadrilaterals with a quadratic mapping and the mesh's
 * manifolds (circular on circular boundary curves, see read_gmsh_mesh()), in one of two sections
 * (MeshSection): bodies of revolution in the (r, z) half plane (x = r, y = z; the paper's spheres,
 * a sphere on a block), u_r held at zero on the symmetry axis; or cross-sections of long bodies in
 * plane strain in the (x, y) plane (a disc, a cylinder on a block), unit thickness.
 * Each body has its own hyperelastic law, density, initial velocity, surface traction and body
 * force (parsed functions of x, y, t) and monitor node. Momentum and tip motion are reported along
 * y (z). Bodies touch through the declared contact pairs.
 */
class MeshModel : public ProblemModel<2>
{
public:
  /** `pairs`: the declared contact pairs (Contact/Pair k); empty: the default, see
   * contact_description(). */
  MeshModel(const MeshParameters& mesh,
            const BodiesParameters& bodies,
            const std::vector<ContactPairParameters>& pairs = {},
            MeshSection section                             = MeshSection::axisymmetric,
            const BoundaryParameters& boundary              = {});

  unsigned int element_degree() const override { return 2; }
  unsigned int n_bodies() const override { return bodies.bodies.size(); }
  /** Reads the mesh; throws InputError if a body has no cells. */
  void create_triangulation(Triangulation<2>& triangulation) override;
  /** The spheres' manifolds (gmsh_mesh.h, attach_manifolds()); after create_triangulation(). */
  void attach_manifolds(Triangulation<2>& triangulation) const override;
  std::vector<BodyMaterial> body_materials() const override;
  std::unique_ptr<Kinematics<2>> create_kinematics() const override;
  /** Body b's `Initial velocity` at X; throws InputError if it is not finite there. */
  Tensor<1, 2> initial_velocity(types::material_id body, const Point<2>& X) const override;
  /**
   * The declared pairs (Contact/Pair k): each a slave boundary against a master boundary or a
   * rigid plane, discretized by Contact/discretization: node-to-node needs matching facing nodes
   * (to 1e-6 h_min), node-to-segment searches within search_radius(). Without declared pairs:
   * with two bodies, contact between their sphere surfaces (boundary ids
   * SphereMeshIds::surface(0), the slave side, and (1), the master side); with one body, none;
   * more bodies need declared pairs (InputError). Surfaces must not overlap (they may touch, to
   * touching_tolerance(), and then start closed); the penalty stiffness scale per unit contact
   * area is E / h_min (E of the stiffest body, h_min the shortest cell edge). Boundary ids the
   * mesh does not have throw InputError when the contact is built (create_contact()).
   */
  ContactDescription<2> contact_description(const NodeIndex<2>& nodes) const override;
  /** u_r on the axis r = 0 in axisymmetry; none in plane strain. */
  std::vector<types::global_dof_index> fixed_dofs(const NodeIndex<2>& nodes) const override;
  /**
   * The Boundary section's symmetry planes (the normal component on a straight boundary curve
   * whose normal lies along x or y) and supports. Throws InputError naming the subsection for a
   * boundary id the mesh does not have, and for a symmetry boundary that is not such a line (a
   * circle, an oblique line).
   */
  std::vector<FixedBoundary> fixed_boundaries() const override;
  /**
   * The node of each body nearest to its `monitor point` (by default its centroid: on the axis,
   * (0, z_c), in axisymmetry). Throws InputError for a given point farther
   * from that node than the body's largest cell diameter (a point outside the body by more than a
   * cell, which would silently report some surface node).
   */
  std::vector<Node<2>> monitor_nodes(const NodeIndex<2>& nodes) const override;
  /**
   * Body b's `Surface traction` on its whole boundary except the axis: every boundary curve of the
   * body (for the sphere meshes the one curve SphereMeshIds::surface(b)). Valid after
   * create_triangulation().
   */
  std::vector<SurfaceTraction<2>> surface_tractions() const override;
  /** Body b's `Body force` on its cells, for every body whose force is not zero. */
  std::vector<BodyForce<2>> body_forces() const override;
  Tensor<1, 2> impact_direction() const override;
  /** Plane strain: x and y; axisymmetric: the axis (the radial momentum of a ring is zero). */
  std::vector<Tensor<1, 2>> momentum_directions() const override;
  /**
   * Writes hertz.csv (time, contact_force, approach of Hertz's theory at `times`) if the problem
   * is a Hertz impact, see hertz_reference(), and finite_sphere.csv (the same columns) if the
   * finite-sphere law applies, see finite_sphere_reference().
   */
  void write_reference(const std::string& directory,
                       const std::vector<double>& times,
                       const std::vector<Node<2>>& monitors) const override;
  /**
   * For a Hertz impact: measures the contact force history (measure_impact()) and writes
   * impact_summary.csv, the peak force, its time, contact start, end and duration, impulse (the
   * contact impulse on body 1, `contact_impulses[0]`, compression positive) and ringing next to
   * Hertz's values and the relative differences, and, where the finite-sphere law
   * applies, its values and the differences from it (columns finite_sphere,
   * finite_sphere_difference). A run of one step has nothing to measure: it writes nothing and
   * says so.
   */
  void summarize_run(const std::string& directory,
                     const History& history,
                     const std::vector<double>& contact_impulses,
                     const std::string& status,
                     std::ostream& log) const override;
  /**
   * Hertz's theory of this impact if it applies (axisymmetric meshes only): one contact pair
   * (declared, or the default of two bodies) between a full sphere (MeshGeometry::sphere()) and
   * another full sphere (HertzImpact::two_spheres, any radii and material constants), or a flat
   * boundary perpendicular to the axis of an elastic body (HertzImpact::sphere_on_flat with that
   * body's E, nu and mass rho V, V its meshed volume of revolution), or a rigid plane perpendicular
   * to the axis (E and mass infinite); the bodies approach along the axis with the initial
   * velocities given (evaluated at the sphere's centre, at the flat surface's point on the axis);
   * first touch at gap / approach speed, at t = 0 if they touch to touching_tolerance(). Empty
   * otherwise (several pairs, other shapes, overlapping or separating bodies). Valid after
   * create_triangulation(). A body of another shape whose contact boundary is a spherical end
   * (an arc of a circle centred on the axis whose pole is the body's extreme point toward the
   * other side, e.g. a cylinder with a hemispherical end) counts as a sphere with the arc's radius
   * and the body's mass rho V: Hertz's rigid-body impact, fair while the contact lasts longer than
   * the waves take to cross the body; no finite-sphere law then.
   */
  std::optional<HertzImpact> hertz_reference() const;
  /**
   * The finite-sphere law (FiniteSphereImpact, doc/method.md section 5) for the impacts of
   * hertz_reference() that it covers: two spheres; a sphere on the rigid plane (the mirrored
   * pair: the same sphere twice at twice the speed); a sphere on an elastic flat body
   * (FiniteSphereImpact::sphere_on_flat(): the sphere's finite-size term on Hertz's half-space;
   * the flat body's own finite size, e.g. a block's depth, is not in it). Empty where Hertz does
   * not apply, and where the law does not (a Poisson's ratio other than 0.3, whose C0 is unknown,
   * or an impact beyond the law's range: FiniteSphereImpact's constructor throws).
   */
  std::optional<FiniteSphereImpact> finite_sphere_reference() const;
  void print_summary(std::ostream& out, double time_step) const override;

private:
  /**
   * One side of a head-on impact along the axis (hertz_reference()): a spherical surface (an arc
   * of a circle centred on the axis) whose pole faces the other side, of a body that is the whole
   * sphere (whole_sphere) or any other shape (a striker's spherical end: Hertz's contact radius is
   * the arc's, the mass the body's); or a flat surface perpendicular to the axis at z = surface_z
   * of an elastic body or of the rigid plane (no body).
   */
  struct ImpactSide
  {
    std::optional<SphereGeometry> sphere;
    double surface_z;
    std::optional<unsigned int> body;
    bool whole_sphere;
  };
  /** The contact pairs in force: the declared ones, or the default of contact_description(). */
  std::vector<ContactPairParameters> effective_pairs() const;
  /** The side of an impact that boundary `id` is, if it is one; see ImpactSide. */
  std::optional<ImpactSide> impact_side(types::boundary_id id) const;
  /**
   * The two sides of the one contact pair, the first a sphere, with their approach speed along
   * the axis and gap at t = 0 (0 if touching); empty where hertz_reference() is.
   */
  struct HeadOnImpact
  {
    ImpactSide sphere, other;
    double approach_speed, gap;
    /** +1 if the other side lies above the sphere side (larger z), else -1. */
    double direction;
  };
  std::optional<HeadOnImpact> head_on_impact() const;
  /**
   * The flat side of a sphere-on-flat impact as Hertz sees it: the elastic body's E, nu and mass
   * rho V (V its meshed volume), or the rigid plane (E and mass infinite).
   */
  ElasticFlatBody flat_body(const ImpactSide& side) const;
  /** The ElasticSphere of body b with the sphere `geometry`. */
  ElasticSphere elastic_sphere(unsigned int body, const SphereGeometry& geometry) const;
  /**
   * The mass of a spherical side as Hertz sees it: rho 4/3 pi R^3 of a whole sphere, rho V (V the
   * body's meshed volume) of a body with a spherical end.
   */
  double spherical_side_mass(const ImpactSide& side) const;
  /**
   * How close surfaces count as touching at t = 0: 1e-9 of the shortest cell edge, and at least
   * the round-off of the positions (8 units in the last place of the largest |coordinate| of a
   * vertex). Valid after create_triangulation().
   */
  double touching_tolerance() const;
  /**
   * Node-to-segment search radius [length]: if both bodies are spheres (MeshGeometry::sphere()),
   * their initial gap plus a quarter of the smaller radius; else the smallest distance between a
   * boundary vertex of body 1 and one of body 2 at t = 0 plus a quarter of the smaller extent in z
   * of the two bodies. Valid after create_triangulation().
   */
  double search_radius() const;

  MeshParameters mesh;
  BodiesParameters bodies;
  MeshSection section;
  BoundaryParameters boundary;
  /// per body: its initial velocity, surface traction and body force, built from the parameters'
  /// expressions
  std::vector<std::shared_ptr<Functions::ParsedFunction<2>>> initial_velocities, tractions, forces;
  std::vector<ContactPairParameters> declared_pairs;
  MeshGeometry geometry;
  unsigned int n_cells;
  double shortest_edge;
  /** Largest |r| or |z| of a vertex [length]. */
  double largest_coordinate;
  /** Smallest distance between boundary vertices of bodies 0 and 1 at t = 0 [length]. */
  double closest_boundary_vertices;
  /** Largest cell diameter of each body [length]. */
  std::vector<double> largest_cell_diameter;
  /** Lowest and highest z of each body's vertices [length]. */
  std::vector<double> body_lowest_z, body_highest_z;
  /**
   * Volume of each body's mesh (Q2 mapping) [length^3]: of revolution, or per unit thickness in
   * plane strain.
   */
  std::vector<double> body_volumes;
  /** Each body's centroid (its volume's; on the axis in axisymmetry) [length]. */
  std::vector<Point<2>> body_centroids;
};
} // namespace dyncontact
