#ifndef tribos_run_simulation_h
#define tribos_run_simulation_h

#include <tribos/core/checkpoint.h>
#include <tribos/core/checkpointer.h>
#include <tribos/core/problem.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/postprocess/run_output.h>
#include <tribos/solver/linear_solver.h>
#include <tribos/solver/load_stepper.h>
#include <tribos/solver/newton_solver.h>
#include <tribos/solver/solver_observer.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/cell_id.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * Thrown by Simulation at the end of a step when the contact work is out
   * of balance (Parallel/Rebalance threshold): not a failure. The state of
   * the step is in @p checkpoint; main() builds the simulation again,
   * partitioned with @p weights, and restarts from it.
   */
  struct Rebalance
  {
    std::string checkpoint;
    /** Rank 0: METIS' weight of every cell with measured contact work
     * (others weigh 1). */
    CellWeights weights;
    /** The contact time's max/min over the processes in the step. */
    double       imbalance = 0;
    unsigned int step      = 0;
    /** Rebalances so far, this one included. */
    unsigned int count = 0;
    /** The wall time of the run before it (for the log's total). */
    double elapsed = 0;
  };



  /**
   * One run of a parameter file: builds the Problem, its outputs
   * (RunOutput) and the solvers (LinearSolver, NewtonSolver, LoadStepper),
   * goes on from a checkpoint if asked (--restart), and runs every load
   * step. It is the solvers' observer: it passes what they report to the
   * outputs, and at the end of each nominal step writes the VTU, the
   * checkpoint (Output/Checkpoint every) and checks the balance of the
   * contact work under MPI (Parallel/Rebalance threshold).
   */
  template <int dim>
  class Simulation : public SolverObserver
  {
  public:
    /** A run of @p parameters; @p previous is the rebalance it goes on
     * from (count 0: none). */
    Simulation(const Parameters::AllParameters &parameters,
               const MPI_Comm                   mpi_communicator,
               const Rebalance                 &previous = Rebalance());

    /**
     * Build the scene, solve every load step and write all output. Throws
     * NonConvergence when the cutbacks are exhausted (after the outputs of
     * all converged steps are written), Rebalance (see there), other
     * exceptions for bad input.
     */
    void
    run();

    /* SolverObserver */
    void
    attempt(const unsigned int step,
            const unsigned int increment,
            const double       time) override;
    void
    iteration(const IterationRecord &record) override;
    void
    increment_converged(const IncrementRecord &record) override;
    void
    step_completed(const StepRecord &record) override;
    void
    message(const std::string &text) override;
    void
    failed(const std::string &reason) override;
    /* SolverObserver: Adaptivity (adaptation.cc) */
    bool
    redo_increment(const unsigned int step,
                   const unsigned int increment,
                   const double       time) override;
    bool
    change_after_step(const unsigned int step) override;
    bool
    change_discretization(const double              time,
                          NonlinearProblem::Vector *change) override;

  private:
    /** Whether the mesh adapts at the end of nominal step @p step
     * (Adaptivity/Every; not after the last). */
    bool
    adapts_after(const unsigned int step) const;
    /** A restart of an adaptive run: the count of adaptations from the
     * checkpoint, and the adaptation after the checkpoint's step that the
     * run made after writing it, with the checkpoint's last change of the
     * unknowns carried over as the run carried its own (or none: then no
     * extrapolation from @p start). */
    void
    restart_adaptation(StepperState &start);

    /** The solvers of the run (AMG gets the rigid-body modes as its
     * near-null space). */
    void
    make_solvers();
    /** The linear solver on the problem's current system: its matrix,
     * multiplier blocks and AMG near-null space (at setup and after a
     * change of the mesh). */
    void
    attach_linear_solver();

    /** What summary.txt says of the run. */
    RunTotals
    totals() const;

    /**
     * The warnings the run's end knows (collective): contact pairs whose
     * slave never came near, and a model with contact pairs that nothing
     * loaded, its contact forces at round-off (support_warnings() leaves
     * that to the run: bodies meshed overlapping are loaded by their
     * contact).
     */
    void
    end_of_run_warnings();

    /** Write the converged state after nominal @p step into
     * @p directory. */
    void
    write_checkpoint(const unsigned int step, const std::string &directory);

    /** At the end of @p step: throws Rebalance if the contact work is out
     * of balance (collective; balance.cc). */
    void
    check_balance(const unsigned int step);

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
    Warnings    warnings;
    /** The discretization, before the problem that holds on to it. */
    Model<dim>                      model;
    Problem<dim>                    problem;
    Checkpointer<dim>               checkpointer;
    std::unique_ptr<RunOutput<dim>> output;
    /** The checkpoint a restart goes on from. */
    std::unique_ptr<Checkpoint>   restart;
    std::unique_ptr<LinearSolver> linear_solver;
    std::unique_ptr<NewtonSolver> newton;
    std::unique_ptr<LoadStepper>  stepper;
    /** The rebalance this run goes on from (count 0: none), whether it may
     * rebalance, and the own times and the wall clock at the last step's
     * end. */
    Rebalance last_rebalance;
    bool      may_rebalance = true;
    /** Adaptivity: the first increment's solves so far that changed the
     * mesh (Initial cycles), the changes of the mesh in all, the increments
     * solved again after their contact grew onto coarse cells (Redo on
     * contact growth), and the last of them (at most once each). */
    unsigned int  n_initial_cycles = 0, n_adaptations = 0;
    unsigned int  n_redone_increments = 0, redone_increment = 0;
    double        contact_time_at_step = 0, assembly_time_at_step = 0;
    dealii::Timer step_clock, run_clock;
  };
} // namespace tribos

#endif
