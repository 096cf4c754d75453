#ifndef tribos_contact_enforcement_h
#define tribos_contact_enforcement_h

#include <tribos/contact/element/contact_ad.h>
#include <tribos/contact/state/node_state.h>
#include <tribos/parameters/contact.h>

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>

#include <memory>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  template <int dim>
  struct ContactPair;

  /**
   * How a pair enforces contact: one object per pair, chosen once from
   * Contact/Method, and the only place that knows the method. The contact
   * elements compute the kinematics of a point (gap, normal, slip, the
   * committed traction turned with the surface); the enforcement turns them
   * into the force on the slave and, if it owns unknowns, the rows of its
   * node; Newton and the load stepping see only the resulting residual and
   * tangent, the unknowns it adds and its outer update.
   *
   * To add a method: derive from this class (penalty.h is the smallest
   * example), implement law(), local_law() and uses_normal_penalty(), and
   * register it in the same source file: an EnforcementMethod that makes
   * it and an EnforcementRegistration (enforcement_method.h; the end of
   * penalty.cc is the example). Contact/Method, the pairs' method= and
   * their messages list it by themselves.
   */
  template <int dim>
  class Enforcement
  {
  public:
    virtual ~Enforcement() = default;

    /**
     * Whether the normal penalty eps_N of the pair enters the law (the log
     * then reports its range over the slave nodes; exact multipliers have
     * none).
     */
    virtual bool
    uses_normal_penalty() const = 0;

    /** How the law is solved, for the log: the penalty's "primal" or
     * "mixed" (Contact/Penalty formulation); empty where there is one
     * way. */
    virtual std::string
    formulation() const
    {
      return std::string();
    }

    /** Unknowns of the system the method adds per slave node: dim (a
     * traction vector) or none. */
    virtual unsigned int
    n_node_unknowns() const
    {
      return 0;
    }

    /**
     * The law's parameters at slave node @p k of @p pair (penalties or
     * complementarity parameters resolved at the node's element size, its
     * current @p state's multiplier, components fixed by @p homogeneous).
     */
    virtual ContactLaw
    law(const ContactPair<dim>          &pair,
        const unsigned int               k,
        const NodeState                 &state,
        const AffineConstraints<double> &homogeneous) const = 0;

    /**
     * The local law at one point: @p force (on the slave, per unit area)
     * and, with unknowns (@p unknowns, seeded for AD), the node's
     * @p constraint rows, from the point's @p kinematics; fills the
     * reported values of @p result.
     */
    virtual void
    local_law(const PointKinematics &kinematics,
              const ContactLaw      &law,
              const Vec3<ContactAD> *unknowns,
              Vec3<ContactAD>       &force,
              Vec3<ContactAD>       &constraint,
              ContactPointResult    &result) const = 0;

    /**
     * The rows of the node's unknowns where it has no master point (off
     * the master, or excluded): none without unknowns. @p scale is the
     * node's own tributary area (the row scaling).
     */
    virtual void
    unpaired_rows(const NodeState & /*state*/,
                  const double /*scale*/,
                  double * /*R*/,
                  double * /*K*/) const
    {
    }

    /**
     * A last look at an element's rows (@p n_displacements displacement
     * rows, then the node's unknowns) before they are assembled, e.g. to
     * replace a row that no free unknown moves.
     */
    virtual void
    finish_rows(const std::vector<types::global_dof_index> & /*dofs*/,
                const unsigned int /*n_displacements*/,
                const AffineConstraints<double> & /*homogeneous*/,
                const double /*area*/,
                const NodeState & /*state*/,
                double * /*R*/,
                double * /*K*/) const
    {
    }

    /** Whether the method has an outer update (Uzawa). */
    virtual bool
    has_outer_update() const
    {
      return false;
    }

    /**
     * The outer update's measure at the converged @p state of a slave node
     * whose element size is @p size: its violation (|g_N| of a closed node
     * over the element size).
     */
    virtual double
    violation(const NodeState & /*state*/, const double /*size*/) const
    {
      return 0;
    }

    /** The outer update of a slave node's @p state (lambda <- t_N). */
    virtual void
    outer_update(NodeState & /*state*/) const
    {
    }
  };



  /**
   * The enforcement of the pair @p pair, by its method (Contact/Method, a
   * pair's method=) with the contact @p parameters: the registered
   * method's own (enforcement_method.h).
   */
  template <int dim>
  std::shared_ptr<const Enforcement<dim>>
  create_enforcement(const Parameters::ContactPair &pair,
                     const Parameters::Contact     &parameters);
} // namespace tribos

#endif
