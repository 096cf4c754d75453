#include <tribos/base/write_atomically.h>
#include <tribos/postprocess/run_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <iomanip>
#include <iostream>

namespace tribos
{
  template <int dim>
  typename RunOutput<dim>::ParallelFigures
  RunOutput<dim>::measure_parallel_figures() const
  {
    const auto     *contact = problem.contact();
    ParallelFigures figures;
    // Load balance: each process's time in the sections its share of the
    // cells and of the contact zone sets (collective, so before rank 0
    // alone goes on). A contact zone on one process makes the others wait.
    figures.balance = {
      {"assembly",
       Utilities::MPI::min_max_avg(problem.bulk().own_time(),
                                   mpi_communicator)},
      {"contact",
       Utilities::MPI::min_max_avg(contact ? contact->own_time() : 0.,
                                   mpi_communicator)}};
    // The slave nodes each process evaluates (the contact's share of the
    // work, whatever their state).
    figures.slave_nodes =
      Utilities::MPI::min_max_avg(contact ?
                                    double(contact->n_own_slave_nodes()) :
                                    0.,
                                  mpi_communicator);
    // Communication: the values each process receives per update of the
    // ghosted solution (all of them, and the contact's share), and the
    // contact across processes.
    figures.n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    // The ghost values per update of the ghosted solution, and the
    // contact's share of them.
    const auto &layout = model.layout();
    const std::pair<types::global_dof_index, types::global_dof_index>
      ghost_values = {layout.system_relevant.n_elements() -
                        layout.system_owned.n_elements(),
                      layout.n_contact_ghosts};
    figures.ghosts =
      Utilities::MPI::min_max_avg(double(ghost_values.first), mpi_communicator);
    figures.contact_ghosts =
      Utilities::MPI::min_max_avg(double(ghost_values.second),
                                  mpi_communicator);
    figures.crossings =
      contact ? contact->process_crossings() : std::pair<unsigned, unsigned>();
    // The master exchange of the contact search: the most values one
    // search brought to a process, and the mean per search.
    figures.exchange_largest =
      Utilities::MPI::min_max_avg(contact ?
                                    double(contact->exchange_volume().largest) :
                                    0.,
                                  mpi_communicator);
    figures.exchange_mean = Utilities::MPI::min_max_avg(
      contact && contact->exchange_volume().n_searches > 0 ?
        double(contact->exchange_volume().total) /
          contact->exchange_volume().n_searches :
        0.,
      mpi_communicator);
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    figures.peak_memory =
      Utilities::MPI::min_max_avg(memory.VmHWM / 1024., mpi_communicator);
    return figures;
  }



  template <int dim>
  void
  RunOutput<dim>::write_parallel_figures(std::ostream          &out,
                                         const ParallelFigures &figures) const
  {
    const auto *contact       = problem.contact();
    const auto &triangulation = model.triangulation();
    out << "peak memory       " << figures.peak_memory.max
        << " MB per process (max), " << figures.peak_memory.sum
        << " MB in all\n";
    if (figures.n_ranks > 1)
    {
      for (const auto &[section, t] : figures.balance)
      {
        out << "balance " << std::left << std::setw(10) << section << std::right
            << "min " << t.min << " s, max " << t.max << " s, max/min ";
        if (t.min > 0)
          out << t.max / t.min << '\n';
        else
          out << (t.max > 0 ? "inf" : "-") << '\n';
      }
      if (contact)
        out << "balance slave nodes min " << figures.slave_nodes.min << ", max "
            << figures.slave_nodes.max << " per process\n";
      out << "ghost values      max " << figures.ghosts.max << " per process ("
          << 8 * figures.ghosts.max << " bytes per update), of which contact "
          << figures.contact_ghosts.max << '\n';
      if (contact)
        out << "master exchange   max " << figures.exchange_largest.max
            << " values per process and search ("
            << 8 * figures.exchange_largest.max << " bytes), mean "
            << figures.exchange_mean.max << '\n';
      if (contact)
        out << "contact across processes " << figures.crossings.first
            << " slave nodes at the end, " << figures.crossings.second
            << " master face changes of process\n";
    }
    if (contact && figures.slave_nodes.sum > 0 &&
        figures.balance[0].second.sum > 0)
    {
      // A cell with a slave face carries about one slave node: its
      // weight is one cell's assembly and one node's contact work,
      // in units of a cell's assembly (sums over the processes).
      const double per_cell =
        figures.balance[0].second.sum / triangulation.n_global_active_cells();
      const double per_node =
        figures.balance[1].second.sum / figures.slave_nodes.sum;
      out << "contact cell weight " << std::lround(1 + per_node / per_cell)
          << " would balance the measured work (Parallel/Contact cell "
             "weight = "
          << parameters.parallel.contact_cell_weight << ")\n";
    }
  }



