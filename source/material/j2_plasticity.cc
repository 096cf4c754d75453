#include <tribos/base/exceptions.h>
#include <tribos/material/j2_plasticity.h>

#include <deal.II/base/symmetric_tensor.h>

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

    /**
     * Eigenvalues and orthonormal eigenvectors (columns of @p Q) of the
     * values of a symmetric matrix; Jacobi rotations for their accuracy
     * near repeated eigenvalues.
     */
    template <typename N>
    std::array<double, 3>
    spectral_values(const Mat3<N> &A, Mat3<double> &Q)
    {
      SymmetricTensor<2, 3> S;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          S[i][j] = 0.5 * (value(A[i][j]) + value(A[j][i]));
      const auto pairs =
        eigenvectors(S, SymmetricTensorEigenvectorMethod::jacobi);
      std::array<double, 3> lambda;
      for (unsigned int k = 0; k < 3; ++k)
      {
        lambda[k] = pairs[k].first;
        for (unsigned int i = 0; i < 3; ++i)
          Q[i][k] = pairs[k].second[i];
      }
      return lambda;
    }

    /** Q diag(f) Q^T, or Q (theta o D) Q^T for a full matrix of weights. */
    Mat3<double>
    spectral_sum(const Mat3<double> &Q, const Mat3<double> &weights)
    {
      return Q * weights * transpose(Q);
    }

    /**
     * (ln a - ln b) / (a - b), ln'(a) = 1/a when a = b: the weight of the
     * (i, j) eigenvector pair in the derivative of the matrix logarithm
     * (Daleckii-Krein). With x = (a - b)/b it is log1p(x)/(x b), exact to
     * round-off however close a and b are.
     */
    double
    log_divided_difference(const double a, const double b)
    {
      const double x = (a - b) / b;
      if (std::abs(x) < 1e-8)
        return (1. - x / 2. + x * x / 3.) / b;
      return std::log1p(x) / (x * b);
    }

    /**
     * Logarithm of an SPD matrix from its spectral decomposition,
     * ln M = sum ln(lambda_i) n_i n_i^T. For AD numbers each derivative
     * direction dM maps to Q (theta o Q^T dM Q) Q^T with the divided
     * differences theta_ij of ln: the exact derivative, at the cost of a
     * few 3x3 products per direction instead of AD through an iterative
     * algorithm.
     */
    template <typename N>
    Mat3<N>
    log_spd(const Mat3<N> &M)
    {
      Mat3<double>                Q;
      const std::array<double, 3> lambda = spectral_values(M, Q);
      for (const double l : lambda)
        if (!(l > 0))
          throw InvertedElement("J2 plasticity: elastic left Cauchy-Green "
                                "tensor with eigenvalue " +
                                to_scientific(l) + " <= 0");
      Mat3<double> log_lambda = identity<double>();
      for (unsigned int i = 0; i < 3; ++i)
        log_lambda[i][i] = std::log(lambda[i]);
      const Mat3<double> L = spectral_sum(Q, log_lambda);

      Mat3<N> result;
      if constexpr (std::is_same_v<N, double>)
        result = L;
      else
      {
        Mat3<double> theta;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            theta[i][j] = log_divided_difference(lambda[i], lambda[j]);
        int n_derivatives = 0;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            n_derivatives = std::max(n_derivatives, M[i][j].size());
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            result[i][j] = N(n_derivatives, L[i][j]);
        const Mat3<double> Q_t = transpose(Q);
        for (int k = 0; k < n_derivatives; ++k)
        {
          Mat3<double> dM;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              dM[i][j] = M[i][j].dx(k);
          Mat3<double> D = Q_t * dM * Q;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              D[i][j] *= theta[i][j];
          const Mat3<double> dL = spectral_sum(Q, D);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              result[i][j].fastAccessDx(k) = dL[i][j];
        }
      }
      return result;
    }

    /** Exponential of a symmetric matrix (values), spectrally. */
    Mat3<double>
    exp_sym(const Mat3<double> &A)
    {
      Mat3<double>                Q;
      const std::array<double, 3> mu          = spectral_values(A, Q);
      Mat3<double>                exponential = identity<double>();
      for (unsigned int i = 0; i < 3; ++i)
        exponential[i][i] = std::exp(mu[i]);
      return spectral_sum(Q, exponential);
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
      // A point that converged plastically starts the next increment with
      // its trial state on the yield surface to round-off (through the
      // logarithm and back): that tie is elastic (no correction, the
      // elastic tangent), as Coulomb's stick at equality in
      // coulomb_return(). Left to round-off, about half such points took
      // the ~1000 times softer plastic tangent, and the first Newton
      // iterate depended on the thread count and the BLAS kernel.
      const bool plastic = value(q_trial) > yield_old * (1. + 1e-12);
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
      throw InvertedElement("J2 plasticity", determinant(F_in));
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

  template <int dim>
  double
  J2Plasticity<dim>::stored_energy(const Tensor<2, dim> &F_in,
                                   const double         *history) const
  {
    // Hencky: tau = 2 G dev(eps_e) + K tr(eps_e) 1, so the elastic energy
    // G |dev eps_e|^2 + K/2 tr(eps_e)^2 is |dev tau|^2 / (4 G) +
    // tr(tau)^2 / (18 K), with tau = J sigma.
    const SymmetricTensor<2, 3> tau =
      determinant(F_in) * cauchy_stress(F_in, history);
    const double                trace = dealii::trace(tau);
    const SymmetricTensor<2, 3> dev   = deviator(tau);
    return (dev * dev) / (4. * shear_modulus) +
           trace * trace / (18. * bulk_modulus);
  }

  template double
  HardeningLaw::yield_stress(const double &) const;
  template class J2Plasticity<2>;
  template class J2Plasticity<3>;
} // namespace tribos
