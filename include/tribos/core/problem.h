#ifndef tribos_core_problem_h
#define tribos_core_problem_h

#include <tribos/contact/contact_handler.h>
#include <tribos/core/checkpoint.h>
#include <tribos/material/material.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/postprocess/contact_output.h>
#include <tribos/postprocess/csv_writer.h>
#include <tribos/solver/load_stepper.h>
#include <tribos/solver/nonlinear_problem.h>
#include <tribos/solver/time_integrator.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The quasi-static boundary value problem of all bodies of a scene:
   * total Lagrangian displacement formulation, one DoFHandler over one
   * triangulation shared by all bodies, Trilinos distributed linear
   * algebra. Under MPI the mesh is shared (every process holds all of it)
   * or distributed (every process holds its own cells and a layer of
   * ghosts; Parallel/Mesh); the contact surfaces are gathered on every
   * process either way (ContactSurface), so the contact search sees every
   * master face. The unknowns are the
   * displacement dofs followed by the contact multipliers (if a pair uses
   * them), in one vector.
   *
   * Problem is the physics: it implements IncrementalProblem (residual,
   * tangent, constraints, commit, restore and the contact and
   * stabilization policies as hooks), and the generic solvers of solver/
   * (NewtonSolver, LoadStepper, LinearSolver) drive it. The implementation
   * is split by responsibility over source/core/: setup, assembly, the
   * solver hooks (increment.cc), the run and the output.
   */
  /**
   * Thrown by Problem::end_step() when the contact work is out of balance
   * (Parallel/Rebalance threshold): not a failure. The state of the step is
   * in @p checkpoint; main() builds the problem again, partitioned with
   * @p weights, and restarts from it.
   */
  struct Rebalance
  {
    std::string checkpoint;
    /** Rank 0: METIS' weight of every cell with measured contact work
     * (others weigh 1). */
    std::vector<std::pair<CellId::binary_type, unsigned int>> weights;
    /** The contact time's max/min over the processes in the step. */
    double       imbalance = 0;
    unsigned int step      = 0;
    /** Rebalances so far, this one included. */
    unsigned int count = 0;
    /** The wall time of the run before it (for the log's total). */
    double elapsed = 0;
  };



  template <int dim>
  class Problem : public IncrementalProblem
  {
  public:
    Problem(const Parameters::AllParameters &parameters,
            const MPI_Comm                   mpi_communicator);

    /**
     * Build the scene, solve every load step and write all output. Throws
     * NonConvergence when the cutbacks are exhausted (after the outputs of
     * all converged steps are written); other exceptions for bad input.
     */
    void
    run();

    /** This run goes on from a rebalance (main(), before run()): its mesh
     * is partitioned with the rebalance's weights. */
    void
    set_rebalance(const Rebalance &rebalance)
    {
      last_rebalance = rebalance;
    }

    /** Access for tests and drivers. */
    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /** The converged displacement, with ghost entries. */
    const TrilinosWrappers::MPI::Vector &
    get_solution() const
    {
      return ghosted_displacement();
    }

    /* IncrementalProblem (increment.cc) */
    void
    begin_increment(const double time, const Vector *predictor) override;
    Residual
    assemble(const bool with_matrix, const bool first_iteration) override;
    TrilinosWrappers::SparseMatrix &
    system_matrix() override
    {
      return matrix;
    }
    Vector &
    system_rhs() override
    {
      return rhs;
    }
    unsigned long
    pattern_version() const override
    {
      return sparsity_version;
    }
    void
    distribute(Vector &update, const bool first_iteration) const override;
    Vector &
    solution() override
    {
      return owned_solution;
    }
    void
    solution_changed() override;
    Norms
    norms(const Vector &v) const override;
    Norms
    change_scale() const override;
    Norms
    round_off_floor() const override
    {
      return {0, traction_floor};
    }
    double
    stagnation_residual_bound() const override
    {
      return stagnation_bound;
    }
    void
    after_assembly(const unsigned int iteration,
                   const double       residual) override;
    Verdict
    at_convergence(IncrementReport &report) override;
    double
    tangent_error() override;
    void
    log_iteration(const unsigned int iteration,
                  const double       residual,
                  const double       relative_residual,
                  const double       update_norm,
                  const double       step_length,
                  const double       order) override;
    void
    message(const std::string &text) override;
    void
    begin_attempt(const unsigned int step,
                  const unsigned int increment) override
    {
      current_step      = step;
      current_increment = increment;
    }
    void
    commit(const double time) override;
    void
    restore() override;
    bool
    outer_update(IncrementReport &report) override;
    void
    write_increment(const unsigned int     step,
                    const unsigned int     increment,
                    const double           time,
                    const IncrementReport &report,
                    const unsigned int     n_cutbacks,
                    const double           wall_time) override;
    std::string
    step_status() const override;
    void
    end_step(const unsigned int step, const double time) override;
    void
    failed(const std::string &message) override;

  private:
    /* setup.cc */
    void
    make_grid();
    /** Parallel/Mesh = distributed: the scene built on the first process,
     * partitioned, and this process's part of it. */
    void
    create_distributed_scene();
    void
    setup_system();
    void
    setup_materials();
    void
    make_sparsity();
    void
    make_constraints(const double               time,
                     const bool                 homogeneous,
                     AffineConstraints<double> &constraints) const;

    /* assembly.cc */
    /**
     * Assemble at the current iterate (ghosted_solution): the tangent
     * matrix and right-hand side -R with @p constraints if @p with_matrix,
     * and always the free residual (homogeneous constraints) into
     * free_residual and the unconstrained R = f_int - f_ext into
     * full_residual. Returns the l2 norm of the free residual.
     */
    double
    assemble_system(const bool                       with_matrix,
                    const AffineConstraints<double> &constraints,
                    const double                     time);

    /* increment.cc */
    /**
     * The stabilization springs at the last assembly: the largest magnitude
     * of their resultant on one body, and its ratio to the load (the
     * largest magnitude of the applied force resultant and of each
     * Dirichlet condition's reaction resultant). Axisymmetric: axial
     * components only.
     */
    std::pair<double, double>
    stabilization_measure() const;

    /**
     * The displacement with ghost entries: the solution itself, or (with
     * multipliers, whose unknowns follow the dofs) its first n_dofs
     * entries, for the finite element evaluations and the output.
     */
    const Vector &
    ghosted_displacement() const
    {
      return n_multipliers == 0 ? ghosted_solution : displacement;
    }

    /* run.cc */
    /** The rigid-body modes (translations, rotations about the centroid)
     * at the locally owned rows, the near-null space of AMG. */
    std::vector<std::vector<double>>
    rigid_body_modes() const;

    /* dynamics.cc */
    /** Dynamics: the integrator, the state vectors, the densities, the
     * massless contact dofs, the initial velocity and acceleration. */
    void
    setup_dynamics();
    /**
     * The mass matrix of @p cell (ring factor included) into @p mass, at
     * the @p fe_values reinitialized on it: consistent, or lumped (row sums)
     * with the mass of the massless dofs moved to the cell's others.
     */
    void
    cell_mass_matrix(const FEValues<dim>                        &fe_values,
                     const std::vector<types::global_dof_index> &dof_indices,
                     const std::vector<unsigned int>            &component,
                     const double                                density,
                     FullMatrix<double>                         &mass,
                     const bool remove_contact_mass = true) const;
    /** Call @p f with the dofs and the mass matrix of every locally owned
     * cell (the contact mass removed or not). */
    void
    for_each_cell_mass(
      const bool remove_contact_mass,
      const std::function<void(const std::vector<types::global_dof_index> &,
                               const FullMatrix<double> &)> &f) const;
    /** M a_0 = f_ext - f_int - f_contact at t = 0 (if that is not zero). */
    void
    compute_initial_acceleration();
    /** The end-of-step velocity and acceleration, the old forces and the
     * energies of a converged increment. */
    void
    commit_dynamics();
    /** Kinetic and stored strain energy and the linear momentum of the
     * converged state. */
    struct Energies
    {
      double         kinetic = 0, stored = 0;
      Tensor<1, dim> momentum;
    };
    Energies
    energies() const;

    /* restart.cc */
    /** Write the converged state after nominal @p step into @p directory,
     * by default <Output/Directory>/checkpoint-NNNNN (Output/Checkpoint
     * every). */
    void
    write_checkpoint(const unsigned int step,
                     const std::string &directory = "");
    /** Whether the checkpoint fits this run (mesh, dofs, pairs, integrator,
     * steps): a clear error before any output is touched. */
    void
    check_checkpoint() const;
    /** Read the checkpoint of parameters.restart_directory into the state
     * of this (set up) problem; returns where the stepping stands. */
    StepperState
    read_checkpoint();
    /** The values of @p v (dof-sized, owned) per active cell, gathered on
     * rank 0 in CellId order (the cells' CellIds into @p cells if given). */
    std::vector<double>
    cell_values(const Vector                         &v,
                std::vector<std::array<unsigned, 4>> *cells = nullptr) const;
    /** Set the owned entries of @p v (dof-sized or the system vector) from
     * cell_values(). */
    void
    set_from_cell_values(const std::vector<double> &values, Vector &v) const;
    /** The checkpoint a restart goes on from (read before the output is
     * opened: it says which rows and files of the earlier run to keep). */
    std::unique_ptr<Checkpoint> restart;

    /* material_points.cc */
    /** What for_each_material_point() calls: the cell, its FEValues, the
     * quadrature point, the deformation gradient the material sees (F, or
     * in an axisymmetric model F3 with the hoop stretch, F then being the
     * in-plane part) and the converged history. */
    using MaterialPointFunction = std::function<
      void(const typename DoFHandler<dim>::active_cell_iterator &cell,
           const FEValues<dim>                                  &fe_values,
           const unsigned int                                    q,
           const Tensor<2, dim>                                 &F,
           const Tensor<2, 3>                                   &F3,
           const double                                         *history)>;
    /**
     * Call @p f at every quadrature point of every locally owned cell at
     * the converged displacement and history, with the deformation
     * gradient its material sees (F-bar scaled where F-bar is on).
     */
    void
    for_each_material_point(const MaterialPointFunction &f) const;

    /* output.cc */
    void
    open_output();
    std::vector<double>
    reaction_forces() const;
    void
    write_vtu(const unsigned int step, const double time);

    void
    write_summary(const std::string &status);
    std::pair<double, double>
    displacement_errors(const double time) const;

    const Parameters::AllParameters &parameters;
    MPI_Comm                         mpi_communicator;
    ConditionalOStream               pcout;
    /**
     * This process's own section times (summary.txt shows the first
     * process's). On the whole communicator every section's end would be a
     * collective step, also while an exception raised on one process only
     * unwinds, and the run would hang there instead of ending.
     */
    TimerOutput timer;

    /** The mesh: parallel::shared or parallel::fullydistributed
     * (Parallel/Mesh). */
    std::unique_ptr<parallel::TriangulationBase<dim>> triangulation_storage;
    parallel::TriangulationBase<dim>                 &triangulation;
    std::unique_ptr<FESystem<dim>>                    fe;
    DoFHandler<dim>                                   dof_handler;
    QGauss<dim>                                       quadrature;
    QGauss<dim - 1>                                   face_quadrature;

    IndexSet locally_owned_dofs;
    /** The dofs the ghosted vectors hold: those of the own and ghost
     * cells, and the slave nodes this process reads
     * (ContactHandler::ghost_dofs(); a shared mesh: every contact dof). */
    IndexSet locally_relevant_dofs;
    /** The dofs the constraints and the sparsity pattern know: the
     * relevant ones and every contact dof (contact writes rows and columns
     * of master dofs anywhere). */
    IndexSet coupled_dofs;
    /** Every process's locally owned dofs. */
    std::vector<IndexSet> owned_per_process;
    /** Dofs ghosted on this process only because of contact (slave nodes
     * beyond its cells): the contact's share of every ghost update. */
    types::global_dof_index n_contact_ghosts = 0;
    /**
     * The unknowns of the linear system: the displacement dofs followed by
     * the contact Lagrange multipliers (none unless a pair uses them). The
     * matrix, right-hand side, residuals and Newton update live on these;
     * the displacement (solution) lives on the dofs alone, the multipliers
     * in the contact handler.
     */
    IndexSet system_owned;
    IndexSet system_relevant;
    /** coupled_dofs and the multipliers. */
    IndexSet                system_coupled;
    types::global_dof_index n_multipliers = 0;

    AffineConstraints<double> homogeneous_constraints;

    TrilinosWrappers::SparseMatrix matrix;
    /** Counts the rebuilds of the matrix's sparsity pattern. */
    unsigned long sparsity_version = 0;
    Vector        rhs;
    Vector        free_residual;
    Vector        full_residual;
    /** The contact forces on the nodes at the last assembly (VTU). */
    Vector contact_forces;
    /** The unknowns: displacement dofs, then the contact multipliers. */
    Vector owned_solution;
    Vector ghosted_solution;
    /** The displacement part, with ghosts (only with multipliers). */
    Vector displacement;
    /** The solution at the start of the increment. */
    Vector increment_start;
    /** A restart's change of the unknowns over its last increment (the
     * load stepper's extrapolation goes on from it). */
    Vector restart_change;
    /** The stabilization springs' anchors: the solution at the start of
     * the increment, moved on at every re-anchoring. */
    Vector ghosted_anchors;
    /** The current increment: its nominal step and number (logs), end
     * time and constraints. */
    unsigned int              current_step      = 0;
    unsigned int              current_increment = 0;
    double                    time              = 0;
    AffineConstraints<double> increment_constraints;
    /** Re-anchorings of the stabilization springs in this increment. */
    unsigned int n_relaxations = 0;
    /** The stabilization forces of the last assembly. */
    Vector stabilization_forces;
    /** The applied (traction and body) forces of the last assembly, kept
     * only with stabilization. */
    Vector external_forces;
    /** Vector component and body of every dof (by global dof number). */
    std::vector<unsigned char>      dof_component;
    std::vector<types::material_id> dof_body;
    /** The bodies (material ids) of the whole mesh, and their number. */
    std::set<types::material_id> body_ids;
    unsigned int                 n_bodies = 0;
    /**
     * Newton's round-off stagnation is accepted only below this residual:
     * 1e-10 E_max A, the force of a stress of 1e-10 times the largest
     * Young's modulus on the area scale A = V^((d-1)/d) of the model
     * (axisymmetric: V with the ring factor, A = V^(2/3)).
     */
    double stagnation_bound = 0;
    /** Tractions below 1e-12 E_max are round-off: the floor of the
     * multipliers' convergence test. */
    double traction_floor = 0;
    /** Warnings for the user, printed when found and listed in
     * summary.txt. */
    std::vector<std::string> warnings;
    void
    warn(const std::string &message);

    /** The contact pairs and their output; null when the scene has none. */
    std::unique_ptr<ContactHandler<dim>> contact;
    std::unique_ptr<ContactOutput<dim>>  contact_output;

    /** One material per body id (index = material_id). */
    std::vector<std::unique_ptr<Material<dim>>> materials;
    /**
     * Axisymmetric models: the same materials in 3D, evaluated at the
     * deformation gradient with the hoop stretch (empty otherwise).
     */
    std::vector<std::unique_ptr<Material<3>>> axisymmetric_materials;

    /** Number of history values per quadrature point of body @p body. */
    unsigned int
    n_history_variables(const types::material_id body) const
    {
      return axisymmetric_materials.empty() ?
               materials[body]->n_history_variables() :
               axisymmetric_materials[body]->n_history_variables();
    }

    /**
     * History storage, only for cells of bodies whose material has memory:
     * offset of a cell's first quadrature point (by active cell index) into
     * the flat arrays, or invalid for cells without history.
     */
    std::vector<unsigned int> history_offset;
    std::vector<double>       history_old;
    std::vector<double>       history_new;

    std::vector<std::unique_ptr<FunctionParser<dim>>> dirichlet_functions;
    std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>>
                                         neumann_functions;
    std::unique_ptr<FunctionParser<dim>> body_force;
    std::unique_ptr<FunctionParser<dim>> exact_displacement;

    /** Per probe point: the dofs of the nearest vertex. */
    std::vector<std::array<types::global_dof_index, dim>> probe_dofs;

    /** Per Dirichlet condition: all dofs on its boundary, per component. */
    std::vector<std::vector<IndexSet>> reaction_dofs;

    std::unique_ptr<CsvWriter>                  history_csv;
    std::unique_ptr<CsvWriter>                  convergence_csv;
    std::vector<std::pair<double, std::string>> pvd_records;

    /**
     * Dynamics (null integrator: quasi-static). Velocity and acceleration of
     * the displacement dofs at the last converged time, the displacement
     * there (ghosted), and the static forces R = f_int - f_contact - f_ext
     * there (the alpha_f part of the generalized-alpha balance).
     */
    std::unique_ptr<TimeIntegrator> integrator;
    /** Assemble the inertia terms (false while computing a_0). */
    bool   with_inertia   = true;
    double committed_time = 0;
    Vector velocity, acceleration;
    Vector ghosted_velocity, ghosted_acceleration, ghosted_start;
    Vector old_forces;
    /** M a_{n+1} of the last assembly (unconstrained): part of the
     * reactions and of the force scale. */
    Vector inertia_forces;
    /** The contact and external (applied plus Dirichlet reaction) forces
     * at the last converged time, for the trapezoidal work sums. */
    Vector old_contact_forces, old_external;
    /** Density per body id. */
    std::vector<double> densities;
    /** Dofs whose lumped mass is moved away (Contact mass removal): the
     * candidates (a cell whose every node is one keeps its mass), and those
     * whose assembled mass is zero (their rows are quasi-static). */
    IndexSet massless_dofs;
    IndexSet massless_rows;
    /** The constrained components of the Dirichlet conditions: their
     * motion is prescribed, and their reactions do work. */
    IndexSet dirichlet_dofs;
    /** Energies of the last converged state: kinetic, stored, the work of
     * the internal forces, the work absorbed by contact, the friction
     * dissipation and the work of the applied loads and Dirichlet
     * reactions (sums since t = 0), and the initial kinetic energy. */
    Tensor<1, dim> momentum;
    double         kinetic_energy = 0, strain_energy = 0, internal_work = 0,
           contact_work = 0, friction_work = 0, external_work = 0,
           initial_kinetic_energy = 0;
    /** The internal forces f_int at the last converged time. */
    Vector old_internal;

    /** This process's own time in the bulk assembly, without waiting for
     * the others (the load balance in summary.txt; the contact's is
     * ContactHandler::own_time()). */
    double own_assembly_time = 0;
    /** Parallel/Rebalance threshold: the rebalance this run goes on from
     * (count 0: none), whether it may rebalance, and the own times and the
     * wall clock at the last step's end. */
    Rebalance     last_rebalance;
    bool          may_rebalance        = true;
    double        contact_time_at_step = 0, assembly_time_at_step = 0;
    dealii::Timer step_clock, run_clock;
    /** At the end of a step: throws Rebalance if the contact work is out of
     * balance (collective). */
    void
    check_balance(const unsigned int step);

    /** The solvers (built by run()). */
    std::unique_ptr<LinearSolver> linear_solver;
    std::unique_ptr<NewtonSolver> newton;
    std::unique_ptr<LoadStepper>  stepper;
  };
} // namespace tribos

#endif
