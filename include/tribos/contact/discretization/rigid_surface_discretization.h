#ifndef tribos_contact_rigid_surface_discretization_h
#define tribos_contact_rigid_surface_discretization_h

#include <tribos/contact/discretization/contact_discretization.h>
#include <tribos/parameters/contact.h>

namespace tribos
{
  /**
   * Node to surface against a rigid analytic master (plane, sphere,
   * cylinder, moving in time; NodeToRigid): every slave node is paired
   * with the surface's closest point, which needs no search, and its
   * element has the node's dofs only. On six-node triangles (P2
   * tetrahedra) the node at an edge's middle is evaluated at the virtual
   * point of the modified basis and its element has the edge's vertices'
   * dofs too (evaluate()).
   */
  template <int dim>
  class RigidSurfaceDiscretization : public ContactDiscretization<dim>
  {
  public:
    explicit RigidSurfaceDiscretization(const Parameters::Contact &parameters);

    std::string
    name() const override
    {
      return "node to rigid surface";
    }

    void
    initialize(const ContactPair<dim> &pair) override;

    bool
    pair_node(ContactPair<dim> &pair, const unsigned int k) override;

    void
    add_couplings(const ContactPair<dim> &,
                  const AffineConstraints<double> &,
                  DynamicSparsityPattern &) const override
    {
    }

    void
    used_couplings(
      const ContactPair<dim> &,
      const unsigned int,
      std::set<std::pair<unsigned int, unsigned int>> &) const override
    {
    }

    void
    begin_assembly(const ContactPair<dim> &pair,
                   const double            time,
                   const double            committed_time) override;

    ElementOutcome
    evaluate(ContactPair<dim>                     &pair,
             const unsigned int                    k,
             const SlaveInput                     &slave,
             double                               *R,
             double                               *K,
             std::vector<types::global_dof_index> &dofs,
             std::string                          &refusal) override;

    /** The node's dofs; at the middle of an edge of six-node triangles
     * also the edge's vertices' (evaluate()); then its unknowns. */
    void
    element_dofs(const ContactPair<dim>               &pair,
                 const unsigned int                    k,
                 const int                             face,
                 std::vector<types::global_dof_index> &dofs) const override;

    unsigned int
    max_element_dofs() const override
    {
      return 3 * NodeToRigid<dim>::n_dofs + dim;
    }

  private:
    /** The virtual point's element of an edge middle (evaluate()). */
    std::vector<double>        point_residual, point_matrix;
    const Parameters::Contact &parameters;
    /** The surface and its translation now and at the last converged
     * step (begin_assembly()). */
    RigidInput<dim> rigid;
  };
} // namespace tribos

#endif
