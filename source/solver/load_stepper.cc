#include <tribos/base/exceptions.h>
#include <tribos/solver/load_stepper.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <sstream>

namespace tribos
{
  LoadStepper::LoadStepper(const Parameters::TimeStepping &parameters,
                           NewtonSolver                   &newton)
    : parameters(parameters)
    , newton(newton)
  {
  }



  IncrementReport
  LoadStepper::solve_increment(IncrementalProblem             &problem,
                               SolverObserver                 &observer,
                               const double                    time,
                               const NonlinearProblem::Vector *guess)
  {
    IncrementReport report = newton.solve(problem, observer, time, guess);
    // Outer updates (Uzawa), each followed by a new solve of the same
    // increment.
    while (problem.outer_update())
    {
      const IncrementReport again = newton.solve(problem, observer, time);
      report.n_iterations += again.n_iterations;
      report.residual = again.residual;
    }
    return report;
  }



  StepRecord
  LoadStepper::advance_step(IncrementalProblem &problem,
                            SolverObserver     &observer,
                            const unsigned int  step,
                            Stepping           &s)
  {
    const auto  &ts     = parameters;
    const double target = step * s.nominal_step;
    // The step's counts; run() adds the rest of its record.
    StepRecord   record;
    unsigned int cutbacks_in_row = 0;

    while (s.time < target - s.epsilon)
    {
      const double next = std::min(s.time + s.increment, target);
      Timer        increment_clock;
      try
      {
        observer.attempt(step, sums.n_increments + 1, next);
        const NonlinearProblem::Vector *guess = nullptr;
        if (s.change_increment > 0 && !s.plain_start)
        {
          s.predictor = change;
          s.predictor *= (next - s.time) / s.change_increment;
          guess = &s.predictor;
        }
        IncrementReport report =
          solve_increment(problem, observer, next, guess);
        if (observer.redo_increment(step, sums.n_increments + 1, next))
        {
          // Back to the committed state, which the new discretization
          // takes over; the increment again on it, without a guess.
          problem.solution() = s.converged;
          problem.solution_changed();
          problem.restore();
          change_discretization(problem, observer, s);
          continue;
        }
        problem.commit(next);
        s.plain_start = false;
        // Every linear solve since the last accepted increment: this
        // increment's failed attempts included.
        report.n_iterations_all = newton.n_linear_solves() - s.solves_accepted;
        s.solves_accepted       = newton.n_linear_solves();
        sums.n_linear_solves += report.n_iterations_all;
        sums.n_newton_iterations += report.n_iterations;
        if (s.extrapolate)
        {
          change = problem.solution();
          change -= s.converged;
          s.change_increment = next - s.time;
        }
        s.converged = problem.solution();
        s.time      = next;
        ++record.n_increments;
        ++sums.n_increments;
        record.n_iterations += report.n_iterations;
        record.n_iterations_all += report.n_iterations_all;
        record.residual = report.residual;
        cutbacks_in_row = 0;
        observer.increment_converged({step,
                                      sums.n_increments,
                                      s.time,
                                      report,
                                      record.n_cutbacks,
                                      increment_clock.wall_time()});
        ++s.converged_in_row;
        if (report.n_iterations <= ts.easy_iterations ||
            (ts.growth_after > 0 && s.converged_in_row >= ts.growth_after))
        {
          s.increment =
            std::min(s.increment * ts.growth_factor, s.nominal_step);
          s.converged_in_row = 0;
        }
      }
      catch (const NonConvergence &failure)
      {
        problem.solution() = s.converged;
        problem.solution_changed();
        problem.restore();
        // An extrapolated start can be worse than the converged state
        // where the last increment's motion does not go on (a contact
        // change, a snap-through: the paper's ring failed in its last
        // step). The same increment is tried once more without it
        // before it is cut.
        if (s.change_increment > 0 && !s.plain_start)
        {
          s.plain_start = true;
          observer.message("  the extrapolated start did not converge (" +
                           std::string(failure.what()) +
                           "): the increment again from the converged state");
          continue;
        }
        ++record.n_cutbacks;
        ++sums.n_cutbacks;
        ++cutbacks_in_row;
        s.converged_in_row = 0;
        s.increment *= 0.5;
        std::string reason;
        if (cutbacks_in_row > ts.max_cutbacks)
          reason = "did not converge after " + std::to_string(ts.max_cutbacks) +
                   " cutbacks (Time stepping/Maximum cutbacks)";
        else if (s.increment < s.epsilon)
          reason = "the increment was cut below 1e-12 of the end time";
        if (!reason.empty())
        {
          const std::string message =
            "step " + std::to_string(step) + " at t = " + to_scientific(next) +
            " " + reason + ": " + failure.what() +
            ". Outputs of the converged steps are kept.";
          observer.failed(message);
          throw NonConvergence(message);
        }
        std::ostringstream line;
        line << "  cutback " << cutbacks_in_row << " at t = " << next << " ("
             << failure.what() << "), new increment " << s.increment;
        observer.message(line.str());
      }
    }
    return record;
  }



  void
  LoadStepper::run(IncrementalProblem             &problem,
                   SolverObserver                 &observer,
                   const StepperState             &start,
                   const NonlinearProblem::Vector *start_change)
  {
    const auto &ts = parameters;
    Timer       wall_clock;

    const bool restarted = start.step > 0;
    Stepping   s(problem.solution());
    s.nominal_step = ts.end_time / ts.n_steps;
    s.epsilon      = 1e-12 * ts.end_time;
    s.time         = restarted ? start.time : 0.;
    s.increment    = restarted ? start.increment : s.nominal_step;
    // Time stepping/Extrapolation: the last converged increment's change
    // and size, from which the next increment's first iterate is guessed.
    s.extrapolate = ts.extrapolate && !ts.dynamic();
    if (s.extrapolate && restarted && start.change_increment > 0)
    {
      AssertThrow(start_change != nullptr, ExcInternalError());
      change             = *start_change;
      s.change_increment = start.change_increment;
    }
    s.converged_in_row = restarted ? start.converged_in_row : 0;
    s.solves_accepted  = newton.n_linear_solves();
    if (restarted)
      sums = start.totals;
    progress = start;

    for (unsigned int step = start.step + 1; step <= ts.n_steps; ++step)
    {
      StepRecord record = advance_step(problem, observer, step, s);

      const double elapsed = wall_clock.wall_time();
      // The state a checkpoint at the step's end saves (state()).
      progress = {step,
                  s.time,
                  s.increment,
                  s.converged_in_row,
                  sums,
                  s.change_increment};

      record.step        = step;
      record.n_steps     = ts.n_steps;
      record.time        = s.time;
      record.load_factor = s.time / ts.end_time;
      record.elapsed     = elapsed;
      record.eta = elapsed / (s.time - start.time) * (ts.end_time - s.time);
      observer.step_completed(record);
      if (observer.change_after_step(step))
      {
        change_discretization(problem, observer, s);
      }
    }
  }



  void
  LoadStepper::change_discretization(IncrementalProblem &problem,
                                     SolverObserver     &observer,
                                     Stepping           &s)
  {
    // (A change is kept only with Time stepping/Extrapolation.)
    const bool has_change = s.change_increment > 0;
    const bool carried =
      observer.change_discretization(s.time, has_change ? &change : nullptr);
    // The unknowns are others: without the change carried over onto them,
    // none to extrapolate from.
    s.converged = problem.solution();
    if (!(has_change && carried))
      s.change_increment = 0;
    s.plain_start             = false;
    progress.change_increment = s.change_increment;
  }
} // namespace tribos
