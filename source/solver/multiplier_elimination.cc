#include <tribos/solver/multiplier_elimination.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>

namespace tribos
{
  template <typename Index>
  void
  regularized_block_inverse(const unsigned int         size,
                            const std::vector<double> &G,
                            const std::vector<Index>  &rows,
                            const std::vector<double> &H,
                            const std::vector<Index>  &columns,
                            const double               stiffness,
                            const double               alpha,
                            LAPACKFullMatrix<double>  &D,
                            std::vector<double>       &inverse)
  {
    const unsigned int n_r = rows.size(), n_c = columns.size();
    D.compute_svd();
    const auto         &U  = D.get_svd_u();
    const auto         &VT = D.get_svd_vt();
    std::vector<double> Gv, Hw;
    inverse.assign(size * size, 0.);
    for (unsigned int s = 0; s < size; ++s)
    {
      // G v and H^T w of this singular pair, and their product over the
      // dofs both touch (rows and columns are sorted).
      Gv.assign(n_r, 0.);
      Hw.assign(n_c, 0.);
      for (unsigned int a = 0; a < n_r; ++a)
        for (unsigned int c = 0; c < size; ++c)
          Gv[a] += G[a * size + c] * VT(s, c);
      for (unsigned int a = 0; a < n_c; ++a)
        for (unsigned int c = 0; c < size; ++c)
          Hw[a] += U(c, s) * H[c * n_c + a];
      double g = 0, h = 0, product = 0;
      for (const double v : Gv)
        g += v * v;
      for (const double v : Hw)
        h += v * v;
      for (unsigned int a = 0, c = 0; a < n_r && c < n_c;)
        if (rows[a] < columns[c])
          ++a;
        else if (columns[c] < rows[a])
          ++c;
        else
          product += Gv[a++] * Hw[c++];
      const double penalty = alpha * std::sqrt(g * h) / stiffness;
      double       sigma   = D.singular_value(s);
      if (sigma < penalty)
        sigma = product > 0 ? -penalty : penalty;
      if (sigma == 0)
        sigma = 1; // no coupling either way: any value
      for (unsigned int c = 0; c < size; ++c)
        for (unsigned int d = 0; d < size; ++d)
          inverse[c * size + d] += VT(s, c) * U(d, s) / sigma;
    }
  }

  template void
  regularized_block_inverse<int>(const unsigned int,
                                 const std::vector<double> &,
                                 const std::vector<int> &,
                                 const std::vector<double> &,
                                 const std::vector<int> &,
                                 const double,
                                 const double,
                                 LAPACKFullMatrix<double> &,
                                 std::vector<double> &);
  template void
  regularized_block_inverse<types::global_dof_index>(
    const unsigned int,
    const std::vector<double> &,
    const std::vector<types::global_dof_index> &,
    const std::vector<double> &,
    const std::vector<types::global_dof_index> &,
    const double,
    const double,
    LAPACKFullMatrix<double> &,
    std::vector<double> &);



