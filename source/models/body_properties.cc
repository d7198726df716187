#include <dyncontact/material/material.h>
#include <dyncontact/models/body_properties.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dyncontact
{
std::vector<BodyMaterial> body_materials(const BodiesParameters& bodies)
{
  std::vector<BodyMaterial> materials;
  for (const BodyParameters& body : bodies.bodies)
    materials.push_back(
        {create_material(body.material, body.youngs_modulus, body.poissons_ratio), body.density});
  return materials;
}

double dilatational_wave_speed(const BodyParameters& body)
{
  const double nu                  = body.poissons_ratio;
  const double constrained_modulus = body.youngs_modulus * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
  return std::sqrt(constrained_modulus / body.density);
}

double touching_tolerance(const double shortest_edge, const double largest_coordinate)
{
  return std::max(1e-9 * shortest_edge,
                  8. * std::numeric_limits<double>::epsilon() * largest_coordinate);
}
} // namespace dyncontact
