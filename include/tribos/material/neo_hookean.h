#ifndef tribos_material_neo_hookean_h
#define tribos_material_neo_hookean_h

#include <tribos/material/material.h>

namespace tribos
{
  /**
   * Compressible neo-Hookean solid with the stored energy
   *   W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
   * (Simo/Bonet form, which reduces to linear elasticity with the same
   * Lame constants for small strains), so
   *   P = mu (F - F^-T) + lambda ln J F^-T.
   */
  template <int dim>
  class NeoHookean : public Material<dim>
  {
  public:
    NeoHookean(const double E, const double nu);

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
