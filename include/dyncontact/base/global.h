#pragma once

#include <deal.II/base/exceptions.h>

#include <charconv>
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
 * A number with every digit it needs: the shortest text that reads back as exactly `value`
 * (0.3 stays "0.3", 0.1 + 0.2 becomes "0.30000000000000004"). For messages about values that
 * differ in digits format_number() drops, such as an overlap of 1e-11 at x = 0.3.
 */
inline std::string format_exact(const double value)
{
  char text[32];
  const auto end = std::to_chars(text, text + sizeof(text), value).ptr;
  return std::string(text, end);
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
