#ifndef tribos_parameters_nonlinear_solver_h
#define tribos_parameters_nonlinear_solver_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /** Subsection `Nonlinear solver`: Newton-Raphson with line search. */
    struct NonlinearSolver
    {
      unsigned int max_iterations;
      double       residual_tolerance;
      double       absolute_residual_tolerance;
      double       increment_tolerance;
      bool         line_search;
      unsigned int max_line_search_steps;
      bool         check_tangent;
      /** The largest increase of a contact node's penetration in one
       * Newton step, over its element size (0: no limit). */
      double penetration_limit;
      /** Relative shift of the tangent's diagonal before every solve. */
      double tangent_shift;
      /** Stabilization spring factor (0: off). */
      double stabilization;
      /** Largest accepted ratio of the stabilization forces to the load. */
      double stabilization_limit;
      /** Re-anchorings of the springs per increment at most. */
      unsigned int max_stabilization_relaxations;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
