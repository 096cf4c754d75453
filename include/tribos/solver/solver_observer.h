#ifndef tribos_solver_solver_observer_h
#define tribos_solver_solver_observer_h

#include <tribos/solver/nonlinear_problem.h>

#include <string>

namespace tribos
{
  /** One Newton iteration as the solver saw it (a row of convergence.csv). */
  struct IterationRecord
  {
    unsigned int iteration = 0;
    /** The free residual's l2 norm, and over the force scale. */
    double residual          = 0;
    double relative_residual = 0;
    /** The update taken before this iteration's assembly (NaN at first). */
    double update_norm = 0;
    /** The line search's step length of that update (NaN at first). */
    double step_length = 0;
    /** The undamped Newton correction that update was a step along (NaN
     * at first): the linear solve's answer. */
    double correction_norm = 0;
    /** The observed order of convergence (NaN until three residuals). */
    double order = 0;
  };



  /** A converged increment (a row of history.csv). */
  struct IncrementRecord
  {
    /** The nominal step it belongs to, and its number over the run. */
    unsigned int    step      = 0;
    unsigned int    increment = 0;
    double          time      = 0;
    IncrementReport report;
    /** Cutbacks of the nominal step so far. */
    unsigned int n_cutbacks = 0;
    /** The wall time of the increment's last attempt. */
    double wall_time = 0;
  };



  /** A completed nominal step (the console line). */
  struct StepRecord
  {
    unsigned int step    = 0;
    unsigned int n_steps = 0;
    double       time    = 0;
    /** time over Time stepping/End time. */
    double       load_factor      = 0;
    unsigned int n_increments     = 0;
    unsigned int n_iterations     = 0;
    unsigned int n_iterations_all = 0;
    double       residual         = 0;
    unsigned int n_cutbacks       = 0;
    /** Increments rejected as too coarse (Maximum contact changes). */
    unsigned int n_rejections = 0;
    /** Seconds since the stepping started, and the estimate of what is
     * left. */
    double elapsed = 0;
    double eta     = 0;
  };



  /**
   * What the load stepper and Newton's method tell as they go, and the
   * only way they tell it: the run's outputs and log listen
   * (postprocess/RunOutput, run/Simulation). The solvers know nothing of
   * files, consoles or checkpoints.
   */
  class SolverObserver
  {
  public:
    virtual ~SolverObserver() = default;

    /** An attempt at @p increment (counted over the run) of nominal step
     * @p step, ending at @p time, starts. */
    virtual void
    attempt(const unsigned int /*step*/,
            const unsigned int /*increment*/,
            const double /*time*/)
    {
    }

    /** A Newton iteration's residual was assembled. */
    virtual void
    iteration(const IterationRecord & /*record*/)
    {
    }

    /** An increment converged (and was committed). */
    virtual void
    increment_converged(const IncrementRecord & /*record*/)
    {
    }

    /** A nominal step is complete. */
    virtual void
    step_completed(const StepRecord & /*record*/)
    {
    }

    /**
     * Increment @p increment of nominal step @p step, ending at @p time,
     * converged and is not yet committed: true to solve it again on
     * another discretization, which the observer has chosen (from this
     * solution) and change_discretization() makes once the problem is
     * back at its committed state.
     */
    virtual bool
    redo_increment(const unsigned int /*step*/,
                   const unsigned int /*increment*/,
                   const double /*time*/)
    {
      return false;
    }

    /** After step_completed() of nominal step @p step: true to change the
     * discretization now (change_discretization()). */
    virtual bool
    change_after_step(const unsigned int /*step*/)
    {
      return false;
    }

    /**
     * Make the change of discretization that redo_increment() or
     * change_after_step() chose: the problem's unknowns, at its committed
     * state at @p time, are replaced by those of the new one (another
     * size). @p change, if given, is the last converged increment's change
     * of the unknowns, from which the stepper extrapolates the next
     * increment's start: true if it was carried over onto the new unknowns
     * (else the stepping goes on without extrapolation).
     */
    virtual bool
    change_discretization(const double /*time*/,
                          NonlinearProblem::Vector * /*change*/)
    {
      return false;
    }

    /** Something for the user (a cutback, the linear solver's name). */
    virtual void
    message(const std::string & /*text*/)
    {
    }

    /** The stepping stops: the cutbacks ran out (@p reason says why). */
    virtual void
    failed(const std::string & /*reason*/)
    {
    }
  };
} // namespace tribos

#endif
