#ifndef tribos_core_problem_h
#define tribos_core_problem_h

#include <tribos/contact/contact_handler.h>
#include <tribos/core/bulk_assembler.h>
#include <tribos/core/checkpoint.h>
#include <tribos/core/create_mesh.h>
#include <tribos/core/dynamics_state.h>
#include <tribos/core/material_state.h>
#include <tribos/core/model.h>
#include <tribos/core/reference_geometry.h>
#include <tribos/core/stabilization.h>
#include <tribos/core/warnings.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/scene/scene.h>
#include <tribos/solver/linear_solver.h>
#include <tribos/solver/load_stepper.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The boundary value problem of all bodies of a scene, quasi-static or
   * dynamic, on a Model's discretization: total Lagrangian displacement
   * formulation, Trilinos distributed linear algebra. The unknowns are the
   * displacement dofs followed by the contact multipliers (if a pair uses
   * them), in one vector (UnknownsLayout).
   *
   * Problem couples the parts for the solver: the Model (mesh, dofs,
   * constraints; Simulation owns it), the materials and their history
   * (MaterialState), the bulk terms (BulkAssembler), the contact
   * (ContactHandler), the dynamics (DynamicsState) and the stabilization
   * springs (Stabilization). It holds the system's vectors and matrix and
   * is the IncrementalProblem the generic solvers of solver/ drive. It
   * writes no output: postprocess/ reads it and the Model through const
   * accessors, run/Simulation drives it. The implementation is split over
   * source/core/: setup.cc, increment.cc (the solver hooks), restart.cc
   * (checkpoints).
   */
  template <int dim>
  class Problem : public IncrementalProblem
  {
  public:
    /** What history.csv reports of the contact's policies in a converged
     * increment (its attempt's solves together). */
    struct ContactCounters
    {
      /** Outer (Uzawa) updates of the augmented Lagrangian. */
      unsigned int n_augmentations = 0;
      /** Most chattering slave nodes seen in an iteration. */
      unsigned int n_chattering = 0;
    };

    /**
     * @p timer gets the sections setup, assembly, contact search, contact
     * assembly and output (checkpoints); @p log prints a line for the user
     * (the first process's); @p warnings gets the warnings about the model.
     */
    Problem(const Parameters::AllParameters                &parameters,
            Model<dim>                                     &model,
            TimerOutput                                    &timer,
            const std::function<void(const std::string &)> &log,
            Warnings                                       &warnings);

    /**
     * Build the scene (partitioned with @p weights, per CellId, if given:
     * a rebalanced run), the dofs, constraints, materials, contact and
     * dynamics.
     */
    void
    setup(const CellWeights *weights = nullptr);

    /** The linear solver that holds on to the system matrix (released
     * before the matrix is rebuilt). */
    void
    attach(LinearSolver &solver)
    {
      linear_solver = &solver;
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
    double
    step_limit(const Vector &update, const bool first_iteration) override;
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
      return {length_floor, traction_floor};
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
    at_convergence() override;
    double
    tangent_error() override;
    void
    commit(const double time) override;
    void
    restore() override;
    bool
    outer_update() override;

    /* Checkpoints (restart.cc) */
    /**
     * The converged state after nominal step @p stepper.step (the stepper's
     * state, the change of its last increment @p change, the VTU series
     * @p pvd_records) into @p directory.
     */
    void
    write_checkpoint(
      const StepperState                                &stepper,
      const Vector                                      &change,
      const std::vector<std::pair<double, std::string>> &pvd_records,
      const std::string                                 &directory);
    /** Whether @p checkpoint fits this run (mesh, dofs, pairs, integrator,
     * steps): a clear error before any output is touched. */
    void
    check_checkpoint(const Checkpoint &checkpoint) const;
    /** What a checkpoint's state depends on beyond the sizes of the
     * mesh and dofs, by name (scene, pairs, materials), as text. */
    std::map<std::string, std::string>
    fingerprint() const;
    /** Moments of the vertex coordinates of the mesh (collective). */
    std::map<std::string, double>
    geometry_moments() const;
    /** Read @p checkpoint into the state of this (set up) problem. */
    void
    read_checkpoint(const Checkpoint &checkpoint);
    /** A restart's change of the unknowns over its last increment (the
     * load stepper's extrapolation goes on from it). */
    const Vector &
    restart_change() const
    {
      return change_of_restart;
    }

    /**
     * The displacement with ghost entries: the solution itself, or (with
     * multipliers, whose unknowns follow the dofs) its first n_dofs
     * entries, for the finite element evaluations and the output.
     */
    const Vector &
    displacement() const
    {
      return layout.n_multipliers == 0 ? ghosted_solution :
                                         ghosted_displacement;
    }
    /** The unknowns (owned entries). */
    const Vector &
    unknowns() const
    {
      return owned_solution;
    }
    /** The contact forces on the nodes at the last assembly. */
    const Vector &
    contact_forces() const
    {
      return contact_force_vector;
    }
    /** The contact; null if the scene has none. */
    const ContactHandler<dim> *
    contact() const
    {
      return contact_handler.get();
    }
    ContactHandler<dim> *
    contact()
    {
      return contact_handler.get();
    }
    /** The dynamics; null if quasi-static. */
    const DynamicsState<dim> *
    dynamics() const
    {
      return dynamics_state.get();
    }
    const MaterialState<dim> &
    materials() const
    {
      return *material_state;
    }
    const BulkAssembler<dim> &
    bulk() const
    {
      return *bulk_assembler;
    }
    /** The stabilization springs (their report of the last increment). */
    const Stabilization<dim> &
    stabilization() const
    {
      return stabilization_springs;
    }
    /** The contact's counters of the last committed increment. */
    const ContactCounters &
    contact_counters() const
    {
      return committed_counters;
    }
    /** Per Dirichlet condition and component, the reaction force (the
     * residual's sum over its dofs; in dynamics with M a) at the last
     * assembly (collective). */
    std::vector<double>
    reaction_forces() const;

  private:
    /* setup.cc */
    /** The mesh (create_mesh()), in the setup timer section. */
    void
    make_grid(const CellWeights *weights);
    void
    setup_system();
    /** What the contact adds to the unknowns (its ghosts, dofs and
     * multipliers), into extra_unknowns. */
    const ContactUnknowns &
    contact_unknowns();
    /** The vectors of the system and the round-off floors. */
    void
    setup_vectors();
    void
    setup_dynamics();
    void
    make_sparsity();

    /* increment.cc */
    /**
     * Assemble at the current iterate: the tangent matrix and right-hand
     * side -R with @p constraints if @p with_matrix, and always the free
     * residual (homogeneous constraints) into free_residual and the
     * unconstrained R = f_int - f_ext into full_residual. Returns the l2
     * norm of the free residual.
     */
    double
    assemble_system(const bool                       with_matrix,
                    const AffineConstraints<double> &constraints,
                    const double                     time);

    /* restart.cc */
    /** The values of @p v (dof-sized, owned) per active cell, gathered on
     * rank 0 in CellId order (the cells' CellIds into @p cells if given). */
    std::vector<double>
    cell_values(const Vector                         &v,
                std::vector<std::array<unsigned, 4>> *cells = nullptr) const;
    /** Set the owned entries of @p v (dof-sized or the system vector) from
     * cell_values() of the cells @p cells of a checkpoint. */
    void
    set_from_cell_values(const std::vector<std::array<unsigned, 4>> &cells,
                         const std::vector<double>                  &values,
                         Vector                                     &v) const;

    const Parameters::AllParameters &parameters;
    /** The discretization (Simulation owns it), its unknowns' layout and
     * its homogeneous constraints. */
    Model<dim>                                    &model;
    const UnknownsLayout                          &layout;
    const AffineConstraints<double>               &homogeneous_constraints;
    MPI_Comm                                       mpi_communicator;
    TimerOutput                                   &timer;
    const std::function<void(const std::string &)> log;
    Warnings                                      &warnings;

    TrilinosWrappers::SparseMatrix matrix;
    /** Counts the rebuilds of the matrix's sparsity pattern. */
    unsigned long sparsity_version = 0;
    Vector        rhs;
    Vector        free_residual;
    Vector        full_residual;
    /** The contact forces on the nodes at the last assembly (VTU). */
    Vector contact_force_vector;
    /** The unknowns: displacement dofs, then the contact multipliers. */
    Vector owned_solution;
    Vector ghosted_solution;
    /** The displacement part, with ghosts (only with multipliers). */
    Vector ghosted_displacement;
    /** The solution at the start of the increment. */
    Vector increment_start;
    /** See restart_change(). */
    Vector change_of_restart;
    /** What the contact adds to the Model's unknowns. */
    ContactUnknowns extra_unknowns;
    /** The current increment's end time and constraints. */
    double                    time = 0;
    AffineConstraints<double> increment_constraints;
    /** The applied (traction and body) forces of the last assembly, kept
     * with stabilization and dynamics. */
    Vector external_forces;
    /**
     * Newton's round-off stagnation is accepted only below this residual:
     * 1e-10 E_max A, the force of a stress of 1e-10 times the largest
     * Young's modulus on the area scale A = V^((d-1)/d) of the model
     * (axisymmetric: V with the ring factor, A = V^(2/3)).
     */
    double stagnation_bound = 0;
    /** Displacement corrections below this are round-off (1e-14 of the
     * model's length scale): the update test's floor, without which an
     * increment that moves nothing (End time 1e-300) never converged. */
    double length_floor = 0;
    /** Tractions below 1e-12 E_max are round-off: the floor of the
     * multipliers' convergence test. */
    double traction_floor = 0;
    /** The springs (they read the Model's dof maps). */
    Stabilization<dim> stabilization_springs;
    /** The contact's counters of this attempt and of the last committed
     * increment. */
    ContactCounters counters, committed_counters;

    std::unique_ptr<MaterialState<dim>> material_state;
    std::unique_ptr<BulkAssembler<dim>> bulk_assembler;
    /** The contact pairs; null when the scene has none. */
    std::unique_ptr<ContactHandler<dim>> contact_handler;
    /** Dynamics (null: quasi-static). */
    std::unique_ptr<DynamicsState<dim>> dynamics_state;

    /** The solver holding the matrix (attach()). */
    LinearSolver *linear_solver = nullptr;
  };
} // namespace tribos

#endif