  bool
  MultiplierElimination::prepare(const CompressedRows &A,
                                 const int             first_multiplier,
                                 const unsigned int    block_size,
                                 CompressedRows       &r)
  {
    const auto &row_start = A.row_start;
    const auto &columns   = A.columns;
    const int   n         = A.n_rows();
    const int   m0        = first_multiplier;
    const int   size      = block_size;
    first                 = first_multiplier;
    this->size            = block_size;
    const auto position   = [&](const int i, const int j)
    {
      return A.position(i, j);
    };
    if (size == 0 || m0 <= 0 || m0 >= n || (n - m0) % size != 0)
      return false;
    const int n_blocks = (n - m0) / size;
    for (int i = m0; i < n; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        if (columns[k] >= m0 && (columns[k] - m0) / size != (i - m0) / size)
          return false;

    g_rows.assign(n_blocks, {});
    h_columns.assign(n_blocks, {});
    for (int i = 0; i < m0; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        if (columns[k] >= m0)
        {
          auto &rows = g_rows[(columns[k] - m0) / size];
          if (rows.empty() || rows.back() != i)
            rows.push_back(i);
        }
    for (int b = 0; b < n_blocks; ++b)
    {
      auto &h = h_columns[b];
      for (int i = m0 + b * size; i < m0 + (b + 1) * size; ++i)
        for (int k = row_start[i]; k < row_start[i + 1]; ++k)
          if (columns[k] < m0)
            h.push_back(columns[k]);
      std::sort(h.begin(), h.end());
      h.erase(std::unique(h.begin(), h.end()), h.end());
    }

    // The eliminated matrix's pattern: K's and, per block, rows x columns.
    std::vector<std::vector<int>> pattern(m0);
    for (int i = 0; i < m0; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        if (columns[k] < m0)
          pattern[i].push_back(columns[k]);
    for (int b = 0; b < n_blocks; ++b)
      for (const int i : g_rows[b])
        pattern[i].insert(pattern[i].end(),
                          h_columns[b].begin(),
                          h_columns[b].end());
    r.row_start.assign(m0 + 1, 0);
    r.columns.clear();
    for (int i = 0; i < m0; ++i)
    {
      auto &row = pattern[i];
      std::sort(row.begin(), row.end());
      row.erase(std::unique(row.begin(), row.end()), row.end());
      r.columns.insert(r.columns.end(), row.begin(), row.end());
      r.row_start[i + 1] = r.columns.size();
      row                = std::vector<int>();
    }
    r.values.assign(r.columns.size(), 0.);
    const auto reduced_position = [&](const int i, const int j)
    {
      const auto begin = r.columns.begin() + r.row_start[i];
      const auto end   = r.columns.begin() + r.row_start[i + 1];
      return int(std::lower_bound(begin, end, j) - r.columns.begin());
    };

    k_entries.assign(columns.size(), -1);
    diagonal.assign(m0, -1);
    for (int i = 0; i < m0; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        if (columns[k] < m0)
        {
          k_entries[k] = reduced_position(i, columns[k]);
          if (columns[k] == i)
            diagonal[i] = k;
        }
    g_entries.resize(n_blocks);
    h_entries.resize(n_blocks);
    d_entries.resize(n_blocks);
    s_entries.resize(n_blocks);
    inverse.assign(n_blocks, std::vector<double>(size * size));
    for (int b = 0; b < n_blocks; ++b)
    {
      const auto &rows = g_rows[b];
      const auto &cols = h_columns[b];
      const int   j0   = m0 + b * size;
      g_entries[b].resize(rows.size() * size);
      for (unsigned int a = 0; a < rows.size(); ++a)
        for (int c = 0; c < size; ++c)
          g_entries[b][a * size + c] = position(rows[a], j0 + c);
      h_entries[b].resize(size * cols.size());
      d_entries[b].resize(size * size);
      for (int c = 0; c < size; ++c)
      {
        for (unsigned int a = 0; a < cols.size(); ++a)
          h_entries[b][c * cols.size() + a] = position(j0 + c, cols[a]);
        for (int d = 0; d < size; ++d)
          d_entries[b][c * size + d] = position(j0 + c, j0 + d);
      }
      s_entries[b].resize(rows.size() * cols.size());
      for (unsigned int a = 0; a < rows.size(); ++a)
        for (unsigned int c = 0; c < cols.size(); ++c)
          s_entries[b][a * cols.size() + c] =
            reduced_position(rows[a], cols[c]);
    }
    residual.resize(n);
    correction.resize(n);
    right_hand_side.resize(m0); // apply()'s
    return true;
  }



  void
  MultiplierElimination::eliminate(const CompressedRows &A,
                                   const double          alpha,
                                   CompressedRows       &r)
  {
    const auto &row_start = A.row_start;
    const auto &values    = A.values;
    const int   n         = A.n_rows();
    const int   m0        = first;
    const int   size      = this->size;
    const int   n_blocks  = (n - m0) / size;
    const auto  value     = [&](const int k)
    {
      return k < 0 ? 0. : values[k];
    };

    std::fill(r.values.begin(), r.values.end(), 0.);
    for (int i = 0; i < m0; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        if (k_entries[k] >= 0)
          r.values[k_entries[k]] += values[k];

    LAPACKFullMatrix<double> D(size, size);
    std::vector<double>      G, H, GI;
    for (int blk = 0; blk < n_blocks; ++blk)
    {
      const auto        &rows = g_rows[blk];
      const auto        &cols = h_columns[blk];
      const unsigned int n_r = rows.size(), n_c = cols.size();
      G.resize(n_r * size);
      H.resize(size * n_c);
      for (unsigned int k = 0; k < G.size(); ++k)
        G[k] = value(g_entries[blk][k]);
      for (unsigned int k = 0; k < H.size(); ++k)
        H[k] = value(h_entries[blk][k]);
      D.reinit(size, size);
      for (int c = 0; c < size; ++c)
        for (int d = 0; d < size; ++d)
          D(c, d) = value(d_entries[blk][c * size + d]);
      double stiffness = 0;
      for (const int i : rows)
        stiffness = std::max(stiffness, std::abs(value(diagonal[i])));
      for (const int j : cols)
        stiffness = std::max(stiffness, std::abs(value(diagonal[j])));
      if (stiffness == 0)
        stiffness = 1;

      regularized_block_inverse(size,
                                G,
                                rows,
                                H,
                                cols,
                                stiffness,
                                alpha,
                                D,
                                inverse[blk]);

      // K - G D^-1 H.
      GI.assign(n_r * size, 0.);
      for (unsigned int a = 0; a < n_r; ++a)
        for (int c = 0; c < size; ++c)
          for (int d = 0; d < size; ++d)
            GI[a * size + d] += G[a * size + c] * inverse[blk][c * size + d];
      for (unsigned int a = 0; a < n_r; ++a)
        for (unsigned int c = 0; c < n_c; ++c)
        {
          double sum = 0;
          for (int d = 0; d < size; ++d)
            sum += GI[a * size + d] * H[d * n_c + c];
          r.values[s_entries[blk][a * n_c + c]] -= sum;
        }
    }
  }



  bool
  MultiplierElimination::apply(const CompressedRows &A,
                               const double         *z,
                               double               *y,
                               const ReducedSolve   &solve)
  {
    // The multipliers' part first through D~^-1, then the reduced solve,
    // then the multipliers from their rows.
    const int  m0       = first;
    const int  size     = this->size;
    const int  n_blocks = (A.n_rows() - m0) / size;
    const auto value    = [&](const int k)
    {
      return k < 0 ? 0. : A.values[k];
    };
    auto &f = right_hand_side;
    std::copy_n(z, m0, f.begin());
    for (int blk = 0; blk < n_blocks; ++blk)
    {
      const double *zl = z + m0 + blk * size;
      double        t[3];
      for (int c = 0; c < size; ++c)
      {
        t[c] = 0;
        for (int d = 0; d < size; ++d)
          t[c] += inverse[blk][c * size + d] * zl[d];
      }
      const auto &rows = g_rows[blk];
      for (unsigned int a = 0; a < rows.size(); ++a)
        for (int c = 0; c < size; ++c)
          f[rows[a]] -= value(g_entries[blk][a * size + c]) * t[c];
    }
    if (!solve(y, f.data()))
      return false;
    for (int blk = 0; blk < n_blocks; ++blk)
    {
      const auto &cols = h_columns[blk];
      double      q[3];
      for (int c = 0; c < size; ++c)
      {
        q[c] = z[m0 + blk * size + c];
        for (unsigned int a = 0; a < cols.size(); ++a)
          q[c] -= value(h_entries[blk][c * cols.size() + a]) * y[cols[a]];
      }
      for (int c = 0; c < size; ++c)
      {
        double sum = 0;
        for (int d = 0; d < size; ++d)
          sum += inverse[blk][c * size + d] * q[d];
        y[m0 + blk * size + c] = sum;
      }
    }
    return true;
  }



  bool
  MultiplierElimination::refine(const CompressedRows &A,
                                const double         *b,
                                double               *x,
                                const double          tolerance,
                                const ReducedSolve   &solve,
                                unsigned int         &n_refinements)
  {
    const int n   = A.n_rows();
    n_refinements = 0;
    auto &res     = residual;
    auto &dx      = correction;
    std::copy_n(b, n, res.begin());
    std::fill_n(x, n, 0.);
    double norm_b = 0;
    for (int i = 0; i < n; ++i)
      norm_b += b[i] * b[i];
    norm_b = std::sqrt(norm_b);
    if (norm_b == 0)
      return true;
    double previous = norm_b;
    for (unsigned int step = 0; step < 30; ++step)
    {
      if (!apply(A, res.data(), dx.data(), solve))
        return false;
      for (int i = 0; i < n; ++i)
        x[i] += dx[i];
      double norm_r = 0;
      for (int i = 0; i < n; ++i)
      {
        double sum = b[i];
        for (int k = A.row_start[i]; k < A.row_start[i + 1]; ++k)
          sum -= A.values[k] * x[A.columns[k]];
        res[i] = sum;
        norm_r += sum * sum;
      }
      norm_r        = std::sqrt(norm_r);
      n_refinements = step + 1;
      if (norm_r <= tolerance * norm_b)
        return true;
      // Stagnation: at round-off if small enough, else a failure.
      if (norm_r > 0.5 * previous)
        return norm_r <= 1e-10 * norm_b;
      previous = norm_r;
    }
    return false;
  }
} // namespace tribos
