#include <tribos/base/exceptions.h>
#include <tribos/material/j2_plasticity.h>

#include <Sacado.hpp>
#include <array>
#include <cmath>
#include <type_traits>

namespace tribos
{
  namespace
  {
    using AD = Sacado::Fad::SLFad<double, 9>;

    double
    value(const double x)
    {
      return x;
    }

    double
    value(const AD &x)
    {
      return x.val();
    }

    template <typename N>
    using Mat3 = std::array<std::array<N, 3>, 3>;

    template <typename N>
    Mat3<N>
    identity()
    {
      Mat3<N> I;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          I[i][j] = (i == j ? 1. : 0.);
      return I;
    }

    template <typename N>
    Mat3<N>
    operator*(const Mat3<N> &A, const Mat3<N> &B)
    {
      Mat3<N> C;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
        {
          C[i][j] = 0.;
          for (unsigned int k = 0; k < 3; ++k)
            C[i][j] += A[i][k] * B[k][j];
        }
      return C;
    }

    template <typename N, typename S>
    Mat3<N>
    combine(const S &a, const Mat3<N> &A, const S &b, const Mat3<N> &B)
    {
      Mat3<N> C;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          C[i][j] = a * A[i][j] + b * B[i][j];
      return C;
    }

    template <typename N>
    Mat3<N>
    transpose(const Mat3<N> &A)
    {
      Mat3<N> T;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          T[i][j] = A[j][i];
      return T;
    }

    template <typename N>
    N
    determinant(const Mat3<N> &A)
    {
      return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
             A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
             A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    }

    template <typename N>
    Mat3<N>
    inverse(const Mat3<N> &A)
    {
      const N det = determinant(A);
      Mat3<N> B;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
        {
          const unsigned int i1 = (j + 1) % 3, i2 = (j + 2) % 3;
          const unsigned int j1 = (i + 1) % 3, j2 = (i + 2) % 3;
          B[i][j] = (A[i1][j1] * A[i2][j2] - A[i1][j2] * A[i2][j1]) / det;
        }
      return B;
    }

    template <typename N>
    double
    norm_value(const Mat3<N> &A)
    {
      double sum = 0;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          sum += value(A[i][j]) * value(A[i][j]);
      return std::sqrt(sum);
    }

    /** Square root of an SPD matrix: Denman-Beavers iteration. */
    template <typename N>
    Mat3<N>
    sqrt_spd(const Mat3<N> &M)
    {
      Mat3<N> Y = M, Z = identity<N>();
      for (unsigned int k = 0; k < 60; ++k)
      {
        const Mat3<N> Y_next = combine<N, double>(0.5, Y, 0.5, inverse(Z));
        const Mat3<N> Z_next = combine<N, double>(0.5, Z, 0.5, inverse(Y));
        const double  change =
          norm_value(combine<N, double>(1., Y_next, -1., Y));
        Y = Y_next;
        Z = Z_next;
        if (change < 1e-16 * norm_value(Y))
          break;
      }
      return Y;
    }

    /**
     * Logarithm of an SPD matrix by inverse scaling and squaring: square
     * roots until M is close to I, then the series of ln(I + X).
     */
    template <typename N>
    Mat3<N>
    log_spd(Mat3<N> M)
    {
      const Mat3<N> I       = identity<N>();
      unsigned int  n_roots = 0;
      while (norm_value(combine<N, double>(1., M, -1., I)) > 0.1 &&
             n_roots < 30)
      {
        M = sqrt_spd(M);
        ++n_roots;
      }
      const Mat3<N> X    = combine<N, double>(1., M, -1., I);
      Mat3<N>       sum  = combine<N, double>(0., X, 0., X);
      Mat3<N>       term = X;
      for (unsigned int k = 1; k < 80; ++k)
      {
        const double sign = (k % 2 == 1 ? 1. : -1.);
        sum               = combine<N, double>(1., sum, sign / k, term);
        if (norm_value(term) / k < 1e-18 * (1 + norm_value(sum)))
          break;
        term = term * X;
      }
      return combine<N, double>(std::pow(2., n_roots), sum, 0., sum);
    }

