#ifndef tribos_solver_newton_solver_h
#define tribos_solver_newton_solver_h

#include <tribos/parameters/nonlinear_solver.h>
#include <tribos/solver/linear_solver.h>
#include <tribos/solver/nonlinear_problem.h>
#include <tribos/solver/solver_observer.h>

#include <limits>
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
   * - so is a correction within the round-off of the positions (the
   *   problem's length floor) while the residual is within ten times its
   *   round-off level (NonlinearProblem::Residual::floor) and the bound:
   *   where the contact's round-off exceeds the relative tolerance (a
   *   stiff penalty on second-order faces), no iterate meets it;
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
     * current solution plus @p predictor (if given); every iteration and
     * message goes to @p observer. */
    IncrementReport
    solve(NonlinearProblem                     &problem,
          SolverObserver                       &observer,
          const double                          time,
          const NonlinearProblem::Vector *const predictor = nullptr);

    /** Linear solves so far, failed attempts included. */
    unsigned int
    n_linear_solves() const
    {
      return linear_solves;
    }

  private:
    /** Where the iterations of one solve stand. */
    struct Iterate
    {
      unsigned int iteration = 0;
      /** The free residual at the start of the increment or of the last
       * relaxation (the scale of the relative residual test, with the
       * force scale), and whether to take it at the next assembly. */
      double reference       = 0;
      bool   reset_reference = true;
      /** The line search's step length of the last update. */
      double step_length = std::numeric_limits<double>::quiet_NaN();
      /** The undamped Newton correction (a line search shortens the step
       * taken, not the distance to the solution), the one before, and the
       * update taken, per kind of unknown. */
      NonlinearProblem::Norms correction{
        std::numeric_limits<double>::quiet_NaN(),
        0},
        earlier{std::numeric_limits<double>::quiet_NaN(), 0},
        taken{std::numeric_limits<double>::quiet_NaN(), 0};
      /** The free residuals of the last two iterations. */
      double previous[2] = {-1, -1};
      /** The last linear tolerance of inexact Newton. */
      double previous_eta = 0.1;
      /** The iteration the problem last asked for more (its budget starts
       * there), and the linear solves of this solve. */
      unsigned int relaxed_at = 0, n_solves = 0;
      /** Assemble the residual first, the tangent only if Newton goes on
       * (the update about to be taken passes the update test). */
      bool residual_first = false;
    };

    /**
     * The update test: the corrections still to come after @p last (the
     * one before it @p before) are below Increment tolerance of @p change,
     * per kind of unknown (multipliers with their round-off @p floor).
     */
    bool
    update_converged(const NonlinearProblem::Norms &last,
                     const NonlinearProblem::Norms &before,
                     const NonlinearProblem::Norms &change,
                     const NonlinearProblem::Norms &floor,
                     const bool                     full_step,
                     const unsigned int             iteration) const;

    /** The convergence tests of iterate @p it with residual @p r: whether
     * the residual test alone passes (first) and whether the iterate is
     * converged (second: the residual and update tests, the round-off
     * residual, or accepted stagnation). */
    std::pair<bool, bool>
    test_convergence(NonlinearProblem                 &problem,
                     const NonlinearProblem::Residual &r,
                     const Iterate                    &it,
                     const NonlinearProblem::Norms    &floor) const;

    /**
     * Move the solution along @p update: the step the problem limits
     * (a contact node carried far through a surface), the line search's,
     * or the whole step; records the step in @p it.
     */
    void
    take_step(NonlinearProblem                          &problem,
              const NonlinearProblem::Vector            &update,
              const double                               residual,
              const bool                                 line_search_allowed,
              Iterate                                   &it,
              std::optional<NonlinearProblem::Residual> &assembled);

    /** The relative tolerance of an iterative linear solve at @p it with
     * free residual @p residual (inexact Newton). */
    double
    linear_tolerance(const Iterate &it,
                     const double   residual,
                     const double   force_scale) const;

    /** Solve the problem's system for @p update to @p eta (0: direct);
     * throws NonConvergence on a non-finite update. */
    void
    solve_linear(NonlinearProblem         &problem,
                 SolverObserver           &observer,
                 NonlinearProblem::Vector &update,
                 const double              eta);

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
