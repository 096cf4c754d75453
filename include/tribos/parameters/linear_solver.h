#ifndef tribos_parameters_linear_solver_h
#define tribos_parameters_linear_solver_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /** Subsection `Linear solver`: direct (Amesos) or GMRES with AMG. */
    struct LinearSolver
    {
      /** Type = direct (else iterative). */
      bool direct;
      /** Direct solver as written: auto or an Amesos solver's name. */
      std::string  direct_solver;
      double       tolerance;
      unsigned int max_iterations;

      /** The Amesos solver for a system of @p n unknowns: the one named,
       * or (auto) KLU up to 5000 unknowns, MUMPS above. */
      std::string
      amesos_solver(const unsigned long n) const;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
