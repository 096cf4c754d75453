#include <tribos/base/text.h>
#include <tribos/parameters/verification.h>

namespace tribos
{
  namespace Parameters
  {
    void
    Verification::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Verification");
      prm.declare_entry("Exact displacement",
                        "",
                        dealii::Patterns::Anything(),
                        "dim comma-separated expressions in x, y, z, t. If "
                        "given, history.csv gets the columns error_L2 and "
                        "error_H1 (H1 seminorm) of the displacement.");
      prm.leave_subsection();
    }



    void
    Verification::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Verification");
      exact_displacement =
        Text::split_top_level(prm.get("Exact displacement"), ',');
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace tribos
