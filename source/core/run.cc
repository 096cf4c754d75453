#include <tribos/base/exceptions.h>
#include <tribos/core/problem.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <map>

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
    stepper->run(
      *this,
      [this](const std::string &text) { message(text); },
      start);

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
          << wall_clock.wall_time() << " s; output in "
          << parameters.output.directory << std::endl;
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
