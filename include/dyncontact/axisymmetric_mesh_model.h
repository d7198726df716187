#pragma once

#include <dyncontact/gmsh_mesh.h>
#include <dyncontact/parameters.h>
#include <dyncontact/problem_model.h>

namespace dyncontact
{
/**
 * Bodies of revolution in the (r, z) half plane (x = r, y = z) from a gmsh mesh, 9-node
 * quadrilaterals with a quadratic mapping and the mesh's spherical manifolds: the paper's spheres.
 * Each body has its own hyperelastic law, density, initial velocity (a parsed function of r, z) and
 * monitor node; u_r is held at zero on the symmetry axis. Momentum and tip motion are reported
 * along z. It has no contact candidates yet (sphere contact is the next step) and no reference
 * solution of its own: the free-vibration and Hertz references are used by the tests.
 */
class AxisymmetricMeshModel : public ProblemModel<2>
{
public:
  AxisymmetricMeshModel(const MeshParameters& mesh, const BodiesParameters& bodies);

  unsigned int element_degree() const override { return 2; }
  unsigned int n_bodies() const override { return bodies.bodies.size(); }
  /** 2 sqrt(6) c_p / h_min: the highest frequency of a lumped 1D 3-node element chain, c_p the
   * dilatational wave speed and h_min the shortest cell edge (a bound, used for warnings). */
  double highest_frequency() const override;
  /** Reads the mesh; throws InputError if a body has no cells. */
  void create_triangulation(Triangulation<2>& triangulation) override;
  std::vector<BodyMaterial> body_materials() const override;
  std::unique_ptr<Kinematics<2>> create_kinematics() const override;
  Tensor<1, 2> initial_velocity(types::material_id body, const Point<2>& X) const override;
  std::vector<ContactPair<2>> contact_pairs(const NodeIndex<2>& nodes) const override;
  std::vector<types::global_dof_index> fixed_dofs(const NodeIndex<2>& nodes) const override;
  std::vector<Node<2>> monitor_nodes(const NodeIndex<2>& nodes) const override;
  /** Body b's `Surface traction` on its surface (boundary id SphereMeshIds::surface(b)). */
  std::vector<SurfaceTraction<2>> surface_tractions() const override;
  Tensor<1, 2> impact_direction() const override;
  void print_summary(std::ostream& out, double time_step) const override;

private:
  /** Dilatational wave speed sqrt((lambda + 2 mu) / rho) of body b. */
  double dilatational_wave_speed(unsigned int body) const;

  MeshParameters mesh;
  BodiesParameters bodies;
  std::vector<SphereGeometry> spheres;
  unsigned int n_cells;
  double shortest_edge;
};
} // namespace dyncontact
