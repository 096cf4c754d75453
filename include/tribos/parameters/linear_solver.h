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
      std::string  type;
      std::string  direct_solver;
      double       tolerance;
      unsigned int max_iterations;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
