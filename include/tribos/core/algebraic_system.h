#ifndef tribos_core_algebraic_system_h
#define tribos_core_algebraic_system_h

#include <tribos/core/unknowns_layout.h>
#include <tribos/solver/linear_solver.h>
#include <tribos/solver/load_stepper.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace tribos
{
  using namespace dealii;

  /**
   * The unknowns (dofs, then multipliers) and the linear system on an
   * UnknownsLayout: the vectors, the matrix and its sparsity pattern's
   * version, and the hooks of NonlinearProblem that are algebra only
   * (measure, constrain and refresh the unknowns). It knows no physics and
   * no dimension; Problem derives from it and fills the vectors by
   * assembly.
   */
  class AlgebraicSystem : public IncrementalProblem
  {
  public:
    /** Round-off scales of the model (Problem computes them from its
     * volume and largest Young's modulus). */
    struct Scales
    {
      /** Displacement corrections below this are round-off (1e-14 of the
       * model's length scale): the update test's floor, without which an
       * increment that moves nothing (End time 1e-300) never converged. */
      double length_floor = 0;
      /** Tractions below 1e-12 E_max are round-off: the floor of the
       * multipliers' convergence test. */
      double traction_floor = 0;
      /**
       * Newton's round-off stagnation is accepted only below this residual:
       * 1e-10 E_max A, the force of a stress of 1e-10 times the largest
       * Young's modulus on the area scale A = V^((d-1)/d) of the model
       * (axisymmetric: V with the ring factor, A = V^(2/3)).
       */
      double stagnation_bound = 0;
      /** The largest magnitude of a coordinate of the reference mesh: the
       * positions' scale for the residual's round-off
       * (residual_round_off()). */
      double position = 0;
    };

    /** The linear solver that holds on to the system matrix (released
     * before the matrix is rebuilt). */
    void
    attach(LinearSolver &solver);

    TrilinosWrappers::SparseMatrix &
    system_matrix() override;
    Vector &
    system_rhs() override;
    unsigned long
    pattern_version() const override;
    void
    distribute(Vector &update, const bool first_iteration) const override;
    Vector &
    solution() override;
    void
    solution_changed() override;
    Norms
    norms(const Vector &v) const override;
    Norms
    change_scale() const override;
    Norms
    round_off_floor() const override;
    double
    stagnation_residual_bound() const override;

    /**
     * The displacement with ghost entries: the solution itself, or (with
     * multipliers, whose unknowns follow the dofs) its first n_dofs
     * entries, for the finite element evaluations and the output.
     */
    const Vector &
    displacement() const;
    /** The unknowns (owned entries). */
    const Vector &
    unknowns() const;
    /** The contact forces on the nodes at the last assembly. */
    const Vector &
    contact_forces() const;

  protected:
    /** Binds the references only: @p layout and @p homogeneous are filled
     * later (Model::set_unknowns()). */
    AlgebraicSystem(const UnknownsLayout            &layout,
                    const AffineConstraints<double> &homogeneous,
                    const MPI_Comm                   mpi_communicator);

    /** The vectors on the layout, and the round-off @p scales
     * (collective). */
    void
    reinit(const Scales &scales);

    /**
     * The round-off level of the free residual assembled with the current
     * matrix (collective): eps |x| times the l2 norm, over the free rows,
     * of sum_j |A_ij| over the displacement columns, |x| the largest
     * position (Scales::position plus the largest displacement). A row's
     * terms that evaluate positions, as a contact gap x_s - x_m does, carry
     * eps |x| times their stiffness whatever the forces; the bulk's, from
     * displacement gradients, carry less, so this bounds the level rather
     * than matching it. Eps times the forces missed the contact's round-off
     * by orders of magnitude: a stiff penalty's gap of round-off size is
     * a force.
     */
    double
    residual_round_off() const override;

    /** The dof part (the first n_dofs entries) of the system vector
     * @p system into @p ghosted (a vector on the locally relevant dofs).
     * Collective. */
    void
    copy_dof_part(const Vector &system, Vector &ghosted) const;

    /** The matrix on the pattern @p dsp (the solver first lets go of the
     * old one); counts the new pattern. Collective. */
    void
    reinit_matrix(const DynamicSparsityPattern &dsp);

    const UnknownsLayout            &layout;
    const AffineConstraints<double> &homogeneous_constraints;
    MPI_Comm                         mpi_communicator;

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
    /** The applied (traction and body) forces of the last assembly, kept
     * with stabilization and dynamics. */
    Vector external_forces;
    /** The current increment's constraints (Dirichlet values). */
    AffineConstraints<double> increment_constraints;
    Scales                    scales;
    /** The solver holding the matrix (attach()). */
    LinearSolver *linear_solver = nullptr;
  };
} // namespace tribos

#endif
