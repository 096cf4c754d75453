#include <tribos/contact/augmented_lagrangian.h>
#include <tribos/contact/contact_pair.h>

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
} // namespace tribos
