#include <tribos/base/exceptions.h>
#include <tribos/core/problem.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>

namespace tribos
{
  template <int dim>
  void
  Problem<dim>::run()
  {
    Timer wall_clock;
    for (const auto &w : parameters.input_warnings)
      warn(w);
    make_grid();
    setup_system();
    open_output();

    pcout << "tribos: " << dim << "D scene <" << parameters.scene.name << ">, "
          << triangulation.n_active_cells() << " cells, "
          << dof_handler.n_dofs() << " dofs, " << n_bodies
          << (n_bodies == 1 ? " body, " : " bodies, ")
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI process(es)" << std::endl;
    if (contact)
      for (const auto &line : contact->describe())
        pcout << "  " << line << std::endl;

    write_vtu(0, 0.);

    // The solvers: the linear solve of a Newton iteration (AMG gets the
    // translations of the displacement components as its near-null
    // space), Newton, and the load stepping around it.
    linear_solver = std::make_unique<LinearSolver>(parameters.linear_solver);
    linear_solver->set_timer(timer);
    if (!parameters.linear_solver.direct)
    {
      std::vector<std::vector<bool>> modes;
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(dim, true),
                                       modes);
      linear_solver->set_near_null_space(modes,
                                         parameters.finite_element.degree > 1);
    }
    newton  = std::make_unique<NewtonSolver>(parameters.nonlinear_solver,
                                            *linear_solver);
    stepper = std::make_unique<LoadStepper>(parameters.time_stepping, *newton);
    stepper->run(*this, [this](const std::string &text) { message(text); });

    if (contact)
      for (const auto &w : contact->run_warnings())
        warn(w);
    write_summary("completed");
    const auto &totals = stepper->totals();
    pcout << "done: " << totals.n_increments << " increments, "
          << totals.n_newton_iterations << " Newton iterations ("
          << newton->n_linear_solves() << " with failed attempts), "
          << totals.n_cutbacks << " cutbacks, " << wall_clock.wall_time()
          << " s; output in " << parameters.output.directory << std::endl;
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
