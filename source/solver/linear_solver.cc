#include <tribos/base/exceptions.h>
#include <tribos/solver/distributed_elimination.h>
#include <tribos/solver/linear_solver.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/vector.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>

#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

namespace tribos
{
  namespace
  {
    /** MUMPS's own report of a failed phase: INFOG(1) and INFOG(2). */
    struct MumpsError
    {
      int infog1 = 0;
      int infog2 = 0;

      /**
       * Whether MUMPS ran out of a workspace it sized from ICNTL(14)
       * (MUMPS 5 user's guide, "Error diagnostics": -8, -14 and -15 the
       * integer workspace IS, -9 the real workspace S, -17 and -20 the
       * send and reception buffers); for each the guide's remedy is a
       * larger ICNTL(14). Not -13: a failed allocation, which more
       * workspace makes worse.
       */
      bool
      out_of_workspace() const
      {
        return infog1 == -8 || infog1 == -9 || infog1 == -14 || infog1 == -15 ||
               infog1 == -17 || infog1 == -20;
      }

      /** For the message: the codes and what the guide says of them. */
      std::string
      describe() const
      {
        std::string meaning;
        switch (infog1)
        {
          case -5:
          case -7:
          case -13:
            meaning = "a workspace could not be allocated (out of memory)";
            break;
          case -6:
            meaning = "the matrix is structurally singular (INFOG(2): its "
                      "structural rank)";
            break;
          case -10:
            meaning = "the matrix is numerically singular (INFOG(2): the "
                      "pivots eliminated)";
            break;
          default:
            meaning = out_of_workspace() ?
                        "a workspace too small for the factorization "
                        "(ICNTL(14))" :
                        "see the MUMPS user's guide, error diagnostics";
        }
        return "MUMPS INFOG(1) = " + std::to_string(infog1) +
               ", INFOG(2) = " + std::to_string(infog2) + ": " + meaning;
      }
    };



    /**
     * Standard error captured while it lives: Amesos_Mumps prints every
     * failed phase ("Amesos_Mumps : ERROR", INFOG(1), ...) whether or not
     * a retry with more workspace then succeeds; solve_amesos() reports
     * what failed in the end itself.
     */
    class QuietAmesos
    {
    public:
      QuietAmesos()
        : old(std::cerr.rdbuf(captured.rdbuf()))
      {
      }

      ~QuietAmesos()
      {
        std::cerr.rdbuf(old);
      }

    private:
      std::ostringstream captured;
      std::streambuf    *old;
    };



