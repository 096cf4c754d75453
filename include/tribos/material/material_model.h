#ifndef tribos_material_material_model_h
#define tribos_material_material_model_h

#include <tribos/base/registry.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tribos
{
  template <int dim>
  class Material;

  /**
   * A constitutive model as the parameter file names it (Materials/Model):
   * the plugin that the model's own source file registers, independent of
   * the dimension. It exists before the run's dimension is known, because
   * the parameters are read first and every body may choose any model
   * (an axisymmetric run makes 2D and 3D materials of one body): it reads
   * and checks the model's own entries of the subsection Materials, answers
   * what the checks of the model and the checkpoint ask about it, and makes
   * each body's Material in 2D or 3D. Everything that depends on the model
   * asks it or its Material, so that no other file names a model.
   */
  class MaterialModel
  {
  public:
    virtual ~MaterialModel() = default;

    /** Read the model's own parameters (@p prm inside the subsection
     * Materials, where its static declare_parameters() declared them). */
    virtual void
    parse_parameters(dealii::ParameterHandler & /*prm*/)
    {
    }

    /**
     * Refuse a per-body list of the model's own entries longer than the
     * mesh's body ids 0 ... @p max_body_id: its extra values would be
     * ignored silently (Parameters::Materials::check_body_count()).
     */
    virtual void
    check_body_count(const unsigned int /*max_body_id*/) const
    {
    }

    /**
     * Refuse the model's own lists if they have no value for body
     * @p body. Asked for every body whatever its model, as the lists of
     * Young's modulus are: a list one value too short is a mistake even
     * while no body uses the model.
     */
    virtual void
    check_body(const unsigned int /*body*/) const
    {
    }

    /**
     * The model's own entries that a checkpoint's state depends on (the
     * history of its points), with their parsed values: a restart refuses
     * a checkpoint written with others. (Every entry is compared as
     * written too; these are compared parsed, so that the same numbers
     * written otherwise are the same model.)
     */
    virtual std::vector<std::pair<std::string, std::vector<double>>>
    fingerprint() const
    {
      return {};
    }

    /**
     * Whether the model locks on linear triangles and tetrahedra
     * (isochoric plastic flow): the run then warns to use Polynomial
     * degree = 2.
     */
    virtual bool
    locks_on_linear_simplices() const
    {
      return false;
    }

    /**
     * The material of body @p body (whose Young's modulus @p E and
     * Poisson's ratio @p nu the caller took from their lists) in 2D or 3D.
     */
    virtual std::unique_ptr<Material<2>>
    create_2d(const unsigned int body,
              const double       E,
              const double       nu) const = 0;
    virtual std::unique_ptr<Material<3>>
    create_3d(const unsigned int body,
              const double       E,
              const double       nu) const = 0;

    /** create_2d() or create_3d(), for code templated on @p dim. */
    template <int dim>
    std::unique_ptr<Material<dim>>
    create(const unsigned int body, const double E, const double nu) const
    {
      static_assert(dim == 2 || dim == 3, "2D or 3D only");
      if constexpr (dim == 2)
        return create_2d(body, E, nu);
      else
        return create_3d(body, E, nu);
    }

    /** The model's Materials/Model value. */
    std::string name;
  };



  /**
   * The registered constitutive models (source/material/), by
   * Materials/Model: each model's file defines a static
   * MaterialRegistration made by register_material().
   */
  Registry<MaterialModel> &
  material_registry();

  /** The object by which a model's file registers it. */
  using MaterialRegistration = Registry<MaterialModel>::Registration;



  /**
   * A model whose Material comes from the member template
   * make<dim>(body, E, nu) of @p Model, in 2D and 3D (one template instead
   * of two overrides that would repeat it).
   */
  template <class Model>
  class MaterialInBothDimensions : public MaterialModel
  {
  public:
    std::unique_ptr<Material<2>>
    create_2d(const unsigned int body,
              const double       E,
              const double       nu) const override
    {
      return static_cast<const Model &>(*this).template make<2>(body, E, nu);
    }

    std::unique_ptr<Material<3>>
    create_3d(const unsigned int body,
              const double       E,
              const double       nu) const override
    {
      return static_cast<const Model &>(*this).template make<3>(body, E, nu);
    }
  };



  /**
   * The registration of @p Model (default constructible; its static
   * declare_parameters(prm) is used if it has one) under @p name, with the
   * @p description of the documentation of Materials/Model and its @p rank
   * there (Registry::Entry; a new model takes 10 or more).
   */
  template <class Model>
  MaterialRegistration
  register_material(const std::string       &name,
                    const std::string       &description,
                    const int                rank,
                    const std::optional<int> documentation_rank = {})
  {
    return register_plugin<Model>(material_registry(),
                                  name,
                                  description,
                                  rank,
                                  documentation_rank);
  }
} // namespace tribos

#endif
