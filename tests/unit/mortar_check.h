/**
 * The finite-difference check of a mortar element shared by the unit tests
 * mortar_tangent (2D) and mortar_tangent_3d: evaluate the element, check
 * that its forces balance and its tangent against central differences of
 * its residual.
 */

#ifndef tribos_tests_mortar_check_h
#define tribos_tests_mortar_check_h

#include <tribos/contact/element/contact_element.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tribos
{
  /** What check_mortar_element() found. */
  struct MortarCheck
  {
    /** The element has a master (else nothing else was checked). */
    bool          paired = false;
    ContactStatus status = ContactStatus::open;
    /** Every perturbed evaluation stayed on the element's branch (paired,
     * the same status) and the tangent is not zero: the error counts. */
    bool checked = false;
    /** max |K_fd - K| / max |K| over all entries. */
    double relative_error = 0;
    /** The largest |sum of the forces| over the largest force, per
     * direction (0 if not applicable). */
    double balance = 0;
  };



  /**
   * Check the element @p Element (Mortar2D, Mortar3D) of @p input with the
   * slave's @p slave (its unknowns @p lambda if @p with_multipliers) and
   * @p enforcement: the force balance and the tangent against central
   * differences with step 1e-7 in every coordinate and unknown.
   */
  template <int dim, typename Element, typename Input>
  MortarCheck
  check_mortar_element(const Input            &input,
                       const SlaveInput       &slave,
                       const Vec3<double>     &lambda,
                       const bool              with_multipliers,
                       const Enforcement<dim> &enforcement)
  {
    MortarCheck        check;
    const unsigned int n_displacements =
      dim * (input.n_slave_nodes + input.n_master_nodes);
    const unsigned int       n = n_displacements + (with_multipliers ? dim : 0);
    std::vector<double>      R(n), K(n * n), Rp(n), Rm(n);
    Vec3<double>             point;
    const ContactPointResult result = Element::evaluate(slave,
                                                        input,
                                                        enforcement,
                                                        R.data(),
                                                        K.data(),
                                                        check.paired,
                                                        point);
    if (!check.paired)
      return check;
    check.status = result.status;

    // Force balance: the forces on all nodes sum to zero (sum D = sum M).
    if (!with_multipliers || result.status != ContactStatus::open)
      for (unsigned int d = 0; d < dim; ++d)
      {
        double sum = 0, scale = 0;
        for (unsigned int i = d; i < n_displacements; i += dim)
        {
          sum += R[i];
          scale = std::max(scale, std::abs(R[i]));
        }
        if (scale > 0)
          check.balance = std::max(check.balance, std::abs(sum) / scale);
      }

    // Central differences, the same branches.
    const double step  = 1e-7;
    double       error = 0, scale = 0;
    for (unsigned int j = 0; j < n; ++j)
    {
      Input        plus = input, minus = input;
      Vec3<double> lambda_plus = lambda, lambda_minus = lambda;
      if (j < dim * input.n_slave_nodes)
      {
        plus.xs[j / dim][j % dim] += step;
        minus.xs[j / dim][j % dim] -= step;
      }
      else if (j < n_displacements)
      {
        const unsigned int l = (j - dim * input.n_slave_nodes) / dim;
        plus.xm[l][j % dim] += step;
        minus.xm[l][j % dim] -= step;
      }
      else
      {
        lambda_plus[j - n_displacements] += step;
        lambda_minus[j - n_displacements] -= step;
      }
      SlaveInput s_plus = slave, s_minus = slave;
      s_plus.position  = plus.xs[0];
      s_minus.position = minus.xs[0];
      if (with_multipliers)
      {
        s_plus.unknowns  = &lambda_plus;
        s_minus.unknowns = &lambda_minus;
      }
      bool       paired_p, paired_m;
      const auto r_p = Element::evaluate(s_plus,
                                         plus,
                                         enforcement,
                                         Rp.data(),
                                         nullptr,
                                         paired_p,
                                         point);
      const auto r_m = Element::evaluate(s_minus,
                                         minus,
                                         enforcement,
                                         Rm.data(),
                                         nullptr,
                                         paired_m,
                                         point);
      if (!paired_p || !paired_m || r_p.status != result.status ||
          r_m.status != result.status)
        return check;
      for (unsigned int i = 0; i < n; ++i)
      {
        const double fd = (Rp[i] - Rm[i]) / (2 * step);
        error           = std::max(error, std::abs(fd - K[i * n + j]));
        scale           = std::max(scale, std::abs(K[i * n + j]));
      }
    }
    if (scale == 0)
      return check;
    check.checked        = true;
    check.relative_error = error / scale;
    return check;
  }
} // namespace tribos

#endif
