#ifndef tribos_contact_penalty_h
#define tribos_contact_penalty_h

#include <tribos/contact/enforcement/enforcement.h>

namespace tribos
{
  /**
   * Penalty enforcement (the paper's (14)-(19)): t_N = eps_N <-g_N> and the
   * Coulomb return map of the trial T_trial = Q T_n + eps_T dg_T, with
   * eps_N, eps_T per slave node (Contact/Penalty factor 'k*E/h'). No
   * unknowns of its own.
   */
  template <int dim>
  class Penalty : public Enforcement<dim>
  {
  public:
    bool
    uses_normal_penalty() const override
    {
      return true;
    }

    std::string
    formulation() const override
    {
      return "primal";
    }

    ContactLaw
    law(const ContactPair<dim>          &pair,
        const unsigned int               k,
        const NodeState                 &state,
        const AffineConstraints<double> &homogeneous) const override;

    void
    local_law(const PointKinematics &kinematics,
              const ContactLaw      &law,
              const Vec3<ContactAD> *unknowns,
              Vec3<ContactAD>       &force,
              Vec3<ContactAD>       &constraint,
              ContactPointResult    &result) const override;
  };
} // namespace tribos

#endif
