#ifndef tribos_core_problem_h
#define tribos_core_problem_h

#include <tribos/contact/contact_handler.h>
#include <tribos/material/material.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/postprocess/csv_writer.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <map>
#include <memory>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /** Counters of one converged increment, reported and written to CSV. */
  struct IncrementReport
  {
    /** Newton iterations of the accepted solve(s). */
    unsigned int n_iterations = 0;
    /** Newton iterations of every attempt at this increment, the failed
     * ones that were cut back included (= linear solves). */
    unsigned int n_iterations_all = 0;
    double       residual         = 0;
    /** Uzawa multiplier updates (augmented Lagrangian). */
    unsigned int n_augmentations = 0;
    /** Most chattering slave nodes seen in an iteration. */
    unsigned int n_chattering = 0;
    /** Largest magnitude of the stabilization springs' resultant on one
     * body at convergence, and its ratio to the load. */
    double stabilization_force = 0;
    double stabilization_ratio = 0;
    /** Re-anchorings of the stabilization springs. */
    unsigned int n_relaxations = 0;
  };

  /**
   * The quasi-static boundary value problem of all bodies of a scene:
   * total Lagrangian displacement formulation, one DoFHandler over one
   * triangulation shared by all bodies, Trilinos distributed linear
   * algebra (parallel::shared::Triangulation, so every process sees the
   * whole geometry, which the contact search needs), Newton-Raphson with
   * line search per increment and load stepping with cutback.
   *
   * The implementation is split by responsibility over several files in
   * source/core/: setup, assembly, Newton, load stepping and output.
   */
  template <int dim>
  class Problem
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
      return ghosted_solution;
    }

  private:
    using Vector = TrilinosWrappers::MPI::Vector;

    /* setup.cc */
    void
    make_grid();
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
    void
    commit_history();

    /* assembly.cc */
    /**
     * Assemble at the current iterate (ghosted_solution): the tangent
     * matrix and right-hand side -R with @p constraints if @p with_matrix,
     * and always the free residual (homogeneous constraints) into
     * free_residual and the unconstrained R = f_int - f_ext into
     * full_residual. Returns the l2 norm of the free residual.
     */
    double
    assemble(const bool                       with_matrix,
             const AffineConstraints<double> &constraints,
             const double                     time);

    /* newton.cc */
    IncrementReport
    solve_increment(const double       time,
                    const unsigned int step,
                    const unsigned int increment);
    void
    solve_linear_system(Vector &newton_update);
    /** Add @p step times the system vector @p update to the displacement
     * and to the multipliers. */
    void
    apply_update(const Vector &update, const double step);
    /** l2 norm of the displacement part of a system vector. */
    double
    displacement_norm(const Vector &v) const;
    double
    tangent_error(const double time);
    /** l2 norm of the multiplier part of a system vector (0 if none). */
    double
    multiplier_norm(const Vector &v) const;
    /**
     * The stabilization springs at the last assembly: the largest magnitude
     * of their resultant on one body, and its ratio to the load (the
     * largest magnitude of the applied force resultant and of each
     * Dirichlet condition's reaction resultant). Axisymmetric: axial
     * components only.
     */
    std::pair<double, double>
    stabilization_measure() const;

    /* output.cc */
    void
    open_output();
    std::vector<double>
    reaction_forces() const;
    void
    write_history_row(const unsigned int     step,
                      const unsigned int     increment,
                      const double           time,
                      const IncrementReport &report,
                      const unsigned int     n_cutbacks,
                      const double           wall_time);
    void
    write_vtu(const unsigned int step, const double time);

    void
    write_summary(const std::string &status);
    std::pair<double, double>
    displacement_errors(const double time) const;

    const Parameters::AllParameters &parameters;
    MPI_Comm                         mpi_communicator;
    ConditionalOStream               pcout;
    TimerOutput                      timer;

    parallel::shared::Triangulation<dim> triangulation;
    std::unique_ptr<FESystem<dim>>       fe;
    DoFHandler<dim>                      dof_handler;
    QGauss<dim>                          quadrature;
    QGauss<dim - 1>                      face_quadrature;

    IndexSet locally_owned_dofs;
    IndexSet locally_relevant_dofs;
    /**
     * The unknowns of the linear system: the displacement dofs followed by
     * the contact Lagrange multipliers (none unless a pair uses them). The
     * matrix, right-hand side, residuals and Newton update live on these;
     * the displacement (solution) lives on the dofs alone, the multipliers
     * in the contact handler.
     */
    IndexSet                system_owned;
    IndexSet                system_relevant;
    types::global_dof_index n_multipliers = 0;

    AffineConstraints<double> homogeneous_constraints;

    TrilinosWrappers::SparseMatrix system_matrix;
    Vector                         system_rhs;
    Vector                         free_residual;
    Vector                         full_residual;
    /** The contact forces on the nodes at the last assembly (VTU). */
    Vector contact_forces;
    Vector solution;
    Vector ghosted_solution;
    /** Solution at the start of the increment (stabilization springs). */
    Vector ghosted_increment_start;
    /** The stabilization forces of the last assembly. */
    Vector stabilization_forces;
    /** The applied (traction and body) forces of the last assembly, kept
     * only with stabilization. */
    Vector external_forces;
    /** Vector component and body of every dof (by global dof number). */
    std::vector<unsigned char>      dof_component;
    std::vector<types::material_id> dof_body;
    /** Number of distinct bodies (material ids) of the mesh. */
    unsigned int n_bodies = 0;
    /**
     * Newton's round-off stagnation is accepted only below this residual:
     * 1e-10 E_max A, the force of a stress of 1e-10 times the largest
     * Young's modulus on the area scale A = V^((d-1)/d) of the model
     * (axisymmetric: V with the ring factor, A = V^(2/3)).
     */
    double stagnation_residual_bound = 0;
    /** Tractions below 1e-12 E_max are round-off: the floor of the
     * multipliers' convergence test. */
    double traction_floor = 0;
    /** Warnings for the user, printed when found and listed in
     * summary.txt. */
    std::vector<std::string> warnings;
    void
    warn(const std::string &message);

    /** The contact pairs; null when the scene has none. */
    std::unique_ptr<ContactHandler<dim>> contact;

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

    unsigned int n_total_newton_iterations = 0;
    /** Every Newton iteration (one linear solve each), failed attempts
     * included. */
    unsigned int n_linear_solves             = 0;
    unsigned int n_total_cutbacks            = 0;
    unsigned int n_converged_increments      = 0;
    double       largest_stabilization_ratio = 0;
  };
} // namespace tribos

#endif
