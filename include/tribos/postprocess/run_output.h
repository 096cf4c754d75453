#ifndef tribos_postprocess_run_output_h
#define tribos_postprocess_run_output_h

#include <tribos/base/directory_lock.h>
#include <tribos/core/checkpoint.h>
#include <tribos/core/problem.h>
#include <tribos/postprocess/contact_output.h>
#include <tribos/postprocess/csv_writer.h>
#include <tribos/solver/linear_solver.h>
#include <tribos/solver/solver_observer.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /** What summary.txt says about the run besides the problem. */
  struct RunTotals
  {
    StepperTotals stepper;
    /** Newton iterations of every attempt (linear solves), a restart's
     * earlier ones included. */
    unsigned int        n_linear_solves = 0;
    const LinearSolver *linear_solver   = nullptr;
    /** The largest ratio of the stabilization springs to the load at a
     * converged increment (Stabilization::largest_ratio()). */
    double largest_stabilization_ratio = 0;
    /** Rebalances so far, the step of the last and its contact time's
     * max/min over the processes. */
    unsigned int n_rebalances = 0;
    /** Changes of the mesh (Adaptivity). */
    unsigned int n_adaptations = 0;
    /** Of those, the increments solved again on the new mesh after their
     * contact zone grew onto coarse cells. */
    unsigned int n_redone_increments = 0;
    unsigned int rebalance_step      = 0;
    double       imbalance           = 0;
  };



  /**
   * The outputs of a run (the names and columns are a contract with users'
   * scripts, README): history.csv (a row per converged increment),
   * convergence.csv (a row per Newton iteration), the console line of
   * each nominal step, contact-NNNNN.csv and solution-NNNNN.vtu (.pvtu)
   * with solution.pvd at the output steps, and summary.txt. It listens to
   * the solvers (SolverObserver) and reads the Problem; the files are
   * opened by the first process on every process's behalf, so that a
   * failure to write ends every process alike.
   *
   * The implementation: run_output.cc (files, rows, console),
   * vtu_output.cc, summary.cc.
   */
  template <int dim>
  class RunOutput : public SolverObserver
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    RunOutput(const Parameters::AllParameters &parameters,
              const Model<dim>                &model,
              const Problem<dim>              &problem,
              const Warnings                  &warnings,
              TimerOutput                     &timer);

    /**
     * Create Output/Directory (removing the series files of an earlier run
     * there; a @p restart keeps those up to its checkpoint) and open
     * history.csv and convergence.csv (a restart continues them after its
     * checkpoint's rows).
     */
    void
    open(const Checkpoint *restart);

    /** Print @p line on the console (first process). */
    void
    print(const std::string &line);

    /** The mesh changed (Adaptivity): the contact pairs are new, the
     * probes on other dofs. Collective. */
    void
    mesh_changed();

    /** Write contact-NNNNN.csv and the VTU of nominal step @p step at
     * @p time (Output/Write VTU). */
    void
    write_step(const unsigned int step, const double time);

    /** The VTU series written so far (time, file), for checkpoints. */
    const std::vector<std::pair<double, std::string>> &
    pvd_records() const
    {
      return records;
    }

    /** Write summary.txt with @p status and @p totals. Collective. */
    void
    write_summary(const std::string &status, const RunTotals &totals);

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

  private:
    /** The history.csv columns (and the probes' dofs). */
    std::vector<std::string>
    history_columns();
    /** Per Output/Probes point, the dofs of the vertex nearest to it (on
     * the current mesh). Collective. */
    void
    find_probe_dofs();

    /** The L2 and H1 errors of the displacement against Verification/
     * Exact displacement at @p time. */
    std::pair<double, double>
    displacement_errors(const double time) const;

    /** The figures of summary.txt taken over the processes (min, max and
     * sum of each process's value). */
    struct ParallelFigures
    {
      /** Each process's own time in assembly and in the contact. */
      std::vector<std::pair<std::string, Utilities::MPI::MinMaxAvg>> balance;
      /** The slave nodes each process evaluates. */
      Utilities::MPI::MinMaxAvg slave_nodes;
      /** The number of processes. */
      unsigned int n_ranks = 0;
      /** The ghost values per update of the ghosted solution, and the
       * contact's share of them. */
      Utilities::MPI::MinMaxAvg ghosts, contact_ghosts;
      /** ContactHandler::process_crossings(). */
      std::pair<unsigned int, unsigned int> crossings;
      /** The master exchange of the contact search: the most values one
       * search brought to a process, and the mean per search. */
      Utilities::MPI::MinMaxAvg exchange_largest, exchange_mean;
      /** The peak resident memory in MB. */
      Utilities::MPI::MinMaxAvg peak_memory;
    };

    /**
     * Gather the ParallelFigures for write_summary(). Collective: every
     * process calls it, with the same reductions in the same order; kept
     * apart from the text, which the first process alone writes.
     */
    ParallelFigures
    measure_parallel_figures() const;

    /**
     * Write the lines of summary.txt on the processes' memory, load
     * balance and communication (and the contact cell weight that would
     * balance the work) from @p figures: a section of write_summary() of
     * its own, the only one that reads the ParallelFigures.
     */
    void
    write_parallel_figures(std::ostream          &out,
                           const ParallelFigures &figures) const;

    const Model<dim>                    &model;
    const Problem<dim>                  &problem;
    const Warnings                      &warnings;
    const Parameters::AllParameters     &parameters;
    MPI_Comm                             mpi_communicator;
    TimerOutput                         &timer;
    ConditionalOStream                   pcout;
    std::unique_ptr<ContactOutput<dim>>  contact_output;
    std::unique_ptr<FunctionParser<dim>> exact_displacement;
    /** Per probe point: the dofs of the nearest vertex. */
    std::vector<std::array<types::global_dof_index, dim>> probe_dofs;
    /** Held by the first process for the run's life (base/DirectoryLock). */
    std::unique_ptr<DirectoryLock>              directory_lock;
    std::unique_ptr<CsvWriter>                  history_csv;
    std::unique_ptr<CsvWriter>                  convergence_csv;
    std::vector<std::pair<double, std::string>> records;
    /** The attempt the iterations belong to. */
    unsigned int current_step = 0, current_increment = 0;
    double       current_time = 0;
  };
} // namespace tribos

#endif
