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
                          "linear elastic|neo-Hookean")),
                        "Constitutive model per body id (comma-separated) or "
                        "one for all bodies. 'linear elastic': small strain; "
                        "'neo-Hookean': compressible, finite strain.");
      prm.declare_entry("Young's modulus",
                        "1",
                        dealii::Patterns::Anything(),
                        "Per body id or one value for all; > 0.");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        dealii::Patterns::Anything(),
                        "Per body id or one value for all; in [0, 0.5).");
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
