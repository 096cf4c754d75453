/**
 * The balance of the contact work under MPI (Parallel/Rebalance
 * threshold): measured at the end of every nominal step.
 */

#include <tribos/run/simulation.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace tribos
{
  template <int dim>
  void
  Simulation<dim>::check_balance(const unsigned int step)
  {
    const double threshold = parameters.parallel.rebalance_threshold;
    auto        *contact   = problem.contact();
    if (threshold == 0 || contact == nullptr ||
        Utilities::MPI::n_mpi_processes(mpi_communicator) == 1 ||
        step == parameters.time_stepping.n_step_ends())
      return;
    // This step's own times (without the waits) and wall clock.
    const double contact_time = contact->own_time() - contact_time_at_step;
    const double assembly_time =
      problem.bulk().own_time() - assembly_time_at_step;
    // The slowest process's clock: each one started its own, and a
    // process that decided alone would leave the rebalance's collective
    // steps waiting for it.
    const double wall =
      Utilities::MPI::max(step_clock.wall_time(), mpi_communicator);
    contact_time_at_step  = contact->own_time();
    assembly_time_at_step = problem.bulk().own_time();
    step_clock.restart();
    const auto work = contact->take_work();
    const auto t = Utilities::MPI::min_max_avg(contact_time, mpi_communicator);
    const double imbalance =
      t.min > 0 ? t.max / t.min : std::numeric_limits<double>::infinity();
    // Out of balance, and by enough to matter: the others wait for the
    // busiest process longer than 5 % of the step.
    if (imbalance <= threshold || t.max - t.avg <= 0.05 * wall)
      return;
    if (!may_rebalance)
      return;
    if (last_rebalance.count > 0 && last_rebalance.step + 1 == step)
    {
      // The step right after a rebalance: its weights did not even out the
      // work (one node's element outweighs a process's share, say).
      may_rebalance = false;
      warnings.warn("the contact work stayed out of balance after rebalancing "
                    "(max/min " +
                    std::to_string(imbalance) + " in step " +
                    std::to_string(step) + "): no further rebalancing");
      return;
    }

    // A node's work in units of one cell's assembly, on its cell.
    const double per_cell =
      std::max(Utilities::MPI::sum(assembly_time, mpi_communicator) /
                 model.triangulation().n_global_active_cells(),
               std::numeric_limits<double>::min());
    std::map<CellId::binary_type, double> mine;
    for (const auto &[cell, seconds] : work)
      mine[cell] += seconds / per_cell;
    Rebalance rebalance;
    rebalance.checkpoint = parameters.output.directory + "/rebalance";
    rebalance.imbalance  = imbalance;
    rebalance.step       = step;
    rebalance.count      = last_rebalance.count + 1;
    rebalance.elapsed    = last_rebalance.elapsed + run_clock.wall_time();
    std::map<CellId::binary_type, double> all;
    for (const auto &part : Utilities::MPI::gather(mpi_communicator, mine, 0))
      for (const auto &[cell, w] : part)
        all[cell] += w;
    for (const auto &[cell, w] : all)
      rebalance.weights.emplace_back(cell,
                                     static_cast<unsigned int>(
                                       std::lround(std::min(w, 1e6))));
    write_checkpoint(step, rebalance.checkpoint);
    std::ostringstream line;
    line << "  rebalance after step " << step
         << ": the contact time's max/min over the processes is " << imbalance
         << " (Parallel/Rebalance threshold " << threshold << ")";
    output->print(line.str());
    throw rebalance;
  }



  template class Simulation<2>;
  template class Simulation<3>;
} // namespace tribos
