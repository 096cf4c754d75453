#include <tribos/base/exceptions.h>
#include <tribos/material/material_model.h>
#include <tribos/material/neo_hookean.h>

#include <cmath>

namespace tribos
{
  template <int dim>
  NeoHookean<dim>::NeoHookean(const double E, const double nu)
    : E(E)
    , lambda(E * nu / ((1 + nu) * (1 - 2 * nu)))
    , mu(E / (2 * (1 + nu)))
  {
  }



  template <int dim>
  void
  NeoHookean<dim>::evaluate(const Tensor<2, dim> &F,
                            const double *,
                            double *,
                            Tensor<2, dim> &P,
                            Tensor<4, dim> *tangent) const
  {
    const double J = determinant(F);
    if (!(J > 0))
      throw InvertedElement("neo-Hookean", J);

    const double         log_J  = std::log(J);
    const Tensor<2, dim> F_inv  = invert(F);
    const Tensor<2, dim> F_invT = transpose(F_inv);
    P                           = mu * (F - F_invT) + lambda * log_J * F_invT;

    if (tangent != nullptr)
    {
      Tensor<4, dim> &A           = *tangent;
      const double    coefficient = mu - lambda * log_J;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              A[i][j][k][l] = (i == k && j == l ? mu : 0.) +
                              coefficient * F_inv[j][k] * F_inv[l][i] +
                              lambda * F_invT[i][j] * F_invT[k][l];
    }
  }



  template <int dim>
  SymmetricTensor<2, 3>
  NeoHookean<dim>::cauchy_stress(const Tensor<2, dim> &F, const double *) const
  {
    const double J = determinant(F);
    Assert(J > 0, ExcInternalError());
    const double         log_J = std::log(J);
    const Tensor<2, dim> b     = F * transpose(F);

    SymmetricTensor<2, 3> sigma;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        sigma[i][j] = mu * (b[i][j] - (i == j ? 1. : 0.)) / J;
    for (unsigned int i = 0; i < 3; ++i)
      sigma[i][i] += lambda * log_J / J;
    return sigma;
  }

  template <int dim>
  double
  NeoHookean<dim>::stored_energy(const Tensor<2, dim> &F, const double *) const
  {
    // tr C of plane strain has C_33 = 1: tr C - 3 = F : F - dim.
    const double log_J = std::log(determinant(F));
    return 0.5 * mu * (scalar_product(F, F) - dim) - mu * log_J +
           0.5 * lambda * log_J * log_J;
  }

  template class NeoHookean<2>;
  template class NeoHookean<3>;



  namespace
  {
    /** Materials/Model = neo-Hookean. */
    class NeoHookeanModel : public MaterialInBothDimensions<NeoHookeanModel>
    {
    public:
      template <int dim>
      std::unique_ptr<Material<dim>>
      make(const unsigned int /*body*/, const double E, const double nu) const
      {
        return std::make_unique<NeoHookean<dim>>(E, nu);
      }
    };

    // Rank 1: the second of Materials/Model's choices (and its default).
    const MaterialRegistration neo_hookean_registration =
      register_material<NeoHookeanModel>("neo-Hookean",
                                         "compressible, finite strain",
                                         1);
  } // namespace
} // namespace tribos
