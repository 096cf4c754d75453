#ifndef tribos_solver_multiplier_elimination_h
#define tribos_solver_multiplier_elimination_h

#include <tribos/solver/compressed_rows.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <functional>
#include <vector>

namespace tribos
{
  /**
   * The inverse of one node's multiplier block @p D (@p size x @p size,
   * overwritten by its SVD) into @p inverse (row-major), with D's singular
   * values that are small against the block's coupling replaced as
   * MultiplierElimination describes: @p G (|rows| x size, row-major) the
   * block's columns in the displacement rows @p rows, @p H (size x
   * |columns|) its rows in the displacement columns @p columns (both
   * sorted), @p stiffness the largest |diagonal entry| of K among them.
   */
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
                            std::vector<double>       &inverse);



  /**
   * Elimination of the contact multipliers from a saddle-point system,
   * for a solver of displacement-only systems (CHOLMOD, AMG).
   *
   * With A = [K G; H D] (displacements, then the multipliers in blocks of
   * one slave node each, D block diagonal), a node's multipliers follow
   * from its rows as lambda_k = D_k^-1 (r_k - H_k u), and K - G D^-1 H is
   * left for u. D_k is singular where a row's condition does not involve
   * the node's own multipliers: the gap row of a closed node, the stick
   * rows. There D_k's singular value is replaced by sigma = alpha |G_k v|
   * |H_k^T w| / k (v, w its right and left singular vectors, k the
   * largest diagonal entry of K among the dofs involved), with the sign
   * that makes the added term -G_k v w^T H_k / sigma a stiffness: a
   * penalty of k / alpha on the constraint. The modified matrix P differs
   * from A in those entries only, so P^-1 preconditions A well: iterative
   * refinement x += P^-1 (b - A x) converges to A's solution at a rate of
   * about alpha, and GMRES faster.
   */
  class MultiplierElimination
  {
  public:
    /**
     * Prepare for @p A's pattern, whose unknowns from @p first on are
     * multipliers in blocks of @p size; @p reduced gets the pattern of the
     * eliminated matrix. False where the elimination does not apply (a
     * multiplier row coupled to another node's multipliers).
     */
    bool
    prepare(const CompressedRows &A,
            const int             first,
            const unsigned int    size,
            CompressedRows       &reduced);

    /** The values of the eliminated matrix K - G D~^-1 H into @p reduced,
     * with the regularization @p alpha. */
    void
    eliminate(const CompressedRows &A,
              const double          alpha,
              CompressedRows       &reduced);

    /** Solves the eliminated system: x, right-hand side. */
    using ReducedSolve = std::function<bool(double *, const double *)>;

    /** @p y = P^-1 @p z, the eliminated system solved by @p solve. */
    bool
    apply(const CompressedRows &A,
          const double         *z,
          double               *y,
          const ReducedSolve   &solve);

    /**
     * @p x = A^-1 @p b by iterative refinement with P, to a residual of
     * @p tolerance |b| (or stagnating below 1e-10 |b|); @p n_steps gets
     * the back substitutions. False if it does not converge.
     */
    bool
    refine(const CompressedRows &A,
           const double         *b,
           double               *x,
           const double          tolerance,
           const ReducedSolve   &solve,
           unsigned int         &n_steps);

  private:
    int          first = 0;
    unsigned int size  = 0;
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
    std::vector<double>              residual, correction, right_hand_side;
  };
} // namespace tribos

#endif
