#ifndef tribos_material_linear_elastic_h
#define tribos_material_linear_elastic_h

#include <tribos/material/material.h>

namespace tribos
{
  /**
   * Small-strain isotropic linear elasticity, sigma = lambda tr(eps) I +
   * 2 mu eps with eps = sym(F - I). Used as P, so the residual is linear
   * in u (one Newton correction solves it, the update test confirms it);
   * valid only for small displacement gradients.
   */
  template <int dim>
  class LinearElastic : public Material<dim>
  {
  public:
    LinearElastic(const double E, const double nu);

    void
    evaluate(const Tensor<2, dim> &F,
             const double         *old_history,
             double               *new_history,
             Tensor<2, dim>       &P,
             Tensor<4, dim>       *tangent) const override;

    SymmetricTensor<2, 3>
    cauchy_stress(const Tensor<2, dim> &F,
                  const double         *history) const override;
    double
    stored_energy(const Tensor<2, dim> &F,
                  const double         *history) const override;

    bool
    has_symmetric_tangent() const override
    {
      return true;
    }

    double
    youngs_modulus() const override
    {
      return E;
    }

  private:
    const double E;
    const double lambda;
    const double mu;
  };
} // namespace tribos

#endif
