#pragma once

#include <Epetra_CrsMatrix.h>

namespace dyncontact
{
/**
 * Calls f(global row, global column, value) for every stored entry of this rank's rows of
 * `matrix`, row by row in the local row order and, within a row, in storage order (the same
 * order on every call for a matrix whose pattern does not change).
 */
template <typename Function>
void for_each_entry(const Epetra_CrsMatrix& matrix, const Function& f)
{
  for (int row = 0; row < matrix.NumMyRows(); ++row)
  {
    int n_entries;
    double* values;
    int* columns;
    matrix.ExtractMyRowView(row, n_entries, values, columns);
    for (int k = 0; k < n_entries; ++k)
      f(matrix.GRID64(row), matrix.GCID64(columns[k]), values[k]);
  }
}
} // namespace dyncontact
