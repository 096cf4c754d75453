#ifndef tribos_parameters_materials_h
#define tribos_parameters_materials_h

#include <deal.II/base/parameter_handler.h>

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace tribos
{
  class MaterialModel;

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
      /** Mass per reference volume (dynamics only). */
      std::vector<double> densities;
      /**
       * Every registered model with its own parameters (J2 plasticity's
       * hardening), by name: any of them may be a body's.
       */
      std::map<std::string, std::shared_ptr<const MaterialModel>>
        material_models;

      /**
       * The model called @p name: from material_models or, if
       * parse_parameters() did not fill them (Materials built by hand),
       * with its parameters' defaults; throws if none is called so.
       */
      std::shared_ptr<const MaterialModel>
      model(const std::string &name) const;

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

      /**
       * Refuses the list of Materials/@p entry of @p n_values values if it
       * is longer than the mesh's body ids 0 ... @p max_body_id (for
       * check_body_count() and the models' own lists).
       */
      static void
      check_count(const std::size_t  n_values,
                  const unsigned int max_body_id,
                  const std::string &entry);

      /**
       * The per-body list of numbers >= 0 of Materials/@p entry (@p prm
       * inside the subsection Materials); throws if it is empty or a value
       * is negative (for Density and the models' own lists).
       */
      static std::vector<double>
      non_negative_list(dealii::ParameterHandler &prm,
                        const std::string        &entry);
    };
  } // namespace Parameters
} // namespace tribos

#endif
