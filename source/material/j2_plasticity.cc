#include <tribos/base/exceptions.h>
#include <tribos/material/j2_plasticity.h>
#include <tribos/material/material_model.h>
#include <tribos/parameters/materials.h>

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace tribos
{
  namespace
  {
    using Mat3 = Tensor<2, 3>;
    using Vec3 = Tensor<1, 3>;



    /** Q diag(d) Q^T. */
    Mat3
    spectral_sum(const Mat3 &Q, const Vec3 &d)
    {
      Mat3 A;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
        {
          for (unsigned int k = 0; k < 3; ++k)
            A[i][j] += Q[i][k] * d[k] * Q[j][k];
          A[j][i] = A[i][j];
        }
      return A;
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

    /** The six independent entries of a symmetric matrix and back. */
    constexpr unsigned int sym_index[6][2] =
      {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};

    /** The symmetric matrix of the six history values @p packed. */
    Mat3
    unpack_symmetric(const double *packed)
    {
      Mat3 A;
      for (unsigned int c = 0; c < 6; ++c)
      {
        A[sym_index[c][0]][sym_index[c][1]] = packed[c];
        A[sym_index[c][1]][sym_index[c][0]] = packed[c];
      }
      return A;
    }
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
    /** F (dim x dim) as a 3x3 matrix, F_33 = 1 in 2D (plane strain). */
    template <int dim>
    Mat3
    embed(const Tensor<2, dim> &F_in)
    {
      Mat3 F = unit_symmetric_tensor<3>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F[i][j] = F_in[i][j];
      return F;
    }



    /**
     * The return map's result at one point, in the principal axes Q of
     * the trial left Cauchy-Green tensor b_trial = F C_p^-1 F^T, which
     * the logarithmic elastic strain and the Kirchhoff stress share.
     */
    struct ReturnMap
    {
      /** Eigenvectors of b_trial (columns) and its eigenvalues. */
      Mat3 Q;
      Vec3 lambda;
      /** Kirchhoff stress. */
      Mat3 tau;
      /** The unit flow direction dev(eps_trial)/|dev(eps_trial)|. */
      Vec3 n;
      /**
       * d tau = K tr(d eps) 1 + beta dev(d eps) - gamma (n : d eps) n for
       * a change d eps of the trial strain: the algorithmic moduli of
       * small-strain J2's radial return (beta = 2G, gamma = 0 elastic).
       */
      double beta  = 0;
      double gamma = 0;
    };



    /**
     * The radial return in logarithmic strains at deformation gradient
     * @p F (3x3, inverse @p F_inv) from the history @p old; writes the new
     * history if @p new_history is not null.
     */
    ReturnMap
    return_map(const Mat3         &F,
               const Mat3         &F_inv,
               const double       *old,
               const double        K,
               const double        G,
               const HardeningLaw &hardening,
               double             *new_history)
    {
      const Mat3 b_trial = F * unpack_symmetric(old) * transpose(F);

      // Jacobi eigenvectors for their accuracy near repeated eigenvalues.
      ReturnMap             result;
      SymmetricTensor<2, 3> b;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          b[i][j] = 0.5 * (b_trial[i][j] + b_trial[j][i]);
      const auto pairs =
        eigenvectors(b, SymmetricTensorEigenvectorMethod::jacobi);
      for (unsigned int k = 0; k < 3; ++k)
      {
        result.lambda[k] = pairs[k].first;
        for (unsigned int i = 0; i < 3; ++i)
          result.Q[i][k] = pairs[k].second[i];
        if (!(result.lambda[k] > 0))
          throw InvertedElement("J2 plasticity: elastic left Cauchy-Green "
                                "tensor with eigenvalue " +
                                to_scientific(result.lambda[k]) + " <= 0");
      }

      // Principal trial strains eps_i = ln(lambda_i) / 2, their trace and
      // deviator.
      Vec3   eps;
      double trace = 0;
      for (unsigned int k = 0; k < 3; ++k)
      {
        eps[k] = 0.5 * std::log(result.lambda[k]);
        trace += eps[k];
      }
      Vec3   deviator;
      double norm_squared = 0;
      for (unsigned int k = 0; k < 3; ++k)
      {
        deviator[k] = eps[k] - trace / 3.;
        norm_squared += deviator[k] * deviator[k];
      }
      const double dev_norm = std::sqrt(norm_squared + 1e-300);
      for (unsigned int k = 0; k < 3; ++k)
        result.n[k] = deviator[k] / dev_norm;
      const double q_trial   = std::sqrt(1.5) * 2. * G * dev_norm;
      const double alpha_old = old[6];
      // A point that converged plastically starts the next increment with
      // its trial state on the yield surface to round-off (through the
      // logarithm and back): that tie is elastic (no correction, the
      // elastic tangent), as Coulomb's stick at equality in
      // coulomb_return(). Left to round-off, about half such points took
      // the ~1000 times softer plastic tangent, and the first Newton
      // iterate depended on the thread count and the BLAS kernel.
      const bool plastic =
        q_trial > hardening.yield_stress(alpha_old) * (1. + 1e-12);
      double delta_alpha = 0, factor = 0;
      result.beta = 2. * G;
      if (plastic)
      {
        // Scalar Newton on q_trial - 3 G da - sigma_y(alpha + da) = 0.
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
          const double r =
            q_trial - 3 * G * da - hardening.yield_stress(alpha_old + da);
          const double step = r / slope(da);
          da += step;
          if (std::abs(step) < 1e-15 * (1 + da))
            break;
        }
        delta_alpha = da;
        // eps_e = eps_trial - f dev(eps_trial); d(da) = d(q_trial) / slope
        // at the root gives d tau's moduli.
        factor       = std::sqrt(1.5) * delta_alpha / dev_norm;
        result.beta  = 2. * G * (1. - factor);
        result.gamma = 2. * G * (3. * G / slope(delta_alpha) - factor);
      }

      // tau = 2 G dev(eps_e) + K tr(eps_e) 1, dev(eps_e) = (1 - f) dev.
      Vec3 tau_principal;
      for (unsigned int k = 0; k < 3; ++k)
        tau_principal[k] = result.beta * deviator[k] + K * trace;
      result.tau = spectral_sum(result.Q, tau_principal);

      if (new_history != nullptr)
      {
        // C_p^-1 = F^-1 b_e F^-T with b_e = exp(2 eps_e), which has the
        // trial eigenvectors (the return is radial).
        Vec3 b_e_principal;
        for (unsigned int k = 0; k < 3; ++k)
          b_e_principal[k] = std::exp(2. * (eps[k] - factor * deviator[k]));
        const Mat3 Cp_new =
          F_inv * spectral_sum(result.Q, b_e_principal) * transpose(F_inv);
        for (unsigned int c = 0; c < 6; ++c)
          new_history[c] = Cp_new[sym_index[c][0]][sym_index[c][1]];
        new_history[6] = alpha_old + delta_alpha;
      }
      return result;
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
    const Mat3      F     = embed(F_in);
    const Mat3      F_inv = invert(F);
    const ReturnMap r     = return_map(F,
                                   F_inv,
                                   old_history,
                                   bulk_modulus,
                                   shear_modulus,
                                   hardening,
                                   new_history);

    // P = tau F^-T.
    const Mat3 G     = transpose(F_inv);
    const Mat3 P_all = r.tau * G;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        P[i][j] = P_all[i][j];
    if (tangent == nullptr)
      return;

    // The tangent dP/dF_ab, direction by direction, in the principal axes
    // Q (hats):
    //   d b_trial = e_a m_b^T + m_b e_a^T, m_b the column b of F C_p^-1;
    //   d eps^ = 1/2 theta o (Q^T d b_trial Q) (Daleckii-Krein, theta the
    //            divided differences of ln);
    //   d tau^ = K tr(d eps) 1 + beta dev(d eps^) - gamma (n : d eps) n;
    //   d P    = Q d tau^ Q^T G - P e_b (G^T e_a)^T  (G = F^-T).
    // The exact derivative of the update above; the finite differences of
    // unit/material_tangent check it.
    const Mat3 &Q = r.Q;
    Mat3        theta;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = 0; l < 3; ++l)
        theta[k][l] = log_divided_difference(r.lambda[k], r.lambda[l]);
    const Mat3   FC = F * unpack_symmetric(old_history);
    const Mat3   W  = transpose(Q) * G;
    const double K  = bulk_modulus;
    for (unsigned int b = 0; b < dim; ++b)
    {
      // Q^T m_b.
      Vec3 m;
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int j = 0; j < 3; ++j)
          m[k] += Q[j][k] * FC[j][b];
      for (unsigned int a = 0; a < dim; ++a)
      {
        // Q^T e_a is the row a of Q.
        Mat3   d_eps;
        double d_trace = 0, n_d_eps = 0;
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            d_eps[k][l] = 0.5 * theta[k][l] * (Q[a][k] * m[l] + m[k] * Q[a][l]);
        for (unsigned int k = 0; k < 3; ++k)
        {
          d_trace += d_eps[k][k];
          n_d_eps += r.n[k] * d_eps[k][k];
        }
        Mat3 d_tau;
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            d_tau[k][l] = r.beta * d_eps[k][l];
        for (unsigned int k = 0; k < 3; ++k)
          d_tau[k][k] +=
            (K - r.beta / 3.) * d_trace - r.gamma * n_d_eps * r.n[k];
        const Mat3 d_P = Q * (d_tau * W);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            (*tangent)[i][j][a][b] = d_P[i][j] - P_all[i][b] * G[a][j];
      }
    }
  }



  template <int dim>
  SymmetricTensor<2, 3>
  J2Plasticity<dim>::cauchy_stress(const Tensor<2, dim> &F_in,
                                   const double         *history) const
  {
    const Mat3            F = embed(F_in);
    const ReturnMap       r = return_map(F,
                                   invert(F),
                                   history,
                                   bulk_modulus,
                                   shear_modulus,
                                   hardening,
                                   nullptr);
    const double          J = determinant(F);
    SymmetricTensor<2, 3> sigma;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        sigma[i][j] = r.tau[i][j] / J;
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



  namespace
  {
    /**
     * Materials/Model = J2 plasticity, and its entries: the hardening law
     * (36) per body id or one for all bodies, like Young's modulus.
     */
    class J2PlasticityModel : public MaterialInBothDimensions<J2PlasticityModel>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Yield stress",
                          "1e100",
                          Patterns::Anything(),
                          "J2 plasticity: initial yield stress s0 of (36) "
                          "(the default: no yield), per body id or one for "
                          "all; > 0.");
        prm.declare_entry("Saturation yield stress",
                          "1e100",
                          Patterns::Anything(),
                          "J2 plasticity: s_inf of (36), >= s0.");
        prm.declare_entry("Hardening exponent",
                          "0",
                          Patterns::Anything(),
                          "J2 plasticity: delta of (36), >= 0.");
        prm.declare_entry("Linear hardening modulus",
                          "0",
                          Patterns::Anything(),
                          "J2 plasticity: H of (36), >= 0.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        using Lists    = Parameters::Materials;
        yield_stresses = Lists::non_negative_list(prm, "Yield stress");
        saturation_yield_stresses =
          Lists::non_negative_list(prm, "Saturation yield stress");
        hardening_exponents =
          Lists::non_negative_list(prm, "Hardening exponent");
        linear_hardening_moduli =
          Lists::non_negative_list(prm, "Linear hardening modulus");
      }

      void
      check_body_count(const unsigned int max_body_id) const override
      {
        using Lists = Parameters::Materials;
        Lists::check_count(yield_stresses.size(), max_body_id, "Yield stress");
        Lists::check_count(saturation_yield_stresses.size(),
                           max_body_id,
                           "Saturation yield stress");
        Lists::check_count(hardening_exponents.size(),
                           max_body_id,
                           "Hardening exponent");
        Lists::check_count(linear_hardening_moduli.size(),
                           max_body_id,
                           "Linear hardening modulus");
      }

      void
      check_body(const unsigned int body) const override
      {
        hardening(body);
      }

      /** The yield stresses decide where the history of a checkpoint is
       * plastic. */
      std::vector<std::pair<std::string, std::vector<double>>>
      fingerprint() const override
      {
        return {{"Materials/Yield stress", yield_stresses}};
      }

      bool
      locks_on_linear_simplices() const override
      {
        return true;
      }

      template <int dim>
      std::unique_ptr<Material<dim>>
      make(const unsigned int body, const double E, const double nu) const
      {
        const HardeningLaw law = hardening(body);
        AssertThrow(law.initial_yield > 0 && law.initial_yield < 1e299 &&
                      law.saturation_yield >= law.initial_yield,
                    ExcMessage("Materials: J2 plasticity needs a Yield "
                               "stress s0 > 0 and a Saturation yield stress "
                               ">= s0 for every plastic body."));
        return std::make_unique<J2Plasticity<dim>>(E, nu, law);
      }

    private:
      /** The law of body @p body (in the order of the lists' checks). */
      HardeningLaw
      hardening(const unsigned int body) const
      {
        using Lists = Parameters::Materials;
        return {Lists::for_body(yield_stresses, body, "Yield stress"),
                Lists::for_body(saturation_yield_stresses,
                                body,
                                "Saturation yield stress"),
                Lists::for_body(hardening_exponents,
                                body,
                                "Hardening exponent"),
                Lists::for_body(linear_hardening_moduli,
                                body,
                                "Linear hardening modulus")};
      }

      std::vector<double> yield_stresses;
      std::vector<double> saturation_yield_stresses;
      std::vector<double> hardening_exponents;
      std::vector<double> linear_hardening_moduli;
    };

    // Rank 2: the third of Materials/Model's choices.
    const MaterialRegistration j2_plasticity_registration =
      register_material<J2PlasticityModel>(
        "J2 plasticity",
        "finite strain, Hencky elasticity, von Mises with the hardening (36)",
        2);
  } // namespace
} // namespace tribos
