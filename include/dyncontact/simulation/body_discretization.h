#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/node_index.h>
#include <dyncontact/discretization/surface_tractions.h>
#include <dyncontact/models/problem_model.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/lac/affine_constraints.h>

#include <memory>
#include <vector>

namespace dyncontact
{
/**
 * The bodies of a ProblemModel discretized: the mesh (shared by every rank of MPI_COMM_WORLD), the
 * vector-valued FE_Q of the model's degree, the curved-cell mapping (its support points computed
 * once from the manifolds), the DoFs and nodes, the kinematics, the elastic bodies with their
 * lumped masses, the DoFs held at zero (as constraints) and the surface loads. Built once; throws
 * the model's InputError for a bad mesh.
 */
template <int dim>
class BodyDiscretization
{
public:
  explicit BodyDiscretization(ProblemModel<dim>& model);

  parallel::shared::Triangulation<dim> triangulation;
  const FESystem<dim> fe;
  MappingQCache<dim> mapping;
  DoFHandler<dim> dof_handler;
  std::unique_ptr<NodeIndex<dim>> nodes;
  std::unique_ptr<Kinematics<dim>> kinematics;
  /**
   * The DoFs held at zero for all time (the axis, clamps) as homogeneous constraints u_i = 0:
   * the tangent's rows and columns of these DoFs are eliminated (ElasticBodies).
   */
  AffineConstraints<double> constraints;
  std::vector<bool> is_fixed_dof; ///< per DoF: constrained
  std::unique_ptr<ElasticBodies<dim>> bodies;
  std::unique_ptr<SurfaceTractions<dim>> loads;
  /** ElasticBodies::highest_frequency_bound() of the bodies with their fixed DoFs [1/time]. */
  double highest_frequency = 0.;

  /** A checksum of the node positions in node order (problem_fingerprint.h, checksum()). */
  std::string node_checksum() const;
};
} // namespace dyncontact
