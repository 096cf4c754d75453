#include <tribos/base/exceptions.h>
#include <tribos/core/problem.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <iomanip>

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

    const auto  &ts           = parameters.time_stepping;
    const double nominal_step = ts.end_time / ts.n_steps;
    const double epsilon      = 1e-12 * ts.end_time;

    write_vtu(0, 0.);

    double       time               = 0;
    double       increment          = nominal_step;
    Vector       converged          = solution;
    unsigned int n_increments_total = 0;
    // Converged increments since the last growth or cutback.
    unsigned int converged_in_row = 0;
    unsigned int solves_accepted  = 0;

    for (unsigned int step = 1; step <= ts.n_steps; ++step)
    {
      const double target           = step * nominal_step;
      unsigned int n_iterations     = 0;
      unsigned int n_iterations_all = 0;
      unsigned int n_cutbacks       = 0;
      unsigned int cutbacks_in_row  = 0;
      double       residual         = 0;
      unsigned int n_increments     = 0;

      while (time < target - epsilon)
      {
        const double next = std::min(time + increment, target);
        Timer        increment_clock;
        try
        {
          IncrementReport report =
            solve_increment(next, step, n_increments_total + 1);

          // Augmented Lagrangian: Uzawa updates of the multipliers,
          // each followed by a new solve of the same increment.
          if (contact && contact->augmented())
            for (;;)
            {
              const auto  &cp = parameters.contact;
              const double violation =
                contact->augment(cp.augmentation_tolerance);
              if (violation <= cp.augmentation_tolerance)
                break;
              if (report.n_augmentations >= cp.max_augmentations)
                throw NonConvergence(
                  "penetration " + to_scientific(violation) +
                  " of the element size after " +
                  std::to_string(report.n_augmentations) +
                  " augmentations (Contact/Maximum augmentations)");
              const IncrementReport again =
                solve_increment(next, step, n_increments_total + 1);
              report.n_iterations += again.n_iterations;
              report.residual = again.residual;
              report.n_chattering =
                std::max(report.n_chattering, again.n_chattering);
              report.stabilization_force = again.stabilization_force;
              report.stabilization_ratio = again.stabilization_ratio;
              report.n_relaxations += again.n_relaxations;
              ++report.n_augmentations;
            }
          commit_history();
          // Every linear solve since the last accepted increment: this
          // increment's failed attempts included.
          report.n_iterations_all = n_linear_solves - solves_accepted;
          solves_accepted         = n_linear_solves;
          largest_stabilization_ratio =
            std::max(largest_stabilization_ratio, report.stabilization_ratio);
          converged = solution;
          time      = next;
          ++n_increments;
          ++n_increments_total;
          ++n_converged_increments;
          n_iterations += report.n_iterations;
          n_iterations_all += report.n_iterations_all;
          residual        = report.residual;
          cutbacks_in_row = 0;
          write_history_row(step,
                            n_increments_total,
                            time,
                            report,
                            n_cutbacks,
                            increment_clock.wall_time());
          ++converged_in_row;
          if (report.n_iterations <= ts.easy_iterations ||
              (ts.growth_after > 0 && converged_in_row >= ts.growth_after))
          {
            increment = std::min(increment * ts.growth_factor, nominal_step);
            converged_in_row = 0;
          }
        }
        catch (const NonConvergence &failure)
        {
          solution         = converged;
          ghosted_solution = solution;
          history_new      = history_old;
          if (contact)
            contact->restore();
          ++n_cutbacks;
          ++n_total_cutbacks;
          ++cutbacks_in_row;
          converged_in_row = 0;
          if (cutbacks_in_row > ts.max_cutbacks)
          {
            const std::string message =
              "step " + std::to_string(step) +
              " at t = " + to_scientific(next) + " did not converge after " +
              std::to_string(ts.max_cutbacks) +
              " cutbacks (Time stepping/Maximum cutbacks): " + failure.what() +
              ". Outputs of the converged steps are kept.";
            if (contact)
              for (const auto &w : contact->run_warnings())
                warn(w);
            write_summary("FAILED: " + message);
            throw NonConvergence(message);
          }
          increment *= 0.5;
          if (increment < epsilon)
          {
            const std::string message =
              "step " + std::to_string(step) +
              " at t = " + to_scientific(next) +
              ": the increment was cut below 1e-12 of the end time (" +
              failure.what() + "). Outputs of the converged steps are kept.";
            if (contact)
              for (const auto &w : contact->run_warnings())
                warn(w);
            write_summary("FAILED: " + message);
            throw NonConvergence(message);
          }
          pcout << "  cutback " << cutbacks_in_row << " at t = " << next << " ("
                << failure.what() << "), new increment " << increment
                << std::endl;
        }
      }

      const double elapsed = wall_clock.wall_time();
      const double eta     = elapsed / time * (ts.end_time - time);
      pcout << "step " << std::setw(4) << step << "/" << ts.n_steps
            << "  t=" << std::setw(9) << std::setprecision(4) << time
            << "  lf=" << std::fixed << std::setprecision(3)
            << time / ts.end_time << std::defaultfloat << "  incr "
            << n_increments << "  newton " << std::setw(3) << n_iterations
            << " (all " << n_iterations_all << ")"
            << "  |R|=" << std::scientific << std::setprecision(2) << residual
            << std::defaultfloat << "  cutbacks " << n_cutbacks;
      if (contact)
      {
        const ContactStatistics s = contact->statistics();
        pcout << "  active/stick/slip " << s.n_active << "/" << s.n_stick << "/"
              << s.n_slip;
      }
      pcout << "  " << std::setprecision(3) << elapsed << " s  ETA " << eta
            << " s" << std::endl;

      if (parameters.output.is_output_step(step, ts.n_steps))
        write_vtu(step, time);
    }

    if (contact)
      for (const auto &w : contact->run_warnings())
        warn(w);
    write_summary("completed");
    pcout << "done: " << n_converged_increments << " increments, "
          << n_total_newton_iterations << " Newton iterations ("
          << n_linear_solves << " with failed attempts), " << n_total_cutbacks
          << " cutbacks, " << wall_clock.wall_time() << " s; output in "
          << parameters.output.directory << std::endl;
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
