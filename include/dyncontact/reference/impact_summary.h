#pragma once

#include <dyncontact/postprocess/history.h>
#include <dyncontact/reference/finite_sphere_impact.h>
#include <dyncontact/reference/hertz_impact.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * The references of a head-on sphere impact, written beside a run: hertz_parameters.csv and
 * hertz.csv (time, contact_force, approach of Hertz's theory at `times`) and, if `law` is given,
 * finite_sphere_parameters.csv and finite_sphere.csv (the same columns; its approach times
 * `law_approach_scale`, 1/2 against a rigid plane, whose law is the mirrored pair's). Plain CSV:
 * a header row, then numbers.
 */
void write_impact_references(const std::string& directory,
                             const std::vector<double>& times,
                             const HertzImpact& hertz,
                             const std::optional<FiniteSphereImpact>& law,
                             double law_approach_scale);

/**
 * Measures the contact force history of `history` (measure_impact(), the force times
 * `whole_body_factor`: 4 for a quarter model on two symmetry planes, else 1) and writes
 * impact_summary.csv: peak force, its time, contact start, end and duration, impulse (`impulse`,
 * the whole bodies' contact impulse along the approach, compression positive) and ringing next to
 * Hertz's values and the relative differences, and, if `law` is given, its values and the
 * differences from it (columns finite_sphere, finite_sphere_difference); `status` ("complete" or
 * "incomplete: <why>") on every row. A short report goes to `log`. A history of fewer than 3 rows
 * has nothing to measure: nothing is written, and `log` says so.
 */
void write_impact_summary(const std::string& directory,
                          const History& history,
                          double whole_body_factor,
                          double impulse,
                          const HertzImpact& hertz,
                          const std::optional<FiniteSphereImpact>& law,
                          const std::string& status,
                          std::ostream& log);
} // namespace dyncontact
