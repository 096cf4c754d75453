#include <tribos/base/exceptions.h>
#include <tribos/solver/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

namespace tribos
{
  NewtonSolver::NewtonSolver(const Parameters::NonlinearSolver &parameters,
                             LinearSolver                      &linear_solver)
    : parameters(parameters)
    , linear_solver(linear_solver)
  {
  }



  double
  NewtonSolver::line_search(
    NonlinearProblem                          &problem,
    const NonlinearProblem::Vector            &update,
    const double                               residual,
    const bool                                 with_tangent,
    std::optional<NonlinearProblem::Residual> &assembled)
  {
    const NonlinearProblem::Vector base = problem.solution();
    double                         step = 1;
    for (unsigned int k = 0;; ++k)
    {
      problem.solution() = base;
      problem.solution().add(step, update);
      problem.solution_changed();
      // The full step with the tangent (@p with_tangent): it is usually
      // taken, and the next iteration's assembly would repeat this one
      // (the paper's cylinder at 1.2M dofs: 165 assemblies for 86 Newton
      // iterations).
      double trial = std::numeric_limits<double>::infinity();
      try
      {
        const bool reuse = (k == 0 && with_tangent);
        const auto r     = problem.assemble(reuse, false);
        trial            = r.free;
        if (reuse)
          assembled = r;
      }
      catch (const InvertedElement &)
      {
      }
      if (trial <= (1 - 1e-4 * step) * residual ||
          k >= parameters.max_line_search_steps)
      {
        if (k > 0)
          assembled.reset();
        return step;
      }
      step *= 0.5;
    }
  }



  bool
  NewtonSolver::update_converged(const NonlinearProblem::Norms &last,
                                 const NonlinearProblem::Norms &before,
                                 const NonlinearProblem::Norms &change,
                                 const NonlinearProblem::Norms &floor,
                                 const bool                     full_step,
                                 const unsigned int             iteration) const
  {
    // The error of an iterate is the corrections still to come, not the
    // one that led to it: where the last two (both after the first
    // iteration, which carries the Dirichlet increment, the last one a full
    // step) contract at a rate rho < 1/2, they sum to at most
    // rho / (1 - rho) times the last. Testing the last correction itself
    // cost one more iteration wherever Newton had converged (the paper's
    // cylinder at 1.2M dofs: 7 of 25 steps).
    const auto error = [&](const double now, const double earlier)
    {
      const double rho = now / earlier;
      if (full_step && iteration >= 3 && earlier > 0 && rho < 0.5)
        return rho / (1 - rho) * now;
      return now;
    };
    const auto &p = parameters;
    return (error(last.displacement, before.displacement) <=
              p.increment_tolerance * change.displacement +
                floor.displacement ||
            change.displacement == 0) &&
           error(last.multipliers, before.multipliers) <=
             p.increment_tolerance * change.multipliers + floor.multipliers;
  }



  double
  NewtonSolver::linear_tolerance(const Iterate &it,
                                 const double   residual,
                                 const double   force_scale) const
  {
    // Inexact Newton (Eisenstat and Walker's second choice) for iterative
    // solves: the linear tolerance follows the decrease of the residual,
    // eta = 0.9 (r_k / r_k-1)^2, kept above 0.9 eta_k-1^2 when that is
    // large (no sudden oversolving) and above half of what the Newton test
    // still asks (no solve beyond the tolerance), at most 1e-3 (0.1 in the
    // quadratic range near the tolerance, below); the first iteration,
    // which carries the Dirichlet increment, at 1e-4. The cap: contact
    // changes the active set between iterations, and a loose direction
    // costs Newton iterations that cost more than the Krylov iterations
    // saved (3D Hertz, 121k unknowns: 23 Newton iterations and 34.7 s with
    // 0.1, 15 and 27.4 s with 1e-3, 15 and 35.1 s with 1e-4, 13 and 43.7 s
    // solving to 1e-10).
    if (it.iteration == 0)
      return 1e-4;
    // previous[1]: the residual of the iteration before this one.
    const double before = it.previous[1];
    double       eta    = 0.9 * std::pow(residual / before, 2);
    if (0.9 * it.previous_eta * it.previous_eta > 0.1)
      eta = std::max(eta, 0.9 * it.previous_eta * it.previous_eta);
    const double target =
      parameters.residual_tolerance * std::max(it.reference, force_scale);
    const double enough = 0.5 * target / residual;
    eta                 = std::min(1e-3, std::max(eta, enough));
    // In Newton's quadratic range (the last iteration took off two decades
    // or more) near the tolerance the cap only oversolves: the solve that
    // confirms a converged iterate's update needs its residual below half
    // the tolerance, not a thousandth of itself (the 161k-dof cylinder: 37
    // of each step's 120 GMRES iterations).
    if (residual < 1e-2 * before)
      eta = std::max(eta, std::min(0.1, enough));
    // A stalled Newton step (the residual not halved) is the active set's
    // doing, not the Krylov tolerance's: solve it tightly.
    if (residual > 0.5 * before)
      eta = std::min(eta, 1e-8);
    return std::max(eta, 1e-12);
  }



