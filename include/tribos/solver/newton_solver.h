#ifndef tribos_solver_newton_solver_h
#define tribos_solver_newton_solver_h

#include <tribos/parameters/nonlinear_solver.h>
#include <tribos/solver/linear_solver.h>
#include <tribos/solver/nonlinear_problem.h>

#include <optional>
#include <set>
#include <string>

namespace tribos
{
  /**
   * Newton-Raphson for one increment of a NonlinearProblem, with Armijo
   * backtracking on the residual norm and the convergence rules of
   * Nonlinear solver:
   *
   * - converged when the free residual is below Residual tolerance of the
   *   force scale (plus the absolute floor) and the last update is below
   *   Increment tolerance of the unknowns' change scale, for each kind of
   *   unknown (displacements; multipliers, which have their own units);
   * - a Newton correction at round-off size (1e-12 of the unknowns) is
   *   accepted as stagnation only when the residual is below the problem's
   *   stagnation bound, so that a tiny correction against a large
   *   displacement does not pass off an unconverged iterate;
   * - the problem has the last word at every converged iterate
   *   (NonlinearProblem::at_convergence()).
   *
   * Failure (too many iterations, a non-finite residual, a failed linear
   * solve) throws NonConvergence, which the load stepper turns into a
   * cutback.
   */
  class NewtonSolver
  {
  public:
    NewtonSolver(const Parameters::NonlinearSolver &parameters,
                 LinearSolver                      &linear_solver);

    /** Solve the increment that ends at @p time, starting from the
     * current solution plus @p predictor (if given). */
    IncrementReport
    solve(NonlinearProblem                     &problem,
          const double                          time,
          const NonlinearProblem::Vector *const predictor = nullptr);

    /** Linear solves so far, failed attempts included. */
    unsigned int
    n_linear_solves() const
    {
      return linear_solves;
    }

  private:
    /**
     * Backtracking from the current iterate along @p update until the
     * residual has fallen by the Armijo factor (or the halvings run out);
     * returns the step length taken. The full step is assembled with its
     * tangent (@p with_tangent; not where it is expected to converge): if
     * it is taken (the usual case), @p assembled holds its residual and
     * the next Newton iteration need not assemble again.
     */
    double
    line_search(NonlinearProblem                          &problem,
                const NonlinearProblem::Vector            &update,
                const double                               residual,
                const bool                                 with_tangent,
                std::optional<NonlinearProblem::Residual> &assembled);

    const Parameters::NonlinearSolver &parameters;
    LinearSolver                      &linear_solver;
    unsigned int                       linear_solves = 0;
    /** The linear solver methods the log has named. */
    std::set<std::string> announced;
  };
} // namespace tribos

#endif
