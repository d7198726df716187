#include <dyncontact/base/dimensions.h>
#include <dyncontact/base/join_over_ranks.h>
#include <dyncontact/simulation/body_discretization.h>
#include <dyncontact/simulation/problem_fingerprint.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>

namespace dyncontact
{
namespace
{
/** The DoFs of the components `boundary` holds on its faces, this rank's (locally relevant). */
template <int dim>
IndexSet held_dofs(const DoFHandler<dim>& dof_handler, const FixedBoundary& boundary)
{
  ComponentMask mask(dim, false);
  for (const unsigned int component : boundary.components)
    mask.set(component, true);
  return DoFTools::extract_boundary_dofs(dof_handler, mask, {boundary.boundary});
}

template <int dim>
void create_mesh(ProblemModel<dim>& model, parallel::shared::Triangulation<dim>& triangulation)
{
  model.create_triangulation(triangulation);
}

template <int dim>
void create_mesh(ProblemModel<dim>& model,
                 parallel::fullydistributed::Triangulation<dim>& triangulation)
{
  // Each rank reads the whole mesh (groups of one rank: the model learns its sizes and bodies from
  // it) and keeps its own part; the whole mesh is freed before the DoFs are distributed.
  const auto description =
      TriangulationDescription::Utilities::create_description_from_triangulation_in_groups<dim,
                                                                                           dim>(
          [&model](Triangulation<dim>& whole) { model.create_triangulation(whole); },
          [](Triangulation<dim>& whole, const MPI_Comm communicator, const unsigned int)
          {
            GridTools::partition_triangulation(Utilities::MPI::n_mpi_processes(communicator),
                                               whole,
                                               SparsityTools::Partitioner::zoltan);
          },
          triangulation.get_communicator(),
          1);
  triangulation.create_triangulation(description);
  model.attach_manifolds(triangulation);
}
} // namespace

template <int dim>
BodyDiscretization<dim>::BodyDiscretization(ProblemModel<dim>& model)
    : triangulation(MPI_COMM_WORLD), fe(FE_Q<dim>(model.element_degree()), dim),
      mapping(model.element_degree())
{
  create_mesh(model, triangulation);
  mapping.initialize(MappingQ<dim>(model.element_degree()), triangulation);
  dof_handler.reinit(triangulation);
  dof_handler.distribute_dofs(fe);
  nodes      = std::make_unique<NodeIndex<dim>>(dof_handler, mapping);
  kinematics = model.create_kinematics();
  is_fixed_dof.assign(dof_handler.n_dofs(), false);
  std::vector<types::global_dof_index> rank_fixed_dofs = model.fixed_dofs(*nodes);
  const std::vector<types::global_dof_index> axis_dofs =
      join_over_ranks(MPI_COMM_WORLD, rank_fixed_dofs);
  const std::vector<FixedBoundary> fixed_boundaries = model.fixed_boundaries();
  std::vector<IndexSet> held;
  for (const FixedBoundary& boundary : fixed_boundaries)
  {
    held.push_back(held_dofs(dof_handler, boundary));
    rank_fixed_dofs.insert(rank_fixed_dofs.end(), held.back().begin(), held.back().end());
  }
  std::vector<types::global_dof_index> fixed_dofs =
      join_over_ranks(MPI_COMM_WORLD, rank_fixed_dofs);
  std::sort(fixed_dofs.begin(), fixed_dofs.end());
  fixed_dofs.erase(std::unique(fixed_dofs.begin(), fixed_dofs.end()), fixed_dofs.end());
  for (const auto dof : fixed_dofs)
  {
    constraints.add_line(dof);
    is_fixed_dof[dof] = true;
  }
  constraints.close();
  prescribed = std::make_unique<PrescribedDisplacements<dim>>(
      dof_handler, *nodes, fixed_boundaries, held, axis_dofs);
  bodies = std::make_unique<ElasticBodies<dim>>(
      dof_handler, mapping, *kinematics, model.body_materials(), &constraints);
  loads = std::make_unique<ExternalLoads<dim>>(
      dof_handler, mapping, *kinematics, model.surface_tractions(), model.body_forces());
  highest_frequency = bodies->highest_frequency_bound(is_fixed_dof);
  std::vector<double> coordinates;
  for (const auto& node : nodes->gather_on_root())
    for (unsigned int d = 0; d < dim; ++d)
      coordinates.push_back(node.position[d]);
  node_positions_checksum = Utilities::MPI::broadcast(MPI_COMM_WORLD, checksum(coordinates), 0);
}

DYNCONTACT_INSTANTIATE_CLASS(BodyDiscretization)
} // namespace dyncontact
