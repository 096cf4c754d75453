#include <tribos/material/linear_elastic.h>
#include <tribos/material/material.h>
#include <tribos/material/neo_hookean.h>

#include <deal.II/base/exceptions.h>

namespace tribos
{
  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string &model, const double E, const double nu)
  {
    if (model == "linear elastic")
      return std::make_unique<LinearElastic<dim>>(E, nu);
    if (model == "neo-Hookean")
      return std::make_unique<NeoHookean<dim>>(E, nu);
    AssertThrow(false,
                ExcMessage("Parameter <Materials/Model>: unknown model <" +
                           model + ">. Allowed: linear elastic, neo-Hookean."));
    return nullptr;
  }

  template std::unique_ptr<Material<2>>
  create_material(const std::string &, const double, const double);
  template std::unique_ptr<Material<3>>
  create_material(const std::string &, const double, const double);
} // namespace tribos
