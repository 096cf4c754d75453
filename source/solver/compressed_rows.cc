#include <tribos/solver/compressed_rows.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace tribos
{
  void
  CompressedRows::extract(const TrilinosWrappers::SparseMatrix &matrix,
                          const bool                            new_pattern)
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    const int               n = A.NumMyRows();
    AssertThrow(A.NumGlobalRows() == n,
                ExcMessage("A sparse direct solve on one process needs "
                           "every row on it."));
    int     length;
    double *entries;
    int    *indices;
    if (!new_pattern)
    {
      for (int i = 0; i < n; ++i)
      {
        A.ExtractMyRowView(i, length, entries, indices);
        for (int k = row_start[i]; k < row_start[i + 1]; ++k)
          values[k] = entries[source[k]];
      }
      return;
    }
    row_start.assign(n + 1, 0);
    columns.clear();
    source.clear();
    columns.reserve(A.NumMyNonzeros());
    source.reserve(A.NumMyNonzeros());
    std::vector<std::pair<int, int>> row;
    for (int i = 0; i < n; ++i)
    {
      AssertThrow(A.RowMap().GID(i) == i,
                  ExcMessage("A sparse direct solve needs the rows in "
                             "order."));
      A.ExtractMyRowView(i, length, entries, indices);
      row.resize(length);
      for (int k = 0; k < length; ++k)
        row[k] = {A.ColMap().GID(indices[k]), k};
      std::sort(row.begin(), row.end());
      for (const auto &[j, k] : row)
      {
        columns.push_back(j);
        source.push_back(k);
      }
      row_start[i + 1] = columns.size();
    }
    values.resize(columns.size());
    extract(matrix, false);
  }



  bool
  CompressedRows::symmetric() const
  {
    double largest = 0;
    for (const double a : values)
      largest = std::max(largest, std::abs(a));
    const double tolerance = 1e-10 * largest;
    for (int i = 0; i < n_rows(); ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
      {
        const int j = columns[k];
        if (j <= i)
          continue;
        const int    t          = position(j, i);
        const double transposed = t >= 0 ? values[t] : 0.;
        if (std::abs(values[k] - transposed) > tolerance)
          return false;
      }
    return true;
  }



  int
  CompressedRows::position(const int i, const int j) const
  {
    const auto begin = columns.begin() + row_start[i];
    const auto end   = columns.begin() + row_start[i + 1];
    const auto found = std::lower_bound(begin, end, j);
    return (found != end && *found == j) ? int(found - columns.begin()) : -1;
  }



  void
  CompressedRows::vmult(const double *x, double *y) const
  {
    for (int i = 0; i < n_rows(); ++i)
    {
      double sum = 0;
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        sum += values[k] * x[columns[k]];
      y[i] = sum;
    }
  }
} // namespace tribos
