#ifndef tribos_parameters_verification_h
#define tribos_parameters_verification_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /**
     * Subsection `Verification`: an exact displacement field, if known, to
     * which the discrete solution is compared in L2 and H1 at every step.
     */
    struct Verification
    {
      std::vector<std::string> exact_displacement;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
