#pragma once

#include <dyncontact/base/global.h>

#include <algorithm>
#include <boost/serialization/vector.hpp>
#include <fstream>
#include <string>
#include <vector>

namespace dyncontact
{
/**
 * A table of named columns with one row per time step: kept in memory (tests read it back) and,
 * once a file is attached, appended to a CSV file row by row and flushed, so that a run that
 * stops early keeps every row it completed. It does not compute anything.
 */
class History
{
public:
  explicit History(std::vector<std::string> column_names);

  /** Starts writing to `filename` (header and the rows so far); throws InputError if it cannot. */
  void attach_file(const std::string& filename);

  /** Appends a row; the number of values must match the number of columns. */
  void add_row(const std::vector<double>& values);

  const std::vector<std::string>& column_names() const { return names; }

  /** Whether there is a column `name`. */
  bool has_column(const std::string& name) const
  {
    return std::find(names.begin(), names.end(), name) != names.end();
  }
  unsigned int n_rows() const { return rows.size(); }

  /** All values of column `name`; throws std::out_of_range if there is no such column. */
  std::vector<double> column(const std::string& name) const;

  /** All values of row `index`, in column order. */
  const std::vector<double>& row(const unsigned int index) const
  {
    AssertIndexRange(index, rows.size());
    return rows[index];
  }

  /** Value of column `name` in row `row`. */
  double value(unsigned int row, const std::string& name) const;

  /** Writes or reads the rows (checkpoints; attach the file after reading). */
  template <class Archive>
  void serialize(Archive& archive, const unsigned int)
  {
    archive& rows;
  }

private:
  unsigned int column_index(const std::string& name) const;
  void write_row(const std::vector<double>& values);

  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  std::ofstream file;
};
} // namespace dyncontact
