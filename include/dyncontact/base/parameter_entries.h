#pragma once

#include <dyncontact/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace dyncontact
{
// Helpers of the modules' parse_parameters(): an entry read with its allowed range, every error an
// InputError naming `section/entry`.

/**
 * The text deal.II attaches to one of its exceptions, without file/line decoration, on one line:
 * every run of white space (line breaks included) becomes one blank.
 */
std::string exception_text(const ExceptionBase& exception);

/** Reads a double that must be strictly positive, naming `section/entry` if it is not. */
double get_positive(ParameterHandler& prm, const std::string& entry, const std::string& section);

/** Reads a number that must lie in [low, high], naming `section/entry` and the range if not. */
double get_in_range(ParameterHandler& prm,
                    const std::string& entry,
                    const std::string& section,
                    double low,
                    double high);

/**
 * Calls f(i, name) inside each of the subsections `prefix 1` .. `prefix n` of the current one,
 * i = 0 .. n - 1, name = "prefix i+1" (e.g. Contact/Pair 1, Bodies/Body 2, Geometry/Bar 3).
 */
template <typename Function>
void for_each_numbered_subsection(ParameterHandler& prm,
                                  const std::string& prefix,
                                  const unsigned int n,
                                  const Function& f)
{
  for (unsigned int i = 0; i < n; ++i)
  {
    const std::string name = prefix + " " + std::to_string(i + 1);
    prm.enter_subsection(name);
    f(i, name);
    prm.leave_subsection();
  }
}
} // namespace dyncontact
