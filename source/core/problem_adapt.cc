/**
 * Problem's adaptation (Adaptivity): the error indicator of the current
 * state, and the change of the mesh with the state carried over.
 */

#include <tribos/core/error_indicator.h>
#include <tribos/core/problem.h>

#include <deal.II/base/mpi.h>

namespace tribos
{
  template <int dim>
  const dealii::Vector<float> &
  Problem<dim>::estimate_error()
  {
    TimerOutput::Scope t(timer, "adaptation");
    indicator = tribos::error_indicator(parameters.adaptivity,
                                        model,
                                        displacement(),
                                        *material_state,
                                        contact_handler.get());
    zone = contact_handler && parameters.adaptivity.contact_zone_depth > 0 ?
             tribos::contact_zone(model, *contact_handler) :
             ContactZone<dim>();
    return indicator;
  }



  template <int dim>
  bool
  Problem<dim>::mark_cells()
  {
    TimerOutput::Scope t(timer, "adaptation");
    AssertThrow(indicator.size() == model.triangulation().n_active_cells(),
                ExcInternalError("marking without a current indicator"));
    return model.mark(indicator, zone);
  }



  template <int dim>
  void
  Problem<dim>::adapt(const double committed_time, Vector *change)
  {
    TimerOutput::Scope t(timer, "adaptation");

    // The converged plastic history of the own cells.
    const auto                      &tria = model.triangulation();
    std::vector<std::vector<double>> history(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() && material_state->has_history(cell))
        history[cell->active_cell_index()] = material_state->cell_history(cell);

    using Carried = typename ContactHandler<dim>::CarriedState;
    const Carried carried =
      contact_handler ? contact_handler->carried_state() : Carried();
    std::vector<const Vector *> old_fields = {&displacement()};
    Vector                      ghosted_change;
    if (change != nullptr)
    {
      // Its dof part, ghosted as the interpolation needs.
      ghosted_change.reinit(layout.locally_owned_dofs,
                            layout.locally_relevant_dofs,
                            mpi_communicator);
      copy_dof_part(*change, ghosted_change);
      old_fields.push_back(&ghosted_change);
    }
    const std::vector<Vector> fields = model.adapt(old_fields, history);
    indicator.reinit(0);
    {
      TimerOutput::Scope t_setup(timer, "setup");
      setup_physics();
    }

    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() && material_state->has_history(cell))
        AssertThrow(
          material_state->set_cell_history(cell,
                                           history[cell->active_cell_index()]),
          ExcInternalError("history of another size"));
    material_state->restore();

    // The displacement on the new dofs, the contact multipliers (unknowns
    // after the dofs) from the carried node states.
    owned_solution = 0;
    for (const auto dof : model.layout().locally_owned_dofs)
      owned_solution[dof] = fields[0][dof];
    owned_solution.compress(VectorOperation::insert);
    if (contact_handler)
    {
      contact_handler->carry_over(carried);
      contact_handler->write_multipliers(owned_solution);
    }
    solution_changed();
    if (contact_handler)
      contact_handler->start_at(ghosted_solution, committed_time);
    if (change != nullptr)
    {
      change->reinit(owned_solution);
      for (const auto dof : model.layout().locally_owned_dofs)
        (*change)[dof] = fields[1][dof];
      change->compress(VectorOperation::insert);
    }
  }



  template <int dim>
  void
  Problem<dim>::refine_to(const std::vector<std::array<unsigned int, 4>> &cells)
  {
    TimerOutput::Scope t(timer, "setup");
    if (model.refine_to(cells))
      setup_physics();
  }



  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