    /** Exponential of a symmetric matrix (values only): scaling, squaring. */
    Mat3<double>
    exp_sym(const Mat3<double> &A)
    {
      unsigned int n_squarings = 0;
      double       scale       = 1;
      while (norm_value(A) * scale > 0.5)
      {
        scale *= 0.5;
        ++n_squarings;
      }
      const Mat3<double> X   = combine<double, double>(scale, A, 0., A);
      Mat3<double>       sum = identity<double>(), term = identity<double>();
      for (unsigned int k = 1; k < 30; ++k)
      {
        term = combine<double, double>(1. / k, term * X, 0., X);
        sum  = combine<double, double>(1., sum, 1., term);
      }
      for (unsigned int k = 0; k < n_squarings; ++k)
        sum = sum * sum;
      return sum;
    }

    /** The six independent entries of a symmetric matrix and back. */
    constexpr unsigned int sym_index[6][2] =
      {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
  } // namespace



  template <typename Number>
  Number
  HardeningLaw::yield_stress(const Number &e) const
  {
    using std::exp;
    return initial_yield +
           (saturation_yield - initial_yield) * (1. - exp(-exponent * e)) +
           linear_modulus * e;
  }



  namespace
  {
    /**
     * @p F_in (dim x dim) as a 3x3 matrix of numbers @p N; as AD numbers its
     * dim x dim entries are the independent variables of the tangent.
     */
    template <typename N, int dim>
    Mat3<N>
    embed(const Tensor<2, dim> &F_in)
    {
      Mat3<N> F = identity<N>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          if constexpr (std::is_same_v<N, AD>)
            F[i][j] = AD(dim * dim, i * dim + j, F_in[i][j]);
          else
            F[i][j] = F_in[i][j];
      return F;
    }



    /**
     * The return map at deformation gradient @p F (3x3) from the history
     * @p old: Kirchhoff stress @p tau, and (values) the new history.
     */
    template <typename N>
    void
    return_map(const Mat3<N>      &F,
               const double       *old,
               const double        K,
               const double        G,
               const HardeningLaw &hardening,
               Mat3<N>            &tau,
               double             *new_history)
    {
      Mat3<N> Cp_inv;
      for (unsigned int c = 0; c < 6; ++c)
      {
        Cp_inv[sym_index[c][0]][sym_index[c][1]] = old[c];
        Cp_inv[sym_index[c][1]][sym_index[c][0]] = old[c];
      }
      const Mat3<N> b_trial = F * Cp_inv * transpose(F);
      const Mat3<N> eps_trial =
        combine<N, double>(0.5, log_spd(b_trial), 0., b_trial);

      const N trace    = eps_trial[0][0] + eps_trial[1][1] + eps_trial[2][2];
      Mat3<N> deviator = eps_trial;
      for (unsigned int i = 0; i < 3; ++i)
        deviator[i][i] -= trace / 3.;
      N norm_squared = 0.;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          norm_squared += deviator[i][j] * deviator[i][j];
      using std::sqrt;
      const N      dev_norm    = sqrt(norm_squared + 1e-300);
      const N      q_trial     = sqrt(1.5) * 2. * G * dev_norm;
      const double alpha_old   = old[6];
      const double yield_old   = hardening.yield_stress(alpha_old);
      N            delta_alpha = 0.;
      const bool   plastic     = value(q_trial) > yield_old;
      if (plastic)
      {
        // Scalar Newton on q_trial - 3 G da - sigma_y(alpha + da) = 0 in
        // values, then one step in the AD type from the root: the exact
        // derivative of the converged da.
        const auto slope = [&](const double da)
        {
          return 3 * G +
                 (hardening.saturation_yield - hardening.initial_yield) *
                   hardening.exponent *
                   std::exp(-hardening.exponent * (alpha_old + da)) +
                 hardening.linear_modulus;
        };
        double da = 0;
        for (unsigned int k = 0; k < 50; ++k)
        {
          const double r = value(q_trial) - 3 * G * da -
                           hardening.yield_stress(alpha_old + da);
          const double step = r / slope(da);
          da += step;
          if (std::abs(step) < 1e-15 * (1 + da))
            break;
        }
        delta_alpha =
          da + (q_trial - 3 * G * da - hardening.yield_stress(alpha_old + da)) /
                 slope(da);
      }

      // eps_e = eps_trial - sqrt(3/2) da n, n = deviator / |deviator|.
      const N factor =
        (plastic ? N(sqrt(1.5) * delta_alpha / dev_norm) : N(0.));
      Mat3<N> eps_e = eps_trial;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          eps_e[i][j] -= factor * deviator[i][j];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          tau[i][j] = 2. * G * (eps_e[i][j] - (i == j ? trace / 3. : N(0.))) +
                      (i == j ? N(K * trace) : N(0.));

      if (new_history != nullptr)
      {
        Mat3<double> eps_value, F_value;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
          {
            eps_value[i][j] = 2 * value(eps_e[i][j]);
            F_value[i][j]   = value(F[i][j]);
          }
        const Mat3<double> b_e    = exp_sym(eps_value);
        const Mat3<double> F_inv  = inverse(F_value);
        const Mat3<double> Cp_new = F_inv * b_e * transpose(F_inv);
        for (unsigned int c = 0; c < 6; ++c)
          new_history[c] = Cp_new[sym_index[c][0]][sym_index[c][1]];
        new_history[6] = alpha_old + value(delta_alpha);
      }
    }
  } // namespace



