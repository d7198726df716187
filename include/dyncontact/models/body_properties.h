#pragma once

#include <dyncontact/discretization/elastic_bodies.h>
#include <dyncontact/discretization/external_loads.h>
#include <dyncontact/models/mesh_parameters.h>

#include <deal.II/base/parsed_function.h>

#include <memory>
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

/**
 * The dead body force of every body of `bodies` whose `Body force` is not zero: `forces[b]`, the
 * model's parsed function of body b, with its density (the load rho b per unit mass).
 */
template <int dim>
std::vector<BodyForce<dim>>
body_forces(const BodiesParameters& bodies,
            const std::vector<std::shared_ptr<Functions::ParsedFunction<dim>>>& forces)
{
  std::vector<BodyForce<dim>> loads;
  for (unsigned int body = 0; body < bodies.bodies.size(); ++body)
    if (!bodies.bodies[body].body_force.is_zero())
      loads.push_back(
          {static_cast<types::material_id>(body), forces[body], bodies.bodies[body].density});
  return loads;
}

/**
 * How close the surfaces of a mesh count as touching at t = 0 [length]: 1e-9 of its shortest
 * cell edge, and at least the round-off of the positions (8 units in the last place of the
 * largest |coordinate| of a vertex).
 */
double touching_tolerance(double shortest_edge, double largest_coordinate);
} // namespace dyncontact
