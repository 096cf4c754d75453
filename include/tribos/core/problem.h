#ifndef tribos_core_problem_h
#define tribos_core_problem_h

#include <tribos/contact/contact_handler.h>
#include <tribos/core/algebraic_system.h>
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
   * accessors, run/Simulation drives it, Checkpointer writes and reads its
   * state (State). The implementation is split over source/core/:
   * problem_setup.cc, problem_increment.cc (the solver hooks).
   */
  template <int dim>
  class Problem : public AlgebraicSystem
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
     * @p timer gets the sections setup, assembly, contact search and
     * contact assembly; @p log prints a line for the user
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
     * dynamics. A SIGTERM or SIGINT noted meanwhile throws Interrupted
     * after the stage it arrived in (Interruption::check(); not a
     * rebalanced run's, which has written its steps).
     */
    void
    setup(const CellWeights *weights = nullptr);

    /* IncrementalProblem: the physics (problem_increment.cc; the algebra is
     * AlgebraicSystem's) */
    void
    begin_increment(const double time, const Vector *predictor) override;
    Residual
    assemble(const bool with_matrix, const bool first_iteration) override;
    double
    step_limit(const Vector &update, const bool first_iteration) override;
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
    ContactChanges
    contact_changes() const override;


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

    /**
     * Adaptivity: the error indicator of the current state (per active
     * cell, error_indicator()), kept for the output. Collective.
     */
    const dealii::Vector<float> &
    estimate_error();
    /** The last estimate_error() (empty before one). */
    const dealii::Vector<float> &
    error_indicator() const
    {
      return indicator;
    }
    /** Adaptivity: flag the cells by the last estimate_error()
     * (Model::mark()); true if some cell is flagged. Collective. */
    bool
    mark_cells();
    /**
     * Adaptivity: refine and coarsen the flagged cells and carry the state
     * over: the solution, which must be the committed one at @p time, and
     * the converged plastic history. The contact pairs are built again on
     * the new surfaces, their node states carried over by reference
     * position (ContactHandler::carry_over()), the multipliers with them;
     * the nodes are paired again from the geometry. @p change, if given
     * (the last increment's change of the unknowns, which the stepper
     * extrapolates from), is carried over too: its dof part interpolated
     * like the displacement, its multipliers' part zero. Collective.
     */
    void
    adapt(const double time, Vector *change = nullptr);

    /**
     * Adaptivity on restart: the mesh refined to a checkpoint's active
     * @p cells (Model::refine_to()) and everything on it set up again, the
     * state left for Checkpointer::read(). Collective.
     */
    void
    refine_to(const std::vector<std::array<unsigned int, 4>> &cells);

    /** What a restart sets (Checkpointer::read()); what a change of the
     * mesh will carry over. */
    struct State
    {
      MaterialState<dim>  &materials;
      ContactHandler<dim> *contact;
      DynamicsState<dim>  *dynamics;
      Stabilization<dim>  &stabilization;
      /** The ghosted unknowns (current after solution_changed()). */
      const Vector &ghosted_unknowns;
      /** The end time of the last committed increment. */
      double &time;
    };
    State
    state();

  private:
    /* problem_setup.cc */
    void
    setup_system();
    /** The materials, bulk terms, contact, unknowns, sparsity and vectors
     * on the Model's dofs (after distribute_dofs(), or an adaptation). */
    void
    setup_physics();
    /** What the contact adds to the unknowns (its ghosts, dofs and
     * multipliers), for Model::set_unknowns(). */
    ContactUnknowns
    contact_unknowns() const;
    /** The vectors of the system, the round-off scales and the springs. */
    void
    setup_vectors();
    void
    setup_dynamics();
    void
    make_sparsity();

    /* problem_increment.cc */
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


    const Parameters::AllParameters &parameters;
    /** The discretization (Simulation owns it). */
    Model<dim>                                    &model;
    TimerOutput                                   &timer;
    const std::function<void(const std::string &)> log;
    Warnings                                      &warnings;

    /** The current increment's end time. */
    double time = 0;
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
    /** The last error indicator (Adaptivity). */
    dealii::Vector<float> indicator;
    /** The last estimate's contact zones (contact_zone(); empty without
     * Contact zone depth). */
    ContactZone<dim> zone;
  };
} // namespace tribos

#endif
