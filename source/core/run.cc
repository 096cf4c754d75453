#include <tribos/base/exceptions.h>
#include <tribos/core/problem.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

namespace tribos
{
  template <int dim>
  void
  Problem<dim>::run()
  {
    run_clock.restart();
    for (const auto &w : parameters.input_warnings)
      warn(w);
    make_grid();
    setup_system();
    setup_dynamics();
    if (!parameters.restart_directory.empty())
    {
      restart = std::make_unique<Checkpoint>();
      restart->load(parameters.restart_directory);
      check_checkpoint();
    }
    open_output();

    pcout << "tribos: " << dim << "D scene <" << parameters.scene.name << ">, "
          << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " dofs, " << n_bodies
          << (n_bodies == 1 ? " body, " : " bodies, ")
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI process(es)" << std::endl;
    if (contact)
      for (const auto &line : contact->describe())
        pcout << "  " << line << std::endl;

    StepperState start;
    if (restart)
      start = read_checkpoint();
    else
      write_vtu(0, 0.);
    if (last_rebalance.count > 0)
    {
      pcout << "  rebalanced: the contact time's max/min over the processes "
               "was "
            << last_rebalance.imbalance << " in step " << last_rebalance.step
            << "; the mesh is partitioned with the measured contact work"
            << std::endl;
      // The state was only the means of the rebalance.
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        std::filesystem::remove_all(last_rebalance.checkpoint);
    }

    // The solvers: the linear solve of a Newton iteration (AMG gets the
    // rigid-body modes as its near-null space), Newton, and the load
    // stepping around it.
    linear_solver = std::make_unique<LinearSolver>(parameters.linear_solver,
                                                   dim,
                                                   n_multipliers > 0);
    linear_solver->set_timer(timer);
    if (n_multipliers > 0)
      linear_solver->set_multiplier_blocks(dof_handler.n_dofs(), dim);
    if (linear_solver->iterative(matrix))
      linear_solver->set_near_null_space(rigid_body_modes(),
                                         parameters.finite_element.degree > 1);
    newton  = std::make_unique<NewtonSolver>(parameters.nonlinear_solver,
                                            *linear_solver);
    stepper = std::make_unique<LoadStepper>(parameters.time_stepping, *newton);
    step_clock.restart();
    stepper->run(
      *this,
      [this](const std::string &text) { message(text); },
      start,
      start.change_increment > 0 ? &restart_change : nullptr);

    if (contact)
      for (const auto &w : contact->run_warnings())
        warn(w);
    write_summary("completed");
    const auto &totals = stepper->totals();
    pcout << "done: " << totals.n_increments << " increments, "
          << totals.n_newton_iterations << " Newton iterations ("
          << (restart ? restart->stepper.totals.n_linear_solves : 0) +
               newton->n_linear_solves()
          << " with failed attempts), " << totals.n_cutbacks << " cutbacks, "
          << last_rebalance.elapsed + run_clock.wall_time() << " s; output in "
          << parameters.output.directory << std::endl;
  }

  template <int dim>
  void
  Problem<dim>::check_balance(const unsigned int step)
  {
    const double threshold = parameters.parallel.rebalance_threshold;
    if (threshold == 0 || !contact ||
        Utilities::MPI::n_mpi_processes(mpi_communicator) == 1 ||
        step == parameters.time_stepping.n_steps)
      return;
    // This step's own times (without the waits) and wall clock.
    const double contact_time  = contact->own_time() - contact_time_at_step;
    const double assembly_time = own_assembly_time - assembly_time_at_step;
    // The slowest process's clock: each one started its own, and a
    // process that decided alone would leave the rebalance's collective
    // steps waiting for it.
    const double wall =
      Utilities::MPI::max(step_clock.wall_time(), mpi_communicator);
    contact_time_at_step  = contact->own_time();
    assembly_time_at_step = own_assembly_time;
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
      warn("the contact work stayed out of balance after rebalancing "
           "(max/min " +
           std::to_string(imbalance) + " in step " + std::to_string(step) +
           "): no further rebalancing");
      return;
    }

    // A node's work in units of one cell's assembly, on its cell.
    const double per_cell =
      std::max(Utilities::MPI::sum(assembly_time, mpi_communicator) /
                 triangulation.n_global_active_cells(),
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
    pcout << "  rebalance after step " << step
          << ": the contact time's max/min over the processes is " << imbalance
          << " (Parallel/Rebalance threshold " << threshold << ")" << std::endl;
    throw rebalance;
  }



  template <int dim>
  std::vector<std::vector<double>>
  Problem<dim>::rigid_body_modes() const
  {
    // The support points of the dofs (reference configuration).
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(MappingQ1<dim>(), dof_handler, points);
    // About the centroid of all support points (every process the same).
    Tensor<1, dim> sum;
    for (const auto dof : locally_owned_dofs)
      sum += points.at(dof);
    const Point<dim>   centre(Utilities::MPI::sum(sum, mpi_communicator) /
                              double(dof_handler.n_dofs()));
    const unsigned int n_modes = dim == 2 ? 3 : 6;
    std::vector<std::vector<double>> modes(
      n_modes,
      std::vector<double>(system_owned.n_elements(), 0.));
    unsigned int local = 0;
    for (const auto dof : system_owned)
    {
      if (dof < dof_handler.n_dofs())
      {
        const unsigned int   c = dof_component[dof];
        const Tensor<1, dim> x = points.at(dof) - centre;
        modes[c][local]        = 1; // translations
        // Rotations: about z in 2D (-y, x); about x, y, z in 3D.
        if constexpr (dim == 2)
          modes[2][local] = (c == 0 ? -x[1] : x[0]);
        else
        {
          const double rotation[3][3] = {{0, -x[2], x[1]},
                                         {x[2], 0, -x[0]},
                                         {-x[1], x[0], 0}};
          for (unsigned int r = 0; r < 3; ++r)
            modes[3 + r][local] = rotation[r][c];
        }
      }
      ++local;
    }
    return modes;
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
