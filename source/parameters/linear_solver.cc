#include <tribos/base/text.h>
#include <tribos/parameters/linear_solver.h>

namespace tribos
{
  namespace Parameters
  {
    void
    LinearSolver::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry(
        "Type",
        "auto",
        dealii::Patterns::Selection("auto|direct|iterative"),
        "direct: a sparse direct solver (Direct solver); iterative: GMRES "
        "preconditioned by algebraic multigrid (ML with the rigid-body "
        "modes), its tolerance following Newton's residual (inexact "
        "Newton); with Lagrange multipliers: GMRES on the "
        "saddle-point system, preconditioned by the multipliers' "
        "elimination with one ML V-cycle on the displacement-only matrix; "
        "auto: iterative for 3D systems above Iterative above "
        "unknowns (Iterative above under MPI on several processes), direct "
        "otherwise (the log says which). A direct 3D solve grows faster with the size than "
        "AMG (Hertz 3D, 121k unknowns: 3.2 s against 1.5 s per solve; "
        "21k: 0.13 against 0.27 s).");
      prm.declare_entry("Iterative above",
                        "50000",
                        dealii::Patterns::Integer(0),
                        "Type = auto: the size (unknowns) above which a 3D "
                        "system is solved iteratively. With multipliers (one "
                        "process) the two break "
                        "even near 56k unknowns (3D Hertz: 1.95 s per "
                        "direct and 1.87 s per iterative solve) and the "
                        "iterative one wins at 121k (5.5 against 9.3 s).");
      prm.declare_entry(
        "Iterative above under MPI",
        "10000",
        dealii::Patterns::Integer(0),
        "Type = auto on several processes: the size (unknowns) above which "
        "a 3D system is solved iteratively. MUMPS, the direct solver under "
        "MPI, pays for its distribution: with mpirun -np 2 GMRES + ML took "
        "0.7 times its wall time on the 3D Hertz at 21k unknowns and 0.42 "
        "times at 36k, and broke even at 2k and 5k.");
      prm.declare_entry(
        "Direct solver",
        "auto",
        dealii::Patterns::Selection(
          "auto|suitesparse|Amesos_Klu|Amesos_Mumps|Amesos_Lapack"),
        "The sparse direct solver of Type = direct. suitesparse (one "
        "process): CHOLMOD's supernodal Cholesky where the matrix is "
        "symmetric positive definite, UMFPACK's LU otherwise; Amesos_*: "
        "Trilinos Amesos (MUMPS runs under MPI). auto: suitesparse on one "
        "process, Amesos_Mumps under MPI. Every solver keeps its symbolic "
        "factorization while the sparsity pattern stays "
        "(benchmarks/direct_solvers.py).");
      prm.declare_entry(
        "Eliminate multipliers",
        "true",
        dealii::Patterns::Bool(),
        "Lagrange multipliers with the suitesparse solver: true: each "
        "node's multipliers are eliminated from a copy of the system whose "
        "multiplier block is regularized in its singular directions (like "
        "a penalty about 1e5 times the stiffness there), CHOLMOD "
        "factorizes the displacement-only matrix, and iterative "
        "refinement on the unmodified system recovers its exact solution. "
        "Where the eliminated matrix is not symmetric positive definite "
        "(sticking or slipping nodes, a body still free) or the refinement "
        "does not converge, "
        "the solve is UMFPACK's LU of the whole system, as with false.");
      prm.declare_entry("Tolerance",
                        "1e-10",
                        Text::non_negative_number(),
                        "The smallest relative residual asked of the "
                        "iterative solver: inexact Newton asks between this "
                        "and 1e-3, following the Newton residual.");
      prm.declare_entry("Maximum iterations",
                        "5000",
                        dealii::Patterns::Integer(1),
                        "Iterations of the iterative solver.");
      prm.leave_subsection();
    }



    std::string
    LinearSolver::direct_solver_for(const bool serial) const
    {
      if (direct_solver != "auto")
        return direct_solver;
      return serial ? "suitesparse" : "Amesos_Mumps";
    }



    bool
    LinearSolver::iterative_for(const unsigned int  dim,
                                const unsigned long n,
                                const bool          serial) const
    {
      if (type != Type::automatic)
        return type == Type::iterative;
      return dim == 3 &&
             n > (serial ? iterative_above : iterative_above_under_mpi);
    }



    void
    LinearSolver::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      const std::string t       = prm.get("Type");
      type                      = t == "direct"    ? Type::direct :
                                  t == "iterative" ? Type::iterative :
                                                     Type::automatic;
      iterative_above           = prm.get_integer("Iterative above");
      iterative_above_under_mpi = prm.get_integer("Iterative above under MPI");
      direct_solver             = prm.get("Direct solver");
      eliminate_multipliers     = prm.get_bool("Eliminate multipliers");
      tolerance                 = prm.get_double("Tolerance");
      max_iterations            = prm.get_integer("Maximum iterations");
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
