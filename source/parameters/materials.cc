#include <tribos/base/text.h>
#include <tribos/material/material_model.h>
#include <tribos/parameters/materials.h>

namespace tribos
{
  namespace Parameters
  {
    void
    Materials::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      // The models that registered themselves (source/material/), with
      // their own descriptions.
      prm.declare_entry("Model",
                        "neo-Hookean",
                        dealii::Patterns::List(dealii::Patterns::Selection(
                          material_registry().selection_pattern())),
                        "Constitutive model per body id (comma-separated) or "
                        "one for all bodies. " +
                          material_registry().documentation("'") + ".");
      prm.declare_entry("Young's modulus",
                        "1",
                        dealii::Patterns::Anything(),
                        "Per body id or one value for all; > 0.");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        dealii::Patterns::Anything(),
                        "Per body id or one value for all; in [0, 0.5).");
      // The models' own entries (J2 plasticity's hardening), where they
      // were declared before the registry (the order numbers the patterns
      // of --print-parameters json).
      material_registry().declare_parameters(prm);
      prm.declare_entry("Density",
                        "0",
                        dealii::Patterns::Anything(),
                        "Mass per reference volume, per body id or one for "
                        "all; used by the dynamic integrators only (Time "
                        "stepping/Integrator), which need it > 0.");
      prm.leave_subsection();
    }



    void
    Materials::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      models          = dealii::Utilities::split_string_list(prm.get("Model"));
      youngs_moduli   = Text::parse_doubles(prm.get("Young's modulus"),
                                          "Materials/Young's modulus");
      poissons_ratios = Text::parse_doubles(prm.get("Poisson's ratio"),
                                            "Materials/Poisson's ratio");
      // Read where the hardening lists were read before the registry, so
      // that a file with several mistakes reports the same first.
      material_models = material_registry().parse_all(prm);
      densities       = non_negative_list(prm, "Density");
      for (const double E : youngs_moduli)
        AssertThrow(E > 0,
                    dealii::ExcMessage(
                      "Parameter <Materials/Young's modulus> = <" +
                      prm.get("Young's modulus") +
                      ">: every value must be > 0."));
      for (const double nu : poissons_ratios)
        AssertThrow(nu >= 0 && nu < 0.5,
                    dealii::ExcMessage(
                      "Parameter <Materials/Poisson's ratio> = <" +
                      prm.get("Poisson's ratio") +
                      ">: every value must lie in [0, 0.5)."));
      AssertThrow(!models.empty() && !youngs_moduli.empty() &&
                    !poissons_ratios.empty(),
                  dealii::ExcMessage("Subsection <Materials>: Model, Young's "
                                     "modulus and Poisson's ratio must not "
                                     "be empty."));
      prm.leave_subsection();
    }



    std::shared_ptr<const MaterialModel>
    Materials::model(const std::string &name) const
    {
      const auto parsed = material_models.find(name);
      if (parsed != material_models.end())
        return parsed->second;
      const auto made = material_registry().create_with_defaults(name);
      AssertThrow(made != nullptr,
                  dealii::ExcMessage("Parameter <Materials/Model>: unknown "
                                     "model <" +
                                     name + ">. Allowed: " +
                                     material_registry().join(", ") + "."));
      return made;
    }



    std::vector<double>
    Materials::non_negative_list(dealii::ParameterHandler &prm,
                                 const std::string        &entry)
    {
      const auto values =
        Text::parse_doubles(prm.get(entry), "Materials/" + entry);
      for (const double v : values)
        AssertThrow(v >= 0,
                    dealii::ExcMessage("Parameter <Materials/" + entry +
                                       "> = <" + prm.get(entry) +
                                       ">: every value must be >= 0."));
      AssertThrow(!values.empty(),
                  dealii::ExcMessage("Parameter <Materials/" + entry +
                                     "> must not be empty."));
      return values;
    }



    template <typename T>
    const T &
    Materials::for_body(const std::vector<T> &values,
                        const unsigned int    body_id,
                        const std::string    &entry)
    {
      if (values.size() == 1)
        return values[0];
      AssertThrow(body_id < values.size(),
                  dealii::ExcMessage(
                    "Parameter <Materials/" + entry + "> lists " +
                    std::to_string(values.size()) +
                    " values, but the mesh has body id " +
                    std::to_string(body_id) +
                    ". Give one value per body id (0, 1, ...) or a single "
                    "value for all bodies."));
      return values[body_id];
    }

    void
    Materials::check_count(const std::size_t  n_values,
                           const unsigned int max_body_id,
                           const std::string &entry)
    {
      AssertThrow(n_values <= 1 || n_values <= max_body_id + 1,
                  dealii::ExcMessage(
                    "Parameter <Materials/" + entry + "> lists " +
                    std::to_string(n_values) +
                    " values, but the mesh's "
                    "body ids run from 0 to " +
                    std::to_string(max_body_id) +
                    ": give one value per body id or a single value for "
                    "all bodies."));
    }



    void
    Materials::check_body_count(const unsigned int max_body_id) const
    {
      check_count(models.size(), max_body_id, "Model");
      check_count(youngs_moduli.size(), max_body_id, "Young's modulus");
      check_count(poissons_ratios.size(), max_body_id, "Poisson's ratio");
      // The models' own lists where the hardening lists were checked.
      for (const std::string &name : material_registry().names())
        model(name)->check_body_count(max_body_id);
      check_count(densities.size(), max_body_id, "Density");
    }



    template const double &
    Materials::for_body(const std::vector<double> &,
                        const unsigned int,
                        const std::string &);
    template const std::string &
    Materials::for_body(const std::vector<std::string> &,
                        const unsigned int,
                        const std::string &);
  } // namespace Parameters
} // namespace tribos
