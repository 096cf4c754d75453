#include <tribos/material/j2_plasticity.h>
#include <tribos/material/linear_elastic.h>
#include <tribos/material/material.h>
#include <tribos/material/neo_hookean.h>

#include <deal.II/base/exceptions.h>

namespace tribos
{
  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string           &model,
                  const double                 E,
                  const double                 nu,
                  const std::array<double, 4> &hardening)
  {
    if (model == "J2 plasticity")
    {
      AssertThrow(hardening[0] > 0 && hardening[0] < 1e299 &&
                    hardening[1] >= hardening[0],
                  ExcMessage("Materials: J2 plasticity needs a Yield "
                             "stress s0 > 0 and a Saturation yield stress "
                             ">= s0 for every plastic body."));
      return std::make_unique<J2Plasticity<dim>>(
        E,
        nu,
        HardeningLaw{hardening[0], hardening[1], hardening[2], hardening[3]});
    }
    if (model == "linear elastic")
      return std::make_unique<LinearElastic<dim>>(E, nu);
    if (model == "neo-Hookean")
      return std::make_unique<NeoHookean<dim>>(E, nu);
    AssertThrow(false,
                ExcMessage("Parameter <Materials/Model>: unknown model <" +
                           model +
                           ">. Allowed: linear elastic, neo-Hookean, J2 "
                           "plasticity."));
    return nullptr;
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
