#include <tribos/parameters/linear_solver.h>

namespace tribos
{
  namespace Parameters
  {
    void
    LinearSolver::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Type",
                        "direct",
                        dealii::Patterns::Selection("direct|iterative"),
                        "direct: sparse LU (Amesos); iterative: GMRES "
                        "preconditioned by algebraic multigrid (ML).");
      prm.declare_entry(
        "Direct solver",
        "auto",
        dealii::Patterns::Selection(
          "auto|Amesos_Klu|Amesos_Mumps|Amesos_Lapack"),
        "Trilinos Amesos package used when Type = direct. auto: KLU for "
        "systems of up to 5000 unknowns (less overhead per factorization), "
        "the multifrontal MUMPS above (less fill-in: 3-6 times faster from "
        "6000 unknowns in 3D, benchmarks/direct_solvers.py).");
      prm.declare_entry("Tolerance",
                        "1e-10",
                        dealii::Patterns::Double(0),
                        "Relative residual reduction of the iterative "
                        "solver.");
      prm.declare_entry("Maximum iterations",
                        "5000",
                        dealii::Patterns::Integer(1),
                        "Iterations of the iterative solver.");
      prm.leave_subsection();
    }



    std::string
    LinearSolver::amesos_solver(const unsigned long n) const
    {
      // KLU's left-looking LU costs least for small systems; the
      // multifrontal MUMPS wins once fill-in dominates (doc/benchmarks.md).
      if (direct_solver != "auto")
        return direct_solver;
      return n > 5000 ? "Amesos_Mumps" : "Amesos_Klu";
    }



    void
    LinearSolver::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      direct         = prm.get("Type") == "direct";
      direct_solver  = prm.get("Direct solver");
      tolerance      = prm.get_double("Tolerance");
      max_iterations = prm.get_integer("Maximum iterations");
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
