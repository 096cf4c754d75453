#include <tribos/solver/distributed_elimination.h>
#include <tribos/solver/multiplier_elimination.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace tribos
{
  namespace
  {
    /** The position of @p index in the sorted @p list. */
    unsigned int
    position(const std::vector<types::global_dof_index> &list,
             const types::global_dof_index               index)
    {
      const auto it = std::lower_bound(list.begin(), list.end(), index);
      AssertThrow(it != list.end() && *it == index, ExcInternalError());
      return it - list.begin();
    }
  } // namespace



  bool
  DistributedElimination::prepare(const TrilinosWrappers::SparseMatrix &A,
                                  const types::global_dof_index         first,
                                  const unsigned int                    size)
  {
    communicator             = A.get_mpi_communicator();
    this->first              = first;
    this->size               = size;
    const auto  n            = A.m();
    const auto &system_owned = A.locally_owned_range_indices();
    AssertThrow(size > 0 && size <= 3 && first < n && (n - first) % size == 0,
                ExcInternalError());
    owned = system_owned.get_view(0, first);

    // The blocks of this process, and the owner of every block.
    std::vector<unsigned int> mine;
    for (const auto i : system_owned.get_view(first, n))
      if (i % size == 0)
        mine.push_back(i / size);
    block_owner.assign((n - first) / size, 0);
    const auto all = Utilities::MPI::all_gather(communicator, mine);
    for (unsigned int rank = 0; rank < all.size(); ++rank)
      for (const auto b : all[rank])
        block_owner[b] = rank;
    blocks.assign(mine.size(), Block());
    for (unsigned int k = 0; k < mine.size(); ++k)
      blocks[k].first = first + mine[k] * size;

    // Per owned row: its diagonal entry, and whether it has entries in
    // multiplier columns (the rows gather_columns() sends).
    const Epetra_CrsMatrix &E = A.trilinos_matrix();
    int                     length;
    double                 *values;
    int                    *indices;
    diagonal_position.assign(owned.n_elements(), -1);
    coupled_rows.clear();
    for (int r = 0; r < int(owned.n_elements()); ++r)
    {
      const types::global_dof_index i = owned.nth_index_in_set(r);
      AssertThrow(E.RowMap().GID(r) == int(i), ExcInternalError());
      E.ExtractMyRowView(r, length, values, indices);
      bool coupled = false;
      for (int k = 0; k < length; ++k)
      {
        const types::global_dof_index j = E.ColMap().GID(indices[k]);
        if (j == i)
          diagonal_position[r] = k;
        coupled = coupled || j >= first;
      }
      if (coupled)
        coupled_rows.push_back(r);
    }

    const bool separate = read_rows(A, true);
    if (Utilities::MPI::min(separate ? 1 : 0, communicator) == 0)
      return false;
    gather_columns(A, true);

    IndexSet g_rows(first);
    h_columns = IndexSet(first);
    for (const auto &b : blocks)
    {
      g_rows.add_indices(b.rows.begin(), b.rows.end());
      h_columns.add_indices(b.columns.begin(), b.columns.end());
    }
    g_rows.compress();
    h_columns.compress();

    // The pattern: K's and, per block, rows x columns (rows anywhere).
    IndexSet relevant = owned;
    relevant.add_indices(g_rows);
    DynamicSparsityPattern               pattern(first, first, relevant);
    std::vector<types::global_dof_index> row;
    for (const auto i : owned)
    {
      E.ExtractMyRowView(E.RowMap().LID(int(i)), length, values, indices);
      row.clear();
      for (int k = 0; k < length; ++k)
      {
        const types::global_dof_index j = E.ColMap().GID(indices[k]);
        if (j < first)
          row.push_back(j);
      }
      std::sort(row.begin(), row.end());
      pattern.add_entries(i, row.begin(), row.end(), true);
    }
    for (const auto &b : blocks)
      for (const auto i : b.rows)
        pattern.add_entries(i, b.columns.begin(), b.columns.end(), true);
    SparsityTools::distribute_sparsity_pattern(pattern,
                                               owned,
                                               communicator,
                                               relevant);
    reduced.clear();
    reduced.reinit(owned, owned, pattern, communicator);

    // Where eliminate() copies K to.
    const Epetra_CrsMatrix &R = reduced.trilinos_matrix();
    AssertThrow(R.NumMyRows() == int(owned.n_elements()), ExcInternalError());
    column_in_reduced.assign(E.NumMyCols(), -1);
    for (int c = 0; c < E.NumMyCols(); ++c)
    {
      const types::global_dof_index j = E.ColMap().GID(c);
      if (j < first)
      {
        column_in_reduced[c] = R.ColMap().LID(int(j));
        AssertThrow(column_in_reduced[c] >= 0, ExcInternalError());
      }
    }
    // eliminate() finds entries by bisection.
    for (int r = 0; r < R.NumMyRows(); ++r)
    {
      R.ExtractMyRowView(r, length, values, indices);
      AssertThrow(std::is_sorted(indices, indices + length),
                  ExcInternalError());
    }

    IndexSet ghosts = owned;
    ghosts.add_indices(h_columns);
    f.reinit(owned, communicator);
    y_reduced.reinit(owned, communicator);
    y_ghosted.reinit(owned, ghosts, communicator);
    import = std::make_unique<Epetra_Import>(y_ghosted.trilinos_vector().Map(),
                                             y_reduced.trilinos_vector().Map());
    diagonal.reinit(owned, ghosts, communicator);
    return true;
  }



  bool
  DistributedElimination::read_rows(const TrilinosWrappers::SparseMatrix &A,
                                    const bool pattern)
  {
    const Epetra_CrsMatrix &E = A.trilinos_matrix();
    // f(c, j, value) for every entry (column j) of the block's row c.
    const auto for_each_entry = [&](const Block &b, const auto &f)
    {
      int     length;
      double *values;
      int    *indices;
      for (unsigned int c = 0; c < size; ++c)
      {
        E.ExtractMyRowView(E.RowMap().LID(int(b.first + c)),
                           length,
                           values,
                           indices);
        for (int k = 0; k < length; ++k)
          f(c, types::global_dof_index(E.ColMap().GID(indices[k])), values[k]);
      }
    };
    bool separate = true;
    for (auto &b : blocks)
    {
      if (pattern)
      {
        b.columns.clear();
        for_each_entry(b,
                       [&](unsigned int, types::global_dof_index j, double)
                       {
                         if (j < first)
                           b.columns.push_back(j);
                         else if (j < b.first || j >= b.first + size)
                           separate = false;
                       });
        std::sort(b.columns.begin(), b.columns.end());
        b.columns.erase(std::unique(b.columns.begin(), b.columns.end()),
                        b.columns.end());
      }
      if (!separate)
        return false;
      b.h.assign(size * b.columns.size(), 0.);
      b.d.assign(size * size, 0.);
      for_each_entry(b,
                     [&](const unsigned int            c,
                         const types::global_dof_index j,
                         const double                  value)
                     {
                       if (j < first)
                         b.h[c * b.columns.size() + position(b.columns, j)] +=
                           value;
                       else
                         b.d[c * size + (j - b.first)] += value;
                     });
    }
    return true;
  }



  void
  DistributedElimination::gather_columns(
    const TrilinosWrappers::SparseMatrix &A,
    const bool                            pattern)
  {
    // Per entry of a displacement row in a multiplier column: the block,
    // the row, the multiplier of the block, the value and the row's
    // diagonal entry, to the block's owner.
    const Epetra_CrsMatrix                     &E = A.trilinos_matrix();
    int                                         length;
    double                                     *values;
    int                                        *indices;
    std::map<unsigned int, std::vector<double>> send;
    for (const int r : coupled_rows)
    {
      const types::global_dof_index i = E.RowMap().GID(r);
      E.ExtractMyRowView(r, length, values, indices);
      const double diagonal_entry =
        diagonal_position[r] >= 0 ? values[diagonal_position[r]] : 0.;
      for (int k = 0; k < length; ++k)
      {
        const types::global_dof_index j = E.ColMap().GID(indices[k]);
        if (j < first)
          continue;
        const unsigned int b = (j - first) / size;
        auto              &m = send[block_owner[b]];
        m.insert(m.end(),
                 {double(b),
                  double(i),
                  double((j - first) % size),
                  values[k],
                  diagonal_entry});
      }
    }
    const auto received = Utilities::MPI::some_to_some(communicator, send);

    // The blocks of this process by global number.
    std::map<types::global_dof_index, unsigned int> local;
    for (unsigned int k = 0; k < blocks.size(); ++k)
      local[(blocks[k].first - first) / size] = k;
    if (pattern)
    {
      for (auto &b : blocks)
        b.rows.clear();
      for (const auto &[rank, m] : received)
        for (std::size_t k = 0; k < m.size(); k += 5)
          blocks[local.at(types::global_dof_index(m[k]))].rows.push_back(
            types::global_dof_index(m[k + 1]));
      for (auto &b : blocks)
      {
        std::sort(b.rows.begin(), b.rows.end());
        b.rows.erase(std::unique(b.rows.begin(), b.rows.end()), b.rows.end());
      }
    }
    for (auto &b : blocks)
    {
      b.g.assign(b.rows.size() * size, 0.);
      b.row_diagonal.assign(b.rows.size(), 0.);
    }
    for (const auto &[rank, m] : received)
      for (std::size_t k = 0; k < m.size(); k += 5)
      {
        auto              &b = blocks[local.at(types::global_dof_index(m[k]))];
        const unsigned int a =
          position(b.rows, types::global_dof_index(m[k + 1]));
        b.g[a * size + (unsigned int)(m[k + 2])] += m[k + 3];
        b.row_diagonal[a] = m[k + 4];
      }
  }



  void
  DistributedElimination::eliminate(const TrilinosWrappers::SparseMatrix &A,
                                    const double                          alpha)
  {
    read_rows(A, false);
    gather_columns(A, false);

    // K, and its diagonal for the regularization's scale, row by row
    // through the maps prepare() made (local indices, sorted rows).
    reduced                   = 0;
    const Epetra_CrsMatrix &E = A.trilinos_matrix();
    // Epetra's views are writable through a const matrix.
    const Epetra_CrsMatrix &R = reduced.trilinos_matrix();
    Vector                  own_diagonal(owned, communicator);
    double                 *diagonal_values = own_diagonal.trilinos_vector()[0];
    int                     length, r_length;
    double                 *values, *r_values;
    int                    *indices, *r_indices;
    for (int r = 0; r < int(owned.n_elements()); ++r)
    {
      E.ExtractMyRowView(r, length, values, indices);
      R.ExtractMyRowView(r, r_length, r_values, r_indices);
      for (int k = 0; k < length; ++k)
      {
        const int c = column_in_reduced[indices[k]];
        if (c >= 0)
          r_values[std::lower_bound(r_indices, r_indices + r_length, c) -
                   r_indices] += values[k];
      }
      diagonal_values[r] =
        diagonal_position[r] >= 0 ? values[diagonal_position[r]] : 0.;
    }
    diagonal = own_diagonal;

    std::vector<double>      entries;
    LAPACKFullMatrix<double> D(size, size);
    std::vector<double>      GI;
    for (auto &b : blocks)
    {
      const unsigned int n_r = b.rows.size(), n_c = b.columns.size();
      double             stiffness = 0;
      for (const double k : b.row_diagonal)
        stiffness = std::max(stiffness, std::abs(k));
      for (const auto j : b.columns)
        stiffness = std::max(stiffness, std::abs(diagonal(j)));
      if (stiffness == 0)
        stiffness = 1;
      D.reinit(size, size);
      for (unsigned int c = 0; c < size; ++c)
        for (unsigned int d = 0; d < size; ++d)
          D(c, d) = b.d[c * size + d];
      regularized_block_inverse(size,
                                b.g,
                                b.rows,
                                b.h,
                                b.columns,
                                stiffness,
                                alpha,
                                D,
                                b.inverse);

      // - G D~^-1 H into the rows of G.
      GI.assign(n_r * size, 0.);
      for (unsigned int a = 0; a < n_r; ++a)
        for (unsigned int c = 0; c < size; ++c)
          for (unsigned int d = 0; d < size; ++d)
            GI[a * size + d] += b.g[a * size + c] * b.inverse[c * size + d];
      entries.resize(n_c);
      for (unsigned int a = 0; a < n_r; ++a)
      {
        for (unsigned int c = 0; c < n_c; ++c)
        {
          double sum = 0;
          for (unsigned int d = 0; d < size; ++d)
            sum += GI[a * size + d] * b.h[d * n_c + c];
          entries[c] = -sum;
        }
        reduced.add(b.rows[a], b.columns, entries, false);
      }
    }
    reduced.compress(VectorOperation::add);
  }



  void
  DistributedElimination::apply(const Vector       &z,
                                Vector             &y,
                                const ReducedSolve &solve)
  {
    // The multipliers' part through D~^-1 into the rows of G, the reduced
    // solve, then the multipliers from their rows.
    const unsigned int n_own = owned.n_elements();
    const auto        &Z     = z.trilinos_vector();
    auto              &Y     = y.trilinos_vector();
    std::copy_n(Z[0], n_own, f.trilinos_vector()[0]);
    std::vector<types::global_dof_index> rows;
    std::vector<double>                  values;
    double                               t[3];
    for (const auto &b : blocks)
    {
      const double *zl = Z[0] + Z.Map().LID(int(b.first));
      for (unsigned int c = 0; c < size; ++c)
      {
        t[c] = 0;
        for (unsigned int d = 0; d < size; ++d)
          t[c] += b.inverse[c * size + d] * zl[d];
      }
      for (unsigned int a = 0; a < b.rows.size(); ++a)
      {
        double sum = 0;
        for (unsigned int c = 0; c < size; ++c)
          sum += b.g[a * size + c] * t[c];
        rows.push_back(b.rows[a]);
        values.push_back(-sum);
      }
    }
    f.add(rows, values);
    f.compress(VectorOperation::add);

    solve(y_reduced, f);
    y_ghosted.trilinos_vector().Import(y_reduced.trilinos_vector(),
                                       *import,
                                       Insert);
    std::copy_n(y_reduced.trilinos_vector()[0], n_own, Y[0]);
    double q[3];
    for (const auto &b : blocks)
    {
      const double      *zl  = Z[0] + Z.Map().LID(int(b.first));
      double            *yl  = Y[0] + Y.Map().LID(int(b.first));
      const unsigned int n_c = b.columns.size();
      for (unsigned int c = 0; c < size; ++c)
      {
        q[c] = zl[c];
        for (unsigned int a = 0; a < n_c; ++a)
          q[c] -= b.h[c * n_c + a] * y_ghosted(b.columns[a]);
      }
      for (unsigned int c = 0; c < size; ++c)
      {
        yl[c] = 0;
        for (unsigned int d = 0; d < size; ++d)
          yl[c] += b.inverse[c * size + d] * q[d];
      }
    }
  }
} // namespace tribos
