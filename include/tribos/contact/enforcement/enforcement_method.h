#ifndef tribos_contact_enforcement_method_h
#define tribos_contact_enforcement_method_h

#include <tribos/base/registry.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <optional>
#include <string>

namespace tribos
{
  template <int dim>
  class Enforcement;

  namespace Parameters
  {
    struct Contact;
    struct ContactPair;
  } // namespace Parameters

  /**
   * An enforcement method as the parameter file names it (Contact/Method,
   * a pair's method=): the plugin that the method's own source file
   * registers, independent of the dimension. It exists before the run's
   * dimension is known, because the parameters are read first and a pair
   * may choose any method: it reads the method's own parameters, answers
   * what the parameter checks ask about the method, and makes the pairs'
   * Enforcement objects in 2D or 3D. Everything that depends on the method
   * asks it or its Enforcement, so that no other file names a method.
   */
  class EnforcementMethod
  {
  public:
    virtual ~EnforcementMethod() = default;

    /** Read the method's own parameters (@p prm inside the subsection
     * Contact, where its static declare_parameters() declared them). */
    virtual void
    parse_parameters(dealii::ParameterHandler & /*prm*/)
    {
    }

    /**
     * Whether the method holds the gap exactly (constraints of the
     * system): then one interface written twice with slave and master
     * swapped over-constrains it (a singular system), which the check of
     * Contact/Pairs refuses. A penalty law may sum both.
     */
    virtual bool
    constrains_gap_exactly() const
    {
      return false;
    }

    /** The enforcement of the pair @p pair in 2D or 3D, with the contact
     * @p parameters (they outlive it). */
    virtual std::shared_ptr<const Enforcement<2>>
    create_2d(const Parameters::ContactPair &pair,
              const Parameters::Contact     &parameters) const = 0;
    virtual std::shared_ptr<const Enforcement<3>>
    create_3d(const Parameters::ContactPair &pair,
              const Parameters::Contact     &parameters) const = 0;

    /** create_2d() or create_3d(), for code templated on @p dim. */
    template <int dim>
    std::shared_ptr<const Enforcement<dim>>
    create(const Parameters::ContactPair &pair,
           const Parameters::Contact     &parameters) const
    {
      static_assert(dim == 2 || dim == 3, "2D or 3D only");
      if constexpr (dim == 2)
        return create_2d(pair, parameters);
      else
        return create_3d(pair, parameters);
    }

    /** The method's Contact/Method value. */
    std::string name;
  };



  /**
   * The registered enforcement methods (source/contact/enforcement/), by
   * Contact/Method: each method's file defines a static
   * EnforcementRegistration made by register_enforcement().
   */
  Registry<EnforcementMethod> &
  enforcement_registry();

  /** The object by which a method's file registers it. */
  using EnforcementRegistration = Registry<EnforcementMethod>::Registration;



  /**
   * A method whose Enforcement comes from the member template
   * make<dim>(pair, parameters) of @p Method, in 2D and 3D (one template
   * instead of two overrides that would repeat it).
   */
  template <class Method>
  class EnforcementInBothDimensions : public EnforcementMethod
  {
  public:
    std::shared_ptr<const Enforcement<2>>
    create_2d(const Parameters::ContactPair &pair,
              const Parameters::Contact     &parameters) const override
    {
      return static_cast<const Method &>(*this).template make<2>(pair,
                                                                 parameters);
    }

    std::shared_ptr<const Enforcement<3>>
    create_3d(const Parameters::ContactPair &pair,
              const Parameters::Contact     &parameters) const override
    {
      return static_cast<const Method &>(*this).template make<3>(pair,
                                                                 parameters);
    }
  };



  /**
   * The registration of @p Method (default constructible; its static
   * declare_parameters(prm) is used if it has one) under @p name, with the
   * @p description of the documentation of Contact/Method and its @p rank
   * there (Registry::Entry; a new method takes 10 or more).
   */
  template <class Method>
  EnforcementRegistration
  register_enforcement(const std::string       &name,
                       const std::string       &description,
                       const int                rank,
                       const std::optional<int> documentation_rank = {})
  {
    return register_plugin<Method>(enforcement_registry(),
                                   name,
                                   description,
                                   rank,
                                   documentation_rank);
  }
} // namespace tribos

#endif
