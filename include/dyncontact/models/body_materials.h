#pragma once

#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/models/mesh_parameters.h>

#include <vector>

namespace dyncontact
{
/** The material law and density of every body of `bodies`, indexed by body (material id). */
std::vector<BodyMaterial> body_materials(const BodiesParameters& bodies);

/**
 * The dilatational (P-) wave speed c_p = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu)) / rho) of `body`
 * [length/time], the speed the Courant number and the stability checks use.
 */
double dilatational_wave_speed(const BodyParameters& body);
} // namespace dyncontact
