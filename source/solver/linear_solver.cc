#include <tribos/base/exceptions.h>
#include <tribos/solver/linear_solver.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <memory>

namespace tribos
{
  LinearSolver::LinearSolver(const Parameters::LinearSolver &parameters)
    : parameters(parameters)
  {
  }



  void
  LinearSolver::set_near_null_space(const std::vector<std::vector<bool>> &modes,
                                    const bool higher)
  {
    constant_modes = modes;
    higher_order   = higher;
  }



  void
  LinearSolver::set_timer(TimerOutput &t)
  {
    timer = &t;
  }



  void
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      Vector                               &x,
                      const Vector                         &rhs)
  {
    std::unique_ptr<TimerOutput::Scope> scope;
    if (timer != nullptr)
      scope = std::make_unique<TimerOutput::Scope>(*timer, "linear solve");
    const auto &p = parameters;
    if (p.direct)
    {
      const std::string name = p.amesos_solver(matrix.m());
      SolverControl     control(1, 0);
      TrilinosWrappers::SolverDirect solver(
        control,
        TrilinosWrappers::SolverDirect::AdditionalData(false, name));
      try
      {
        solver.solve(matrix, x, rhs);
      }
      catch (const std::exception &e)
      {
        // A singular matrix (e.g. an unsupported body, or a degenerate
        // active set) fails this increment; the load stepping cuts back.
        throw NonConvergence("the direct solver " + name +
                             " failed (singular system?)");
      }
      return;
    }

    TrilinosWrappers::PreconditionAMG                 amg;
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.constant_modes        = constant_modes;
    data.elliptic              = true;
    data.higher_order_elements = higher_order;
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = 0.02;
    amg.initialize(matrix, data);

    SolverControl       control(p.max_iterations, p.tolerance * rhs.l2_norm());
    SolverGMRES<Vector> solver(control,
                               SolverGMRES<Vector>::AdditionalData(200));
    try
    {
      solver.solve(matrix, x, rhs, amg);
    }
    catch (const SolverControl::NoConvergence &e)
    {
      throw NonConvergence("GMRES/AMG did not converge in " +
                           std::to_string(e.last_step) +
                           " iterations (Linear solver/Maximum "
                           "iterations); try Type = direct");
    }
  }
} // namespace tribos
