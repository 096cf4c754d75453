#include <tribos/solver/sparse_direct.h>

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
  SparseDirect::solve_cholmod(double *x, const double *b)
  {
    const int      n = row_start.size() - 1;
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
    if (state->factor == nullptr)
      return false;
    cholmod_factorize(&A, state->factor, &common);
    if (common.status != CHOLMOD_OK || state->factor->minor < std::size_t(n))
      return false;

    cholmod_dense B;
    B.nrow           = n;
    B.ncol           = 1;
    B.nzmax          = n;
    B.d              = n;
    B.x              = const_cast<double *>(b);
    B.z              = nullptr;
    B.xtype          = CHOLMOD_REAL;
    B.dtype          = CHOLMOD_DOUBLE;
    cholmod_dense *X = cholmod_solve(CHOLMOD_A, state->factor, &B, &common);
    if (X == nullptr)
      return false;
    std::copy_n(static_cast<double *>(X->x), n, x);
    cholmod_free_dense(&X, &common);
    return true;
  }



  bool
  SparseDirect::solve_umfpack(double *x, const double *b)
  {
    // The rows are UMFPACK's columns: the matrix it sees is the
    // transpose, and UMFPACK_At solves with the transpose of that.
    const int n = row_start.size() - 1;
    double    info[UMFPACK_INFO];
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
    if (umfpack_di_numeric(row_start.data(),
                           columns.data(),
                           values.data(),
                           state->umfpack_symbolic,
                           &state->umfpack_numeric,
                           state->control,
                           info) != UMFPACK_OK)
      return false;
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
      free_factorizations();
      version    = pattern_version;
      n_failures = 0;
    }
    double       *x_values = x.trilinos_vector()[0];
    const double *b_values = rhs.trilinos_vector()[0];
    if (n_failures < 2 && symmetric())
    {
      last_method = "CHOLMOD";
      if (solve_cholmod(x_values, b_values))
      {
        n_failures = 0;
        return true;
      }
      // The symbolic factorization stays for the next attempt; given up,
      // its memory goes.
      if (++n_failures == 2 && state->factor != nullptr)
        cholmod_free_factor(&state->factor, &state->common);
    }
    last_method = "UMFPACK";
    return solve_umfpack(x_values, b_values);
  }
} // namespace tribos
