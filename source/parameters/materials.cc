#include <tribos/base/text.h>
#include <tribos/parameters/materials.h>

namespace tribos
{
  namespace Parameters
  {
    void
    Materials::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Materials");
      prm.declare_entry("Model",
                        "neo-Hookean",
                        dealii::Patterns::List(dealii::Patterns::Selection(
                          "linear elastic|neo-Hookean|J2 plasticity")),
                        "Constitutive model per body id (comma-separated) or "
                        "one for all bodies. 'linear elastic': small strain; "
                        "'neo-Hookean': compressible, finite strain; 'J2 "
                        "plasticity': finite strain, Hencky elasticity, von "
                        "Mises with the hardening (36).");
      prm.declare_entry("Young's modulus",
                        "1",
                        dealii::Patterns::Anything(),
                        "Per body id or one value for all; > 0.");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        dealii::Patterns::Anything(),
                        "Per body id or one value for all; in [0, 0.5).");
      prm.declare_entry(
        "Yield stress",
        "1e100",
        dealii::Patterns::Anything(),
        "J2 plasticity: initial yield stress s0 of (36) (the default: no yield), per "
        "body id or one for all; > 0.");
      prm.declare_entry("Saturation yield stress",
                        "1e100",
                        dealii::Patterns::Anything(),
                        "J2 plasticity: s_inf of (36), >= s0.");
      prm.declare_entry("Hardening exponent",
                        "0",
                        dealii::Patterns::Anything(),
                        "J2 plasticity: delta of (36), >= 0.");
      prm.declare_entry("Linear hardening modulus",
                        "0",
                        dealii::Patterns::Anything(),
                        "J2 plasticity: H of (36), >= 0.");
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
      const auto read = [&](const std::string &entry)
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
      };
      yield_stresses            = read("Yield stress");
      saturation_yield_stresses = read("Saturation yield stress");
      hardening_exponents       = read("Hardening exponent");
      linear_hardening_moduli   = read("Linear hardening modulus");
      densities                 = read("Density");
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
    Materials::check_body_count(const unsigned int max_body_id) const
    {
      const auto check =
        [max_body_id](const std::size_t n_values, const std::string &entry)
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
      };
      check(models.size(), "Model");
      check(youngs_moduli.size(), "Young's modulus");
      check(poissons_ratios.size(), "Poisson's ratio");
      check(yield_stresses.size(), "Yield stress");
      check(saturation_yield_stresses.size(), "Saturation yield stress");
      check(hardening_exponents.size(), "Hardening exponent");
      check(linear_hardening_moduli.size(), "Linear hardening modulus");
      check(densities.size(), "Density");
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
