#pragma once

#include <dyncontact/base/global.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * The names of one enumerated choice of the parameter file, in one place: the Patterns::Selection
 * string declared, the parse (an unknown name is an InputError naming the entry and the allowed
 * names, never a silent fall-through to a default) and the name printed back in logs and records.
 */
template <typename Enum>
class NameTable
{
public:
  NameTable(std::initializer_list<std::pair<std::string, Enum>> entries) : entries(entries) {}

  /** "name1|name2|...", for Patterns::Selection. */
  std::string selection() const
  {
    std::string names;
    for (const auto& [name, value] : entries)
      names += (names.empty() ? "" : "|") + name;
    return names;
  }

  /**
   * The value called `name`. `entry` ("Section/entry") names the parameter in the InputError
   * thrown for any other name.
   */
  Enum parse(const std::string& name, const std::string& entry) const
  {
    for (const auto& [known, value] : entries)
      if (known == name)
        return value;
    std::string allowed;
    for (const auto& [known, value] : entries)
      allowed += (allowed.empty() ? "'" : ", '") + known + "'";
    throw InputError(entry + " = '" + name + "' is not allowed: it must be one of " + allowed +
                     ".");
  }

  /** The name of `value`; every enumerator is in the table. */
  const std::string& name(const Enum value) const
  {
    for (const auto& [known, known_value] : entries)
      if (known_value == value)
        return known;
    throw std::logic_error("NameTable: an enumerator without a name");
  }

  /** Every (name, value), in the table's order. */
  const std::vector<std::pair<std::string, Enum>>& pairs() const { return entries; }

private:
  std::vector<std::pair<std::string, Enum>> entries;
};
} // namespace dyncontact