  void
  NewtonSolver::solve_linear(NonlinearProblem         &problem,
                             SolverObserver           &observer,
                             NonlinearProblem::Vector &update,
                             const double              eta)
  {
    // Nonlinear solver/Tangent shift: a singular tangent (a body whose
    // first iterate rests on one frictionless node turns freely) gets a
    // defined solve, a regular one changes by the shift only.
    if (parameters.tangent_shift > 0)
    {
      auto &matrix = problem.system_matrix();
      for (const auto i : matrix.locally_owned_range_indices())
        matrix.add(i, i, parameters.tangent_shift * matrix.diag_element(i));
      matrix.compress(VectorOperation::add);
    }
    update = 0;
    ++linear_solves;
    linear_solver.solve(problem.system_matrix(),
                        problem.pattern_version(),
                        update,
                        problem.system_rhs(),
                        eta);
    // A singular system can come back as NaN from a direct solver: say
    // so, instead of letting the material report a NaN deformation.
    if (!std::isfinite(update.l2_norm()))
      throw NonConvergence("the linear solver (" + linear_solver.method() +
                           ") returned a non-finite update (singular "
                           "system?)");
    // Each method once: frictional runs switch between Cholesky and LU
    // as the tangent's symmetry comes and goes.
    if (announced.insert(linear_solver.method()).second)
      observer.message("  linear solver: " + linear_solver.method());
  }



  std::pair<bool, bool>
  NewtonSolver::test_convergence(NonlinearProblem                 &problem,
                                 const NonlinearProblem::Residual &r,
                                 const Iterate                    &it,
                                 const NonlinearProblem::Norms    &floor) const
  {
    const auto &p = parameters;
    const bool  residual_converged =
      r.free <= p.residual_tolerance * std::max(it.reference, r.force_scale) +
                  p.absolute_residual_tolerance;
    const auto change = problem.change_scale();
    // Round-off stagnation: accepted only below the stated bound.
    const bool stagnated =
      it.correction.displacement <= 1e-12 * change.displacement &&
      it.correction.multipliers <=
        1e-12 * change.multipliers + floor.multipliers &&
      r.free <= problem.stagnation_residual_bound();
    // At the floor: a correction within the round-off of the positions
    // (not of the displacements, 1e-12 of which is far below it early in
    // a run) and a residual within ten times the round-off of its own
    // assembly (the problem's estimate, asked only here: it reads the
    // whole matrix), below the stated bound too. The iterate is then the
    // discrete solution to round-off: a stiff penalty on second-order
    // faces stalled at |R| = 1.2e-7 with corrections of 4e-15, above the
    // relative tolerance (5e-8), and every increment was cut back until
    // the run failed. (Every process takes the same branches: the norms
    // are global.)
    const bool at_floor = it.correction.displacement <= floor.displacement &&
                          it.correction.multipliers <=
                            1e-12 * change.multipliers + floor.multipliers &&
                          r.free <= problem.stagnation_residual_bound() &&
                          r.free <= 10 * problem.residual_round_off();
    // A residual at round-off (1e-4 of its tolerance) says the iterate
    // solves the discrete equations: the correction still to come is
    // round-off too, and the solve that would confirm it is skipped
    // (Abaqus's test of linear increments). After an active-set change on
    // a linear body, Newton lands there without the contraction the update
    // test needs (2D Hertz: 7 solves instead of 6; 3D: 5 for 4). Not where
    // multipliers are unknowns: their rows' scale is not the residual's.
    const bool at_round_off = change.multipliers == 0 &&
                              r.free <= 1e-4 * p.residual_tolerance *
                                          std::max(it.reference, r.force_scale);
    const bool converged =
      (residual_converged &&
       (at_round_off || update_converged(it.taken,
                                         it.earlier,
                                         change,
                                         floor,
                                         it.step_length == 1,
                                         it.iteration))) ||
      stagnated || at_floor;
    return {residual_converged, converged};
  }



  void
  NewtonSolver::take_step(NonlinearProblem               &problem,
                          const NonlinearProblem::Vector &update,
                          const double                    residual,
                          const bool                      line_search_allowed,
                          Iterate                        &it,
                          std::optional<NonlinearProblem::Residual> &assembled)
  {
    // A step the problem limits is taken as limited: the residual of a node
    // entering contact may rise, and the Armijo test would only shorten it
    // more.
    it.step_length = problem.step_limit(update, it.iteration == 0);
    if (it.step_length == 1 && line_search_allowed)
      it.step_length =
        line_search(problem, update, residual, !it.residual_first, assembled);
    else
    {
      problem.solution().add(it.step_length, update);
      problem.solution_changed();
    }
  }



