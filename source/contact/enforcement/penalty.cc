#include <tribos/contact/contact_pair.h>
#include <tribos/contact/enforcement/enforcement_method.h>
#include <tribos/contact/enforcement/lagrange_multiplier.h>
#include <tribos/contact/enforcement/penalty.h>

#include <cmath>

namespace tribos
{
  template <int dim>
  ContactLaw
  Penalty<dim>::law(const ContactPair<dim> &pair,
                    const unsigned int      k,
                    const NodeState &,
                    const AffineConstraints<double> &) const
  {
    const double h = pair.slave->nodes()[k].size;
    const double E = pair.contact_modulus;
    ContactLaw   law;
    law.friction_coefficient = pair.description.friction_coefficient;
    law.normal_penalty       = pair.description.normal_penalty.resolve(E, h);
    law.tangential_penalty = pair.description.tangential_penalty.resolve(E, h);
    law.touch              = 1e-12 * h;
    return law;
  }



  template <int dim>
  void
  Penalty<dim>::local_law(const PointKinematics &kinematics,
                          const ContactLaw      &law,
                          const Vec3<ContactAD> *,
                          Vec3<ContactAD> &force,
                          Vec3<ContactAD> &,
                          ContactPointResult &result) const
  {
    using AD            = ContactAD;
    const AD      &gap  = kinematics.gap;
    const auto    &n    = kinematics.normal;
    const Vec3<AD> zero = {{AD(0.), AD(0.), AD(0.)}};
    force               = zero;
    // Closed for lambda - eps_N g_N >= 0 (g_N <= 0 for pure penalty): a
    // node that just touches carries no pressure but gives the Newton
    // matrix its contact stiffness, so that the first iteration of a step
    // does not push it deep into the master.
    if (!law.frozen_closed &&
        law.multiplier - law.normal_penalty * (value_of(gap) - law.touch) < 0)
      return;

    const AD pressure = law.multiplier - law.normal_penalty * (gap - law.touch);
    result.pressure   = value_of(pressure);
    result.status     = ContactStatus::closed;
    force             = scale(-pressure, n);
    if (law.friction_coefficient == 0)
      return;

    // Stick trial (16): the committed traction, turned with the surface,
    // plus the elastic part of the slip increment; slip indicator (17)
    // and return map (18)-(19). A node held closed by the chattering
    // remedy may carry a tensile pressure: the bound is never negative.
    const Vec3<AD> trial =
      kinematics.committed + scale(law.tangential_penalty, kinematics.slip);
    const AD limit = law.friction_coefficient * positive_part(pressure);
    Vec3<AD> traction;
    AD       magnitude;
    result.status = ContactStatus::stick;
    traction      = trial;
    if (!law.frozen_stick && coulomb_return(trial, limit, traction, magnitude))
    {
      result.status = ContactStatus::slip;
      result.slip_increment =
        value_of((magnitude - limit) / law.tangential_penalty);
    }
    force = force + traction;
    for (unsigned int d = 0; d < 3; ++d)
      result.traction[d] = value_of(traction[d]);
  }



  template class Penalty<2>;
  template class Penalty<3>;



  namespace
  {
    /**
     * Contact/Method = penalty. Contact/Penalty formulation (resolved per
     * pair: Contact::resolve_pairs()) chooses how the law is solved: primal,
     * Penalty; mixed, the same law with the tractions as unknowns
     * (LagrangeMultiplier in its regularized form), which has the same
     * solution.
     */
    class PenaltyMethod : public EnforcementInBothDimensions<PenaltyMethod>
    {
    public:
      template <int dim>
      std::shared_ptr<const Enforcement<dim>>
      make(const Parameters::ContactPair &pair,
           const Parameters::Contact     &parameters) const
      {
        if (pair.penalty_formulation == Parameters::PenaltyFormulation::mixed)
          return std::make_shared<LagrangeMultiplier<dim>>(parameters, true);
        return std::make_shared<Penalty<dim>>();
      }
    };

    // Rank 0: the first of Contact/Method's choices.
    const EnforcementRegistration penalty_registration =
      register_enforcement<PenaltyMethod>("penalty", "t_N = eps_N <-g_N>", 0);
  } // namespace
} // namespace tribos
