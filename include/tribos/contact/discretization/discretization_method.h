#ifndef tribos_contact_discretization_method_h
#define tribos_contact_discretization_method_h

#include <tribos/base/registry.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <optional>
#include <string>

namespace tribos
{
  template <int dim>
  class ContactDiscretization;

  namespace Parameters
  {
    struct Contact;
    struct ContactPair;
  } // namespace Parameters

  /**
   * A contact discretization as the parameter file names it
   * (Contact/Discretization, a pair's discretization=): the plugin that
   * the discretization's own source file registers, independent of the
   * dimension. It exists before the run's dimension is known, because the
   * parameters are read first and a pair may choose any discretization:
   * it reads its own parameters, answers what the parameter checks ask
   * about it, and makes each pair's ContactDiscretization in 2D or 3D,
   * choosing among its variants (the rigid or smoothed master of node to
   * segment). Everything that depends on the discretization asks it or
   * its ContactDiscretization, so that no other file names one.
   */
  class DiscretizationMethod
  {
  public:
    virtual ~DiscretizationMethod() = default;

    /** Read the discretization's own parameters (@p prm inside the
     * subsection Contact, where its static declare_parameters() declared
     * them). */
    virtual void
    parse_parameters(dealii::ParameterHandler & /*prm*/)
    {
    }

    /**
     * Whether it meets a rigid analytic master. A pair with a rigid master
     * takes the default discretization if that does, else the first
     * registered one that does; its own discretization= must.
     */
    virtual bool
    handles_rigid_master() const
    {
      return false;
    }

    /**
     * Whether Contact/Master smoothing = automatic gives this
     * discretization's pairs against another body's deformable master the
     * averaged normals in @p dim dimensions (Contact::resolve_pairs()):
     * where the smoothing is available and the robust choice.
     */
    virtual bool
    smooths_master_by_default(const unsigned int /*dim*/) const
    {
      return false;
    }

    /**
     * Refuse, with a message naming @p pair, what the discretization
     * cannot do with the @p contact parameters in @p dim dimensions, before
     * the mesh is built (Contact::check()).
     */
    virtual void
    check(const Parameters::ContactPair & /*pair*/,
          const Parameters::Contact & /*contact*/,
          const unsigned int /*dim*/) const
    {
    }

    /**
     * The discretization of the pair described by @p pair in 2D or 3D,
     * with the contact @p parameters (they outlive it; @p axisymmetric:
     * the model is a body of revolution).
     */
    virtual std::unique_ptr<ContactDiscretization<2>>
    create_2d(const Parameters::ContactPair &pair,
              const Parameters::Contact     &parameters,
              const bool                     axisymmetric) const = 0;
    virtual std::unique_ptr<ContactDiscretization<3>>
    create_3d(const Parameters::ContactPair &pair,
              const Parameters::Contact     &parameters,
              const bool                     axisymmetric) const = 0;

    /** create_2d() or create_3d(), for code templated on @p dim. */
    template <int dim>
    std::unique_ptr<ContactDiscretization<dim>>
    create(const Parameters::ContactPair &pair,
           const Parameters::Contact     &parameters,
           const bool                     axisymmetric) const
    {
      static_assert(dim == 2 || dim == 3, "2D or 3D only");
      if constexpr (dim == 2)
        return create_2d(pair, parameters, axisymmetric);
      else
        return create_3d(pair, parameters, axisymmetric);
    }

    /** The discretization's Contact/Discretization value. */
    std::string name;
  };



  /**
   * The registered discretizations (source/contact/discretization/), by
   * Contact/Discretization: each discretization's file defines a static
   * DiscretizationRegistration made by register_discretization().
   */
  Registry<DiscretizationMethod> &
  discretization_registry();

  /** The object by which a discretization's file registers it. */
  using DiscretizationRegistration =
    Registry<DiscretizationMethod>::Registration;



  /**
   * A discretization whose ContactDiscretization comes from the member
   * template make<dim>(pair, parameters, axisymmetric) of @p Method, in 2D
   * and 3D (one template instead of two overrides that would repeat it).
   */
  template <class Method>
  class DiscretizationInBothDimensions : public DiscretizationMethod
  {
  public:
    std::unique_ptr<ContactDiscretization<2>>
    create_2d(const Parameters::ContactPair &pair,
              const Parameters::Contact     &parameters,
              const bool                     axisymmetric) const override
    {
      return static_cast<const Method &>(*this).template make<2>(pair,
                                                                 parameters,
                                                                 axisymmetric);
    }

    std::unique_ptr<ContactDiscretization<3>>
    create_3d(const Parameters::ContactPair &pair,
              const Parameters::Contact     &parameters,
              const bool                     axisymmetric) const override
    {
      return static_cast<const Method &>(*this).template make<3>(pair,
                                                                 parameters,
                                                                 axisymmetric);
    }
  };



  /**
   * The registration of @p Method (default constructible; its static
   * declare_parameters(prm) is used if it has one) under @p name, with the
   * @p description of the documentation of Contact/Discretization and its
   * @p rank there (Registry::Entry; a new discretization takes 10 or
   * more).
   */
  template <class Method>
  DiscretizationRegistration
  register_discretization(const std::string       &name,
                          const std::string       &description,
                          const int                rank,
                          const std::optional<int> documentation_rank = {})
  {
    return register_plugin<Method>(discretization_registry(),
                                   name,
                                   description,
                                   rank,
                                   documentation_rank);
  }
} // namespace tribos

#endif
