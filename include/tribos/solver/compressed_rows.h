#ifndef tribos_solver_compressed_rows_h
#define tribos_solver_compressed_rows_h

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * A sparse matrix held on one process in compressed rows with sorted
   * global column indices: the form SuiteSparse (as the transpose's
   * compressed columns) and the multiplier elimination work on, copied
   * from a Trilinos matrix whose every row this process owns.
   */
  struct CompressedRows
  {
    std::vector<int>    row_start, columns;
    std::vector<double> values;
    /** Per entry, its position in the Trilinos row it was copied from. */
    std::vector<int> source;

    int
    n_rows() const
    {
      return int(row_start.size()) - 1;
    }

    /**
     * Copy @p matrix; with @p new_pattern false only the values (same
     * pattern, same order: no column lookup and no sort).
     */
    void
    extract(const TrilinosWrappers::SparseMatrix &matrix,
            const bool                            new_pattern);

    /** Whether the values are symmetric to 1e-10 of the largest entry. */
    bool
    symmetric() const;

    /** The position of entry (@p i, @p j) in columns and values, -1 if
     * the pattern has none. */
    int
    position(const int i, const int j) const;

    /** y = this x. */
    void
    vmult(const double *x, double *y) const;
  };
} // namespace tribos

#endif