  template <int dim>
  J2Plasticity<dim>::J2Plasticity(const double        E,
                                  const double        nu,
                                  const HardeningLaw &law)
    : E(E)
    , bulk_modulus(E / (3 * (1 - 2 * nu)))
    , shear_modulus(E / (2 * (1 + nu)))
    , hardening(law)
  {
  }



  template <int dim>
  void
  J2Plasticity<dim>::initialize_history(double *history) const
  {
    for (unsigned int c = 0; c < 7; ++c)
      history[c] = (c < 3 ? 1. : 0.);
  }



  template <int dim>
  void
  J2Plasticity<dim>::evaluate(const Tensor<2, dim> &F_in,
                              const double         *old_history,
                              double               *new_history,
                              Tensor<2, dim>       &P,
                              Tensor<4, dim>       *tangent) const
  {
    if (!(determinant(F_in) > 0))
      throw InvertedElement(
        "J2 plasticity: det F = " + to_scientific(determinant(F_in)) +
        " <= 0 at a quadrature point");
    // P = tau F^-T of the return map, in the number type of F.
    const auto first_piola = [&](const auto &F)
    {
      std::decay_t<decltype(F)> tau;
      return_map(F,
                 old_history,
                 bulk_modulus,
                 shear_modulus,
                 hardening,
                 tau,
                 new_history);
      return tau * transpose(inverse(F));
    };
    if (tangent == nullptr)
    {
      // Residual only (line search, reactions): plain doubles, without
      // carrying empty derivatives.
      const Mat3<double> P_full = first_piola(embed<double>(F_in));
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          P[i][j] = P_full[i][j];
      return;
    }
    const Mat3<AD> P_full = first_piola(embed<AD>(F_in));
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
      {
        P[i][j] = P_full[i][j].val();
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            (*tangent)[i][j][k][l] = P_full[i][j].dx(k * dim + l);
      }
  }



  template <int dim>
  SymmetricTensor<2, 3>
  J2Plasticity<dim>::cauchy_stress(const Tensor<2, dim> &F_in,
                                   const double         *history) const
  {
    const Mat3<double> F = embed<double>(F_in);
    Mat3<double>       tau;
    return_map(F,
               history,
               bulk_modulus,
               shear_modulus,
               hardening,
               tau,
               nullptr);
    const double          J = determinant(F);
    SymmetricTensor<2, 3> sigma;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        sigma[i][j] = tau[i][j] / J;
    return sigma;
  }

  template double
  HardeningLaw::yield_stress(const double &) const;
  template class J2Plasticity<2>;
  template class J2Plasticity<3>;
} // namespace tribos
