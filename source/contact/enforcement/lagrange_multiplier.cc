#include <tribos/contact/contact_pair.h>
#include <tribos/contact/enforcement/enforcement_method.h>
#include <tribos/contact/enforcement/lagrange_multiplier.h>

#include <cmath>
#include <map>

namespace tribos
{
  namespace
  {
    /**
     * An orthonormal tangent frame of the unit normal @p n: t_0 from the
     * coordinate axis least aligned with n (fixed while n varies, so the
     * frame is differentiable), t_1 = n x t_0. In 2D always the in-plane
     * tangent t_0 = (-n_y, n_x) (t_1 = e_z is unused): choosing it by the
     * axis test too made t_0 flip sign where n_x passes through 0 (the
     * test |n_z| < |n_x| fails at n_x = 0 exactly), so a multiplier row
     * changed sign between a Newton iterate and its neighbour (the
     * tangent check of the smoothed ironing: 7.9e-3 at the node under the
     * symmetric indenter).
     */
    template <int dim, typename Number>
    void
    tangent_frame(const Vec3<Number> &n, Vec3<Number> (&t)[2])
    {
      if (dim == 2)
      {
        t[0] = {{Number(-n[1]), Number(n[0]), Number(0.)}};
        t[1] = {{Number(0.), Number(0.), Number(1.)}};
        return;
      }
      unsigned int axis = 0;
      for (unsigned int d = 1; d < 3; ++d)
        if (std::abs(value_of(n[d])) < std::abs(value_of(n[axis])))
          axis = d;
      Vec3<Number> e = {{Number(0.), Number(0.), Number(0.)}};
      e[axis]        = 1.;
      t[0]           = e - scale(n[axis], n);
      t[0]           = scale(1. / norm(t[0]), t[0]);
      t[1]           = cross(n, t[0]);
    }
  } // namespace



  template <int dim>
  LagrangeMultiplier<dim>::LagrangeMultiplier(
    const Parameters::Contact &parameters,
    const bool                 regularized)
    : parameters(parameters)
    , regularized(regularized)
  {
  }



  template <int dim>
  ContactLaw
  LagrangeMultiplier<dim>::law(
    const ContactPair<dim> &pair,
    const unsigned int      k,
    const NodeState &,
    const AffineConstraints<double> &homogeneous) const
  {
    const auto  &node = pair.slave->nodes()[k];
    const double E    = pair.contact_modulus;
    ContactLaw   law;
    law.friction_coefficient = pair.description.friction_coefficient;
    // The semismooth parameters c (normal) and c_T (stick/slip).
    law.normal_penalty =
      parameters.normal_complementarity.resolve(E, node.size);
    law.tangential_penalty =
      parameters.friction_complementarity.resolve(E, node.size);
    law.touch = 1e-12 * node.size;
    if (regularized)
    {
      law.normal_compliance =
        1. / pair.description.normal_penalty.resolve(E, node.size);
      if (law.friction_coefficient > 0)
        law.tangential_compliance =
          1. / pair.description.tangential_penalty.resolve(E, node.size);
    }
    for (unsigned int d = 0; d < dim; ++d)
      if (homogeneous.is_constrained(node.dofs[d]) &&
          homogeneous.get_constraint_entries(node.dofs[d])->empty())
        law.fixed_components |= (1u << d);
    return law;
  }



