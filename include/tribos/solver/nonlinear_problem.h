#ifndef tribos_solver_nonlinear_problem_h
#define tribos_solver_nonlinear_problem_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>

namespace tribos
{
  using namespace dealii;

  /**
   * What the solvers count of one converged increment, reported and written
   * to CSV. Only the solvers' own counts: what a problem's policies count
   * (contact, stabilization) the problem keeps and the observer reads from
   * it.
   */
  struct IncrementReport
  {
    /** Newton iterations of the accepted solve(s). */
    unsigned int n_iterations = 0;
    /** Newton iterations of every attempt at this increment, the failed
     * ones that were cut back included (= linear solves). */
    unsigned int n_iterations_all = 0;
    double       residual         = 0;
  };



  /**
   * What Newton's method needs of a problem, and nothing of what the problem
   * is: assemble the residual and tangent at the current iterate, apply the
   * constraints to an update, measure the unknowns, and the hooks through
   * which a problem's own policies act (contact chattering, stabilization,
   * acceptance checks). The unknowns are one distributed vector that may
   * hold two kinds (displacements and contact multipliers, whose units
   * differ): norms are returned per kind.
   *
   * The interface follows the shape of ExaDG's Newton::Solver and dolfinx's
   * NewtonSolver: the solver owns the iteration, the problem the physics.
   */
  class NonlinearProblem
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** Residual norms of one assembly. */
    struct Residual
    {
      /** l2 norm of the residual with the constrained rows removed. */
      double free = 0;
      /** l2 norm of the unconstrained residual f_int - f_ext (essentially
       * the reactions): the force scale of the relative test. */
      double force_scale = 0;
    };

    /** A norm per kind of unknown. */
    struct Norms
    {
      double displacement = 0;
      double multipliers  = 0;
    };

    /** What the problem says at an iterate that passed Newton's tests. */
    enum class Verdict
    {
      /** The increment is converged. */
      accept,
      /** Not yet (e.g. the stabilization springs were re-anchored): go on
       * iterating, with a fresh iteration budget. */
      iterate
    };

    virtual ~NonlinearProblem() = default;

    /**
     * Start solving the increment that ends at @p time from the current
     * solution: remember it as the increment's start, add @p predictor to
     * the solution (if given: the first iterate's guess of the change),
     * and prepare the increment's (inhomogeneous) constraints, which then
     * take the solution to the increment's Dirichlet values from the
     * predicted state.
     */
    virtual void
    begin_increment(const double time, const Vector *predictor) = 0;

    /**
     * Assemble at the current iterate: the residual always, the tangent and
     * right-hand side (-R) if @p with_matrix; with the increment's
     * constraints on the @p first_iteration (which carries the Dirichlet
     * increment), else with homogeneous ones. May throw NonConvergence (a
     * void iterate, e.g. an inverted element).
     */
    virtual Residual
    assemble(const bool with_matrix, const bool first_iteration) = 0;

    virtual TrilinosWrappers::SparseMatrix &
    system_matrix() = 0;

    virtual Vector &
    system_rhs() = 0;

    /** Changes whenever the system matrix's sparsity pattern does (a
     * direct solver keeps its symbolic factorization while it does not). */
    virtual unsigned long
    pattern_version() const = 0;

    /** Set the constrained entries of a Newton @p update. */
    virtual void
    distribute(Vector &update, const bool first_iteration) const = 0;

    /**
     * The longest step in (0, 1] the problem allows along @p update
     * (distributed) from the current solution (contact: no node carried
     * far through a surface); 1 by default. May evaluate the problem at
     * trial points, but leaves its state as it was.
     */
    virtual double
    step_limit(const Vector & /*update*/, const bool /*first_iteration*/)
    {
      return 1;
    }

    /** The unknowns (locally owned entries). */
    virtual Vector &
    solution() = 0;

    /** Call after every change of solution(): refreshes ghost values. */
    virtual void
    solution_changed() = 0;

    /** Norms of @p v per kind of unknown. */
    virtual Norms
    norms(const Vector &v) const = 0;

    /**
     * The scale of the unknowns for the update test, per kind: the larger
     * of the change since the start of the increment and the size.
     */
    virtual Norms
    change_scale() const = 0;

    /**
     * Absolute floors below which a norm of the unknowns is round-off (per
     * kind; the displacements': of the positions), and the residual below
     * which round-off stagnation may be accepted.
     */
    virtual Norms
    round_off_floor() const = 0;

    virtual double
    stagnation_residual_bound() const = 0;

    /**
     * The round-off level of the free residual, below which no iterate's
     * goes: the problem's estimate from its last tangent (0: none).
     * Collective; asked only of an iterate whose correction is round-off.
     * Contact evaluates gaps as differences of positions, so a stiff
     * penalty's rows carry eps |x| times their stiffness, far above eps
     * times the forces, and they set it (C3D20 with mortar at 1000 E/h:
     * 1.2e-7, above the relative tolerance's 5e-8).
     */
    virtual double
    residual_round_off() const
    {
      return 0;
    }

    /** Called after every assembly with a matrix (e.g. chattering
     * detection), with the free residual's norm; may throw
     * NonConvergence. */
    virtual void
    after_assembly(const unsigned int /*iteration*/, const double /*residual*/)
    {
    }

    /**
     * Called at an iterate that passed Newton's tests. The problem may
     * accept it, throw NonConvergence, or ask for more iterations.
     */
    virtual Verdict
    at_convergence()
    {
      return Verdict::accept;
    }

    /** Relative error of the tangent against finite differences of the
     * residual at the current iterate (Nonlinear solver/Check tangent). */
    virtual double
    tangent_error() = 0;
  };
} // namespace tribos

#endif