    /**
     * The error of @p mumps's last phase, on every process of
     * @p communicator: INFOG is defined on the host only (the first
     * process; the others may not even be among MUMPS's processes, which
     * Amesos limits for small matrices).
     */
    MumpsError
    mumps_error(Amesos_Mumps &mumps, const MPI_Comm communicator)
    {
      int codes[2] = {0, 0};
      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        codes[0] = mumps.GetINFOG()[0];
        codes[1] = mumps.GetINFOG()[1];
      }
      MPI_Bcast(codes, 2, MPI_INT, 0, communicator);
      return {codes[0], codes[1]};
    }
  } // namespace



  struct LinearSolver::Amesos
  {
    Epetra_LinearProblem               problem;
    std::unique_ptr<Amesos_BaseSolver> solver;
    std::string                        name;
    const Epetra_CrsMatrix            *matrix  = nullptr;
    unsigned long                      version = static_cast<unsigned long>(-1);
  };



  /**
   * The iterative solve of a system with multipliers: the multipliers are
   * eliminated from a copy regularized like a penalty of 1/alpha times the
   * local stiffness (DistributedElimination), and one V-cycle of ML on
   * that displacement-only matrix, with the multipliers recovered from
   * their rows, preconditions GMRES on the unmodified saddle-point system,
   * which removes the regularization.
   */
  struct LinearSolver::Eliminated
  {
    unsigned long          version = static_cast<unsigned long>(-1);
    DistributedElimination elimination;
    Hierarchy              hierarchy;
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
    multiplier_block = size;
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
    if (iterative(matrix) && saddle_point)
    {
      solve_iterative_eliminated(matrix, pattern_version, x, rhs, tolerance);
      return;
    }
    if (iterative(matrix))
    {
      solve_iterative(matrix, pattern_version, x, rhs, tolerance);
      return;
    }
    const bool serial = dealii::Utilities::MPI::n_mpi_processes(
                          matrix.get_mpi_communicator()) == 1;
    const std::string name = parameters.direct_solver_for(serial);
    if (name == "suitesparse")
    {
      if (!suitesparse)
      {
        suitesparse = std::make_unique<SparseDirect>();
        suitesparse->set_multiplier_blocks(first_multiplier,
                                           parameters.eliminate_multipliers ?
                                             multiplier_block :
                                             0);
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
    if (mumps_workspace_percent != mumps_default_workspace_percent)
      last +=
        " (workspace ICNTL(14) = " + std::to_string(mumps_workspace_percent) +
        " %)";
  }



  void
  LinearSolver::solve_iterative_eliminated(
    const TrilinosWrappers::SparseMatrix &matrix,
    const unsigned long                   pattern_version,
    Vector                               &x,
    const Vector                         &rhs,
    const double                          tolerance)
  {
    // A penalty of about 100 times the local stiffness, like the default
    // penalty factors, which AMG handles; GMRES removes it.
    constexpr double alpha = 1e-2;
    if (!eliminated)
      eliminated = std::make_unique<Eliminated>();
    auto &e = *eliminated;
    if (e.version != pattern_version)
    {
      // The hierarchy refers to the eliminated matrix prepare() rebuilds.
      e.hierarchy.amg.reset();
      if (!e.elimination.prepare(matrix, first_multiplier, multiplier_block))
        throw NonConvergence(
          "the multipliers cannot be eliminated (a multiplier row couples "
          "to another node's multipliers): use Linear solver/Type = direct");
      e.version = pattern_version;
    }
    e.elimination.eliminate(matrix, alpha);

    x = 0;
    try
    {
      solve_with_amg(matrix,
                     e.hierarchy,
                     x,
                     rhs,
                     std::max(tolerance, parameters.tolerance),
                     &e.elimination);
    }
    catch (const SolverControl::NoConvergence &failure)
    {
      throw NonConvergence("GMRES with the multipliers eliminated did not "
                           "converge in " +
                           std::to_string(failure.last_step) +
                           " iterations (Linear solver/Maximum iterations); "
                           "try Type = direct");
    }
    last = "GMRES + eliminated multipliers (ML)";
  }



  void
  LinearSolver::begin_increment()
  {
    if (suitesparse)
      suitesparse->begin_increment();
  }



  void
  LinearSolver::release_matrix()
  {
    amesos.reset();
    hierarchy.amg.reset();
  }



  void
  LinearSolver::solve_amesos(const TrilinosWrappers::SparseMatrix &matrix,
                             const unsigned long pattern_version,
                             Vector             &x,
                             const Vector       &rhs,
                             const std::string  &name)
  {
    // Every process takes the same branch: Amesos_Lapack, for one,
    // reports a failed factorization on its first process only, and a
    // process that skipped Solve() would leave the others waiting in it.
    const MPI_Comm communicator = matrix.get_mpi_communicator();
    const auto     failed       = [&](const int code)
    {
      return dealii::Utilities::MPI::max(code != 0 ? 1 : 0, communicator) > 0;
    };
    // What MUMPS says of a failed phase, for the message (collective).
    const auto mumps_report = [&](Amesos_Mumps *mumps)
    {
      return mumps != nullptr ?
               " (" + mumps_error(*mumps, communicator).describe() + ")" :
               std::string();
    };

    // The symbolic factorization once per pattern (and matrix object),
    // the numeric one at every solve.
    const Epetra_CrsMatrix &A     = matrix.trilinos_matrix();
    const bool              fresh = !amesos || amesos->name != name ||
                       amesos->matrix != &A ||
                       amesos->version != pattern_version;
    if (fresh)
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
    }
    auto *const mumps   = dynamic_cast<Amesos_Mumps *>(amesos->solver.get());
    const auto  analyse = [&]()
    {
      // MUMPS with the workspace that an earlier factorization needed.
      if (mumps != nullptr)
        mumps->SetICNTL(14, mumps_workspace_percent);
      if (failed(amesos->solver->SymbolicFactorization()))
      {
        const std::string report = mumps_report(mumps);
        amesos.reset();
        throw NonConvergence("the direct solver " + name +
                             " failed in its symbolic factorization" + report);
      }
    };
    if (fresh)
      analyse();
    amesos->problem.SetLHS(
      static_cast<Epetra_MultiVector *>(&x.trilinos_vector()));
    amesos->problem.SetRHS(const_cast<Epetra_MultiVector *>(
      static_cast<const Epetra_MultiVector *>(&rhs.trilinos_vector())));

    // MUMPS sizes the workspace of its factorization from the analysis's
    // estimate plus ICNTL(14) percent. Pivoting on the multipliers' zero
    // diagonal, chosen for the values the analysis saw, can outgrow that
    // (INFOG(1) = -9: every increment of a 2 x 2 x 1 block with friction
    // under -np 2 was cut back as a "singular system"). Each retry doubles
    // the workspace, to at most about 50 times the estimate; Amesos hands
    // ICNTL over to MUMPS in its analysis only, so a retry analyses again
    // (with the current values: a pivot order of their own too). The
    // method's name says the workspace once it was raised.
    constexpr int most_workspace_percent = 5000;
    const auto    factorize              = [&]()
    {
      const QuietAmesos quiet;
      return amesos->solver->NumericFactorization();
    };
    while (failed(factorize()))
    {
      if (mumps == nullptr)
        throw NonConvergence("the direct solver " + name +
                             " failed (singular system?)");
      const MumpsError error = mumps_error(*mumps, communicator);
      if (!error.out_of_workspace() ||
          mumps_workspace_percent >= most_workspace_percent)
        throw NonConvergence(
          "the direct solver " + name + " failed (" + error.describe() +
          (error.out_of_workspace() ?
             ", with ICNTL(14) = " + std::to_string(mumps_workspace_percent) :
             std::string()) +
          ")");
      mumps_workspace_percent =
        std::min(2 * mumps_workspace_percent + 100, most_workspace_percent);
      analyse();
    }
    if (failed(amesos->solver->Solve()))
      throw NonConvergence("the direct solver " + name +
                           " failed in its solve" + mumps_report(mumps));
  }



  std::unique_ptr<TrilinosWrappers::PreconditionAMG>
  LinearSolver::make_amg(const TrilinosWrappers::SparseMatrix &matrix)
  {
    // ML with the rigid-body modes as its near-null space (translations and
    // rotations: an elastic body's energy-free motions), on the matrix's
    // rows (the displacement rows come first: a system without its
    // multipliers takes the modes' first entries).
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = higher_order;
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = 0.02;
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> unused;
    data.set_parameters(list, unused, matrix);
    std::vector<double> modes;
    const unsigned int  n_rows = matrix.trilinos_matrix().NumMyRows();
    if (!null_space.empty())
    {
      for (const auto &mode : null_space)
      {
        AssertThrow(mode.size() >= n_rows, ExcInternalError());
        modes.insert(modes.end(), mode.begin(), mode.begin() + n_rows);
      }
      list.set("null space: type", "pre-computed");
      list.set("null space: dimension", int(null_space.size()));
      list.set("null space: vectors", modes.data());
    }
    auto preconditioner = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    preconditioner->initialize(matrix, list);
    ++n_amg_setups;
    return preconditioner;
  }



  void
  LinearSolver::solve_with_amg(const TrilinosWrappers::SparseMatrix &matrix,
                               Hierarchy                            &h,
                               Vector                               &x,
                               const Vector                         &rhs,
                               const double                          relative,
                               DistributedElimination *elimination)
  {
    // One V-cycle of h's ML: on the system, or, with multipliers, on the
    // eliminated matrix, the multipliers then recovered from their rows.
    // Either way a fixed linear operator, which GMRES needs (an inner
    // Krylov solve to a tolerance would need FGMRES: the elimination's
    // first version did that, and took 1.6 times as long; doc/scaling.md).
    struct Preconditioner
    {
      const Hierarchy        &h;
      DistributedElimination *elimination;
      void
      vmult(Vector &y, const Vector &z) const
      {
        if (elimination == nullptr)
        {
          h.amg->vmult(y, z);
          return;
        }
        elimination->apply(z,
                           y,
                           [this](Vector &y_reduced, const Vector &z_reduced)
                           { h.amg->vmult(y_reduced, z_reduced); });
      }
    };
    const Preconditioner preconditioner{h, elimination};

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
      try
      {
        solver.solve(matrix, x, rhs, preconditioner);
      }
      catch (const SolverControl::NoConvergence &e)
      {
        total_iterations += e.last_step;
        throw;
      }
      total_iterations += control.last_step();
      return control.last_step();
    };

    // The hierarchy of an earlier matrix of the same pattern preconditions
    // the next Newton matrix nearly as well (its finest level, the smoother,
    // sees the current values): it is kept while the solves stay within
    // twice the iterations per decade of its first solve (at least 20
    // iterations), and rebuilt when a solve needs more. ML's setup costs
    // several GMRES solves of the inexact Newton tolerances. Per decade,
    // since Newton's tolerances range from 1e-1 to 1e-8: a cap of twice
    // the first solve's count let a stale hierarchy fail only after twice
    // a tight solve's iterations (the 161k-dof cylinder's stroke, -np 2:
    // 3412 GMRES iterations and 151 s of linear solve with that cap, 3034
    // and 117 s with this one, the same 79 Newton iterations).
    const double decades = std::max(1., std::log10(1. / relative));
    if (h.amg)
    {
      const Vector start = x;
      try
      {
        gmres(static_cast<unsigned int>(
          std::max(20., std::ceil(2 * h.iterations_per_decade * decades))));
        return;
      }
      catch (const SolverControl::NoConvergence &)
      {
        x = start;
      }
    }
    h.amg = make_amg(elimination != nullptr ? elimination->matrix() : matrix);
    try
    {
      h.iterations_per_decade = gmres(parameters.max_iterations) / decades;
    }
    catch (const SolverControl::NoConvergence &)
    {
      h.amg.reset();
      throw;
    }
  }



  void
  LinearSolver::solve_iterative(const TrilinosWrappers::SparseMatrix &matrix,
                                const unsigned long pattern_version,
                                Vector             &x,
                                const Vector       &rhs,
                                const double        tolerance)
  {
    if (hierarchy.version != pattern_version)
    {
      hierarchy.amg.reset();
      hierarchy.version = pattern_version;
    }
    try
    {
      solve_with_amg(matrix,
                     hierarchy,
                     x,
                     rhs,
                     std::max(tolerance, parameters.tolerance));
    }
    catch (const SolverControl::NoConvergence &e)
    {
      throw NonConvergence("GMRES/AMG did not converge in " +
                           std::to_string(e.last_step) +
                           " iterations (Linear solver/Maximum "
                           "iterations); try Type = direct");
    }
    last = "GMRES + ML";
  }
} // namespace tribos
