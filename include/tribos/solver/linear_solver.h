#ifndef tribos_solver_linear_solver_h
#define tribos_solver_linear_solver_h

#include <tribos/parameters/linear_solver.h>
#include <tribos/solver/sparse_direct.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  class DistributedElimination;

  /**
   * The linear solve of a Newton iteration, chosen by Linear solver (Type
   * = auto: iterative for large 3D systems, direct otherwise):
   *
   * - direct: on one process SuiteSparse (CHOLMOD for symmetric positive
   *   definite matrices, UMFPACK otherwise, contact multipliers eliminated
   *   for CHOLMOD where that applies: SparseDirect), under MPI Trilinos
   *   Amesos (MUMPS by default); either way the symbolic factorization is
   *   computed once per sparsity pattern and reused;
   * - iterative: GMRES preconditioned by ML algebraic multigrid with the
   *   near-null space it is given (the rigid-body modes), the tolerance
   *   given by the Newton solver (inexact Newton); with multipliers
   *   GMRES on the whole system, preconditioned by their elimination
   *   (DistributedElimination, any number of processes) with one ML
   *   V-cycle on the displacement-only matrix.
   *
   * A failure (singular matrix, GMRES without convergence) throws
   * NonConvergence, which cuts the increment.
   */
  class LinearSolver
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** Solves the systems of a @p dim dimensional problem, with
     * multipliers (@p saddle_point) or not. */
    LinearSolver(const Parameters::LinearSolver &parameters,
                 const unsigned int              dim,
                 const bool                      saddle_point);
    ~LinearSolver();

    /**
     * The near-null space for AMG: per mode, its value at every locally
     * owned row; @p higher_order for elements of degree > 1.
     */
    void
    set_near_null_space(const std::vector<std::vector<double>> &modes,
                        const bool                              higher_order);

    /**
     * The unknowns from @p first on are contact multipliers, @p size per
     * slave node: SparseDirect eliminates them (Linear solver/Eliminate
     * multipliers).
     */
    void
    set_multiplier_blocks(const types::global_dof_index first,
                          const unsigned int            size);

    /**
     * A new increment begins. What a direct solve does then depends only
     * on the sparsity pattern and on the matrices of this increment (not
     * on the failures of an earlier increment), so that a restart, whose
     * solver starts afresh, reproduces the uninterrupted run bit for bit.
     * An AMG hierarchy stays across increments (its setup costs several
     * solves): iterative solves reproduce it to the Newton tolerance.
     */
    void
    begin_increment();

    /** Time every solve in @p timer's section "linear solve". */
    void
    set_timer(TimerOutput &timer);

    /**
     * Solve @p matrix @p x = @p rhs; @p pattern_version changes whenever
     * the matrix's sparsity pattern does (the symbolic factorization is
     * kept while it does not); an iterative solve stops at @p tolerance
     * times |rhs| (0: Linear solver/Tolerance).
     */
    void
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          const unsigned long                   pattern_version,
          Vector                               &x,
          const Vector                         &rhs,
          const double                          tolerance = 0);

    /**
     * Let go of everything that refers to the current system matrix (the
     * Amesos solver, the AMG hierarchy): call before the matrix is
     * rebuilt. Their destructors reach into the matrix (Amesos_Mumps
     * frees MUMPS' data through the matrix's communicator), so destroying
     * them after it crashed every MPI run whose contact pattern changed.
     */
    void
    release_matrix();

    /** What the last solve used, for the log: "CHOLMOD (SuiteSparse)",
     * "UMFPACK (SuiteSparse)", "Amesos_Mumps", "GMRES + ML". */
    const std::string &
    method() const
    {
      return last;
    }

    /** AMG hierarchies built so far (iterative solves). */
    unsigned long
    n_preconditioner_setups() const
    {
      return n_amg_setups;
    }

    /** Krylov iterations of all iterative solves so far. */
    unsigned long
    n_iterations() const
    {
      return total_iterations;
    }

    /** Refinement steps of all solves with eliminated multipliers. */
    unsigned long
    n_refinements() const
    {
      return total_refinements;
    }

    /** Whether @p matrix is solved iteratively (inexact Newton applies). */
    bool
    iterative(const TrilinosWrappers::SparseMatrix &matrix) const
    {
      return parameters.iterative_for(dim,
                                      matrix.m(),
                                      Utilities::MPI::n_mpi_processes(
                                        matrix.get_mpi_communicator()) == 1);
    }

  private:
    /** An AMG hierarchy, the pattern it was built for and the iterations
     * of its first solve. */
    struct Hierarchy
    {
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
      unsigned long version = static_cast<unsigned long>(-1);
      /**
       * GMRES iterations per decade of residual reduction in the first
       * solve with this hierarchy: the measure of its later solves, whose
       * tolerances differ by orders of magnitude.
       */
      double iterations_per_decade = 0;
    };

    void
    solve_amesos(const TrilinosWrappers::SparseMatrix &matrix,
                 const unsigned long                   pattern_version,
                 Vector                               &x,
                 const Vector                         &rhs,
                 const std::string                    &name);

    /** Iterative solve of a system with multipliers (Eliminated). */
    void
    solve_iterative_eliminated(const TrilinosWrappers::SparseMatrix &matrix,
                               const unsigned long pattern_version,
                               Vector             &x,
                               const Vector       &rhs,
                               const double        tolerance);

    /**
     * GMRES on @p matrix to @p relative |rhs|, preconditioned by one
     * V-cycle of the AMG hierarchy @p h: of @p matrix itself, or with
     * multipliers of the matrix @p elimination eliminated them from,
     * which then gives the multipliers. @p h is kept while its solves stay
     * within twice the iterations of its first one (at least 20), rebuilt
     * when one needs more or it has none. Throws
     * SolverControl::NoConvergence if a new hierarchy fails.
     */
    void
    solve_with_amg(const TrilinosWrappers::SparseMatrix &matrix,
                   Hierarchy                            &h,
                   Vector                               &x,
                   const Vector                         &rhs,
                   const double                          relative,
                   DistributedElimination               *elimination = nullptr);

    /** ML on @p matrix with the near-null space (on its rows). */
    std::unique_ptr<TrilinosWrappers::PreconditionAMG>
    make_amg(const TrilinosWrappers::SparseMatrix &matrix);

    void
    solve_iterative(const TrilinosWrappers::SparseMatrix &matrix,
                    const unsigned long                   pattern_version,
                    Vector                               &x,
                    const Vector                         &rhs,
                    const double                          tolerance);

    const Parameters::LinearSolver &parameters;
    const unsigned int              dim;
    const bool                      saddle_point;
    unsigned long                   total_iterations  = 0;
    unsigned long                   total_refinements = 0;
    /** The hierarchy of the systems without multipliers. */
    Hierarchy                        hierarchy;
    unsigned long                    n_amg_setups = 0;
    std::vector<std::vector<double>> null_space;
    bool                             higher_order = false;
    TimerOutput                     *timer        = nullptr;
    std::unique_ptr<SparseDirect>    suitesparse;
    types::global_dof_index          first_multiplier = 0;
    unsigned int                     multiplier_block = 0;
    std::string                      last;
    /**
     * MUMPS's ICNTL(14): the percentage by which its factorization's
     * workspace exceeds the estimate of its analysis (MUMPS's default 20).
     * Numerical pivoting on the zero diagonal of the multipliers' rows can
     * need more than that (INFOG(1) = -9 on a 2 x 2 x 1 block with
     * friction, -np 2): solve_amesos() then raises it and factorizes again,
     * and the later factorizations keep the raised value.
     */
    static constexpr int mumps_default_workspace_percent = 20;
    int mumps_workspace_percent = mumps_default_workspace_percent;

    /** Amesos: the solver, its problem and the pattern it analysed. */
    struct Amesos;
    std::unique_ptr<Amesos> amesos;
    /** The iterative solve with eliminated multipliers. */
    struct Eliminated;
    std::unique_ptr<Eliminated> eliminated;
  };
} // namespace tribos

#endif
