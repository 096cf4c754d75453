#ifndef tribos_contact_contact_handler_h
#define tribos_contact_contact_handler_h

#include <tribos/contact/contact_pair.h>
#include <tribos/contact/search/pairing.h>
#include <tribos/contact/state/chattering_monitor.h>
#include <tribos/parameters/contact.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The contact of a scene: its pairs (ContactPair, each with its
   * enforcement), the search that pairs slave nodes with master points
   * (Pairing), the chattering monitor, and the assembly of the contact
   * elements into the system. The data flows one way: search -> pairs'
   * node states -> elements (kinematics) -> enforcement (law) -> system.
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
      const bool                                       axisymmetric = false,
      const Mapping<dim> *curved_geometry                           = nullptr);

    /**
     * The dofs of every contact node. Contact may couple a slave node with
     * any of them: the constraints and the sparsity pattern of a process
     * know them all.
     */
    const IndexSet &
    contact_dofs() const
    {
      return all_contact_dofs;
    }

    /**
     * The dofs of the slave nodes this process reads
     * (ContactPair::read_slave_nodes): the solution must be ghosted on
     * them. The master nodes' positions come by exchange_master_nodes().
     */
    const IndexSet &
    ghost_dofs() const
    {
      return slave_read_dofs;
    }

    /** What the master exchanges of update() brought to this process:
     * values (numbers) received, the most in one search and in all, and
     * the number of searches. */
    struct ExchangeVolume
    {
      std::size_t  largest    = 0;
      std::size_t  total      = 0;
      unsigned int n_searches = 0;
    };
    const ExchangeVolume &
    exchange_volume() const
    {
      return exchange;
    }

    /**
     * Unknowns the enforcements add (multipliers): numbered after the
     * dofs, every one of them with a row in the system.
     */
    types::global_dof_index
    n_unknowns() const
    {
      return n_enforcement_unknowns;
    }

    /** The pairs (for the output). */
    const std::vector<ContactPair<dim>> &
    pairs() const
    {
      return contact_pairs;
    }

    /**
     * Search at the unknowns @p solution (displacements ghosted on
     * ghost_dofs(), then the multipliers) and time @p time: pair every
     * slave node with a master point and read the multipliers. Collective.
     */
    void
    update(const TrilinosWrappers::MPI::Vector &solution, const double time);

    /** Whether a slave node met a master face that is not yet coupled in
     * the sparsity pattern (the same answer on every process). */
    bool
    sparsity_outdated() const
    {
      return outdated;
    }

    /** Add every registered coupling to @p dsp, condensed through
     * @p constraints as distribute_local_to_global() will write it. */
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
     * The longest step in (0, 1] from the last evaluated state towards the
     * unknowns @p trial (ghosted like update()'s) at which no slave node's
     * penetration grows by more than @p fraction of its element size: the
     * gaps at @p trial (searched and evaluated, @p homogeneous giving the
     * laws' fixed components) interpolated linearly from the last
     * evaluation's. Leaves the contact state as it was. Collective.
     */
    double
    step_limit(const TrilinosWrappers::MPI::Vector &trial,
               const double                         time,
               const double                         fraction,
               const AffineConstraints<double>     &homogeneous);

    /**
     * The weight of the contact forces and tangent in @p rhs, @p matrix
     * and @p free_residual (not in @p full_residual and @p contact_forces):
     * 1 - alpha_f of a generalized-alpha step, 1 otherwise.
     */
    void
    set_force_weight(const double weight)
    {
      force_weight = weight;
    }

    /**
     * The energy the friction law dissipated in the increment of the last
     * evaluation: the sum over the slave nodes of |T| times the slip
     * increment times the tributary area (the return mapping's
     * dissipation). Collective.
     */
    double
    frictional_dissipation() const;

    /**
     * The committed state of every slave node of every pair (pairing,
     * traction, slip, multipliers), each from the process that owns the
     * node, as bytes: the same on every process. For checkpoints.
     * Collective.
     */
    std::vector<char>
    committed_state() const;

    /**
     * Make @p state (committed_state() of a run on the same mesh and
     * pairs) the committed and current state, and the last positions (of
     * update(), which must have run at the restored solution) the
     * committed ones, as at the end of the increment that ended at
     * @p time.
     */
    void
    load_committed_state(const std::vector<char> &state, const double time);

    /**
     * The committed states of every pair's slave nodes (of all
     * processes), with the nodes' reference positions and the slave
     * faces' vertices: what carry_over() takes to the pairs of a new mesh.
     */
    struct CarriedState
    {
      struct Pair
      {
        std::vector<Vec3<double>>                reference;
        std::vector<std::array<unsigned int, 4>> faces;
        std::vector<NodeState>                   states;
        bool                                     ever_near = false;
      };
      std::vector<Pair> pairs;
    };
    /** Collective. */
    CarriedState
    carried_state() const;

    /**
     * The committed (and current) states of the slave nodes from those of
     * the old mesh's, by reference position: a node where an old one was
     * takes its state; a new node (on a refined face) takes the state of
     * the nearest vertex of the old face it lies on, with the slip, the
     * multipliers, the tractions, the normal, the gap and the stick point
     * interpolated by the face's shape functions. The pairing is
     * forgotten (the old master's faces are gone): the next search pairs
     * the nodes again. Call before start_at().
     */
    void
    carry_over(const CarriedState &carried);

    /** The committed Lagrange multipliers of the own nodes into
     * @p unknowns (owned entries). Collective. */
    void
    write_multipliers(TrilinosWrappers::MPI::Vector &unknowns) const;

    /** Start from @p solution at @p time (a new mesh): positions and
     * multipliers read, the committed positions set to them. */
    void
    start_at(const TrilinosWrappers::MPI::Vector &solution, const double time);

    /** Start an increment (the chattering remedy's counts). */
    void
    begin_increment();

    /**
     * After the assembly of Newton iteration @p iteration (free residual
     * @p residual): the chattering detector and its remedy
     * (ChatteringMonitor::after_iteration()); @p say tells the user. May
     * throw NonConvergence (Contact/Chattering remedy = cutback).
     */
    void
    watch_iteration(const unsigned int                              iteration,
                    const double                                    residual,
                    const std::function<void(const std::string &)> &say);

    /**
     * At an iterate that passed Newton's tests: whether the contact accepts
     * it (false: held nodes were released and Newton goes on;
     * ChatteringMonitor::accept()). Throws NonConvergence (the increment
     * is cut) where a held node ends inadmissible, or where a slave node
     * in contact at the increment's start has its contact normal turned
     * over: it went through the master (past a rigid circle's centre,
     * behind a face to the master's far side). The premise: a node in
     * contact does not go round a master's corner sharper than a right
     * angle within one increment. Mortar's normal is the slave's own,
     * which never turns over; its search takes master faces behind the
     * slave instead.
     */
    bool
    accept_iterate(const std::function<void(const std::string &)> &say);

    /** The most chattering slave nodes seen in an iteration of this
     * increment. */
    unsigned int
    n_chattering() const
    {
      return monitor.most_chattering();
    }

    /** The last evaluated state becomes the converged history. */
    void
    commit();
    /**
     * Contact across processes, over all processes (collective): the slave
     * nodes paired at the last commit with a master face whose cell
     * another process owns, and the number of times, summed over the
     * commits, that a slave node's master face passed to another process
     * (sliding across a partition border).
     */
    std::pair<unsigned int, unsigned int>
    process_crossings() const;

    /**
     * Seconds this process has spent in update() and assemble() on its own
     * slave nodes, without the collective steps where it waits for the
     * others: the measure of the contact's load balance (a timer around
     * the calls would show every process the slowest one's time).
     */
    double
    own_time() const
    {
      return own_seconds;
    }

    /**
     * The work of this process's slave nodes since the last call, per
     * node the seconds its element took and the cell of its first slave
     * face; resets it (the weights of a rebalanced partition).
     */
    std::vector<std::pair<CellId::binary_type, double>>
    take_work();

    /** The slave nodes this process evaluates, over all pairs. */
    unsigned int
    n_own_slave_nodes() const
    {
      unsigned int n = 0;
      for (const auto &pair : contact_pairs)
        n += std::count(pair.owned.begin(), pair.owned.end(), true);
      return n;
    }

    /** Back to the last committed state (pairing included). */
    void
    restore();

    /**
     * The outer update of the enforcements at the last evaluated
     * (converged) state (the augmented Lagrangian's Uzawa step): if the
     * largest violation (|g_N| of a closed node over its element size)
     * exceeds Contact/Augmentation tolerance, the enforcements update and
     * the increment must be solved again (true); @p n_augmentations counts
     * the updates of the increment. Throws NonConvergence after Contact/
     * Maximum augmentations. Collective.
     */
    bool
    outer_update(unsigned int &n_augmentations);

    /** See penalty_warnings(). */
    std::vector<std::string>
    setup_warnings() const;

    /** A pair none of whose slave nodes ever came within Contact/Search
     * distance of its master. Collective. */
    std::vector<std::string>
    run_warnings() const;

    /** One line per pair for the log. */
    std::vector<std::string>
    describe() const;

    MPI_Comm
    communicator() const
    {
      return mpi_communicator;
    }

  private:
    /** Size the element buffers for the largest element of any pair. */
    void
    size_element_buffers();

    /** The law of slave node @p k of pair @p p at its @p state (the
     * enforcement's, with the chattering remedy's holds). */
    SlaveInput
    slave_input(const unsigned int               p,
                const unsigned int               k,
                const AffineConstraints<double> &homogeneous);

    const Parameters::Contact    &parameters;
    MPI_Comm                      mpi_communicator;
    std::vector<ContactPair<dim>> contact_pairs;
    Pairing<dim>                  pairing;
    ChatteringMonitor<dim>        monitor;
    IndexSet                      all_contact_dofs;
    IndexSet                      slave_read_dofs;
    ExchangeVolume                exchange;
    double                        force_weight = 1;
    /** The buffers of an element's residual and tangent (assemble()). */
    std::vector<double>     element_residual, element_matrix;
    types::global_dof_index n_enforcement_unknowns = 0;
    /** Unknowns below this number are displacements. */
    types::global_dof_index n_displacement_dofs;
    /** This process's slave nodes paired across processes at the last
     * commit, and their changes of the master's process so far. */
    unsigned int n_paired_across = 0, n_owner_changes = 0;
    bool         outdated       = true;
    double       time           = 0;
    double       committed_time = 0;
    /** See own_time(). */
    double own_seconds = 0;
  };
} // namespace tribos

#endif
