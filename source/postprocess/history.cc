#include <dyncontact/postprocess/history.h>

#include <algorithm>
#include <iomanip>
#include <stdexcept>

namespace dyncontact
{
History::History(std::vector<std::string> column_names) : names(std::move(column_names)) {}

void History::attach_file(const std::string& filename)
{
  file.open(filename);
  if (!file)
    throw InputError("cannot write '" + filename + "'.");
  for (unsigned int c = 0; c < names.size(); ++c)
    file << (c > 0 ? "," : "") << names[c];
  file << '\n' << std::setprecision(15);
  for (const auto& row : rows)
    write_row(row);
  file.flush();
}

void History::add_row(const std::vector<double>& values)
{
  AssertDimension(values.size(), names.size());
  rows.push_back(values);
  if (file.is_open())
  {
    write_row(values);
    file.flush();
  }
}

void History::write_row(const std::vector<double>& values)
{
  for (unsigned int c = 0; c < values.size(); ++c)
    file << (c > 0 ? "," : "") << values[c];
  file << '\n';
}

unsigned int History::column_index(const std::string& name) const
{
  const auto position = std::find(names.begin(), names.end(), name);
  if (position == names.end())
    throw std::out_of_range("History has no column '" + name + "'.");
  return position - names.begin();
}

std::vector<double> History::column(const std::string& name) const
{
  const unsigned int index = column_index(name);
  std::vector<double> values;
  values.reserve(rows.size());
  for (const auto& row : rows)
    values.push_back(row[index]);
  return values;
}

double History::value(const unsigned int row, const std::string& name) const
{
  AssertIndexRange(row, rows.size());
  return rows[row][column_index(name)];
}
} // namespace dyncontact
