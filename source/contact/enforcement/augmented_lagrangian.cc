#include <tribos/contact/contact_pair.h>
#include <tribos/contact/enforcement/augmented_lagrangian.h>
#include <tribos/contact/enforcement/enforcement_method.h>

#include <cmath>

namespace tribos
{
  template <int dim>
  ContactLaw
  AugmentedLagrangian<dim>::law(
    const ContactPair<dim>          &pair,
    const unsigned int               k,
    const NodeState                 &state,
    const AffineConstraints<double> &homogeneous) const
  {
    ContactLaw law = Penalty<dim>::law(pair, k, state, homogeneous);
    law.multiplier = state.multiplier;
    return law;
  }



  template <int dim>
  double
  AugmentedLagrangian<dim>::violation(const NodeState &state,
                                      const double     size) const
  {
    // Closed nodes must touch: a gap of either sign is a violation (a
    // positive one means the warm-started multiplier of an unloading node
    // is too large).
    return state.closed() ? std::abs(state.result.gap) / size : 0.;
  }



  template <int dim>
  void
  AugmentedLagrangian<dim>::outer_update(NodeState &state) const
  {
    state.multiplier = state.result.pressure;
  }

  template class AugmentedLagrangian<2>;
  template class AugmentedLagrangian<3>;



  namespace
  {
    /** Contact/Method = augmented lagrangian. */
    class AugmentedLagrangianMethod
      : public EnforcementInBothDimensions<AugmentedLagrangianMethod>
    {
    public:
      template <int dim>
      std::shared_ptr<const Enforcement<dim>>
      make(const Parameters::ContactPair &, const Parameters::Contact &) const
      {
        return std::make_shared<AugmentedLagrangian<dim>>();
      }
    };

    // Rank 2 keeps Contact/Method's choices in their order; documented
    // second, next to the penalty law it augments.
    const EnforcementRegistration augmented_lagrangian_registration =
      register_enforcement<AugmentedLagrangianMethod>(
        "augmented lagrangian",
        "t_N = <lambda - eps_N g_N> with the multiplier lambda of each slave "
        "node updated (Uzawa) until the penetration is below Augmentation "
        "tolerance",
        2,
        1);
  } // namespace
} // namespace tribos