  /**
   * The unknown (@p unknowns) is the slave's contact traction vector Lambda
   * (force per unit area on the slave, so t_N = -Lambda . n and T = P_T
   * Lambda), and @p constraint receives the node's equations: while open
   * the multiplier itself, while closed the normal condition (component 0)
   * and the tangential one in the frame t_1, t_2 (components 1, 2):
   *
   *   open  (t_N - c g_N < 0):    C = Lambda                 (no traction)
   *   closed, normal:             C_0 = c g_N                (g_N = 0)
   *   frictionless:               C_a = t_a . T              (T = 0)
   *   stick (|T + c_T dg_T| <= mu t_N^+):  C_a = t_a . c_T dg_T  (no slip)
   *   slip:   C_a = t_a . (T - mu t_N^+ (T + c_T dg_T)/|T + c_T dg_T|)  (22)
   *
   * with t_N^+ = max(0, t_N - c g_N). This is the primal-dual active set
   * strategy written as a semismooth Newton method (Alart and Curnier's
   * augmented form): the contact and stick/slip status follow from the
   * current multipliers and gaps at every evaluation, so the active set is
   * updated inside Newton, and the derivative of C is the generalized
   * Jacobian on each branch. The slip branch couples T to the normal
   * multiplier non-symmetrically, as in the paper's (22) and (35). c and
   * c_T change the iterates (which branch a node takes) and the row
   * scaling only, never the converged solution. c_T must not be much
   * stiffer than the body: with c_T = 1000 E a slip of 1e-6 h already
   * decides the branch, and the iteration cycled between stick and slip on
   * the 3D upsetting.
   */
  template <int dim>
  void
  LagrangeMultiplier<dim>::local_law(const PointKinematics &kinematics,
                                     const ContactLaw      &law,
                                     const Vec3<ContactAD> *unknowns,
                                     Vec3<ContactAD>       &force,
                                     Vec3<ContactAD>       &constraint,
                                     ContactPointResult    &result) const
  {
    using AD                   = ContactAD;
    const AD       &gap        = kinematics.gap;
    const Vec3<AD> &n          = kinematics.normal;
    const Vec3<AD> &multiplier = *unknowns;
    force                      = multiplier;
    const AD       pressure    = -dot(multiplier, n);
    const Vec3<AD> tau         = multiplier + scale(pressure, n);
    // The gap of the conditions: g_N, or with the penalty in mixed form
    // g_N + t_N/eps_N (zero where the penalty law holds).
    const AD condition_gap = gap + law.normal_compliance * pressure;
    if (!law.frozen_closed &&
        value_of(pressure) -
            law.normal_penalty * (value_of(condition_gap) - law.touch) <
          0)
    {
      constraint    = multiplier;
      result.status = ContactStatus::open;
      return;
    }
    result.pressure = value_of(pressure);
    result.status   = law.friction_coefficient > 0 ? ContactStatus::stick :
                                                     ContactStatus::closed;

    // Tangents in which the slave cannot move (symmetry planes,
    // Dirichlet): there the condition is T . t = 0 (what symmetry implies);
    // a stick condition would be singular. The friction law acts in the
    // remaining tangent directions.
    Vec3<AD>     fixed[2];
    unsigned int n_fixed = 0;
    for (unsigned int d = 0; d < 3 && n_fixed < 2; ++d)
      if (law.fixed_components & (1u << d))
      {
        Vec3<AD> t = {{AD(0.), AD(0.), AD(0.)}};
        t[d]       = 1.;
        t          = t - scale(n[d], n);
        for (unsigned int i = 0; i < n_fixed; ++i)
          t = t - scale(dot(t, fixed[i]), fixed[i]);
        const AD length = norm(t);
        if (value_of(length) >= 0.5)
          fixed[n_fixed++] = scale(1. / length, t);
      }
    const auto free_part = [&](const Vec3<AD> &v)
    {
      Vec3<AD> part = v;
      for (unsigned int i = 0; i < n_fixed; ++i)
        part = part - scale(dot(v, fixed[i]), fixed[i]);
      return part;
    };
    const Vec3<AD> tau_free = free_part(tau);

    Vec3<AD> tangential = tau_free;
    if (law.friction_coefficient > 0)
    {
      // The slip of the conditions: dg_T, or in mixed form its part
      // beyond the elastic slip (T - T_n)/eps_T of the penalty law.
      Vec3<AD> slip = free_part(kinematics.slip);
      if (law.tangential_compliance > 0)
        slip = slip - scale(law.tangential_compliance,
                            tau_free - free_part(kinematics.committed));
      const Vec3<AD> trial = tau_free + scale(law.tangential_penalty, slip);
      // The Coulomb bound of the augmented (Alart-Curnier) form, on
      // max(0, t_N - c g_N): never negative, also in iterates whose
      // multiplier is tensile; equal to mu t_N at convergence (g_N = 0).
      const AD limit =
        law.friction_coefficient *
        positive_part(AD(pressure - law.normal_penalty * condition_gap));
      Vec3<AD> returned;
      AD       magnitude;
      if (!law.frozen_stick &&
          coulomb_return(trial, limit, returned, magnitude))
      {
        tangential            = tau_free - returned;
        result.status         = ContactStatus::slip;
        result.slip_increment = value_of(norm(slip));
      }
      else
        tangential = scale(law.tangential_penalty, slip);
    }
    tangential = tangential + (tau - tau_free);

    // Rows in the local frame (n, t_1, t_2): the normal row must not see
    // the tangential rows' geometry. (As one global vector c g n + P_T C,
    // the term c g dn/du of a penetrating node would put spurious
    // tangential forces into every iterate.)
    Vec3<AD> t[2];
    tangent_frame<dim>(n, t);
    constraint[0] = law.normal_penalty * condition_gap;
    constraint[1] = dot(tangential, t[0]);
    constraint[2] = dot(tangential, t[1]);
    for (unsigned int d = 0; d < 3; ++d)
      result.traction[d] = value_of(tau[d]);
  }



