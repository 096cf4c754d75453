#ifndef tribos_solver_linear_solver_h
#define tribos_solver_linear_solver_h

#include <tribos/parameters/linear_solver.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The linear solve of a Newton iteration, chosen by Linear solver/Type:
   * a sparse direct solver (Trilinos Amesos: KLU for small systems, MUMPS
   * for large ones) or GMRES preconditioned by ML algebraic multigrid with
   * the near-null space it is given. A failure (singular matrix, GMRES
   * without convergence) throws NonConvergence, which cuts the increment.
   */
  class LinearSolver
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    explicit LinearSolver(const Parameters::LinearSolver &parameters);

    /**
     * The near-null space for AMG: per mode, which rows it contains (the
     * translations of the displacement components); @p higher_order for
     * elements of degree > 1.
     */
    void
    set_near_null_space(const std::vector<std::vector<bool>> &modes,
                        const bool                            higher_order);

    /** Time every solve in @p timer's section "linear solve". */
    void
    set_timer(TimerOutput &timer);

    /** Solve @p matrix @p x = @p rhs. */
    void
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          Vector                               &x,
          const Vector                         &rhs);

  private:
    const Parameters::LinearSolver &parameters;
    std::vector<std::vector<bool>>  constant_modes;
    bool                            higher_order = false;
    TimerOutput                    *timer        = nullptr;
  };
} // namespace tribos

#endif
