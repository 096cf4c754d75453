/**
 * Checkpoints and restarts: the converged state written per active cell and
 * per slave node, so that a run can go on from it with another number of
 * MPI processes and either Parallel/Mesh (the mesh is the same: it is
 * built from the parameter file; cells are named by their CellId, which
 * no partition changes).
 */

#include <tribos/base/exceptions.h>
#include <tribos/base/text.h>
#include <tribos/core/checkpointer.h>
#include <tribos/material/material_model.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/cell_id.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace tribos
{
  namespace
  {
    using CellKey = std::array<unsigned int, 4>;

    /** CellId order on the binary form. */
    bool
    cell_less(const CellKey &a, const CellKey &b)
    {
      return CellId(a) < CellId(b);
    }

    /** Gather the records of every process on rank 0, in CellId order
     * (empty elsewhere). */
    template <typename T>
    std::vector<std::pair<CellKey, T>>
    gather_by_cell(const std::vector<std::pair<CellKey, T>> &mine,
                   const MPI_Comm                            communicator)
    {
      std::vector<std::pair<CellKey, T>> all;
      for (auto &part : Utilities::MPI::gather(communicator, mine))
        all.insert(all.end(), part.begin(), part.end());
      std::sort(all.begin(),
                all.end(),
                [](const auto &a, const auto &b)
                { return cell_less(a.first, b.first); });
      return all;
    }
  } // namespace



  template <int dim>
  Checkpointer<dim>::Checkpointer(
    const Parameters::AllParameters                &parameters,
    const Model<dim>                               &model,
    Problem<dim>                                   &problem,
    TimerOutput                                    &timer,
    const std::function<void(const std::string &)> &log)
    : parameters(parameters)
    , model(model)
    , problem(problem)
    , timer(timer)
    , log(log)
    , mpi_communicator(model.communicator())
  {
  }



  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  Checkpointer<dim>::restart_change() const
  {
    return change_of_restart;
  }



  template <int dim>
  TrilinosWrappers::MPI::Vector &
  Checkpointer<dim>::restart_change()
  {
    return change_of_restart;
  }



  template <int dim>
  std::vector<double>
  Checkpointer<dim>::cell_values(
    const Vector                         &v,
    std::vector<std::array<unsigned, 4>> *cells) const
  {
    const auto &layout = model.layout();
    Vector      ghosted(layout.locally_owned_dofs,
                   layout.locally_relevant_dofs,
                   mpi_communicator);
    ghosted                                = v;
    const unsigned int                   n = model.fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    std::vector<std::pair<CellKey, std::vector<double>>> mine;
    for (const auto &cell : model.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
      {
        cell->get_dof_indices(dofs);
        std::vector<double> values(n);
        for (unsigned int i = 0; i < n; ++i)
          values[i] = ghosted[dofs[i]];
        mine.emplace_back(cell->id().template to_binary<dim>(), values);
      }
    std::vector<double> values;
    for (const auto &[cell, cell_values] :
         gather_by_cell(mine, mpi_communicator))
    {
      values.insert(values.end(), cell_values.begin(), cell_values.end());
      if (cells != nullptr)
        cells->push_back(cell);
    }
    return values;
  }



  template <int dim>
  void
  Checkpointer<dim>::set_from_cell_values(
    const std::vector<std::array<unsigned, 4>> &cells,
    const std::vector<double>                  &values,
    Vector                                     &v) const
  {
    const auto                          &layout = model.layout();
    const unsigned int                   n      = model.fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    AssertThrow(values.size() == cells.size() * n,
                ExcMessage("The checkpoint's vector does not fit the mesh."));
    unsigned int n_missing = 0;
    for (const auto &cell : model.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const CellKey key = cell->id().template to_binary<dim>();
        const auto    it =
          std::lower_bound(cells.begin(), cells.end(), key, cell_less);
        if (it == cells.end() || *it != key)
        {
          ++n_missing;
          continue;
        }
        const std::size_t position = it - cells.begin();
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          if (layout.locally_owned_dofs.is_element(dofs[i]))
            v[dofs[i]] = values[position * n + i];
      }
    // Every process says so, or none (no process waits for the others).
    n_missing = Utilities::MPI::sum(n_missing, mpi_communicator);
    AssertThrow(n_missing == 0,
                ExcMessage("--restart <" + parameters.restart_directory +
                           ">: the checkpoint's mesh is not this run's (" +
                           std::to_string(n_missing) + " cells missing)."));
    v.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  Checkpointer<dim>::write(
    const StepperState                                &stepper,
    const Vector                                      &change,
    const std::vector<std::pair<double, std::string>> &pvd_records,
    const std::map<std::string, double>               &run_scalars,
    const std::string                                 &directory) const
  {
    const auto        &layout = model.layout();
    TimerOutput::Scope t(timer, "output");
    Checkpoint         c;
    c.dimension      = dim;
    c.n_active_cells = model.triangulation().n_global_active_cells();
    c.dofs_per_cell  = model.fe().n_dofs_per_cell();
    c.n_dofs         = model.dof_handler().n_dofs();
    c.n_multipliers  = layout.n_multipliers;
    c.stepper        = stepper;
    c.largest_stabilization_ratio = problem.stabilization().largest_ratio();

    // The multipliers of a system vector, each from its owner, summed over
    // the processes (only the owner has a node's multipliers).
    const auto multipliers_of = [&](const Vector &v)
    {
      std::vector<double> values(layout.n_multipliers, 0.);
      for (const auto i : layout.system_owned)
        if (i >= model.dof_handler().n_dofs())
          values[i - model.dof_handler().n_dofs()] = v[i];
      Utilities::MPI::sum(values, mpi_communicator, values);
      return values;
    };

    // The displacement part of the solution, then the multipliers.
    Vector owned(layout.locally_owned_dofs, mpi_communicator);
    for (const auto i : layout.locally_owned_dofs)
      owned[i] = problem.unknowns()[i];
    owned.compress(VectorOperation::insert);
    c.cell_values["solution"] = cell_values(owned, &c.cells);
    c.multipliers             = multipliers_of(problem.unknowns());

    // The last increment's change, which the next one extrapolates: its
    // displacement part per cell, its multipliers.
    if (c.stepper.change_increment > 0)
    {
      for (const auto i : layout.locally_owned_dofs)
        owned[i] = change[i];
      owned.compress(VectorOperation::insert);
      c.cell_values["change"] = cell_values(owned);
      c.multiplier_change     = multipliers_of(change);
    }

    // Plastic history of the owned cells, gathered in cell order.
    std::vector<std::pair<CellKey, std::vector<double>>> mine;
    for (const auto &cell : model.triangulation().active_cell_iterators())
      if (cell->is_locally_owned() && problem.materials().has_history(cell))
        mine.emplace_back(cell->id().template to_binary<dim>(),
                          problem.materials().cell_history(cell));
    c.history = gather_by_cell(mine, mpi_communicator);

    if (const auto *contact = problem.contact())
      c.contact = contact->committed_state();

    if (const auto *dynamics = problem.dynamics())
    {
      for (const auto &[name, vector] : dynamics->checkpoint_vectors())
        c.cell_values[name] = cell_values(*vector);
      c.scalars = dynamics->scalars();
    }
    c.scalars.insert(run_scalars.begin(), run_scalars.end());
    c.pvd_records = pvd_records;
    c.fingerprint = fingerprint();
    c.geometry    = geometry_moments();

    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      c.save(directory);
    MPI_Barrier(mpi_communicator);
  }



  template <int dim>
  std::map<std::string, double>
  Checkpointer<dim>::geometry_moments() const
  {
    // Two sums over the owned cells' vertices: a weighted first moment (an
    // irrational weight per coordinate) and the second moment.
    const double weights[3] = {0.7071067811865476,
                               0.5773502691896258,
                               0.3183098861837907};
    // The body and boundary ids weigh the cells' and boundary faces'
    // centres: the same mesh with two surfaces' tags or two bodies' ids
    // swapped differs (a restart took it and lost its contact force).
    double     first = 0, second = 0, bodies = 0, boundaries = 0;
    const auto moment = [&](const Point<dim> &x)
    {
      double m = 0;
      for (unsigned int d = 0; d < dim; ++d)
        m += weights[d] * x[d];
      return m;
    };
    for (const auto &cell : model.triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
      {
        for (const auto v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
          {
            first += weights[d] * cell->vertex(v)[d];
            second += cell->vertex(v)[d] * cell->vertex(v)[d];
          }
        bodies += (cell->material_id() + 1.) * moment(cell->center());
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            boundaries += (face->boundary_id() + 1.) * moment(face->center());
      }
    return {
      {"first vertex moment", Utilities::MPI::sum(first, mpi_communicator)},
      {"second vertex moment", Utilities::MPI::sum(second, mpi_communicator)},
      {"body id moment", Utilities::MPI::sum(bodies, mpi_communicator)},
      {"boundary id moment",
       Utilities::MPI::sum(boundaries, mpi_communicator)}};
  }



  template <int dim>
  void
  Checkpointer<dim>::check(const Checkpoint &c) const
  {
    const auto       &layout = model.layout();
    const std::string where =
      "--restart <" + parameters.restart_directory + ">: ";
    const auto require = [&](const unsigned int stored,
                             const unsigned int here,
                             const std::string &what)
    {
      AssertThrow(stored == here,
                  ExcMessage(where + "the checkpoint has " +
                             std::to_string(stored) + " " + what +
                             ", this run " + std::to_string(here) +
                             ": restart with the parameter file (scene, "
                             "mesh, finite element, contact pairs) of the "
                             "run that wrote it."));
    };
    require(c.dimension, dim, "dimensions");
    require(c.n_active_cells,
            model.triangulation().n_global_active_cells(),
            "cells");
    require(c.dofs_per_cell, model.fe().n_dofs_per_cell(), "dofs per cell");
    require(c.n_dofs, model.dof_handler().n_dofs(), "dofs");
    require(c.n_multipliers, layout.n_multipliers, "contact multipliers");
    for (const auto &[name, value] : geometry_moments())
    {
      const auto   stored = c.geometry.find(name);
      const double scale  = std::max(std::abs(value), 1e-300);
      AssertThrow(stored != c.geometry.end() &&
                    std::abs(stored->second - value) <= 1e-9 * scale,
                  ExcMessage(where +
                             "the mesh differs from the checkpoint's "
                             "(its vertices moved, or its body or boundary "
                             "ids changed: " +
                             name + " " +
                             (stored == c.geometry.end() ?
                                std::string("missing") :
                                to_scientific(stored->second)) +
                             " there, " + to_scientific(value) +
                             " here) although cells and dofs agree: restart "
                             "with the scene and mesh of the run that wrote "
                             "it."));
    }
    // The same sizes with another model (materials, friction, contact
    // discretization, adaptivity, ...) would go on from a state that does
    // not belong to it: exit 0 and another history (it did for Adaptivity/
    // Maximum level and Contact/Friction coefficient). Each entry that
    // differs is named with both values.
    const std::vector<std::string> changed = changed_entries(c);
    if (!changed.empty())
    {
      std::string list;
      for (const auto &line : changed)
        list += (list.empty() ? "" : "; ") + line;
      AssertThrow(false,
                  ExcMessage(where + "the checkpoint was written with " +
                             (changed.size() == 1 ?
                                std::string("another value of an entry") :
                                std::to_string(changed.size()) +
                                  " other values of entries") +
                             " that define the model: " + list +
                             ". Restart with the parameter file of the run "
                             "that wrote it; a restart may change only " +
                             may_change_at_restart_list() + "."));
    }
    AssertThrow(c.stepper.time < parameters.time_stepping.end_time,
                ExcMessage(where + "the checkpoint is at t = " +
                           to_scientific(c.stepper.time) +
                           ", at or past Time stepping/End time = " +
                           to_scientific(parameters.time_stepping.end_time) +
                           ": nothing is left to do."));
    const auto &ts = parameters.time_stepping;
    AssertThrow(c.stepper.step < ts.n_step_ends(),
                ExcMessage(where + "the checkpoint is at step " +
                           std::to_string(c.stepper.step) +
                           ", the run has only " +
                           std::to_string(ts.n_step_ends()) +
                           " (Time stepping/Number of steps and Output "
                           "times): nothing is left to do."));
    // A restart may change End time, Number of steps and Output times,
    // which place the steps' ends: the next one must lie after the
    // checkpoint's time, or the steps up to it would be reported with
    // nothing done.
    const double next_end = ts.step_times[c.stepper.step];
    AssertThrow(next_end > c.stepper.time + 1e-12 * ts.end_time,
                ExcMessage(where + "the checkpoint is at step " +
                           std::to_string(c.stepper.step) +
                           ", t = " + to_scientific(c.stepper.time) +
                           "; with this run's Time stepping/End time = " +
                           to_scientific(ts.end_time) +
                           ", Number of steps = " + std::to_string(ts.n_steps) +
                           " and Output times, step " +
                           std::to_string(c.stepper.step + 1) +
                           " would end at t = " + to_scientific(next_end) +
                           ", not after it: keep the steps of the run "
                           "that wrote it or make them larger."));
    // And the checkpoint's step must end at its time in this run's steps
    // too, or the steps after it would be numbered (and written) as other
    // times than those of the uninterrupted run.
    const double this_end =
      c.stepper.step > 0 ? ts.step_times[c.stepper.step - 1] : 0.;
    AssertThrow(std::abs(this_end - c.stepper.time) <= 1e-12 * ts.end_time,
                ExcMessage(where + "the checkpoint is at step " +
                           std::to_string(c.stepper.step) +
                           ", t = " + to_scientific(c.stepper.time) +
                           "; with this run's Time stepping/End time, "
                           "Number of steps and Output times step " +
                           std::to_string(c.stepper.step) +
                           " ends at t = " + to_scientific(this_end) +
                           ": keep the steps' ends up to the checkpoint as "
                           "the run that wrote it had them."));
    AssertThrow(c.cell_values.count("velocity") ==
                  (problem.dynamics() != nullptr ? 1 : 0),
                ExcMessage(where +
                           "the checkpoint and this run disagree on "
                           "Time stepping/Integrator (static or dynamic)."));
  }



  template <int dim>
  void
  Checkpointer<dim>::read(const Checkpoint &c)
  {
    const auto       &layout         = model.layout();
    auto              state          = problem.state();
    Vector           &owned_solution = problem.solution();
    const std::string where =
      "--restart <" + parameters.restart_directory + ">: ";
    set_from_cell_values(c.cells, c.cell_values.at("solution"), owned_solution);
    for (types::global_dof_index i = 0; i < layout.n_multipliers; ++i)
      if (layout.system_owned.is_element(model.dof_handler().n_dofs() + i))
        owned_solution[model.dof_handler().n_dofs() + i] = c.multipliers[i];
    owned_solution.compress(VectorOperation::insert);
    problem.solution_changed();
    if (c.stepper.change_increment > 0)
    {
      change_of_restart.reinit(layout.system_owned, mpi_communicator);
      set_from_cell_values(c.cells,
                           c.cell_values.at("change"),
                           change_of_restart);
      for (types::global_dof_index i = 0; i < layout.n_multipliers; ++i)
        if (layout.system_owned.is_element(model.dof_handler().n_dofs() + i))
          change_of_restart[model.dof_handler().n_dofs() + i] =
            c.multiplier_change[i];
      change_of_restart.compress(VectorOperation::insert);
    }

    unsigned int                                   n_missing = 0;
    std::map<CellKey, const std::vector<double> *> by_cell;
    for (const auto &[cell, values] : c.history)
      by_cell[cell] = &values;
    for (const auto &cell : model.triangulation().active_cell_iterators())
      if (cell->is_locally_owned() && state.materials.has_history(cell))
      {
        const auto it = by_cell.find(cell->id().template to_binary<dim>());
        if (it == by_cell.end() ||
            !state.materials.set_cell_history(cell, *it->second))
          ++n_missing;
      }
    AssertThrow(Utilities::MPI::sum(n_missing, mpi_communicator) == 0,
                ExcMessage(where + "the checkpoint has no plastic "
                                   "history for a cell that needs one: "
                                   "Materials must be those of the run "
                                   "that wrote it."));
    state.materials.restore();
    state.stabilization.set_largest_ratio(c.largest_stabilization_ratio);

    state.time = c.stepper.time;
    if (state.contact != nullptr)
    {
      state.contact->update(state.ghosted_unknowns, state.time);
      state.contact->load_committed_state(c.contact, state.time);
    }

    if (state.dynamics != nullptr)
      state.dynamics->restart(
        [&](const std::string &name, Vector &v)
        { set_from_cell_values(c.cells, c.cell_values.at(name), v); },
        c.scalars,
        problem.displacement(),
        c.stepper.time);
    std::ostringstream line;
    line << "  restarted from " << parameters.restart_directory
         << " after step " << c.stepper.step << " (t = " << c.stepper.time
         << ", " << c.stepper.totals.n_increments << " increments)";
    log(line.str());
  }

  template class Checkpointer<2>;
  template class Checkpointer<3>;
} // namespace tribos
