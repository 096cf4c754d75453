#ifndef tribos_contact_contact_handler_h
#define tribos_contact_contact_handler_h

#include <tribos/contact/contact_element.h>
#include <tribos/contact/contact_point.h>
#include <tribos/contact/contact_search.h>
#include <tribos/contact/contact_surface.h>
#include <tribos/contact/rigid_surface.h>
#include <tribos/parameters/contact.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /** Totals of the contact state, summed over all processes. */
  struct ContactStatistics
  {
    /** Per pair: sum of A t_N, sum of A |T|, and the resultant force
     * on the slave body (x, y, z). */
    std::vector<std::array<double, 5>> pair_forces;
    double                             max_penetration = 0;
    unsigned int                       n_active        = 0;
    unsigned int                       n_stick         = 0;
    unsigned int                       n_slip          = 0;
  };

  /**
   * All contact pairs of a scene: surfaces, search, history and the
   * assembly of the penalty contact terms. The search (update()) pairs each
   * slave node with a master face or rigid surface and is independent of
   * the enforcement; assemble() consumes those pairs with penalty,
   * augmented Lagrangian (Uzawa) or Lagrange multiplier enforcement.
   *
   * Each process evaluates the slave nodes whose dofs it owns, so every
   * contact element is assembled exactly once under MPI.
   */
  template <int dim>
  class ContactHandler
  {
  public:
    ContactHandler(
      const Parameters::Contact                       &parameters,
      const DoFHandler<dim>                           &dof_handler,
      const std::function<double(types::material_id)> &youngs_modulus,
      const IndexSet                                  &locally_owned_dofs,
      const MPI_Comm                                   mpi_communicator,
      const bool                                       axisymmetric = false);

    /** The dofs of every contact node: they must be ghosted on all ranks. */
    const IndexSet &
    contact_dofs() const
    {
      return all_contact_dofs;
    }

    /**
     * Search at the unknowns @p solution (displacements ghosted on
     * contact_dofs(), then the multipliers) and time @p time: pair every
     * slave node with a master face (or its rigid surface), and read the
     * multipliers. Collective.
     */
    void
    update(const TrilinosWrappers::MPI::Vector &solution, const double time);

    /**
     * Whether a slave node met a master face that is not yet coupled in the
     * sparsity pattern (the same answer on every process).
     */
    bool
    sparsity_outdated() const
    {
      return outdated;
    }

    /**
     * Add every registered slave-master coupling to @p dsp, condensed
     * through @p constraints as distribute_local_to_global() will write it.
     */
    void
    add_couplings(DynamicSparsityPattern          &dsp,
                  const AffineConstraints<double> &constraints);

    /**
     * Add the contact terms: -R into @p rhs and dR/du into @p matrix with
     * @p constraints (if @p with_matrix), -R into @p free_residual with
     * @p homogeneous, R into @p full_residual unconstrained, and the
     * contact forces on the nodes (-R on the displacement dofs, slave and
     * master alike) into @p contact_forces.
     */
    void
    assemble(const bool                       with_matrix,
             const AffineConstraints<double> &constraints,
             const AffineConstraints<double> &homogeneous,
             TrilinosWrappers::SparseMatrix  &matrix,
             TrilinosWrappers::MPI::Vector   &rhs,
             TrilinosWrappers::MPI::Vector   &free_residual,
             TrilinosWrappers::MPI::Vector   &full_residual,
             TrilinosWrappers::MPI::Vector   &contact_forces);

    /**
     * Number of Lagrange multiplier unknowns: dim per slave node of every
     * pair enforced by Lagrange multipliers (zero otherwise). They are
     * numbered after the n displacement dofs, n + offset + dim k + d, and
     * every one of them has a row in the system: the node's constraint
     * while it is closed, the multiplier itself (Lambda = 0) while open.
     */
    types::global_dof_index
    n_multipliers() const
    {
      return n_multiplier_dofs;
    }

    /** Start counting status changes for a new increment. */
    void
    begin_increment();

    /**
     * Compare every slave node's contact status (open or closed) at the
     * last evaluation with the previous one and count the changes of this
     * increment; returns the
     * number of nodes (all processes) with more than @p limit changes.
     */
    unsigned int
    track_status_changes(const unsigned int limit);

    /**
     * Hold every node that changed its contact status more than @p limit
     * times in this increment closed until the increment ends; returns
     * how many are held (all processes).
     */
    unsigned int
    freeze_chattering(const unsigned int limit);

    /** Number of held nodes whose pressure is tensile (all processes). */
    unsigned int
    n_frozen_in_tension() const;

    /** Make the last evaluated state the converged history. */
    void
    commit();

    /** Return to the last committed state (after a failed increment). */
    void
    restore();

    /** Whether any pair is enforced by the augmented Lagrangian. */
    bool
    augmented() const;

    /**
     * Uzawa step of the augmented Lagrangian pairs at the last evaluated
     * (converged) state: returns the largest |g_N| of a closed slave node
     * (penetration, or separation under a too large warm-started
     * multiplier) relative to its element size; if that exceeds
     * @p tolerance the
     * multipliers are updated to lambda <- t_N (the increment must then be
     * solved again), otherwise they are left as they are.
     */
    double
    augment(const double tolerance);

    ContactStatistics
    statistics() const;

    /**
     * Warnings about the input, known after setup: a pair whose normal or
     * tangential penalty is below 1e-3 E/h or above 1e8 E/h at some slave
     * node (too soft to keep the bodies apart, or stiffer than round-off
     * allows). Collective.
     */
    std::vector<std::string>
    setup_warnings() const;

    /**
     * One line per pair for the log: enforcement, contact modulus, the
     * range of the slave nodes' element sizes h and of the normal penalty.
     */
    std::vector<std::string>
    describe() const;

    /**
     * Warnings known at the end of a run: a pair none of whose slave nodes
     * ever came within Contact/Search distance of its master. Collective.
     */
    std::vector<std::string>
    run_warnings() const;

    /** Names of the history.csv columns that statistics() fills. */
    std::vector<std::string>
    column_names() const;

    /** The statistics as a row matching column_names(). */
    std::vector<double>
    columns() const;

    /** Write contact-NNNNN.csv (rank 0 gathers). */
    void
    write_csv(const std::string &filename) const;

    /**
     * Nodal fields for the VTU output: CPRESS, COPEN, CSLIP, CSTATUS on a
     * scalar Q1 numbering (@p vertex_to_dof), CSHEAR on the displacement
     * numbering. Summed over processes; nodes without contact get 0 (COPEN:
     * the gap where a projection exists).
     */
    void
    nodal_fields(const std::vector<types::global_dof_index> &vertex_to_dof,
                 std::array<dealii::Vector<double>, 4>      &scalars,
                 dealii::Vector<double>                     &shear) const;

  private:
    struct Pairing
    {
      bool       valid = false;
      int        face  = -1;
      Projection projection;
      /** Distance to the closest point of the master surface (also for a
       * node that slid off its end: its gap then); NaN if unknown. */
      double distance = std::numeric_limits<double>::quiet_NaN();
    };

    struct Pair
    {
      Parameters::ContactPair              description;
      std::shared_ptr<ContactSurface<dim>> slave;
      std::shared_ptr<ContactSurface<dim>> master;
      std::shared_ptr<RigidSurface<dim>>   rigid;
      /** The friction coefficient; penalties are per node (node_law()). */
      ContactLaw law;
      /** The contact modulus E of the penalties 'k*E/h' (see the
       * constructor). */
      double             contact_modulus = 0;
      double             area_factor     = 1;
      ContactSearch<dim> search;
      /** Per slave node: tributary area times area_factor, with the areas
       * of excluded nodes handed to the nodes that carry them. */
      std::vector<double> area;
      /** Whether a slave node within the search distance was ever met. */
      bool ever_near = false;

      std::vector<bool> owned;
      /** Status at the last tracked evaluation and changes in the
       * increment (chattering detector). */
      std::vector<int>          tracked_status;
      std::vector<unsigned int> status_changes;
      std::vector<bool>         frozen;
      /** Lagrange pairs: slave nodes without a multiplier of their own
       * (hanging nodes, nodes left to an earlier pair), see
       * exclude_dependent_nodes(). */
      std::vector<bool>   excluded;
      std::vector<double> multipliers, committed_multipliers;
      /** Lagrange multiplier method: first multiplier number, and per
       * slave node the traction vector Lambda (current and committed). */
      bool                            lagrange         = false;
      types::global_dof_index         first_multiplier = 0;
      std::vector<Vec3<double>>       lagrange_values;
      std::vector<SlaveHistory>       history;
      std::vector<Pairing>            pairing;
      std::vector<ContactPointResult> results;
      std::vector<Vec3<double>>       slave_positions, old_slave_positions;
      std::vector<Vec3<double>>       master_positions, old_master_positions;
      std::set<std::pair<unsigned int, unsigned int>> couplings;
    };

    /** The dofs of the element of slave @p node against master @p face
     * (slave first, then the face's nodes, with Master smoothing the
     * face's neighbour nodes, then the node's multipliers for a Lagrange
     * pair), into @p dofs. */
    void
    element_dofs(const Pair                           &pair,
                 const unsigned int                    node,
                 const int                             face,
                 std::vector<types::global_dof_index> &dofs) const;

    /** Whether the pair's master is smoothed (SmoothedSegment). */
    bool
    smoothed(const Pair &pair) const;

    /**
     * The nodes of @p face for SmoothedSegment (segment, node before, node
     * after) at @p positions, and which neighbours exist.
     */
    void
    smoothed_stencil(const Pair                      &pair,
                     const unsigned int               face,
                     const std::vector<Vec3<double>> &positions,
                     Vec3<double>                    *x,
                     bool                            *has) const;

    /**
     * The faces near slave point @p x: the closest face (CGAL search) and
     * its neighbours; empty if the master is farther than Search
     * distance. Sets @p pairing.distance.
     */
    std::vector<unsigned int>
    candidate_faces(const Pair         &pair,
                    const Vec3<double> &x,
                    Pairing            &pairing) const;

    /**
     * Pair slave @p k with the faceted master: keep the face of the last
     * evaluation while the node projects onto it (or its extension within
     * the edge band), else the closest projection inside a candidate face
     * (else the closest clamped one); near a free end of the master, the
     * end face's extension within the edge band.
     */
    void
    pair_faceted(Pair &pair, const unsigned int k) const;

    /**
     * Pair slave @p k with the smoothed master: the face whose smoothed
     * normal line through the node has xi in [-1, 1] (the nearest such);
     * near a free end of the master, the end face's extension within the
     * edge band. Unpaired (invalid) otherwise.
     */
    void
    pair_smoothed(Pair &pair, const unsigned int k) const;

    /**
     * Lagrange pairs: mark the slave nodes whose constraint rows would
     * depend on other rows (hanging nodes, from @p hanging_constraints;
     * nodes that an earlier pair already constrains against the same
     * master) and hand their tributary areas to the nodes that carry them.
     */
    void
    exclude_dependent_nodes(
      Pair                            &pair,
      const AffineConstraints<double> &hanging_constraints);

    /**
     * The interface law at slave node @p k: the pair's friction, the
     * penalties resolved at the node's element size, the augmented
     * multiplier, the chattering hold and (multipliers) the components
     * fixed by @p homogeneous.
     */
    ContactLaw
    node_law(const Pair                      &pair,
             const unsigned int               k,
             const AffineConstraints<double> &homogeneous) const;

    /**
     * Lagrange pairs: replace every constraint row of an element (@p R,
     * @p K with n_displacements + dim rows) that depends on no free
     * unknown by Lambda_d = 0.
     */
    void
    guard_constraint_rows(const std::vector<types::global_dof_index> &dofs,
                          const unsigned int               n_displacements,
                          const AffineConstraints<double> &homogeneous,
                          const double                     area,
                          const Vec3<double>              &lambda,
                          double                          *R,
                          double                          *K) const;

    const Parameters::Contact &parameters;
    MPI_Comm                   mpi_communicator;
    bool                       consistent;
    std::vector<Pair>          pairs;
    IndexSet                   all_contact_dofs;
    /** Unknowns below this number are displacements (then multipliers). */
    types::global_dof_index n_displacement_dofs;
    types::global_dof_index n_multiplier_dofs = 0;
    bool                    outdated          = true;
    double                  time              = 0;
    double                  committed_time    = 0;
  };
} // namespace tribos

#endif
