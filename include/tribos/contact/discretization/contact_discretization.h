#ifndef tribos_contact_contact_discretization_h
#define tribos_contact_contact_discretization_h

#include <tribos/contact/element/contact_element.h>
#include <tribos/parameters/contact.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  template <int dim>
  struct ContactPair;

  /** What the evaluation of one slave node's element gave. */
  struct ElementOutcome
  {
    enum class Kind
    {
      /** The element's rows are in R, K and dofs (NodeState::result and
       * NodeState::point are set). */
      element,
      /** The node has no master point after all (a mortar weight too
       * small): it is treated as unpaired. */
      unpaired,
      /** The element cannot be evaluated (the reason is in the refusal):
       * the iterate is void, the increment is cut back. */
      refused
    };
    Kind kind = Kind::unpaired;
    /** Whether the node counts as near its master (the run's warning about
     * pairs that never met). */
    bool near = false;
  };



  /**
   * How a contact pair is discretized: the search that pairs its slave
   * nodes with master points, the couplings its elements need in the
   * sparsity pattern, and the element of a slave node (its kinematics,
   * from which the pair's Enforcement makes forces and rows). One object
   * per pair, made once by the pair's registered DiscretizationMethod
   * (discretization_method.h), which reads its own parameters (Mortar
   * basis) and chooses among its variants (rigid or smoothed master).
   * Each implementation owns the state that only it needs (the mortar
   * element's master faces per node, the overlap cache).
   *
   * The search is independent of the enforcement (the paper, section 1),
   * and the enforcement of the discretization: Penalty, LagrangeMultiplier
   * and AugmentedLagrangian see only the PointKinematics an element makes.
   *
   * Implementations: NodeToSegmentDiscretization (faceted master, 2D
   * segments and 3D bilinear faces), SmoothedNodeToSegmentDiscretization
   * and SmoothedNodeToFaceDiscretization (2D and 3D, averaged nodal
   * normals), RigidSurfaceDiscretization (analytic
   * masters) and MortarDiscretization (2D Q1/Q2 segments, 3D bilinear
   * faces, dual or standard basis). To add one (triangle faces, say):
   * derive from this class, implement the search and the element, and
   * register a DiscretizationMethod that makes it in the same source file
   * (the end of node_to_segment_discretization.cc is the example).
   */
  template <int dim>
  class ContactDiscretization
  {
  public:
    virtual ~ContactDiscretization() = default;

    /** The name for the log ("node to segment", "mortar, dual basis"). */
    virtual std::string
    name() const = 0;

    /**
     * Check that this discretization can work on @p pair (its surfaces
     * and enforcement; a clear error otherwise) and size its own state.
     * Called once the pair's nodes, areas and exclusions are known.
     */
    virtual void
    initialize(const ContactPair<dim> &pair) = 0;

    /**
     * Whether the slave nodes that hang on others (a refinement border)
     * hand their functions to their parents even without unknowns of the
     * enforcement (mortar: a node of its own there would weigh the gap
     * unlike its neighbours).
     */
    virtual bool
    parents_carry_hanging_nodes() const
    {
      return false;
    }

    /**
     * The slave nodes whose positions the element of slave node @p k
     * reads, @p k first.
     */
    virtual void
    stencil(const ContactPair<dim>    &pair,
            const unsigned int         k,
            std::vector<unsigned int> &nodes) const;

    /**
     * How far beyond the box of the slave nodes a process reads (the
     * search distance and three master face sizes aside) master nodes may
     * lie that the element of slave node @p k can reach (the master
     * exchange under MPI).
     */
    virtual double
    exchange_reach(const ContactPair<dim> & /*pair*/,
                   const unsigned int /*k*/) const
    {
      return 0;
    }

    /** Whether a master face is usable only with the nodes around it
     * known (a smoothed master's normals: 2D the nodes beyond its ends,
     * 3D the ring of ContactSurface::Face). */
    virtual bool
    needs_nodes_beyond() const
    {
      return false;
    }

    /**
     * The search of owned, not excluded slave node @p k at the current
     * positions of @p pair: its pairing in NodeState (paired, face,
     * projection, distance of ContactPair::current), and the couplings
     * its element will need (ContactPair::couplings). Returns whether a
     * coupling was new (the sparsity pattern must then be rebuilt).
     */
    virtual bool
    pair_node(ContactPair<dim> &pair, const unsigned int k) = 0;

    /** Whether a self-contact pair (a surface its own master) may use this
     * discretization. */
    virtual bool
    takes_self_contact() const
    {
      return false;
    }

    /** Warnings about the pair found by initialize() (printed once, at
     * the start of the run). */
    virtual std::vector<std::string>
    setup_warnings() const
    {
      return {};
    }

    /** The couplings of @p pair's registered (slave node, master face)
     * pairs into @p dsp, condensed through @p constraints. */
    virtual void
    add_couplings(const ContactPair<dim>          &pair,
                  const AffineConstraints<double> &constraints,
                  DynamicSparsityPattern          &dsp) const;

    /**
     * Add to @p into the couplings slave node @p k uses at its current
     * pairing (those not used by any node are pruned at a commit).
     */
    virtual void
    used_couplings(const ContactPair<dim>                          &pair,
                   const unsigned int                               k,
                   std::set<std::pair<unsigned int, unsigned int>> &into) const;

    /**
     * The dofs of the element of slave node @p k against master @p face
     * (-1: none): the slave's (mortar: of its stencil), then the master's,
     * then the node's unknowns.
     */
    virtual void
    element_dofs(const ContactPair<dim>               &pair,
                 const unsigned int                    k,
                 const int                             face,
                 std::vector<types::global_dof_index> &dofs) const;

    /** Called before an assembly evaluates the elements of @p pair at
     * @p time (the last converged one: @p committed_time). */
    virtual void
    begin_assembly(const ContactPair<dim> & /*pair*/,
                   const double /*time*/,
                   const double /*committed_time*/)
    {
    }

    /**
     * Evaluate the element of paired slave node @p k of @p pair with the
     * @p slave's law and the pair's enforcement: R (dofs.size() entries)
     * and K (their square, row-major) with the element's @p dofs; sets the
     * node's result and contact point in ContactPair::current. An element
     * that cannot be evaluated gets its reason in @p refusal (the first
     * one met is kept).
     */
    virtual ElementOutcome
    evaluate(ContactPair<dim>                     &pair,
             const unsigned int                    k,
             const SlaveInput                     &slave,
             double                               *R,
             double                               *K,
             std::vector<types::global_dof_index> &dofs,
             std::string                          &refusal) = 0;

    /** The most dofs an element of this discretization has (the size of
     * the buffers R and K of evaluate()). */
    virtual unsigned int
    max_element_dofs() const = 0;

  protected:
    /** Add to @p into the couplings of slave node @p k with master
     * @p face: the face and its neighbours (the node may slide onto them
     * within an increment). */
    static void
    insert_couplings(const ContactPair<dim>                          &pair,
                     const unsigned int                               k,
                     const unsigned int                               face,
                     std::set<std::pair<unsigned int, unsigned int>> &into);
  };



  /**
   * Refuse @p pair if its slave surface is quadratic: node to surface
   * elements know the vertices and straight faces of Q1 only.
   */
  template <int dim>
  void
  require_linear_slave_faces(const ContactPair<dim> &pair);



  /**
   * The discretization of the pair described by @p description with the
   * contact @p parameters (@p axisymmetric: the model is a body of
   * revolution): its registered discretization's (discretization_method.h).
   */
  template <int dim>
  std::unique_ptr<ContactDiscretization<dim>>
  create_discretization(const Parameters::ContactPair &description,
                        const Parameters::Contact     &parameters,
                        const bool                     axisymmetric);
} // namespace tribos

#endif
