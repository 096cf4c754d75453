#ifndef tribos_parameters_time_stepping_h
#define tribos_parameters_time_stepping_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /** Subsection `Time stepping`: pseudo-time, load steps and cutbacks. */
    struct TimeStepping
    {
      double       end_time;
      unsigned int n_steps;
      unsigned int max_cutbacks;
      double       growth_factor;
      unsigned int easy_iterations;
      unsigned int growth_after;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
