#ifndef tribos_core_stabilization_h
#define tribos_core_stabilization_h

#include <tribos/parameters/all_parameters.h>
#include <tribos/solver/nonlinear_problem.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_vector.h>

#include <set>
#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The stabilization springs (Nonlinear solver/Stabilization factor): a
   * spring per dof pulls the unknowns towards anchors, so that a body held
   * only by a contact that is still open has no singular rigid-body modes.
   * The anchors start at the converged state of each Newton solve; where the
   * springs still carry more than Stabilization limit of the load at
   * convergence, they are moved to the iterate and the solve goes on
   * (pseudo-transient continuation), at most Maximum stabilization
   * relaxations times.
   *
   * It owns the anchors and the springs' forces (the bulk assembly fills
   * them) and what history.csv and summary.txt report of them. An
   * increment's attempt accumulates a Record; commit() makes it the last
   * increment's, restore() drops it (a cutback), so that the report needs
   * no field of the generic solver's.
   */
  template <int dim>
  class Stabilization
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** What history.csv reports of a converged increment. */
    struct Record
    {
      /** Largest magnitude of the springs' resultant on one body at the
       * last convergence test, and its ratio to the load. */
      double force = 0;
      double ratio = 0;
      /** Re-anchorings in all solves of the increment. */
      unsigned int relaxations = 0;
    };

    /**
     * The dofs' component and body (by global dof number) and the owned
     * dofs are read at every measure, not copied: the vectors behind the
     * references are refilled by each setup.
     */
    Stabilization(const Parameters::AllParameters       &parameters,
                  const MPI_Comm                         communicator,
                  const IndexSet                        &owned_dofs,
                  const std::vector<unsigned char>      &dof_component,
                  const std::vector<types::material_id> &dof_body);

    /** Whether the springs are on (Stabilization factor > 0). */
    bool
    enabled() const;

    /** The anchors and forces on the system's unknowns, for the mesh's
     * bodies @p body_ids (the same on every process; collective). */
    void
    reinit(const IndexSet                     &system_owned,
           const IndexSet                     &system_relevant,
           const std::set<types::material_id> &body_ids);

    /** A Newton solve starts at @p ghosted_solution: the anchors are set
     * there, its re-anchorings counted from zero. */
    void
    begin_solve(const Vector &ghosted_solution);

    /** The anchors (ghosted) the springs pull towards. */
    const Vector &
    anchors() const;

    /** The springs' forces, the assembly's target; null if not enabled(). */
    Vector *
    forces();

    /**
     * At an iterate that passed Newton's tests: measure the springs against
     * the load (the applied forces @p external_forces and the Dirichlet
     * @p reactions, per condition and component); above the limit move the
     * anchors to @p ghosted_solution and ask for more iterations. Throws
     * NonConvergence when the re-anchorings are used up. Collective.
     */
    NonlinearProblem::Verdict
    at_convergence(const Vector              &ghosted_solution,
                   const Vector              &external_forces,
                   const std::vector<double> &reactions);

    /** The attempt's record becomes the last increment's. */
    void
    commit();

    /** Drop the attempt's record (the increment is cut back). */
    void
    restore();

    /** The record of the last committed increment. */
    const Record &
    last_increment() const;

    /** The largest ratio of every committed increment (summary.txt), a
     * restart's earlier ones included (set_largest_ratio()). */
    double
    largest_ratio() const;

    void
    set_largest_ratio(const double ratio);

  private:
    /**
     * The springs at the last assembly: the largest magnitude of their
     * resultant on one body, and its ratio to the load (the largest
     * magnitude of the applied force resultant and of each Dirichlet
     * condition's reaction resultant). Axisymmetric: axial components only.
     */
    std::pair<double, double>
    measure(const Vector              &external_forces,
            const std::vector<double> &reactions) const;

    const Parameters::AllParameters       &parameters;
    MPI_Comm                               communicator;
    const IndexSet                        &owned_dofs;
    const std::vector<unsigned char>      &dof_component;
    const std::vector<types::material_id> &dof_body;
    /** The mesh's body ids in ascending order: the resultants are summed
     * per body found among them (an id is no index: it may be 2^31 - 1). */
    std::vector<types::material_id> bodies;

    Vector anchor_vector;
    Vector force_vector;
    /** Re-anchorings in this Newton solve (the limit is per solve). */
    unsigned int n_relaxations = 0;
    Record       attempt;
    Record       committed;
    double       largest = 0;
  };
} // namespace tribos

#endif
