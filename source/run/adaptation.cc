/**
 * Simulation's part in Adaptivity: when the mesh changes (the first
 * increment solved again on the meshes its solutions ask for; the end of
 * every n-th step), and what follows a change (the solvers on the new
 * system, the output on the new contact pairs).
 */

#include <tribos/core/error_indicator.h>
#include <tribos/run/simulation.h>

#include <sstream>

namespace tribos
{
  template <int dim>
  bool
  Simulation<dim>::adapts_after(const unsigned int step) const
  {
    const auto &a = parameters.adaptivity;
    return a.enable && a.every > 0 && step % a.every == 0 &&
           step < parameters.time_stepping.n_step_ends();
  }



  template <int dim>
  void
  Simulation<dim>::restart_adaptation(StepperState &start)
  {
    n_adaptations =
      static_cast<unsigned int>(restart->scalars.at("adaptations"));
    n_redone_increments =
      static_cast<unsigned int>(restart->scalars.at("redone increments"));
    n_initial_cycles = parameters.adaptivity.initial_cycles;
    // The run wrote the checkpoint at the step's end and adapted after it
    // (change_after_step()): the same indicator on the same state.
    if (!adapts_after(start.step))
      return;
    problem.estimate_error();
    if (!problem.mark_cells())
      return;
    if (!change_discretization(start.time,
                               start.change_increment > 0 ?
                                 &checkpointer.restart_change() :
                                 nullptr))
      start.change_increment = 0;
  }



  template <int dim>
  bool
  Simulation<dim>::redo_increment(const unsigned int,
                                  const unsigned int increment,
                                  const double       time)
  {
    const auto &a = parameters.adaptivity;
    if (!a.enable)
      return false;
    if (increment == 1)
    {
      if (n_initial_cycles >= a.initial_cycles)
        return false;
      ++n_initial_cycles;
      problem.estimate_error();
      if (problem.mark_cells())
        return true;
      // The mesh is what the indicator asks for: no more cycles.
      n_initial_cycles = a.initial_cycles;
      return false;
    }

    // The contact zone grew beyond the refined cells: once per increment.
    if (!a.redo_on_contact_growth || problem.contact() == nullptr ||
        increment == redone_increment)
      return false;
    const unsigned int n_faces = n_faces_closed_below_level(*problem.contact(),
                                                            a.maximum_level,
                                                            mpi_communicator);
    if (n_faces == 0)
      return false;
    problem.estimate_error();
    if (!problem.mark_cells())
      return false;
    redone_increment = increment;
    ++n_redone_increments;
    std::ostringstream line;
    line << "  the increment to t = " << time << " closed " << n_faces
         << " contact face(s) below Adaptivity/Maximum level: the mesh is "
            "adapted to its solution and the increment solved again";
    output->message(line.str());
    return true;
  }



  template <int dim>
  bool
  Simulation<dim>::change_after_step(const unsigned int step)
  {
    return adapts_after(step) && problem.mark_cells();
  }



  template <int dim>
  bool
  Simulation<dim>::change_discretization(const double              time,
                                         NonlinearProblem::Vector *change)
  {
    problem.adapt(time, change);
    ++n_adaptations;
    // The solvers on the new system (their counters go on).
    attach_linear_solver();
    output->mesh_changed();
    std::ostringstream line;
    line << "  adapted the mesh at t = " << time << ": "
         << model.triangulation().n_global_active_cells() << " cells, "
         << model.dof_handler().n_dofs() << " dofs";
    output->message(line.str());
    return change != nullptr;
  }



  template class Simulation<2>;
  template class Simulation<3>;
} // namespace tribos
