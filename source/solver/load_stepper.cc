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
    const double target = ts.step_times[step - 1];
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
        bool        may_grow = true;
        std::string reason;
        if (too_coarse(problem, next - s.time, s, may_grow, reason))
        {
          // Converged, but too coarse for the path: the same increment
          // halved, from the converged state and its extrapolation.
          problem.solution() = s.converged;
          problem.solution_changed();
          problem.restore();
          s.increment        = 0.5 * (next - s.time);
          s.converged_in_row = 0;
          ++record.n_rejections;
          ++sums.n_rejections;
          std::ostringstream line;
          line << "  increment to t = " << next << " rejected: " << reason
               << "; new increment " << s.increment;
          observer.message(line.str());
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
        if (may_grow &&
            (report.n_iterations <= ts.easy_iterations ||
             (ts.growth_after > 0 && s.converged_in_row >= ts.growth_after)))
        {
          s.increment =
            std::min(s.increment * ts.growth_factor, ts.maximum_increment);
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
        // Half of what was tried: an increment shortened to land on a
        // step's end would otherwise be tried again at the same size.
        s.increment = 0.5 * (next - s.time);
        std::string reason;
        if (cutbacks_in_row > ts.max_cutbacks)
          reason = "did not converge after " + std::to_string(ts.max_cutbacks) +
                   " cutbacks (Time stepping/Maximum cutbacks)";
        else if (s.increment < ts.minimum_increment * (1 - 1e-12))
          reason = "the increment was cut below " +
                   to_scientific(ts.minimum_increment) +
                   " (Time stepping/Minimum increment)";
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
    s.epsilon   = 1e-12 * ts.end_time;
    s.time      = restarted ? start.time : 0.;
    s.increment = restarted ? std::min(start.increment, ts.maximum_increment) :
                              ts.initial_increment;
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

    const unsigned int n_steps = ts.n_step_ends();
    for (unsigned int step = start.step + 1; step <= n_steps; ++step)
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
      record.n_steps     = n_steps;
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



  bool
  LoadStepper::too_coarse(const IncrementalProblem &problem,
                          const double              increment,
                          Stepping                 &s,
                          bool                     &may_grow,
                          std::string              &reason) const
  {
    const double fraction = parameters.max_contact_changes;
    if (fraction == 0)
      return false;
    const auto         changes = problem.contact_changes();
    const unsigned int allowed =
      std::max(1u, static_cast<unsigned int>(fraction * changes.n_active));
    const unsigned int n_new = changes.n_changed;
    // A grown increment would change about growth factor times as many
    // nodes.
    may_grow = n_new * parameters.growth_factor <= allowed;
    // Halving must stay above the minimum and separate the nodes: where
    // the last halving left as many changes, the nodes change together
    // (a symmetric ring) and the increment is accepted.
    if (n_new <= allowed ||
        0.5 * increment < parameters.minimum_increment * (1 - 1e-12) ||
        n_new >= s.rejected_changes)
    {
      s.rejected_changes = Stepping::none;
      return false;
    }
    s.rejected_changes = n_new;
    reason = std::to_string(n_new) + " of " + std::to_string(changes.n_active) +
             " active frictional contact nodes closed or began to stick, "
             "more than " +
             std::to_string(allowed) +
             " (Time stepping/Maximum contact changes)";
    return true;
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
    s.rejected_changes        = Stepping::none;
    progress.change_increment = s.change_increment;
  }
} // namespace tribos
