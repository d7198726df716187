#pragma once
// Test support: a mesh problem's discretization as far as a run builds it before contact.

#include <dyncontact/contact/contact_factory.h>
#include <dyncontact/models/mesh_model.h>
#include <dyncontact/simulation/parameter_reader.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <memory>
#include <string>
#include <vector>

#include "case_run.h"

namespace dyncontact::testing
{
/**
 * The discretization of a mesh prm with overrides, as far as a run builds it before contact (its
 * section, axisymmetric or plane strain, and boundary conditions as the prm says).
 */
struct MeshSetUp
{
  MeshSetUp(const std::string& prm_file, const std::vector<std::string>& overrides)
      : parameters(ParameterReader(source_path(prm_file), overrides).parameters()),
        model(parameters.mesh,
              parameters.bodies,
              parameters.contact.pairs,
              mesh_section(parameters.problem.geometry),
              parameters.boundary),
        dof_handler(triangulation), fe(FE_Q<2>(2), 2), mapping(2)
  {
    model.create_triangulation(triangulation);
    dof_handler.distribute_dofs(fe);
    nodes      = std::make_unique<NodeIndex<2>>(dof_handler, mapping);
    kinematics = model.create_kinematics();
  }

  /** The run's contact (create_contact() from the model's description). */
  Contact<2> contact() const
  {
    return create_contact(
        model.contact_description(*nodes), dof_handler, *kinematics, *nodes, parameters.contact);
  }

  /** The message of the InputError contact() throws, or "" if it throws none. */
  std::string contact_error() const
  {
    try
    {
      contact();
    }
    catch (const InputError& error)
    {
      return error.what();
    }
    return "";
  }

  RunParameters parameters;
  MeshModel model;
  Triangulation<2> triangulation;
  DoFHandler<2> dof_handler;
  const FESystem<2> fe;
  const MappingQ<2> mapping;
  std::unique_ptr<NodeIndex<2>> nodes;
  std::unique_ptr<Kinematics<2>> kinematics;
};
} // namespace dyncontact::testing
