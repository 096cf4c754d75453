#ifndef tribos_parameters_output_h
#define tribos_parameters_output_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /** Subsection `Output`: where and how often results are written. */
    struct Output
    {
      std::string               directory;
      unsigned int              frequency;
      std::vector<unsigned int> steps;
      bool                      write_vtu;
      /** Probe points (coordinates as given; checked against Dimension). */
      std::vector<std::vector<double>> probes;
      /** Write a checkpoint after every this many nominal steps (0: never)
       * into directory/checkpoint-NNNNN. */
      unsigned int checkpoint_every;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Whether the nominal step @p step (1-based) of @p n_steps is written.
       */
      bool
      is_output_step(const unsigned int step, const unsigned int n_steps) const;
    };
  } // namespace Parameters
} // namespace tribos

#endif
