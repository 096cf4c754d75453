#include <tribos/solver/sparse_direct.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_FEVector.h>
#include <Epetra_Map.h>
#include <cholmod.h>
#include <omp.h>
#include <umfpack.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace tribos
{
  struct SparseDirect::State
  {
    cholmod_common  common;
    cholmod_factor *factor           = nullptr;
    void           *umfpack_symbolic = nullptr;
    void           *umfpack_numeric  = nullptr;
    double          control[UMFPACK_CONTROL];
  };



  /**
   * With A = [K G; H D] (displacements, then the multipliers in blocks of
   * one node each, D block diagonal) the multipliers of a node follow
   * from its rows as lambda_k = D_k^-1 (r_k - H_k u), and K - G D^-1 H is
   * left for u. D_k is singular where a row's condition does not involve
   * the node's own multipliers: the gap row of a closed node, the stick
   * rows. There D_k's singular value is replaced by sigma = alpha |G_k v|
   * |H_k^T w| / k (v, w its right and left singular vectors, k the
   * largest diagonal entry of K among the dofs involved), with the sign
   * that makes the added term -G_k v w^T H_k / sigma a stiffness: a
   * penalty of k / alpha on the constraint. The modified matrix P then
   * differs from A in those entries only, and the iteration x += P^-1 (b
   * - A x) converges to A's solution at a rate of about alpha.
   */
  struct SparseDirect::Elimination
  {
    /** The pattern it was prepared for, and whether it applies. */
    unsigned long version = static_cast<unsigned long>(-1);
    bool          usable  = false;
    /** Failed refinements in a row (2: LU of the whole system for the
     * rest of the pattern's life). */
    unsigned int n_failures = 0;
    /** Per block: the displacement rows with entries in its columns (G),
     * the displacement columns of its rows (H), and the positions in A's
     * values of G (row-major, |rows| x size), H (size x |columns|) and D
     * (size x size); -1 where the pattern has no entry. */
    std::vector<std::vector<int>> g_rows, h_columns;
    std::vector<std::vector<int>> g_entries, h_entries, d_entries;
    /** Per block: positions in the eliminated matrix of its G D^-1 H
     * (|rows| x |columns|). */
    std::vector<std::vector<int>> s_entries;
    /** Per entry of A: its position in the eliminated matrix (-1: a
     * multiplier row or column). */
    std::vector<int> k_entries;
    /** Per displacement row: the position of its diagonal entry in A. */
    std::vector<int> diagonal;
    /** Per block: the inverse of its regularized D (size x size). */
    std::vector<std::vector<double>> inverse;
    /** The displacement-only matrix and its factorization. */
    SparseDirect        reduced;
    std::vector<double> residual, correction, right_hand_side;
  };



  SparseDirect::SparseDirect()
    : state(std::make_unique<State>())
  {
    cholmod_start(&state->common);
    // CHOLMOD's supernodal factorization opens an OpenMP region per
    // supernode for its copy loops with a compiled-in request of 4 threads,
    // whatever the machine has; on 2 cores the fork, join and yielding cost
    // more than the loops (2D Hertz, 31.9k unknowns: 90 ms per solve, 45 ms
    // without). The dense blocks keep OpenBLAS's own threads; tribos'
    // threads are TBB's.
    omp_set_max_active_levels(0);
    // A matrix that is not positive definite is handled (LU): no warning.
    state->common.print = 0;
    umfpack_di_defaults(state->control);
    // METIS' nested dissection: a third fewer flops than AMD on the 2D
    // contact systems (0.67 against 1.06 GFlop for 2D Hertz, 31.9k unknowns).
    state->control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
    // No iterative refinement: a Newton iteration is one already (its
    // residual is evaluated afresh), and refinement cost a quarter of
    // every solve (26 of 98 ms at 31.9k unknowns (2D Hertz)).
    state->control[UMFPACK_IRSTEP] = 0;
  }



  void
  SparseDirect::set_multiplier_blocks(const int first, const unsigned int size)
  {
    first_multiplier = first;
    block_size       = size;
  }



  SparseDirect::~SparseDirect()
  {
    free_factorizations();
    cholmod_finish(&state->common);
  }



  void
  SparseDirect::free_factorizations()
  {
    if (state->factor != nullptr)
      cholmod_free_factor(&state->factor, &state->common);
    if (state->umfpack_symbolic != nullptr)
      umfpack_di_free_symbolic(&state->umfpack_symbolic);
    if (state->umfpack_numeric != nullptr)
      umfpack_di_free_numeric(&state->umfpack_numeric);
  }



  void
  SparseDirect::extract(const TrilinosWrappers::SparseMatrix &matrix,
                        const bool                            new_pattern)
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    const int               n = A.NumMyRows();
    AssertThrow(A.NumGlobalRows() == n,
                ExcMessage("SparseDirect needs every row on one process."));
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
                  ExcMessage("SparseDirect needs the rows in order."));
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
  SparseDirect::symmetric() const
  {
    double largest = 0;
    for (const double a : values)
      largest = std::max(largest, std::abs(a));
    const double tolerance = 1e-10 * largest;
    const int    n         = row_start.size() - 1;
    for (int i = 0; i < n; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
      {
        const int j = columns[k];
        if (j <= i)
          continue;
        const auto   begin = columns.begin() + row_start[j];
        const auto   end   = columns.begin() + row_start[j + 1];
        const auto   found = std::lower_bound(begin, end, i);
        const double transposed =
          (found != end && *found == i) ? values[found - columns.begin()] : 0.;
        if (std::abs(values[k] - transposed) > tolerance)
          return false;
      }
    return true;
  }



  bool
  SparseDirect::factorize(const bool lu_allowed)
  {
    const int n = row_start.size() - 1;
    if (n_failures < 2 && symmetric())
    {
      cholmod_sparse A;
      A.nrow       = n;
      A.ncol       = n;
      A.nzmax      = values.size();
      A.p          = row_start.data();
      A.i          = columns.data();
      A.nz         = nullptr;
      A.x          = values.data();
      A.z          = nullptr;
      A.stype      = 1; // symmetric, the upper triangle of the (C)SC form
      A.itype      = CHOLMOD_INT;
      A.xtype      = CHOLMOD_REAL;
      A.dtype      = CHOLMOD_DOUBLE;
      A.sorted     = 1;
      A.packed     = 1;
      auto &common = state->common;
      if (state->factor == nullptr)
        state->factor = cholmod_analyze(&A, &common);
      if (state->factor != nullptr)
      {
        cholmod_factorize(&A, state->factor, &common);
        if (common.status == CHOLMOD_OK &&
            state->factor->minor == std::size_t(n))
        {
          n_failures      = 0;
          factorized_with = "CHOLMOD";
          return true;
        }
      }
      // The symbolic factorization stays for the next attempt; given up,
      // its memory goes.
      if (++n_failures == 2 && state->factor != nullptr)
        cholmod_free_factor(&state->factor, &state->common);
    }
    if (!lu_allowed)
    {
      factorized_with.clear();
      return false;
    }

    // The rows are UMFPACK's columns: the matrix it sees is the
    // transpose (back_substitute() solves with the transpose of that).
    factorized_with = "UMFPACK";
    double info[UMFPACK_INFO];
    if (state->umfpack_symbolic == nullptr &&
        umfpack_di_symbolic(n,
                            n,
                            row_start.data(),
                            columns.data(),
                            values.data(),
                            &state->umfpack_symbolic,
                            state->control,
                            info) != UMFPACK_OK)
      return false;
    if (state->umfpack_numeric != nullptr)
      umfpack_di_free_numeric(&state->umfpack_numeric);
    return umfpack_di_numeric(row_start.data(),
                              columns.data(),
                              values.data(),
                              state->umfpack_symbolic,
                              &state->umfpack_numeric,
                              state->control,
                              info) == UMFPACK_OK;
  }



  bool
  SparseDirect::back_substitute(double *x, const double *b)
  {
    const int n = row_start.size() - 1;
    if (factorized_with == "CHOLMOD")
    {
      cholmod_dense B;
      B.nrow                = n;
      B.ncol                = 1;
      B.nzmax               = n;
      B.d                   = n;
      B.x                   = const_cast<double *>(b);
      B.z                   = nullptr;
      B.xtype               = CHOLMOD_REAL;
      B.dtype               = CHOLMOD_DOUBLE;
      auto          &common = state->common;
      cholmod_dense *X = cholmod_solve(CHOLMOD_A, state->factor, &B, &common);
      if (X == nullptr)
        return false;
      std::copy_n(static_cast<double *>(X->x), n, x);
      cholmod_free_dense(&X, &common);
      return true;
    }
    double info[UMFPACK_INFO];
    return umfpack_di_solve(UMFPACK_At,
                            row_start.data(),
                            columns.data(),
                            values.data(),
                            x,
                            b,
                            state->umfpack_numeric,
                            state->control,
                            info) == UMFPACK_OK;
  }



  bool
  SparseDirect::prepare_elimination()
  {
    auto      &e        = *elimination;
    const int  n        = row_start.size() - 1;
    const int  m0       = first_multiplier;
    const int  size     = block_size;
    const auto position = [&](const int i, const int j)
    {
      const auto begin = columns.begin() + row_start[i];
      const auto end   = columns.begin() + row_start[i + 1];
      const auto found = std::lower_bound(begin, end, j);
      return (found != end && *found == j) ? int(found - columns.begin()) : -1;
    };
    if (m0 <= 0 || m0 >= n || (n - m0) % size != 0)
      return false;
    const int n_blocks = (n - m0) / size;
    for (int i = m0; i < n; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        if (columns[k] >= m0 && (columns[k] - m0) / size != (i - m0) / size)
          return false;

    e.g_rows.assign(n_blocks, {});
    e.h_columns.assign(n_blocks, {});
    for (int i = 0; i < m0; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        if (columns[k] >= m0)
        {
          auto &rows = e.g_rows[(columns[k] - m0) / size];
          if (rows.empty() || rows.back() != i)
            rows.push_back(i);
        }
    for (int b = 0; b < n_blocks; ++b)
    {
      auto &h = e.h_columns[b];
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
      for (const int i : e.g_rows[b])
        pattern[i].insert(pattern[i].end(),
                          e.h_columns[b].begin(),
                          e.h_columns[b].end());
    auto &r = e.reduced;
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
    r.free_factorizations();
    r.n_failures                = 0;
    r.factorization_current     = true;
    const auto reduced_position = [&](const int i, const int j)
    {
      const auto begin = r.columns.begin() + r.row_start[i];
      const auto end   = r.columns.begin() + r.row_start[i + 1];
      return int(std::lower_bound(begin, end, j) - r.columns.begin());
    };

    e.k_entries.assign(columns.size(), -1);
    e.diagonal.assign(m0, -1);
    for (int i = 0; i < m0; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        if (columns[k] < m0)
        {
          e.k_entries[k] = reduced_position(i, columns[k]);
          if (columns[k] == i)
            e.diagonal[i] = k;
        }
    e.g_entries.resize(n_blocks);
    e.h_entries.resize(n_blocks);
    e.d_entries.resize(n_blocks);
    e.s_entries.resize(n_blocks);
    e.inverse.assign(n_blocks, std::vector<double>(size * size));
    for (int b = 0; b < n_blocks; ++b)
    {
      const auto &rows = e.g_rows[b];
      const auto &cols = e.h_columns[b];
      const int   j0   = m0 + b * size;
      e.g_entries[b].resize(rows.size() * size);
      for (unsigned int a = 0; a < rows.size(); ++a)
        for (int c = 0; c < size; ++c)
          e.g_entries[b][a * size + c] = position(rows[a], j0 + c);
      e.h_entries[b].resize(size * cols.size());
      e.d_entries[b].resize(size * size);
      for (int c = 0; c < size; ++c)
      {
        for (unsigned int a = 0; a < cols.size(); ++a)
          e.h_entries[b][c * cols.size() + a] = position(j0 + c, cols[a]);
        for (int d = 0; d < size; ++d)
          e.d_entries[b][c * size + d] = position(j0 + c, j0 + d);
      }
      e.s_entries[b].resize(rows.size() * cols.size());
      for (unsigned int a = 0; a < rows.size(); ++a)
        for (unsigned int c = 0; c < cols.size(); ++c)
          e.s_entries[b][a * cols.size() + c] =
            reduced_position(rows[a], cols[c]);
    }
    e.residual.resize(n);
    e.correction.resize(n);
    e.right_hand_side.resize(m0);
    return true;
  }



  SparseDirect::Outcome
  SparseDirect::solve_eliminated(double *x, const double *b)
  {
    // The penalty of the regularization relative to the stiffness it acts
    // on is 1/alpha; the refinement's error contracts by about alpha per
    // step. Smaller alpha: fewer steps but a worse conditioned matrix.
    constexpr double alpha = 1e-5;
    // The refinement stops at this relative residual: far below what
    // Newton needs of a step (its own tolerance is relative to the
    // increment's largest residual, this one to the current one), and
    // each step is a back substitution (10 ms at 50k unknowns in 2D).
    constexpr double tolerance = 1e-11;
    auto            &e         = *elimination;
    auto            &r         = e.reduced;
    const int        n         = row_start.size() - 1;
    const int        m0        = first_multiplier;
    const int        size      = block_size;
    const int        n_blocks  = (n - m0) / size;
    const auto       value     = [&](const int k)
    {
      return k < 0 ? 0. : values[k];
    };

    std::fill(r.values.begin(), r.values.end(), 0.);
    for (int i = 0; i < m0; ++i)
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        if (e.k_entries[k] >= 0)
          r.values[e.k_entries[k]] += values[k];

    LAPACKFullMatrix<double> D(size, size);
    std::vector<double>      G, H, GI, Gv, Hw;
    for (int blk = 0; blk < n_blocks; ++blk)
    {
      const auto        &rows = e.g_rows[blk];
      const auto        &cols = e.h_columns[blk];
      const unsigned int n_r = rows.size(), n_c = cols.size();
      G.resize(n_r * size);
      H.resize(size * n_c);
      for (unsigned int k = 0; k < G.size(); ++k)
        G[k] = value(e.g_entries[blk][k]);
      for (unsigned int k = 0; k < H.size(); ++k)
        H[k] = value(e.h_entries[blk][k]);
      D.reinit(size, size);
      for (int c = 0; c < size; ++c)
        for (int d = 0; d < size; ++d)
          D(c, d) = value(e.d_entries[blk][c * size + d]);
      double stiffness = 0;
      for (const int i : rows)
        stiffness = std::max(stiffness, std::abs(value(e.diagonal[i])));
      for (const int j : cols)
        stiffness = std::max(stiffness, std::abs(value(e.diagonal[j])));
      if (stiffness == 0)
        stiffness = 1;

      D.compute_svd();
      const auto &U       = D.get_svd_u();
      const auto &VT      = D.get_svd_vt();
      auto       &inverse = e.inverse[blk];
      std::fill(inverse.begin(), inverse.end(), 0.);
      for (int s = 0; s < size; ++s)
      {
        // G v and H^T w of this singular pair, and their product over the
        // dofs both touch (rows and columns are sorted).
        Gv.assign(n_r, 0.);
        Hw.assign(n_c, 0.);
        for (unsigned int a = 0; a < n_r; ++a)
          for (int c = 0; c < size; ++c)
            Gv[a] += G[a * size + c] * VT(s, c);
        for (unsigned int a = 0; a < n_c; ++a)
          for (int c = 0; c < size; ++c)
            Hw[a] += U(c, s) * H[c * n_c + a];
        double g = 0, h = 0, product = 0;
        for (const double v : Gv)
          g += v * v;
        for (const double v : Hw)
          h += v * v;
        for (unsigned int a = 0, c = 0; a < n_r && c < n_c;)
          if (rows[a] < cols[c])
            ++a;
          else if (cols[c] < rows[a])
            ++c;
          else
            product += Gv[a++] * Hw[c++];
        const double penalty = alpha * std::sqrt(g * h) / stiffness;
        double       sigma   = D.singular_value(s);
        if (sigma < penalty)
          sigma = product > 0 ? -penalty : penalty;
        if (sigma == 0)
          sigma = 1; // no coupling either way: any value
        for (int c = 0; c < size; ++c)
          for (int d = 0; d < size; ++d)
            inverse[c * size + d] += VT(s, c) * U(d, s) / sigma;
      }

      // K - G D^-1 H.
      GI.assign(n_r * size, 0.);
      for (unsigned int a = 0; a < n_r; ++a)
        for (int c = 0; c < size; ++c)
          for (int d = 0; d < size; ++d)
            GI[a * size + d] += G[a * size + c] * inverse[c * size + d];
      for (unsigned int a = 0; a < n_r; ++a)
        for (unsigned int c = 0; c < n_c; ++c)
        {
          double sum = 0;
          for (int d = 0; d < size; ++d)
            sum += GI[a * size + d] * H[d * n_c + c];
          r.values[e.s_entries[blk][a * n_c + c]] -= sum;
        }
    }
    if (!r.symmetric())
      return Outcome::not_definite;
    // Only Cholesky pays: where it fails (a body still free in the first
    // iterate) LU of the whole system is as cheap as LU of this one.
    if (!r.factorize(false))
      return Outcome::not_definite;

    // P^-1 z: lambda-part first through D^-1, then the reduced solve.
    const auto apply = [&](const double *z, double *y)
    {
      auto &f = e.right_hand_side;
      std::copy_n(z, m0, f.begin());
      for (int blk = 0; blk < n_blocks; ++blk)
      {
        const double *zl = z + m0 + blk * size;
        double        t[3];
        for (int c = 0; c < size; ++c)
        {
          t[c] = 0;
          for (int d = 0; d < size; ++d)
            t[c] += e.inverse[blk][c * size + d] * zl[d];
        }
        const auto &rows = e.g_rows[blk];
        for (unsigned int a = 0; a < rows.size(); ++a)
          for (int c = 0; c < size; ++c)
            f[rows[a]] -= value(e.g_entries[blk][a * size + c]) * t[c];
      }
      if (!r.back_substitute(y, f.data()))
        return false;
      for (int blk = 0; blk < n_blocks; ++blk)
      {
        const auto &cols = e.h_columns[blk];
        double      q[3];
        for (int c = 0; c < size; ++c)
        {
          q[c] = z[m0 + blk * size + c];
          for (unsigned int a = 0; a < cols.size(); ++a)
            q[c] -= value(e.h_entries[blk][c * cols.size() + a]) * y[cols[a]];
        }
        for (int c = 0; c < size; ++c)
        {
          double sum = 0;
          for (int d = 0; d < size; ++d)
            sum += e.inverse[blk][c * size + d] * q[d];
          y[m0 + blk * size + c] = sum;
        }
      }
      return true;
    };

    // Iterative refinement on A itself.
    auto &res = e.residual;
    auto &dx  = e.correction;
    std::copy_n(b, n, res.begin());
    std::fill_n(x, n, 0.);
    double norm_b = 0;
    for (int i = 0; i < n; ++i)
      norm_b += b[i] * b[i];
    norm_b = std::sqrt(norm_b);
    if (norm_b == 0)
      return Outcome::solved;
    double previous = norm_b;
    for (unsigned int step = 0; step < 30; ++step)
    {
      if (!apply(res.data(), dx.data()))
        return Outcome::failed;
      for (int i = 0; i < n; ++i)
        x[i] += dx[i];
      double norm_r = 0;
      for (int i = 0; i < n; ++i)
      {
        double sum = b[i];
        for (int k = row_start[i]; k < row_start[i + 1]; ++k)
          sum -= values[k] * x[columns[k]];
        res[i] = sum;
        norm_r += sum * sum;
      }
      norm_r        = std::sqrt(norm_r);
      n_refinements = step + 1;
      if (norm_r <= tolerance * norm_b)
        return Outcome::solved;
      // Stagnation: at round-off if small enough, else a failure.
      if (norm_r > 0.5 * previous)
        return norm_r <= 1e-10 * norm_b ? Outcome::solved : Outcome::failed;
      previous = norm_r;
    }
    return Outcome::failed;
  }



  bool
  SparseDirect::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      const unsigned long                   pattern_version,
                      Vector                               &x,
                      const Vector                         &rhs)
  {
    const bool new_pattern =
      pattern_version != version ||
      int(row_start.size()) != matrix.trilinos_matrix().NumMyRows() + 1 ||
      int(columns.size()) != matrix.trilinos_matrix().NumMyNonzeros();
    extract(matrix, new_pattern);
    if (new_pattern)
    {
      version               = pattern_version;
      factorization_current = false;
    }
    double       *x_values = x.trilinos_vector()[0];
    const double *b_values = rhs.trilinos_vector()[0];
    n_refinements          = 0;

    if (block_size > 0)
    {
      if (!elimination)
        elimination = std::make_unique<Elimination>();
      auto &e = *elimination;
      if (new_pattern || e.version != version)
      {
        e.version    = version;
        e.n_failures = 0;
        e.usable     = prepare_elimination();
      }
      if (e.usable && e.n_failures < 2)
      {
        const auto outcome = solve_eliminated(x_values, b_values);
        if (outcome == Outcome::solved)
        {
          e.n_failures = 0;
          last_method  = e.reduced.factorized_with + ", multipliers eliminated";
          return true;
        }
        ++e.n_failures;
      }
    }

    if (!factorization_current)
    {
      free_factorizations();
      n_failures            = 0;
      factorization_current = true;
    }
    if (!factorize())
      return false;
    last_method = factorized_with;
    return back_substitute(x_values, b_values);
  }
} // namespace tribos
