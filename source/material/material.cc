#include <tribos/material/material.h>
#include <tribos/material/material_model.h>
#include <tribos/parameters/materials.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <sstream>

namespace tribos
{
  Registry<MaterialModel> &
  material_registry()
  {
    // Constructed on first use: the models' files register during static
    // initialization, in no defined order.
    static Registry<MaterialModel> models("material model");
    return models;
  }



  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string           &model,
                  const double                 E,
                  const double                 nu,
                  const std::array<double, 4> &hardening)
  {
    // The subsection Materials as a parameter file with these values would
    // give it, so that the model is made and checked exactly as in a run.
    // The values as text with 17 digits read back to the same doubles.
    ParameterHandler prm;
    Parameters::Materials::declare_parameters(prm);
    prm.enter_subsection("Materials");
    const char *const entries[] = {"Yield stress",
                                   "Saturation yield stress",
                                   "Hardening exponent",
                                   "Linear hardening modulus"};
    for (unsigned int i = 0; i < hardening.size(); ++i)
    {
      std::ostringstream text;
      text.precision(17);
      text << hardening[i];
      prm.set(entries[i], text.str());
    }
    prm.leave_subsection();
    Parameters::Materials materials;
    materials.parse_parameters(prm);
    return materials.model(model)->template create<dim>(0, E, nu);
  }

  template std::unique_ptr<Material<2>>
  create_material(const std::string &,
                  const double,
                  const double,
                  const std::array<double, 4> &);
  template std::unique_ptr<Material<3>>
  create_material(const std::string &,
                  const double,
                  const double,
                  const std::array<double, 4> &);
} // namespace tribos
