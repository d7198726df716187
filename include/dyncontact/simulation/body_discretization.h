#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/discretization/external_loads.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/discretization/prescribed_displacements.h>
#include <dyncontact/models/problem_model.h>

#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/lac/affine_constraints.h>

#include <memory>
#include <type_traits>
#include <vector>

namespace dyncontact
{
/**
 * The mesh of the bodies on the ranks of MPI_COMM_WORLD. A meshed body's mesh (dim >= 2) is
 * distributed: each rank holds its own cells and one layer of ghost cells around them
 * (parallel::fullydistributed, as deal.II builds it from a mesh read by every rank; the cells
 * partitioned by Zoltan, as the shared triangulation before it). The bars' meshes are small and
 * stay whole on every rank (a shared triangulation).
 */
template <int dim>
using BodyTriangulation = std::conditional_t<dim == 1,
                                             parallel::shared::Triangulation<dim>,
                                             parallel::fullydistributed::Triangulation<dim>>;

/**
 * The bodies of a ProblemModel discretized: the mesh (BodyTriangulation), the vector-valued FE_Q of
 * the model's degree, the curved-cell mapping (its support points computed once from the
 * manifolds), the DoFs and nodes, the kinematics, the elastic bodies with their lumped masses, the
 * DoFs held at zero or prescribed (as constraints on Newton's updates) and the surface loads. Built
 * once; throws the model's InputError for a bad mesh.
 */
template <int dim>
class BodyDiscretization
{
public:
  explicit BodyDiscretization(ProblemModel<dim>& model);

  BodyTriangulation<dim> triangulation;
  const FESystem<dim> fe;
  MappingQCache<dim> mapping;
  DoFHandler<dim> dof_handler;
  std::unique_ptr<NodeIndex<dim>> nodes;
  std::unique_ptr<Kinematics<dim>> kinematics;
  /**
   * The DoFs held for all time (the axis, clamps at zero, Dirichlet boundaries at g(X, t)) as
   * homogeneous constraints on Newton's updates, du_i = 0,
   * every one on every rank (they are few, and the contact rows of one rank may couple to another
   * rank's): the tangent's rows and columns of these DoFs are eliminated (ElasticBodies).
   */
  AffineConstraints<double> constraints;
  std::vector<bool> is_fixed_dof; ///< per DoF of the mesh: constrained
  /** The fixed DoFs of Dirichlet boundaries, with their displacement g(X, t). */
  std::unique_ptr<PrescribedDisplacements<dim>> prescribed;
  std::unique_ptr<ElasticBodies<dim>> bodies;
  std::unique_ptr<ExternalLoads<dim>> loads;
  /** ElasticBodies::highest_frequency_bound() of the bodies with their fixed DoFs [1/time]. */
  double highest_frequency = 0.;

  /**
   * A checksum of the node positions of the whole mesh in node order (problem_fingerprint.h,
   * checksum()), the same on every rank; computed once (collectively) by the constructor.
   */
  const std::string& node_checksum() const { return node_positions_checksum; }

private:
  std::string node_positions_checksum;
};
} // namespace dyncontact