  template <int dim>
  void
  LagrangeMultiplier<dim>::unpaired_rows(const NodeState &state,
                                         const double     scale,
                                         double          *R,
                                         double          *K) const
  {
    for (unsigned int i = 0; i < dim; ++i)
    {
      R[i] = scale * state.lambda[i];
      for (unsigned int j = 0; j < dim; ++j)
        K[i * dim + j] = (i == j ? scale : 0.);
    }
  }



  template <int dim>
  void
  LagrangeMultiplier<dim>::finish_rows(
    const std::vector<types::global_dof_index> &dofs,
    const unsigned int                          n_displacements,
    const AffineConstraints<double>            &homogeneous,
    const double                                area,
    const NodeState                            &state,
    double                                     *R,
    double                                     *K) const
  {
    // A constraint row that depends on no free unknown (e.g. a slave node
    // fixed by Dirichlet conditions pressed onto a rigid surface, or whose
    // only free motion on an inclined symmetry plane is tangential to the
    // gap) would make the system singular: its multiplier does no work on
    // any free dof, so it is set to zero (the reaction goes to the
    // constraints instead). The test is on the row as the solver sees it,
    // condensed through the constraints (u_j = sum_k c_jk u_k): entries of
    // different constrained columns may cancel on the same free dof.
    const unsigned int                        n = n_displacements + dim;
    std::map<types::global_dof_index, double> condensed;
    for (unsigned int i = n_displacements; i < n; ++i)
    {
      condensed.clear();
      double scale = 0;
      for (unsigned int j = 0; j < n; ++j)
      {
        const double entry = K[i * n + j];
        scale              = std::max(scale, std::abs(entry));
        if (j >= n_displacements || !homogeneous.is_constrained(dofs[j]))
          condensed[dofs[j]] += entry;
        else
          for (const auto &e : *homogeneous.get_constraint_entries(dofs[j]))
            condensed[e.first] += entry * e.second;
      }
      double free = 0;
      for (const auto &[dof, value] : condensed)
        free = std::max(free, std::abs(value));
      if (free > 1e-10 * scale)
        continue;
      const unsigned int d = i - n_displacements;
      R[i]                 = area * state.lambda[d];
      for (unsigned int j = 0; j < n; ++j)
        K[i * n + j] = (j == i ? area : 0.);
    }
  }

  template class LagrangeMultiplier<2>;
  template class LagrangeMultiplier<3>;



  namespace
  {
    /** Contact/Method = lagrange multiplier: exact contact. */
    class LagrangeMultiplierMethod
      : public EnforcementInBothDimensions<LagrangeMultiplierMethod>
    {
    public:
      bool
      constrains_gap_exactly() const override
      {
        return true;
      }

      template <int dim>
      std::shared_ptr<const Enforcement<dim>>
      make(const Parameters::ContactPair & /*pair*/,
           const Parameters::Contact &parameters) const
      {
        return std::make_shared<LagrangeMultiplier<dim>>(parameters);
      }
    };

    // Rank 1 keeps Contact/Method's choices in their order; documented
    // last, after the two penalty laws its complementarity refers to.
    const EnforcementRegistration lagrange_multiplier_registration =
      register_enforcement<LagrangeMultiplierMethod>(
        "lagrange multiplier",
        "exact contact, the traction of every slave node is an unknown of "
        "the system (saddle point; direct or, the multipliers eliminated, "
        "iterative solves, on any number of MPI processes); the active set "
        "and stick/slip follow from lambda - eps_N g_N inside Newton, so "
        "eps_N then only affects the iterates",
        1,
        2);
  } // namespace
} // namespace tribos
