#ifndef tribos_solver_load_stepper_h
#define tribos_solver_load_stepper_h

#include <tribos/parameters/time_stepping.h>
#include <tribos/solver/newton_solver.h>
#include <tribos/solver/nonlinear_problem.h>
#include <tribos/solver/solver_observer.h>

#include <string>

namespace tribos
{
  /**
   * A NonlinearProblem solved in increments of a pseudo-time: what the load
   * stepper needs besides Newton's interface.
   */
  class IncrementalProblem : public NonlinearProblem
  {
  public:
    /** Make the converged increment ending at @p time the history. */
    virtual void
    commit(const double time) = 0;

    /**
     * Return to the last committed state after a failed attempt (the
     * stepper has already reset solution()).
     */
    virtual void
    restore() = 0;

    /**
     * An outer update after a converged increment (the augmented
     * Lagrangian's Uzawa step): true if the increment must be solved again.
     * May throw NonConvergence.
     */
    virtual bool
    outer_update()
    {
      return false;
    }

    /** The frictional contact nodes at the end of the increment just
     * solved (not yet committed). */
    struct ContactChanges
    {
      /** Closed (stick or slip). */
      unsigned int n_active = 0;
      /** Closed now and open at the increment's start, or stuck now and
       * slipping at its start. */
      unsigned int n_changed = 0;
    };

    /** The frictional contact nodes' changes in the increment just solved
     * (the accuracy of a frictional path); none without contact.
     * Collective. */
    virtual ContactChanges
    contact_changes() const
    {
      return {};
    }
  };



  /** Totals of a run. */
  struct StepperTotals
  {
    unsigned int n_increments        = 0;
    unsigned int n_newton_iterations = 0;
    unsigned int n_cutbacks          = 0;
    /** Converged increments rejected as too coarse (Time stepping/Maximum
     * contact changes) and solved again smaller; not cutbacks, which are
     * failures. */
    unsigned int n_rejections = 0;
    /** Linear solves of the converged increments, their failed attempts
     * included. */
    unsigned int n_linear_solves = 0;
  };

  /**
   * Where the stepping stands after a nominal step: what a restart needs
   * to go on exactly as the uninterrupted run would (the increment size
   * and the growth counter included).
   */
  struct StepperState
  {
    /** The last completed nominal step (0: none). */
    unsigned int  step             = 0;
    double        time             = 0;
    double        increment        = 0;
    unsigned int  converged_in_row = 0;
    StepperTotals totals;
    /** The size of the last converged increment, whose change of the
     * unknowns (LoadStepper::last_change()) the next increment
     * extrapolates (Time stepping/Extrapolation); 0: none yet. */
    double change_increment = 0;
  };



  /**
   * Automatic incrementation over the steps of Time stepping (the nominal
   * steps' ends and the Output times, each landed on), with Abaqus
   * *STATIC's semantics: the first increment is Initial increment; a failed
   * one (NonConvergence) is restored and halved, up to Maximum cutbacks in
   * a row, and an increment cut below Minimum increment is a failure; an
   * increment grows by Growth factor after an easy one (at most Easy
   * iterations) or after Growth after converged increments in a row, up to
   * Maximum increment. With Maximum contact changes, a converged
   * increment in which too many frictional contact nodes closed or began
   * to stick is rejected
   * and halved (the accuracy of a frictional path), and the increment grows
   * only while a larger one would pass. Outer updates (Uzawa) re-solve the
   * same increment.
   */
  class LoadStepper
  {
  public:
    LoadStepper(const Parameters::TimeStepping &parameters,
                NewtonSolver                   &newton);

    /**
     * Run every nominal step after @p start (a restart's state, with the
     * change of its last increment @p start_change if it has one; by
     * default the beginning), telling @p observer what happens; throws
     * NonConvergence when it stops. state() is that of the step when
     * @p observer hears of its end.
     */
    void
    run(IncrementalProblem             &problem,
        SolverObserver                 &observer,
        const StepperState             &start        = {},
        const NonlinearProblem::Vector *start_change = nullptr);

    /** The change of the unknowns over the last converged increment (for a
     * checkpoint; meaningful where state().change_increment > 0). */
    const NonlinearProblem::Vector &
    last_change() const
    {
      return change;
    }

    /** The state after the last completed nominal step (for a checkpoint
     * written at its end). */
    const StepperState &
    state() const
    {
      return progress;
    }

    const StepperTotals &
    totals() const
    {
      return sums;
    }

  private:
    /** Solve the increment ending at @p time from the current solution
     * plus @p guess, with the outer updates (Uzawa) the problem asks. */
    IncrementReport
    solve_increment(IncrementalProblem             &problem,
                    SolverObserver                 &observer,
                    const double                    time,
                    const NonlinearProblem::Vector *guess);

    /**
     * What run() carries from one increment to the next, over the nominal
     * steps (advance_step() reads and updates it).
     */
    struct Stepping
    {
      /** Copies @p solution as the converged state the stepping starts
       * from. */
      explicit Stepping(const NonlinearProblem::Vector &solution)
        : converged(solution)
      {
      }

      /** Round-off of the times (1e-12 of the end time). */
      double epsilon = 0;
      /** Time stepping/Extrapolation (not in a dynamic run). */
      bool extrapolate = false;
      /** The time reached and the size of the next increment. */
      double time      = 0;
      double increment = 0;
      /** The unknowns at time, to which a failed attempt returns. */
      NonlinearProblem::Vector converged;
      /** The size of the last converged increment, whose change
       * (LoadStepper::change) guesses the next increment's first iterate
       * (in predictor); 0: none. */
      double                   change_increment = 0;
      NonlinearProblem::Vector predictor;
      /** Set when an extrapolated attempt failed: the increment is tried
       * again from the converged state, and so are its cutbacks. */
      bool plain_start = false;
      /** Converged increments since the last growth or cutback, and the
       * linear solves when the last increment was accepted. */
      unsigned int converged_in_row = 0;
      unsigned int solves_accepted  = 0;
      /** The changed contact nodes of the last increment rejected for
       * accuracy (Maximum contact changes); none: no rejection since
       * the last accepted increment. */
      unsigned int                  rejected_changes = none;
      static constexpr unsigned int none = static_cast<unsigned int>(-1);
    };

    /**
     * Maximum contact changes: whether the converged increment of
     * size @p increment must be solved again smaller (then @p s records
     * why), and in @p may_grow whether the next may be larger.
     */
    bool
    too_coarse(const IncrementalProblem &problem,
               const double              increment,
               Stepping                 &s,
               bool                     &may_grow,
               std::string              &reason) const;

    /**
     * Reach nominal step @p step from @p s.time by increments: each
     * attempt, its acceptance (the increment's growth) or failure (the
     * retry without extrapolation, the cutback, or the end of the run:
     * NonConvergence). Returns the step's counts in a StepRecord whose
     * other fields run() fills. Separate from run(), which sets the
     * stepping up and completes each step, so that each reads on its own.
     */
    StepRecord
    advance_step(IncrementalProblem &problem,
                 SolverObserver     &observer,
                 const unsigned int  step,
                 Stepping           &s);

    /** The observer changes the discretization at the committed state:
     * the stepping goes on from the new unknowns, extrapolating from the
     * last change if the observer carried it over. */
    void
    change_discretization(IncrementalProblem &problem,
                          SolverObserver     &observer,
                          Stepping           &s);

    const Parameters::TimeStepping &parameters;
    NewtonSolver                   &newton;
    StepperTotals                   sums;
    StepperState                    progress;
    NonlinearProblem::Vector        change;
  };
} // namespace tribos

#endif
