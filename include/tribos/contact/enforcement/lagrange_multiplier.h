#ifndef tribos_contact_lagrange_multiplier_h
#define tribos_contact_lagrange_multiplier_h

#include <tribos/contact/enforcement/enforcement.h>

namespace tribos
{
  /**
   * Lagrange multipliers: the traction vector Lambda of every slave node
   * (dim unknowns, numbered after the displacement dofs) and its rows, the
   * semismooth complementarity conditions of normal contact and Coulomb
   * friction (primal-dual active set; see local_law() in the source). c
   * (Normal complementarity parameter) and c_T (Friction complementarity
   * parameter) steer the active set and scale the rows; they never change
   * the solution.
   *
   * With @p regularized (Contact/Penalty formulation = mixed) the same
   * unknowns solve the penalty law instead of exact contact: the gap in
   * the conditions is g_N + t_N/eps_N and the stick slip dg_T - (T -
   * T_n)/eps_T (the perturbed Lagrangian of Method = penalty, whose
   * solution it has).
   */
  template <int dim>
  class LagrangeMultiplier : public Enforcement<dim>
  {
  public:
    explicit LagrangeMultiplier(const Parameters::Contact &parameters,
                                const bool                 regularized = false);

    /** Only in the penalty law's mixed form. */
    bool
    uses_normal_penalty() const override
    {
      return regularized;
    }

    std::string
    formulation() const override
    {
      return regularized ? "mixed" : "";
    }

    unsigned int
    n_node_unknowns() const override
    {
      return dim;
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

    /** Lambda = 0, scaled by the node's own tributary area. */
    void
    unpaired_rows(const NodeState &state,
                  const double     scale,
                  double          *R,
                  double          *K) const override;

    /**
     * A constraint row that depends on no free unknown once condensed
     * through the constraints becomes Lambda_d = 0 (see the source).
     */
    void
    finish_rows(const std::vector<types::global_dof_index> &dofs,
                const unsigned int                          n_displacements,
                const AffineConstraints<double>            &homogeneous,
                const double                                area,
                const NodeState                            &state,
                double                                     *R,
                double                                     *K) const override;

  private:
    const Parameters::Contact &parameters;
    /** The penalty law in mixed form (see the class). */
    const bool regularized;
  };
} // namespace tribos

#endif
