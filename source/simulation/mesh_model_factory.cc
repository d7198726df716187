#include <dyncontact/simulation/mesh_model_factory.h>

namespace dyncontact
{
std::unique_ptr<MeshModel> create_mesh_model(const RunParameters& parameters)
{
  return std::make_unique<MeshModel>(parameters.mesh,
                                     parameters.bodies,
                                     parameters.contact.pairs,
                                     mesh_section(parameters.problem.geometry),
                                     parameters.boundary);
}

std::unique_ptr<SolidMeshModel> create_solid_mesh_model(const RunParameters& parameters)
{
  return std::make_unique<SolidMeshModel>(
      parameters.mesh, parameters.bodies, parameters.contact.pairs, parameters.boundary);
}
} // namespace dyncontact
