#include <tribos/contact/augmented_lagrangian.h>
#include <tribos/contact/lagrange_multiplier.h>
#include <tribos/contact/penalty.h>

namespace tribos
{
  template <int dim>
  std::shared_ptr<const Enforcement<dim>>
  create_enforcement(const Parameters::EnforcementMethod method,
                     const Parameters::Contact          &parameters)
  {
    switch (method)
    {
      case Parameters::EnforcementMethod::penalty:
        if (parameters.penalty_formulation ==
            Parameters::PenaltyFormulation::mixed)
          return std::make_shared<LagrangeMultiplier<dim>>(parameters, true);
        return std::make_shared<Penalty<dim>>();
      case Parameters::EnforcementMethod::augmented_lagrangian:
        return std::make_shared<AugmentedLagrangian<dim>>();
      case Parameters::EnforcementMethod::lagrange_multiplier:
        return std::make_shared<LagrangeMultiplier<dim>>(parameters);
    }
    return nullptr;
  }

  template std::shared_ptr<const Enforcement<2>>
  create_enforcement(const Parameters::EnforcementMethod,
                     const Parameters::Contact &);
  template std::shared_ptr<const Enforcement<3>>
  create_enforcement(const Parameters::EnforcementMethod,
                     const Parameters::Contact &);
} // namespace tribos