  template <int dim>
  void
  RunOutput<dim>::write_summary(const std::string &status, const RunTotals &run)
  {
    const auto *contact       = problem.contact();
    const auto &triangulation = model.triangulation();
    // The figures over the processes (collective, so before rank 0 alone
    // goes on).
    const ParallelFigures figures = measure_parallel_figures();
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    const StepperTotals &totals        = run.stepper;
    const LinearSolver  *linear_solver = run.linear_solver;
    const auto wall  = timer.get_summary_data(TimerOutput::total_wall_time);
    const auto calls = timer.get_summary_data(TimerOutput::n_calls);
    double     total = 0;
    for (const auto &[section, seconds] : wall)
      total += seconds;

    write_atomically(
      parameters.output.directory + "/summary.txt",
      [&](std::ostream &out)
      {
        out << "status            " << status << '\n'
            << "dimension         " << dim << '\n'
            << "scene             " << parameters.scene.name << '\n'
            << "cells             " << triangulation.n_global_active_cells()
            << '\n'
            << "dofs              " << model.dof_handler().n_dofs() << '\n'
            << "contact dofs      "
            << (contact ? contact->contact_dofs().n_elements() : 0) << '\n'
            << "multipliers       " << model.layout().n_multipliers << '\n'
            << "bodies            " << problem.materials().bodies().size()
            << '\n'
            << "MPI processes     "
            << Utilities::MPI::n_mpi_processes(mpi_communicator) << '\n'
            << "increments        " << totals.n_increments << '\n'
            << "newton iterations " << totals.n_newton_iterations << '\n'
            << "newton iterations (all attempts) " << run.n_linear_solves
            << '\n'
            << "cutbacks          " << totals.n_cutbacks << '\n'
            << "rejected for accuracy " << totals.n_rejections << '\n'
            << "linear solver     "
            << (linear_solver && !linear_solver->method().empty() ?
                  linear_solver->method() :
                  "none")
            << '\n';
        if (linear_solver && linear_solver->n_iterations() > 0)
          out << "linear iterations " << linear_solver->n_iterations() << '\n'
              << "AMG setups        "
              << linear_solver->n_preconditioner_setups() << '\n';
        if (linear_solver && linear_solver->n_refinements() > 0)
          out << "refinement steps  " << linear_solver->n_refinements() << '\n';
        if (parameters.nonlinear_solver.stabilization > 0)
          out << "largest stabilization ratio "
              << run.largest_stabilization_ratio << '\n';
        write_parallel_figures(out, figures);
        if (parameters.adaptivity.enable)
        {
          out << "adaptations       " << run.n_adaptations << '\n';
          out << "redone increments " << run.n_redone_increments << '\n';
        }
        if (run.n_rebalances > 0)
          out << "rebalanced        " << run.n_rebalances
              << " time(s), the last after step " << run.rebalance_step
              << " (contact time max/min " << run.imbalance
              << "); balance and sections since then\n";
        for (const auto &w : warnings.list())
          out << "warning           " << w << '\n';
        out << "\nsection               calls    wall [s]  share\n";
        for (const auto &[section, seconds] : wall)
          out << std::left << std::setw(20) << section << std::right
              << std::setw(8) << static_cast<unsigned int>(calls.at(section))
              << ' ' << std::setw(11) << std::fixed << std::setprecision(4)
              << seconds << ' ' << std::setw(6) << std::setprecision(2)
              << (total > 0 ? 100 * seconds / total : 0) << "%\n"
              << std::defaultfloat;
      });
  }

  template class RunOutput<2>;
  template class RunOutput<3>;
} // namespace tribos
