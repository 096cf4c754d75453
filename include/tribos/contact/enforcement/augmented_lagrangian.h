#ifndef tribos_contact_augmented_lagrangian_h
#define tribos_contact_augmented_lagrangian_h

#include <tribos/contact/enforcement/penalty.h>

namespace tribos
{
  /**
   * The augmented Lagrangian (Uzawa): the penalty law with a multiplier
   * lambda per slave node, t_N = <lambda - eps_N g_N>, which the outer
   * update sets to the converged t_N until every closed node touches within
   * Contact/Augmentation tolerance of its element size. The multipliers are
   * data, not unknowns: the system is the penalty's.
   */
  template <int dim>
  class AugmentedLagrangian : public Penalty<dim>
  {
  public:
    ContactLaw
    law(const ContactPair<dim>          &pair,
        const unsigned int               k,
        const NodeState                 &state,
        const AffineConstraints<double> &homogeneous) const override;

    bool
    has_outer_update() const override
    {
      return true;
    }

    double
    violation(const NodeState &state, const double size) const override;

    void
    outer_update(NodeState &state) const override;
  };
} // namespace tribos

#endif
