#ifndef tribos_solver_sparse_direct_h
#define tribos_solver_sparse_direct_h

#include <tribos/solver/compressed_rows.h>

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
   * unknowns, 280 against 130 ms per solve), and until the next increment
   * (begin_increment()): what a solve does depends on the pattern and on
   * the increment's own matrices only, so that a run restarted from a
   * checkpoint, whose solver starts afresh, solves as the uninterrupted
   * one to the last bit.
   *
   * Systems with Lagrange multipliers (set_multiplier_blocks()) are
   * indefinite and not symmetric positive definite, so they would all go
   * to LU. Instead each node's multipliers are eliminated from a copy of
   * the system whose multiplier block is perturbed in its singular
   * directions only (the normal row of a closed node, the rows of a
   * sticking node): a penalty about 1/alpha = 1e5 times the stiffness
   * there. The displacement-only matrix that is left is factorized by
   * CHOLMOD, and that factorization preconditions iterative refinement on
   * the unmodified system, which removes the perturbation: the error
   * contracts by about alpha per step, so two or three back substitutions
   * give the multiplier solution to a relative residual of 1e-11. Only a
   * symmetric positive definite eliminated matrix is worth it
   * (frictionless contact: Cholesky instead of LU, half the time or less);
   * with friction the eliminated matrix is unsymmetric, and its LU costs
   * more than that of the whole system (3D upsetting: 230 against 173 ms
   * per solve), so such a system, one whose Cholesky factorization fails
   * (a body still free in the first iterate), and one whose refinement
   * does not converge go to LU of the whole system (after two in a
   * row, for the rest of the pattern's life).
   */
  class SparseDirect
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    SparseDirect();
    ~SparseDirect();

    /**
     * The unknowns from @p first on are Lagrange multipliers in blocks of
     * @p size, one block per slave node whose rows couple to no other
     * node's multipliers; eliminate them as described above (@p size 0:
     * solve the whole system as it is).
     */
    void
    set_multiplier_blocks(const int first, const unsigned int size);

    /** A new increment: Cholesky is tried again (the factorizations and
     * their symbolic analyses stay). */
    void
    begin_increment();

    /**
     * Solve @p matrix @p x = @p rhs (one process owns every row). Returns
     * false if the matrix is singular.
     */
    bool
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          const unsigned long                   pattern_version,
          Vector                               &x,
          const Vector                         &rhs);

    /** "CHOLMOD" or "UMFPACK", followed by ", multipliers eliminated" if
     * they were: what the last solve used. */
    const std::string &
    method() const
    {
      return last_method;
    }

    /** Refinement steps of the last solve with eliminated multipliers. */
    unsigned int
    refinements() const
    {
      return n_refinements;
    }

  private:
    /** Factorize the matrix (CHOLMOD, or UMFPACK where Cholesky fails or
     * the matrix is not symmetric, if @p lu_allowed), reusing the symbolic
     * analysis. */
    bool
    factorize(const bool lu_allowed = true);

    /** Solve with the last factorization. */
    bool
    back_substitute(double *x, const double *b);

    void
    free_factorizations();

    /** How a solve with the multipliers eliminated ended. */
    enum class Outcome
    {
      solved,
      /** The eliminated matrix is not symmetric positive definite (friction,
       * slip, a free body): LU of the whole system is cheaper than LU of
       * it. */
      not_definite,
      /** The refinement did not converge. */
      failed
    };

    /** The solve with the multipliers eliminated. */
    Outcome
    solve_eliminated(double *x, const double *b);

    /** The matrix (as compressed columns: its transpose). */
    CompressedRows system;
    unsigned long  version = static_cast<unsigned long>(-1);
    /** Whether the factorization objects belong to the current pattern. */
    bool factorization_current = false;
    /** "CHOLMOD" or "UMFPACK": the current factorization. */
    std::string factorized_with;
    /** Multipliers: the first one and the block size (0: none). */
    int          first_multiplier = 0;
    unsigned int block_size       = 0;
    unsigned int n_refinements    = 0;
    /** Cholesky failures in a row (2: LU for the rest of the pattern's
     * life in this increment). */
    unsigned int n_failures = 0;
    std::string  last_method;

    /** Opaque SuiteSparse state (cholmod_common, factors, UMFPACK's
     * symbolic and numeric objects). */
    struct State;
    std::unique_ptr<State> state;

    /** The elimination of the multipliers, the pattern it was prepared
     * for, and the displacement-only matrix with its factorization. */
    struct Elimination;
    std::unique_ptr<Elimination> elimination;
  };
} // namespace tribos

#endif
