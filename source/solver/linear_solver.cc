#include <tribos/base/exceptions.h>
#include <tribos/solver/linear_solver.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <memory>

namespace tribos
{
  struct LinearSolver::Amesos
  {
    Epetra_LinearProblem               problem;
    std::unique_ptr<Amesos_BaseSolver> solver;
    std::string                        name;
    const Epetra_CrsMatrix            *matrix  = nullptr;
    unsigned long                      version = static_cast<unsigned long>(-1);
  };



  LinearSolver::LinearSolver(const Parameters::LinearSolver &parameters,
                             const unsigned int              dim,
                             const bool                      saddle_point)
    : parameters(parameters)
    , dim(dim)
    , saddle_point(saddle_point)
  {
  }



  LinearSolver::~LinearSolver() = default;



  void
  LinearSolver::set_near_null_space(
    const std::vector<std::vector<double>> &modes,
    const bool                              higher)
  {
    null_space   = modes;
    higher_order = higher;
  }



  void
  LinearSolver::set_multiplier_blocks(const types::global_dof_index first,
                                      const unsigned int            size)
  {
    first_multiplier = first;
    multiplier_block = parameters.eliminate_multipliers ? size : 0;
  }



  void
  LinearSolver::set_timer(TimerOutput &t)
  {
    timer = &t;
  }



  void
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      const unsigned long                   pattern_version,
                      Vector                               &x,
                      const Vector                         &rhs,
                      const double                          tolerance)
  {
    std::unique_ptr<TimerOutput::Scope> scope;
    if (timer != nullptr)
      scope = std::make_unique<TimerOutput::Scope>(*timer, "linear solve");
    if (iterative(matrix))
    {
      solve_iterative(matrix, pattern_version, x, rhs, tolerance);
      return;
    }
    const bool serial =
      Utilities::MPI::n_mpi_processes(matrix.get_mpi_communicator()) == 1;
    const std::string name = parameters.direct_solver_for(serial);
    if (name == "suitesparse")
    {
      if (!suitesparse)
      {
        suitesparse = std::make_unique<SparseDirect>();
        suitesparse->set_multiplier_blocks(first_multiplier, multiplier_block);
      }
      if (!suitesparse->solve(matrix, pattern_version, x, rhs))
        throw NonConvergence("the direct solver " + suitesparse->method() +
                             " failed (singular system?)");
      last = suitesparse->method() + " (SuiteSparse)";
      total_refinements += suitesparse->refinements();
      return;
    }
    solve_amesos(matrix, pattern_version, x, rhs, name);
    last = name;
  }



  void
  LinearSolver::release_matrix()
  {
    amesos.reset();
    amg.reset();
  }



  void
  LinearSolver::solve_amesos(const TrilinosWrappers::SparseMatrix &matrix,
                             const unsigned long pattern_version,
                             Vector             &x,
                             const Vector       &rhs,
                             const std::string  &name)
  {
    // The symbolic factorization once per pattern (and matrix object),
    // the numeric one at every solve.
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    if (!amesos || amesos->name != name || amesos->matrix != &A ||
        amesos->version != pattern_version)
    {
      amesos = std::make_unique<Amesos>();
      amesos->problem.SetOperator(const_cast<Epetra_CrsMatrix *>(&A));
      ::Amesos factory;
      amesos->solver.reset(factory.Create(name.c_str(), amesos->problem));
      AssertThrow(amesos->solver != nullptr,
                  ExcMessage("Linear solver/Direct solver = <" + name +
                             ">: Trilinos has no such Amesos solver."));
      amesos->name    = name;
      amesos->matrix  = &A;
      amesos->version = pattern_version;
      if (amesos->solver->SymbolicFactorization() != 0)
      {
        amesos.reset();
        throw NonConvergence("the direct solver " + name +
                             " failed in its symbolic factorization");
      }
    }
    amesos->problem.SetLHS(
      static_cast<Epetra_MultiVector *>(&x.trilinos_vector()));
    amesos->problem.SetRHS(const_cast<Epetra_MultiVector *>(
      static_cast<const Epetra_MultiVector *>(&rhs.trilinos_vector())));
    if (amesos->solver->NumericFactorization() != 0 ||
        amesos->solver->Solve() != 0)
      throw NonConvergence("the direct solver " + name +
                           " failed (singular system?)");
  }



  void
  LinearSolver::solve_iterative(const TrilinosWrappers::SparseMatrix &matrix,
                                const unsigned long pattern_version,
                                Vector             &x,
                                const Vector       &rhs,
                                const double        tolerance)
  {
    const double relative = std::max(tolerance, parameters.tolerance);
    // Right preconditioning: GMRES then measures the true residual
    // |rhs - A x|, which the tolerance (relative to |rhs|, from inexact
    // Newton) is about; left preconditioning measures the AMG-scaled one,
    // which can be below a loose tolerance before the first iteration.
    const auto gmres = [&](const unsigned int max_iterations)
    {
      SolverControl       control(max_iterations, relative * rhs.l2_norm());
      SolverGMRES<Vector> solver(control,
                                 SolverGMRES<Vector>::AdditionalData(200,
                                                                     true));
      solver.solve(matrix, x, rhs, *amg);
      return control.last_step();
    };

    // The hierarchy of an earlier matrix of the same pattern preconditions
    // the next Newton matrix nearly as well (its finest level, the smoother,
    // sees the current values): it is kept while the solves stay within
    // twice the iterations of its first solve (at least 20), and rebuilt
    // when a solve needs more or the pattern changes. ML's setup costs
    // several GMRES solves of the inexact Newton tolerances.
    if (amg && amg_version == pattern_version)
    {
      const unsigned int budget = std::max(20u, 2 * amg_iterations);
      const Vector       start  = x;
      try
      {
        const unsigned int n = gmres(budget);
        total_iterations += n;
        last = "GMRES + ML";
        return;
      }
      catch (const SolverControl::NoConvergence &e)
      {
        total_iterations += e.last_step;
        x = start;
      }
    }

    // ML with the rigid-body modes as its near-null space (translations and
    // rotations: an elastic body's energy-free motions).
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = higher_order;
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = 0.02;
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> unused;
    data.set_parameters(list, unused, matrix);
    std::vector<double> modes;
    if (!null_space.empty())
    {
      for (const auto &mode : null_space)
        modes.insert(modes.end(), mode.begin(), mode.end());
      list.set("null space: type", "pre-computed");
      list.set("null space: dimension", int(null_space.size()));
      list.set("null space: vectors", modes.data());
    }
    amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    amg->initialize(matrix, list);
    amg_version = pattern_version;
    ++n_amg_setups;

    try
    {
      amg_iterations = gmres(parameters.max_iterations);
      total_iterations += amg_iterations;
    }
    catch (const SolverControl::NoConvergence &e)
    {
      amg.reset();
      throw NonConvergence("GMRES/AMG did not converge in " +
                           std::to_string(e.last_step) +
                           " iterations (Linear solver/Maximum "
                           "iterations); try Type = direct");
    }
    last = "GMRES + ML";
  }
} // namespace tribos