  IncrementReport
  NewtonSolver::solve(NonlinearProblem                     &problem,
                      SolverObserver                       &observer,
                      const double                          time,
                      const NonlinearProblem::Vector *const predictor)
  {
    const auto  &p   = parameters;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    problem.begin_increment(time, predictor);
    linear_solver.begin_increment();

    // A new vector of the right-hand side's layout, not a copy: a copy
    // would take along entries for other processes that an interrupted
    // assembly left in it, and the constraints' distribute() would write
    // them into the update (a cutback under MPI then started from a
    // state its serial run never saw).
    NonlinearProblem::Vector update;
    update.reinit(problem.system_rhs());
    const auto floor = problem.round_off_floor();

    IncrementReport report;
    Iterate         it;
    // The system at the current iterate where the line search assembled
    // it already (its full step, taken).
    std::optional<NonlinearProblem::Residual> assembled;
    for (it.iteration = 0;; ++it.iteration)
    {
      const unsigned int iteration = it.iteration;
      const bool         first     = (iteration == 0);
      // (The line search assembles no tangent where residual_first is set.)
      const bool with_matrix = !it.residual_first;
      const auto r =
        assembled ? *assembled : problem.assemble(with_matrix, first);
      assembled.reset();
      if (!std::isfinite(r.free))
        throw NonConvergence("the residual is not finite");
      problem.after_assembly(iteration, r.free);

      // Observed order of convergence from three successive residuals
      // after the first solve (iteration 0 precedes the Dirichlet
      // increment and says nothing about the rate).
      double order = nan;
      if (iteration >= 3 && it.previous[0] > 0 && it.previous[1] > 0 &&
          r.free > 0 && it.previous[0] != it.previous[1])
        order = std::log(r.free / it.previous[0]) /
                std::log(it.previous[0] / it.previous[1]);
      it.previous[1] = it.previous[0];
      it.previous[0] = r.free;
      const double scale =
        std::max(std::max(it.reference, r.free), r.force_scale);
      observer.iteration({iteration,
                          r.free,
                          scale > 0 ? r.free / scale : 0.,
                          it.taken.displacement,
                          it.step_length,
                          it.correction.displacement,
                          order});

      bool residual_converged = false;
      if (!first)
      {
        bool converged = false;
        std::tie(residual_converged, converged) =
          test_convergence(problem, r, it, floor);
        if (converged)
        {
          report.residual = r.free;
          if (problem.at_convergence() == NonlinearProblem::Verdict::accept)
          {
            report.n_iterations = it.n_solves;
            return report;
          }
          it.relaxed_at      = iteration;
          it.reset_reference = true;
          it.residual_first  = false;
          continue;
        }
        // The limit counts the iterations that still reduce the residual:
        // an iterate whose residual already meets its tolerance gets the
        // solve that confirms its update (two at most), instead of a
        // cutback of a converged increment (3D Hertz, 226k unknowns: cut
        // back at |R| = 2e-15 relative in the 20th iteration).
        if (iteration - it.relaxed_at >=
            p.max_iterations + (residual_converged ? 2 : 0))
          throw NonConvergence("Newton did not converge in " +
                               std::to_string(iteration - it.relaxed_at) +
                               " iterations (|R| = " + to_scientific(r.free) +
                               "; Nonlinear solver/Maximum iterations)");
      }
      // The scale of the relative test: the residual at the start of the
      // increment (or of a relaxation), with the force scale. Not the
      // largest residual of the increment: after an iterate that flew
      // apart (a singular first step, residual 1e15) every later one
      // passed (a floating Hertz sphere "converged" with a contact force
      // 175 times its load).
      if (it.reset_reference)
      {
        it.reference       = r.free;
        it.reset_reference = false;
      }
      if (!with_matrix)
        problem.assemble(true, first);

      if (p.check_tangent && !first)
      {
        observer.message("  tangent check, iteration " +
                         std::to_string(iteration) + ": relative error " +
                         to_scientific(problem.tangent_error()));
        problem.assemble(true, first);
      }

      double eta = 0;
      if (linear_solver.iterative(problem.system_matrix()))
      {
        eta             = linear_tolerance(it, r.free, r.force_scale);
        it.previous_eta = eta;
      }
      solve_linear(problem, observer, update, eta);
      ++it.n_solves;
      problem.distribute(update, first);

      // No line search on the first iteration (it carries the Dirichlet
      // increment) nor once the residual is at its tolerance (only the
      // update is still too large): there is nothing left to decrease.
      const auto next_correction = problem.norms(update);
      // Where the update about to be taken already passes the update test,
      // the next iterate is likely the last: its residual is assembled
      // first, the tangent only if Newton goes on. A converged increment's
      // last tangent was never used (the 42k-dof cylinder: 25 of 103
      // assemblies). (The change so far before this update: near
      // convergence the same.)
      it.residual_first = !first && update_converged(next_correction,
                                                     it.correction,
                                                     problem.change_scale(),
                                                     floor,
                                                     true,
                                                     iteration + 1);
      take_step(problem,
                update,
                r.free,
                p.line_search && !first && !residual_converged,
                it,
                assembled);
      // A shortened step is not the one the test was passed by.
      it.residual_first     = it.residual_first && it.step_length == 1;
      it.earlier            = it.correction;
      it.correction         = next_correction;
      it.taken.displacement = it.step_length * it.correction.displacement;
      it.taken.multipliers  = it.step_length * it.correction.multipliers;
    }
  }
} // namespace tribos
