#include <tribos/contact/enforcement/enforcement.h>
#include <tribos/contact/enforcement/enforcement_method.h>

namespace tribos
{
  Registry<EnforcementMethod> &
  enforcement_registry()
  {
    // Constructed on first use: the methods' files register during static
    // initialization, in no defined order.
    static Registry<EnforcementMethod> methods("enforcement method");
    return methods;
  }



  template <int dim>
  std::shared_ptr<const Enforcement<dim>>
  create_enforcement(const Parameters::ContactPair &pair,
                     const Parameters::Contact     &parameters)
  {
    return parameters.enforcement_method(pair.method)
      ->template create<dim>(pair, parameters);
  }

  template std::shared_ptr<const Enforcement<2>>
  create_enforcement(const Parameters::ContactPair &,
                     const Parameters::Contact &);
  template std::shared_ptr<const Enforcement<3>>
  create_enforcement(const Parameters::ContactPair &,
                     const Parameters::Contact &);
} // namespace tribos
