/**
 * Simulation's part in Adaptivity: when the mesh changes (the first
 * increment solved again on the meshes its solutions ask for; the end of
 * every n-th step), and what follows a change (the solvers on the new
 * system, the output on the new contact pairs).
 */

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
           step < parameters.time_stepping.n_steps;
  }



  template <int dim>
  bool
  Simulation<dim>::redo_increment(const unsigned int,
                                  const unsigned int increment,
                                  const double)
  {
    const auto &a = parameters.adaptivity;
    if (!a.enable || increment != 1 || n_initial_cycles >= a.initial_cycles)
      return false;
    ++n_initial_cycles;
    problem.estimate_error();
    if (problem.mark_cells())
      return true;
    // The mesh is what the indicator asks for: no more cycles.
    n_initial_cycles = a.initial_cycles;
    return false;
  }



  template <int dim>
  bool
  Simulation<dim>::change_after_step(const unsigned int step)
  {
    return adapts_after(step) && problem.mark_cells();
  }



  template <int dim>
  void
  Simulation<dim>::change_discretization(const double time)
  {
    problem.adapt(time);
    ++n_adaptations;
    // The solvers on the new system (their counters go on).
    attach_linear_solver();
    output->mesh_changed();
    std::ostringstream line;
    line << "  adapted the mesh at t = " << time << ": "
         << model.triangulation().n_global_active_cells() << " cells, "
         << model.dof_handler().n_dofs() << " dofs";
    output->message(line.str());
  }



  template class Simulation<2>;
  template class Simulation<3>;
} // namespace tribos
