#pragma once

#include <deal.II/base/exceptions.h>

#include <sstream>
#include <stdexcept>
#include <string>

/**
 * Everything of dyncontact lives in this namespace; deal.II's names are imported here only, never
 * at global scope.
 */
namespace dyncontact
{
using namespace dealii;

/** A number as a user wants to read it in a message: %g style, 6 significant digits. */
inline std::string format_number(const double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

/**
 * A problem the user caused and can fix: a bad parameter value, an unreadable file, an output
 * directory that cannot be written. The message names the parameter or file and says what is
 * allowed. It is not for programming errors (those are deal.II Asserts).
 */
class InputError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * A solve that could not be completed (Newton or the contact active set did not converge). The
 * message says at which step and why; what was already written stays on disk.
 */
class SolverFailure : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};
} // namespace dyncontact
