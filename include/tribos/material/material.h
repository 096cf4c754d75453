#ifndef tribos_material_material_h
#define tribos_material_material_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <memory>
#include <string>

namespace tribos
{
  using namespace dealii;

  /**
   * The one interface between the continuum assembly and a constitutive
   * law. Everything is written in the total Lagrangian form: given the
   * deformation gradient F at a quadrature point, a material returns the
   * first Piola-Kirchhoff stress P and its exact derivative A = dP/dF. The
   * same residual int P : grad(v) dV then serves small-strain elasticity
   * (P = sigma(eps)), hyperelasticity and plasticity, and the Newton tangent
   * is exact by construction as long as each material's A is.
   *
   * Materials with memory (plasticity) declare how many doubles they keep
   * per quadrature point; the problem allocates that storage only for the
   * cells of bodies that need it, and commits it only on converged steps.
   *
   * In 2D the state is plane strain: F_33 = 1.
   */
  template <int dim>
  class Material
  {
  public:
    virtual ~Material() = default;

    /** Doubles of history per quadrature point (0 for elastic laws). */
    virtual unsigned int
    n_history_variables() const
    {
      return 0;
    }

    /** Initial values of the history variables. */
    virtual void
    initialize_history(double *history) const
    {
      (void)history;
    }

    /**
     * Stress P(F) and, if @p tangent is not null, A = dP/dF. History
     * materials read @p old_history and write @p new_history (both null
     * for elastic laws).
     */
    virtual void
    evaluate(const Tensor<2, dim> &F,
             const double         *old_history,
             double               *new_history,
             Tensor<2, dim>       &P,
             Tensor<4, dim>       *tangent) const = 0;

    /**
     * The Cauchy stress as a 3x3 tensor (with the out-of-plane component
     * of plane strain in 2D), for output. @p history is the converged one.
     */
    virtual SymmetricTensor<2, 3>
    cauchy_stress(const Tensor<2, dim> &F, const double *history) const = 0;

    /** Equivalent plastic strain for output; 0 for elastic laws. */
    virtual double
    equivalent_plastic_strain(const double *history) const
    {
      (void)history;
      return 0;
    }

    /**
     * The elastic energy stored per reference volume at @p F with the
     * converged @p history (plasticity: the elastic part only), for the
     * energy balance of dynamic runs.
     */
    virtual double
    stored_energy(const Tensor<2, dim> &F, const double *history) const = 0;

    /**
     * Whether the tangent has the major symmetry A_ijkl = A_klij, as the
     * derivative of a stress from a potential has (J2's radial return too:
     * its algorithmic moduli are symmetric). The assembly then computes
     * half of each cell matrix. False unless a material says so.
     */
    virtual bool
    has_symmetric_tangent() const
    {
      return false;
    }

    /** Young's modulus, used to scale penalty parameters. */
    virtual double
    youngs_modulus() const = 0;
  };

  /**
   * Create the material called @p model (a registered MaterialModel,
   * material_model.h) with Young's modulus @p E and Poisson's ratio @p nu;
   * @p hardening holds s0, s_inf, delta, H of the paper's (36), the
   * entries Yield stress, Saturation yield stress, Hardening exponent and
   * Linear hardening modulus of J2 plasticity; the other entries of
   * Materials keep their defaults. For tests and benchmarks that make one
   * material without a parameter file; a run asks its parsed
   * Parameters::Materials::model().
   */
  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string           &model,
                  const double                 E,
                  const double                 nu,
                  const std::array<double, 4> &hardening = {{0, 0, 0, 0}});
} // namespace tribos

#endif
