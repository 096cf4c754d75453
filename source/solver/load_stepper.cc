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



  void
  LoadStepper::run(IncrementalProblem             &problem,
                   SolverObserver                 &observer,
                   const StepperState             &start,
                   const NonlinearProblem::Vector *start_change)
  {
    const auto  &ts           = parameters;
    const double nominal_step = ts.end_time / ts.n_steps;
    const double epsilon      = 1e-12 * ts.end_time;
    Timer        wall_clock;

    const bool restarted = start.step > 0;
    double     time      = restarted ? start.time : 0.;
    double     increment = restarted ? start.increment : nominal_step;
    NonlinearProblem::Vector converged = problem.solution();
    // Time stepping/Extrapolation: the last converged increment's change
    // and size, from which the next increment's first iterate is guessed.
    const bool extrapolate      = ts.extrapolate && !ts.dynamic();
    double     change_increment = 0;
    if (extrapolate && restarted && start.change_increment > 0)
    {
      AssertThrow(start_change != nullptr, ExcInternalError());
      change           = *start_change;
      change_increment = start.change_increment;
    }
    NonlinearProblem::Vector predictor;
    // Set when an extrapolated attempt failed: the increment is tried
    // again from the converged state, and so are its cutbacks.
    bool plain_start = false;
    // Converged increments since the last growth or cutback, and the
    // linear solves when the last increment was accepted.
    unsigned int converged_in_row = restarted ? start.converged_in_row : 0;
    unsigned int solves_accepted  = newton.n_linear_solves();
    if (restarted)
      sums = start.totals;
    progress = start;

    for (unsigned int step = start.step + 1; step <= ts.n_steps; ++step)
    {
      const double target           = step * nominal_step;
      unsigned int n_iterations     = 0;
      unsigned int n_iterations_all = 0;
      unsigned int n_cutbacks       = 0;
      unsigned int cutbacks_in_row  = 0;
      double       residual         = 0;
      unsigned int n_increments     = 0;

      while (time < target - epsilon)
      {
        const double next = std::min(time + increment, target);
        Timer        increment_clock;
        try
        {
          observer.attempt(step, sums.n_increments + 1, next);
          const NonlinearProblem::Vector *guess = nullptr;
          if (change_increment > 0 && !plain_start)
          {
            predictor = change;
            predictor *= (next - time) / change_increment;
            guess = &predictor;
          }
          IncrementReport report =
            solve_increment(problem, observer, next, guess);
          problem.commit(next);
          plain_start = false;
          // Every linear solve since the last accepted increment: this
          // increment's failed attempts included.
          report.n_iterations_all = newton.n_linear_solves() - solves_accepted;
          solves_accepted         = newton.n_linear_solves();
          sums.n_linear_solves += report.n_iterations_all;
          sums.n_newton_iterations += report.n_iterations;
          if (extrapolate)
          {
            change = problem.solution();
            change -= converged;
            change_increment = next - time;
          }
          converged = problem.solution();
          time      = next;
          ++n_increments;
          ++sums.n_increments;
          n_iterations += report.n_iterations;
          n_iterations_all += report.n_iterations_all;
          residual        = report.residual;
          cutbacks_in_row = 0;
          observer.increment_converged({step,
                                        sums.n_increments,
                                        time,
                                        report,
                                        n_cutbacks,
                                        increment_clock.wall_time()});
          ++converged_in_row;
          if (report.n_iterations <= ts.easy_iterations ||
              (ts.growth_after > 0 && converged_in_row >= ts.growth_after))
          {
            increment = std::min(increment * ts.growth_factor, nominal_step);
            converged_in_row = 0;
          }
        }
        catch (const NonConvergence &failure)
        {
          problem.solution() = converged;
          problem.solution_changed();
          problem.restore();
          // An extrapolated start can be worse than the converged state
          // where the last increment's motion does not go on (a contact
          // change, a snap-through: the paper's ring failed in its last
          // step). The same increment is tried once more without it
          // before it is cut.
          if (change_increment > 0 && !plain_start)
          {
            plain_start = true;
            observer.message("  the extrapolated start did not converge (" +
                             std::string(failure.what()) +
                             "): the increment again from the converged state");
            continue;
          }
          ++n_cutbacks;
          ++sums.n_cutbacks;
          ++cutbacks_in_row;
          converged_in_row = 0;
          increment *= 0.5;
          std::string reason;
          if (cutbacks_in_row > ts.max_cutbacks)
            reason = "did not converge after " +
                     std::to_string(ts.max_cutbacks) +
                     " cutbacks (Time stepping/Maximum cutbacks)";
          else if (increment < epsilon)
            reason = "the increment was cut below 1e-12 of the end time";
          if (!reason.empty())
          {
            const std::string message =
              "step " + std::to_string(step) +
              " at t = " + to_scientific(next) + " " + reason + ": " +
              failure.what() + ". Outputs of the converged steps are kept.";
            observer.failed(message);
            throw NonConvergence(message);
          }
          std::ostringstream line;
          line << "  cutback " << cutbacks_in_row << " at t = " << next << " ("
               << failure.what() << "), new increment " << increment;
          observer.message(line.str());
        }
      }

      const double elapsed = wall_clock.wall_time();
      progress =
        {step, time, increment, converged_in_row, sums, change_increment};
      observer.step_completed(
        {step,
         ts.n_steps,
         time,
         time / ts.end_time,
         n_increments,
         n_iterations,
         n_iterations_all,
         residual,
         n_cutbacks,
         elapsed,
         elapsed / (time - start.time) * (ts.end_time - time)});
    }
  }
} // namespace tribos
