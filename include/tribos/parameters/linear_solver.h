#ifndef tribos_parameters_linear_solver_h
#define tribos_parameters_linear_solver_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /** Subsection `Linear solver`: direct (SuiteSparse or Amesos) or GMRES
     * with AMG, or chosen by the system. */
    struct LinearSolver
    {
      enum class Type
      {
        automatic,
        direct,
        iterative
      };
      Type type;
      /** auto: 3D systems above this many unknowns are solved
       * iteratively. */
      unsigned long iterative_above;
      /** The same on several processes (the direct solver is MUMPS). */
      unsigned long iterative_above_under_mpi;
      /** Direct solver as written: auto or an Amesos solver's name. */
      std::string direct_solver;
      /** Multipliers (serial suitesparse solves): eliminated from a
       * regularized copy (SparseDirect), or LU of the whole system. */
      bool         eliminate_multipliers;
      double       tolerance;
      unsigned int max_iterations;

      /**
       * The direct solver on one process (@p serial) or several: the one
       * named, or (auto) SuiteSparse ("suitesparse": CHOLMOD or UMFPACK) on
       * one process, MUMPS under MPI.
       */
      std::string
      direct_solver_for(const bool serial) const;

      /**
       * Whether a system of @p n unknowns in @p dim dimensions is solved
       * iteratively: Type = iterative, or auto for a 3D system above
       * Iterative above, or on several processes (not @p serial) above
       * Iterative above under MPI.
       */
      bool
      iterative_for(const unsigned int  dim,
                    const unsigned long n,
                    const bool          serial) const;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
