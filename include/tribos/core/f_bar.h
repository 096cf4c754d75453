#ifndef tribos_core_f_bar_h
#define tribos_core_f_bar_h

#include <deal.II/base/tensor.h>

#include <cmath>

namespace tribos
{
  using namespace dealii;

  /**
   * The F-bar element (de Souza Neto, Peric, Dutko, Owen 1996) for Q1:
   * the material sees F_bar = s F, s = (J_0 / J)^(1/dim), whose volume
   * change J_0 is that of the cell centre, so isochoric plastic flow does
   * not lock. The internal force int B^T sigma(F_bar) dv becomes, in the
   * reference configuration, int P_eff : grad(v) dV with
   *   P_eff = s^(1 - dim) P(F_bar),
   * and the exact tangent couples every quadrature point with the centre:
   *   dP_eff/dF  = s^(2 - dim) A + G (x) ds/dF,
   *   dP_eff/dF0 = G (x) ds/dF0,
   *   G = (1 - dim) s^(-dim) P + s^(1 - dim) A : F,
   *   ds/dF = -s/dim F^-T, ds/dF0 = s/dim F0^-T.
   * (2D is plane strain with F_33 = 1, where dim = 2 is the right
   * exponent for the in-plane volume change.)
   */
  template <int dim>
  struct FBar
  {
    static double
    scale(const Tensor<2, dim> &F, const double J0)
    {
      return std::pow(J0 / determinant(F), 1. / dim);
    }

    /**
     * Given P = P(F_bar) and A = dP/dF_bar at F_bar = s F, the effective
     * stress and, if @p A is not null, its derivatives.
     */
    static void
    effective(const Tensor<2, dim> &F,
              const Tensor<2, dim> &F0,
              const double          s,
              const Tensor<2, dim> &P,
              const Tensor<4, dim> *A,
              Tensor<2, dim>       &P_eff,
              Tensor<4, dim>       &dP_dF,
              Tensor<4, dim>       &dP_dF0)
    {
      const double factor = std::pow(s, 1. - dim);
      P_eff               = factor * P;
      if (A == nullptr)
        return;
      Tensor<2, dim> A_F;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int m = 0; m < dim; ++m)
            for (unsigned int n = 0; n < dim; ++n)
              A_F[i][j] += (*A)[i][j][m][n] * F[m][n];
      const Tensor<2, dim> G =
        (1. - dim) * std::pow(s, -1. * dim) * P + factor * A_F;
      const Tensor<2, dim> ds_dF  = (-s / dim) * transpose(invert(F));
      const Tensor<2, dim> ds_dF0 = (s / dim) * transpose(invert(F0));
      const double         scale  = std::pow(s, 2. - dim);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
            {
              dP_dF[i][j][k][l] =
                scale * (*A)[i][j][k][l] + G[i][j] * ds_dF[k][l];
              dP_dF0[i][j][k][l] = G[i][j] * ds_dF0[k][l];
            }
    }
  };
} // namespace tribos

#endif
