#ifndef tribos_material_j2_plasticity_h
#define tribos_material_j2_plasticity_h

#include <tribos/material/material.h>

namespace tribos
{
  /** Data of the isotropic hardening law (36) of the paper. */
  struct HardeningLaw
  {
    /** Initial yield stress s0. */
    double initial_yield;
    /** Saturation yield stress s_inf. */
    double saturation_yield;
    /** Saturation exponent delta. */
    double exponent;
    /** Linear hardening modulus H. */
    double linear_modulus;

    /** sigma_y(e_p) = s0 + (s_inf - s0)(1 - exp(-delta e_p)) + H e_p. */
    template <typename Number>
    Number
    yield_stress(const Number &plastic_strain) const;
  };

  /**
   * Finite-strain J2 plasticity: multiplicative split F = F_e F_p,
   * logarithmic (Hencky) elastic strains eps_e = ln(V_e), isotropic
   * linear elasticity between Kirchhoff stress and eps_e (bulk K, shear
   * G), von Mises yield with the hardening (36), and the exponential return
   * map (Simo 1992), which in logarithmic strains is the radial return of
   * small-strain J2. History per quadrature point: C_p^-1 (6 values) and
   * the equivalent plastic strain.
   *
   * The algorithmic tangent dP/dF is the exact derivative of this update
   * in closed form, in the principal axes of the trial left Cauchy-Green
   * tensor, which the trial strain, the flow direction and the Kirchhoff
   * stress share: the derivative of the matrix logarithm is the
   * Daleckii-Krein formula Q (theta o Q^T dM Q) Q^T with the divided
   * differences theta_ij of ln, evaluated by log1p so that repeated
   * principal stretches (uniaxial states, the undeformed state) need no
   * special case; the return map's moduli are small-strain J2's. It
   * replaced forward AD (Sacado) through the map, which cost 3.3 times as
   * much per evaluation with the tangent (benchmarks/material_speed).
   * The eigenvectors come from one Jacobi decomposition per evaluation,
   * for their accuracy near repeated eigenvalues; the new history reuses
   * them (the return is radial).
   */
  template <int dim>
  class J2Plasticity : public Material<dim>
  {
  public:
    J2Plasticity(const double E, const double nu, const HardeningLaw &law);

    unsigned int
    n_history_variables() const override
    {
      return 7;
    }

    void
    initialize_history(double *history) const override;

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

    double
    equivalent_plastic_strain(const double *history) const override
    {
      return history[6];
    }

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
    const double       E;
    const double       bulk_modulus;
    const double       shear_modulus;
    const HardeningLaw hardening;
  };
} // namespace tribos

#endif
