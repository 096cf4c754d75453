#ifndef tribos_parameters_materials_h
#define tribos_parameters_materials_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace tribos
{
  namespace Parameters
  {
    /**
     * Subsection `Materials`: one constitutive model per body. Every entry
     * is a comma-separated list indexed by body id, or a single value that
     * applies to all bodies (the convention of ASPECT's compositional
     * fields), so that any number of bodies needs no new subsections.
     */
    struct Materials
    {
      std::vector<std::string> models;
      std::vector<double>      youngs_moduli;
      std::vector<double>      poissons_ratios;
      std::vector<double>      yield_stresses;
      std::vector<double>      saturation_yield_stresses;
      std::vector<double>      hardening_exponents;
      std::vector<double>      linear_hardening_moduli;
      /** Mass per reference volume (dynamics only). */
      std::vector<double> densities;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** The entry of @p values that belongs to body @p body_id. */
      template <typename T>
      static const T &
      for_body(const std::vector<T> &values,
               const unsigned int    body_id,
               const std::string    &entry);

      /** Refuses a per-body list longer than the mesh's body ids 0 ...
       * @p max_body_id: its extra values would be ignored silently. */
      void
      check_body_count(const unsigned int max_body_id) const;
    };
  } // namespace Parameters
} // namespace tribos

#endif
