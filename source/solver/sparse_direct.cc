#include <tribos/solver/multiplier_elimination.h>
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



  struct SparseDirect::Elimination
  {
    /** The pattern it was prepared for, and whether it applies. */
    unsigned long         version = static_cast<unsigned long>(-1);
    bool                  usable  = false;
    MultiplierElimination elimination;
    /** The displacement-only matrix and its factorization. */
    SparseDirect reduced;
    /** Failed eliminations in a row (2: LU of the whole system for the
     * rest of the pattern's life). */
    unsigned int n_failures = 0;
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



  void
  SparseDirect::begin_increment()
  {
    n_failures = 0;
    if (elimination)
    {
      elimination->n_failures         = 0;
      elimination->reduced.n_failures = 0;
    }
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



  bool
  SparseDirect::factorize(const bool lu_allowed)
  {
    const int n = system.n_rows();
    if (n_failures < 2 && system.symmetric())
    {
      cholmod_sparse A;
      A.nrow       = n;
      A.ncol       = n;
      A.nzmax      = system.values.size();
      A.p          = system.row_start.data();
      A.i          = system.columns.data();
      A.nz         = nullptr;
      A.x          = system.values.data();
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
      // The symbolic factorization stays for the next attempt, also once
      // Cholesky is given up for the increment: the next one tries it
      // again (begin_increment()) without a new analysis.
      ++n_failures;
    }
    if (!lu_allowed)
    {
      factorized_with.clear();
      return false;
    }

    // The rows are UMFPACK's columns: the system it sees is the
    // transpose (back_substitute() solves with the transpose of that).
    factorized_with = "UMFPACK";
    double info[UMFPACK_INFO];
    if (state->umfpack_symbolic == nullptr &&
        umfpack_di_symbolic(n,
                            n,
                            system.row_start.data(),
                            system.columns.data(),
                            system.values.data(),
                            &state->umfpack_symbolic,
                            state->control,
                            info) != UMFPACK_OK)
      return false;
    if (state->umfpack_numeric != nullptr)
      umfpack_di_free_numeric(&state->umfpack_numeric);
    return umfpack_di_numeric(system.row_start.data(),
                              system.columns.data(),
                              system.values.data(),
                              state->umfpack_symbolic,
                              &state->umfpack_numeric,
                              state->control,
                              info) == UMFPACK_OK;
  }



  bool
  SparseDirect::back_substitute(double *x, const double *b)
  {
    const int n = system.n_rows();
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
                            system.row_start.data(),
                            system.columns.data(),
                            system.values.data(),
                            x,
                            b,
                            state->umfpack_numeric,
                            state->control,
                            info) == UMFPACK_OK;
  }



  SparseDirect::Outcome
  SparseDirect::solve_eliminated(double *x, const double *b)
  {
    // The penalty of the regularization relative to the stiffness it acts
    // on is 1/alpha; the refinement's error contracts by about alpha per
    // step. Smaller alpha: fewer steps but a worse conditioned system.
    constexpr double alpha = 1e-5;
    // The refinement stops at this relative residual: far below what
    // Newton needs of a step (its own tolerance is relative to the
    // increment's largest residual, this one to the current one), and
    // each step is a back substitution (10 ms at 50k unknowns in 2D).
    constexpr double tolerance = 1e-11;
    auto            &e         = *elimination;
    auto            &r         = e.reduced;
    e.elimination.eliminate(system, alpha, r.system);
    // Only Cholesky pays: where the eliminated matrix is unsymmetric or
    // Cholesky fails (a body still free in the first iterate) LU of the
    // whole system is as cheap as LU of this one.
    if (!r.factorize(false))
      return Outcome::not_definite;
    const auto solve = [&](double *y, const double *z)
    {
      return r.back_substitute(y, z);
    };
    return e.elimination.refine(system, b, x, tolerance, solve, n_refinements) ?
             Outcome::solved :
             Outcome::failed;
  }



  bool
  SparseDirect::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      const unsigned long                   pattern_version,
                      Vector                               &x,
                      const Vector                         &rhs)
  {
    const bool new_pattern =
      pattern_version != version ||
      system.n_rows() != matrix.trilinos_matrix().NumMyRows() ||
      int(system.columns.size()) != matrix.trilinos_matrix().NumMyNonzeros();
    system.extract(matrix, new_pattern);
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
        e.usable     = e.elimination.prepare(system,
                                         first_multiplier,
                                         block_size,
                                         e.reduced.system);
        e.reduced.free_factorizations();
        e.reduced.n_failures            = 0;
        e.reduced.factorization_current = true;
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
