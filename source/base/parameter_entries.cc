#include <dyncontact/base/parameter_entries.h>

#include <sstream>

namespace dyncontact
{
/**
 * The text deal.II attaches to one of its exceptions, without file/line decoration, on one line:
 * every run of white space (line breaks included) becomes one blank.
 */
std::string exception_text(const ExceptionBase& exception)
{
  std::ostringstream text;
  exception.print_info(text);
  std::istringstream words(text.str());
  std::string word, message;
  while (words >> word)
    message += (message.empty() ? "" : " ") + word;
  return message;
}

/** Reads a double that must be strictly positive, naming `section/entry` if it is not. */
double get_positive(ParameterHandler& prm, const std::string& entry, const std::string& section)
{
  const double value = prm.get_double(entry);
  if (!(value > 0.))
    throw InputError(section + "/" + entry + " = " + prm.get(entry) +
                     " is not allowed: it must be > 0.");
  return value;
}

/** Reads a number that must lie in [low, high], naming `section/entry` and the range if not. */
double get_in_range(ParameterHandler& prm,
                    const std::string& entry,
                    const std::string& section,
                    const double low,
                    const double high)
{
  const double value = prm.get_double(entry);
  if (!(value >= low && value <= high))
    throw InputError(section + "/" + entry + " = " + prm.get(entry) +
                     " is not allowed: it must lie in " + format_number(low) + ".." +
                     format_number(high) + ".");
  return value;
}
} // namespace dyncontact
