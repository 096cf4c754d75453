#ifndef tribos_solver_sparse_direct_h
#define tribos_solver_sparse_direct_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * Sparse direct solve of a matrix held on one process, with SuiteSparse:
   * CHOLMOD's supernodal Cholesky where the matrix is symmetric and
   * positive definite (frictionless penalty contact of hyperelastic bodies),
   * UMFPACK's multifrontal LU otherwise (friction, multipliers, F-bar).
   * Both call the BLAS for their dense blocks (Debian's OpenBLAS where it
   * is installed).
   *
   * The ordering and symbolic analysis depend on the sparsity pattern only:
   * they are computed once per pattern (@p pattern_version changes when the
   * matrix is rebuilt) and every later solve only factorizes numerically.
   * Whether the matrix is symmetric is checked on its values at every solve
   * (it changes with the stick/slip state). A Cholesky factorization that
   * finds the matrix not positive definite hands that solve to LU; after
   * two such failures in a row LU stays for the rest of the pattern's life
   * (a singular first iterate, a body not yet in contact, is no reason to
   * give up Cholesky for the whole run: 2D Hertz under load control, 49k
   * unknowns, 280 against 130 ms per solve).
   */
  class SparseDirect
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    SparseDirect();
    ~SparseDirect();

    /**
     * Solve @p matrix @p x = @p rhs (one process owns every row). Returns
     * false if the matrix is singular.
     */
    bool
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          const unsigned long                   pattern_version,
          Vector                               &x,
          const Vector                         &rhs);

    /** "CHOLMOD" or "UMFPACK": what the last solve used. */
    const std::string &
    method() const
    {
      return last_method;
    }

  private:
    /** Copy the matrix into compressed rows (global, sorted columns);
     * with @p new_pattern false only the values (same pattern, same
     * order: no column lookup and no sort). */
    void
    extract(const TrilinosWrappers::SparseMatrix &matrix,
            const bool                            new_pattern);

    /** Whether the values are symmetric to 1e-10 of the largest entry. */
    bool
    symmetric() const;

    bool
    solve_cholmod(double *x, const double *b);

    bool
    solve_umfpack(double *x, const double *b);

    void
    free_factorizations();

    /** The matrix in compressed rows (as compressed columns: its
     * transpose). */
    std::vector<int>    row_start, columns;
    std::vector<double> values;
    /** Per entry of the compressed rows, its position in Trilinos' row. */
    std::vector<int> source;
    unsigned long    version = static_cast<unsigned long>(-1);
    /** Cholesky failures in a row (2: LU for the pattern's life). */
    unsigned int n_failures = 0;
    std::string  last_method;

    /** Opaque SuiteSparse state (cholmod_common, factors, UMFPACK's
     * symbolic and numeric objects). */
    struct State;
    std::unique_ptr<State> state;
  };
} // namespace tribos

#endif
