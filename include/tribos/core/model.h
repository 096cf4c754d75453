#ifndef tribos_core_model_h
#define tribos_core_model_h

#include <tribos/core/create_mesh.h>
#include <tribos/core/reference_geometry.h>
#include <tribos/core/unknowns_layout.h>
#include <tribos/core/warnings.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The contact zones of a model's pairs (Adaptivity, Contact zone
   * depth): per active cell the size of its slave face in a zone and of
   * its master face that a zone's node is closed on (0: none), and per
   * pair with closed nodes the box of their reference positions.
   * Empty: no zone rule.
   */
  template <int dim>
  struct ContactZone
  {
    dealii::Vector<float>         slave_size;
    dealii::Vector<float>         master_size;
    std::vector<BoundingBox<dim>> boxes;
  };



  /**
   * The discretization of all bodies of a scene: one mesh (parallel::shared
   * or parallel::fullydistributed, Parallel/Mesh; a p4est
   * parallel::distributed one that adapts, Adaptivity), its reference geometry
   * (curved cells), the finite element and Gauss rules of its cell kind, one
   * DoFHandler, who holds which unknowns (UnknownsLayout), the constraints
   * (hanging nodes, Dirichlet, symmetry) and the dofs of each Dirichlet
   * condition. It knows nothing of materials, contact or the solver: the
   * contact's extra unknowns reach it as plain data (ContactUnknowns). This
   * is where a change of the mesh during a run belongs.
   *
   * Built in three steps, in this order: create_mesh(), distribute_dofs(),
   * set_unknowns(). Others keep references into it (the DoFHandler, the
   * mapping, the quadrature, the layout): it is not copied.
   */
  template <int dim>
  class Model
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** @p timer gets the mesh's creation in its section "setup". */
    Model(const Parameters::AllParameters &parameters,
          const MPI_Comm                   mpi_communicator,
          TimerOutput                     &timer,
          Warnings                        &warnings);
    Model(const Model &) = delete;
    Model &
    operator=(const Model &) = delete;

    /** The mesh of the scene (create_mesh()), partitioned with @p weights
     * if given. Collective. */
    void
    create_mesh(const CellWeights *weights);

    /** The finite element, the Gauss rules, the dofs, the curved geometry
     * on them and the dofs of each Dirichlet condition. Collective. */
    void
    distribute_dofs();

    /** The system's unknowns (with the contact's ghosts and multipliers,
     * if @p contact is given), the homogeneous constraints, and each dof's
     * component and body. Collective. */
    void
    set_unknowns(const ContactUnknowns *contact);

    /**
     * Hanging nodes, Dirichlet and symmetry constraints into
     * @p constraints: du = g(time) - u at the Dirichlet dofs with
     * @p ghosted_solution u, or du = 0 if it is null (homogeneous).
     */
    void
    make_constraints(const double               time,
                     const Vector              *ghosted_solution,
                     AffineConstraints<double> &constraints) const;

    /** Constraints with du = 0 (the Newton corrections after the first). */
    const AffineConstraints<double> &
    homogeneous_constraints() const;

    /** The cells' couplings of the dofs into @p dsp (on system_coupled). */
    void
    bulk_sparsity(DynamicSparsityPattern &dsp) const;

    const parallel::TriangulationBase<dim> &
    triangulation() const;
    const DoFHandler<dim> &
    dof_handler() const;

    /**
     * The locally owned active cells, in the order every sum over them
     * takes (the assembly). A mesh that is adapted during the run (p4est)
     * stores its cells, and deal.II numbers their dofs, in an order that
     * depends on the refinements and coarsenings that made it; a restart,
     * which refines the coarse mesh to the checkpoint's cells at once,
     * would sum in another order and round otherwise. There the cells are
     * visited in the order of their CellIds and the dofs numbered
     * hierarchically (both functions of the cells alone); a mesh that
     * never changes keeps the triangulation's order.
     */
    const std::vector<typename DoFHandler<dim>::active_cell_iterator> &
    owned_cells() const;
    const FESystem<dim> &
    fe() const;
    const Quadrature<dim> &
    quadrature() const;
    const Quadrature<dim - 1> &
    face_quadrature() const;

    /**
     * The cells' reference geometry, for every evaluation on them: the
     * curved cells of a second-order mesh with Polynomial degree = 2
     * (MappingFEField on the dofs' reference positions), else the mesh's
     * straight cells (the linear mapping of its cell kind).
     */
    const Mapping<dim> &
    mapping() const;
    /** The curved cells' mapping; null: straight cells. */
    const Mapping<dim> *
    curved_mapping() const;

    const UnknownsLayout &
    layout() const;
    MPI_Comm
    communicator() const;

    /** Per Dirichlet condition: all dofs on its boundary, per component. */
    const std::vector<std::vector<IndexSet>> &
    reaction_dofs() const;
    /** Vector component and body of every dof (by global dof number). */
    const std::vector<unsigned char> &
    dof_component() const;
    const std::vector<types::material_id> &
    dof_body() const;

    /**
     * Per Dirichlet condition and component, the sum over its dofs of
     * @p residual (and of @p inertia if given), the unconstrained forces
     * of the assembly, after each hanging node's force has gone to its
     * parents with the weights of its constraint (collective). A hanging
     * node moves with its parents, so its force acts on them: where a
     * parent is a support's dof and the hanging node is not (the edge of
     * a refined region that meets the support), the support carries a
     * share of it, which the raw residual at the support's dofs misses.
     */
    std::vector<double>
    reaction_forces(const Vector &residual, const Vector *inertia) const;

    /** The rigid-body modes (translations, rotations about the centroid)
     * at the locally owned rows, the near-null space of AMG. */
    std::vector<std::vector<double>>
    rigid_body_modes() const;

    /**
     * Adaptivity: flag the cells by @p indicator (per active cell) with
     * the strategy, the levels and the dof budget of the subsection
     * Adaptivity, and no more cells than the memory holds
     * (adaptive_cell_limit(); warned once); with a nonempty @p zone, the cells
     * whose centres lie within Contact zone depth times a box's width of one of
     * its boxes are refined to the finest level flagged among its slave cells,
     * and its master cells until their faces are no larger than 1.5 times the
     * finest slave face (a node-to-segment pressure oscillates with the period
     * of a master coarser than its slave); none of these is coarsened. True if
     * some cell is flagged. Collective.
     */
    bool
    mark(const dealii::Vector<float> &indicator, const ContactZone<dim> &zone);

    /**
     * Refine and coarsen the flagged cells (p4est partitions the mesh
     * again) and distribute the dofs on them (distribute_dofs()). The
     * ghosted dof vectors @p fields are interpolated to the new dofs and
     * returned (owned entries; hanging nodes interpolated); @p cell_data
     * (per active cell, a cell's quadrature-point values, [point][value])
     * is replaced by the new cells': a child's point takes the parent's
     * nearest point, a parent's point its child's nearest (copies, so a
     * homogeneous state stays homogeneous). Collective.
     */
    std::vector<Vector>
    adapt(const std::vector<const Vector *> &fields,
          std::vector<std::vector<double>>  &cell_data);

    /**
     * Adaptivity on restart: refine the mesh until its active cells are
     * @p cells (CellId::to_binary, a checkpoint's list), level by level, and
     * distribute the dofs on it. The mesh a run adapted to is a forest of
     * refinements of the coarse mesh, so it is rebuilt from its leaves
     * whatever refinements and coarsenings made it. False if nothing was
     * refined. A cell of this mesh that is neither among @p cells nor an
     * ancestor of one of them is an error (the checkpoint's mesh is not of
     * this scene). Collective.
     */
    bool
    refine_to(const std::vector<std::array<unsigned int, 4>> &cells);

  private:
    /**
     * The refinement that mark() flagged (@p n_refine cells to refine,
     * @p n_coarsen to coarsen) cut until it fits the budgets: Adaptivity/
     * Maximum dofs, and always the cells the memory holds
     * (adaptive_cell_limit()). @p flag_fraction flags a fixed fraction of
     * the cells to refine (with the levels and the contact zone) and
     * returns the counts as p4est will carry them out. Collective.
     */
    std::pair<double, double>
    fit_budget(
      double                                                  n_refine,
      double                                                  n_coarsen,
      const std::function<std::pair<double, double>(double)> &flag_fraction);

    /** The p4est mesh of Adaptivity/Enable. */
    parallel::distributed::Triangulation<dim> &
    adaptive_triangulation();

    const Parameters::AllParameters &parameters;
    MPI_Comm                         mpi_communicator;
    TimerOutput                     &timer;
    Warnings                        &warnings;

    /** Declared before what holds on to it (DoFHandler, mapping). */
    std::unique_ptr<parallel::TriangulationBase<dim>> triangulation_storage;
    std::unique_ptr<FESystem<dim>>                    fe_storage;
    DoFHandler<dim>                                   dofs;
    std::vector<typename DoFHandler<dim>::active_cell_iterator> owned_cells_;
    /** A second-order mesh's curved geometry per active cell (own cells
     * on a distributed mesh); empty: straight cells. */
    CurvedCells<dim> curved_cells;
    /** After the DoFHandler, whose dofs its mapping reads. */
    ReferenceGeometry<dim> geometry;
    /** Gauss rules of the mesh's cell kind and of its faces. */
    Quadrature<dim>     cell_quadrature;
    Quadrature<dim - 1> cell_face_quadrature;

    UnknownsLayout layout_;
    /** Every process's locally owned dofs. */
    std::vector<IndexSet>     owned_per_process;
    AffineConstraints<double> homogeneous;
    /**
     * The hanging nodes' constraints alone, on the locally relevant dofs
     * (reaction_forces()): without the Dirichlet lines, which would take
     * the supports' dofs out of the hanging nodes' lines (close() puts
     * their values in), so that their shares of the forces were lost.
     */
    AffineConstraints<double> hanging;
    /** Whether any process has a hanging node (the same on all). */
    bool any_hanging = false;

    std::vector<std::unique_ptr<FunctionParser<dim>>> dirichlet_functions;
    std::vector<std::vector<IndexSet>>                dirichlet_dofs;
    std::vector<unsigned char>                        components;
    std::vector<types::material_id>                   bodies;
    /** Whether mark() has cut a refinement to the memory (warned once). */
    bool memory_limited = false;
  };
} // namespace tribos

#endif
