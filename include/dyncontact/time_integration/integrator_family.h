#pragma once

#include <dyncontact/base/name_table.h>

namespace dyncontact
{
/**
 * The member of the generalized-alpha family a run integrates with (Time integration/integrator;
 * GeneralizedAlpha holds the coefficients and their sources).
 */
enum class IntegratorFamily
{
  newmark,          ///< Newmark (beta, gamma), the paper's integrator
  hht,              ///< Hilber, Hughes & Taylor 1977, by rho_inf in [1/2, 1]
  bossak,           ///< Wood, Bossak & Zienkiewicz 1980, by rho_inf in [0, 1]
  generalized_alpha ///< Chung & Hulbert 1993, by rho_inf in [0, 1]
};

/** The names of Time integration/integrator. */
inline const NameTable<IntegratorFamily>& integrator_family_names()
{
  static const NameTable<IntegratorFamily> names{
      {"newmark", IntegratorFamily::newmark},
      {"hht", IntegratorFamily::hht},
      {"bossak", IntegratorFamily::bossak},
      {"generalized-alpha", IntegratorFamily::generalized_alpha}};
  return names;
}
} // namespace dyncontact
