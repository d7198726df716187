#pragma once

#include <dyncontact/models/mesh_model.h>
#include <dyncontact/models/solid_mesh_model.h>
#include <dyncontact/simulation/run_parameters.h>

#include <memory>

namespace dyncontact
{
/**
 * The MeshModel of a run with a mesh geometry (Problem/geometry = axisymmetric mesh or plane
 * strain mesh): its Mesh, Bodies and Contact/Pair k sections in the geometry's section. Asserts
 * that the geometry is not bars.
 */
std::unique_ptr<MeshModel> create_mesh_model(const RunParameters& parameters);

/** The SolidMeshModel of a run with Problem/geometry = 3d mesh. */
std::unique_ptr<SolidMeshModel> create_solid_mesh_model(const RunParameters& parameters);
} // namespace dyncontact
