#include <tribos/base/exceptions.h>
#include <tribos/core/problem.h>

#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribos
{
  template <int dim>
  void
  Problem<dim>::begin_increment(const double end_time, const Vector *predictor)
  {
    time            = end_time;
    increment_start = owned_solution;
    stabilization_springs.begin_solve(ghosted_solution);
    // The start is the converged state (the update test measures the
    // increment's change from it, the stabilization springs hold to it);
    // the first iterate is the predicted one, and the increment's
    // constraints below take it to the Dirichlet values.
    if (predictor != nullptr)
    {
      owned_solution.add(1., *predictor);
      solution_changed();
    }
    if (contact_handler)
      contact_handler->begin_increment();
    if (dynamics_state)
      dynamics_state->begin_increment(time);
    model.make_constraints(time, &ghosted_solution, increment_constraints);
  }



  template <int dim>
  NonlinearProblem::Residual
  Problem<dim>::assemble(const bool with_matrix, const bool first_iteration)
  {
    Residual r;
    r.free        = assemble_system(with_matrix,
                             first_iteration ? increment_constraints :
                                                      homogeneous_constraints,
                             time);
    r.force_scale = full_residual.l2_norm();
    // Dynamics: the inertia forces are forces of the balance too (a body
    // in free flight has no other).
    if (dynamics_state)
      r.force_scale =
        std::max(r.force_scale, dynamics_state->inertia_forces().l2_norm());
    return r;
  }



  namespace
  {
    /**
     * Zero a vector that the assembly adds to, with what an interrupted
     * assembly left in it: entries added for other processes wait in the
     * Trilinos vector until compress() sends them, and zeroing does not
     * drop them. An assembly that threw (an inverted cell, a mortar
     * element too large: both on every process) never reached its
     * compress(), and the next one added them to its residual (a cutback
     * under MPI retried from a state 8.4 off equilibrium).
     */
    void
    clear(TrilinosWrappers::MPI::Vector &v)
    {
      v.compress(VectorOperation::add);
      v = 0;
    }
  } // namespace



  template <int dim>
  double
  Problem<dim>::assemble_system(const bool                       with_matrix,
                                const AffineConstraints<double> &constraints,
                                const double                     time)
  {
    if (contact_handler)
    {
      TimerOutput::Scope search_timer(timer, "contact search");
      contact_handler->update(ghosted_solution, time);
      if (with_matrix && contact_handler->sparsity_outdated())
        make_sparsity();
    }

    TimerOutput::Scope t(timer, "assembly");
    const bool stabilized     = parameters.nonlinear_solver.stabilization > 0;
    const bool track_external = stabilized || dynamics_state;
    const bool dynamic = dynamics_state && dynamics_state->with_inertia();
    typename BulkAssembler<dim>::Targets targets;
    if (with_matrix)
    {
      matrix = 0;
      clear(rhs);
      targets.matrix = &matrix;
      targets.rhs    = &rhs;
    }
    clear(free_residual);
    clear(full_residual);
    targets.free_residual = &free_residual;
    targets.full_residual = &full_residual;
    if (stabilized)
    {
      clear(*stabilization_springs.forces());
      targets.stabilization = stabilization_springs.forces();
    }
    if (track_external)
    {
      clear(external_forces);
      targets.external = &external_forces;
    }
    if (dynamic)
    {
      clear(dynamics_state->inertia_forces());
      targets.inertia = &dynamics_state->inertia_forces();
    }
    bulk_assembler->assemble(displacement(),
                             ghosted_solution,
                             stabilization_springs.anchors(),
                             time,
                             constraints,
                             homogeneous_constraints,
                             dynamics_state.get(),
                             targets);
    t.stop();

    if (contact_handler)
    {
      TimerOutput::Scope contact_timer(timer, "contact assembly");
      clear(contact_force_vector);
      contact_handler->assemble(with_matrix,
                                constraints,
                                homogeneous_constraints,
                                matrix,
                                rhs,
                                free_residual,
                                full_residual,
                                contact_force_vector);
      contact_force_vector.compress(VectorOperation::add);
    }
    if (dynamics_state)
      dynamics_state->add_old_forces(homogeneous_constraints,
                                     free_residual,
                                     with_matrix ? &rhs : nullptr);

    if (with_matrix)
    {
      matrix.compress(VectorOperation::add);
      rhs.compress(VectorOperation::add);
    }
    free_residual.compress(VectorOperation::add);
    full_residual.compress(VectorOperation::add);
    if (stabilized)
      stabilization_springs.forces()->compress(VectorOperation::add);
    if (track_external)
      external_forces.compress(VectorOperation::add);
    if (dynamic)
      dynamics_state->inertia_forces().compress(VectorOperation::add);
    return free_residual.l2_norm();
  }



  template <int dim>
  std::vector<double>
  Problem<dim>::reaction_forces() const
  {
    return model.reaction_forces(full_residual,
                                 dynamics_state ?
                                   &dynamics_state->inertia_forces() :
                                   nullptr);
  }



  template <int dim>
  double
  Problem<dim>::step_limit(const Vector &update, const bool first_iteration)
  {
    const double fraction = parameters.nonlinear_solver.penetration_limit;
    if (!contact_handler || fraction == 0)
      return 1;
    // The first iteration carries the increment's Dirichlet values: a
    // shortened step would leave them unreached.
    if (first_iteration &&
        Utilities::MPI::max(increment_constraints.has_inhomogeneities() ? 1 : 0,
                            mpi_communicator) > 0)
      return 1;
    TimerOutput::Scope t(timer, "contact search");
    const Vector       start = owned_solution;
    owned_solution.add(1., update);
    solution_changed();
    const double limit = contact_handler->step_limit(ghosted_solution,
                                                     time,
                                                     fraction,
                                                     homogeneous_constraints);
    owned_solution     = start;
    solution_changed();
    return limit;
  }



  template <int dim>
  void
  Problem<dim>::after_assembly(const unsigned int iteration,
                               const double       residual)
  {
    if (contact_handler)
      contact_handler->watch_iteration(iteration, residual, log);
  }



  template <int dim>
  NonlinearProblem::Verdict
  Problem<dim>::at_convergence()
  {
    if (contact_handler && !contact_handler->accept_iterate(log))
      return Verdict::iterate;
    // The monitor's count is a running maximum of the solve; the most of
    // every solve of the attempt.
    if (contact_handler)
      counters.n_chattering =
        std::max(counters.n_chattering, contact_handler->n_chattering());
    if (!stabilization_springs.enabled())
      return Verdict::accept;
    return stabilization_springs.at_convergence(ghosted_solution,
                                                external_forces,
                                                reaction_forces());
  }



  template <int dim>
  double
  Problem<dim>::tangent_error()
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(mpi_communicator) == 1,
                ExcMessage("Nonlinear solver/Check tangent works in serial "
                           "runs only."));
    assemble(true, false);
    const Vector start = owned_solution;
    const auto   reset = [&]()
    {
      owned_solution = start;
      solution_changed();
    };
    const types::global_dof_index n_system = layout.system_owned.size();

    // Columns: every free contact dof, every multiplier and every 7th free
    // dof.
    std::vector<types::global_dof_index> columns;
    for (types::global_dof_index j = 0; j < n_system; ++j)
      if (!homogeneous_constraints.is_constrained(j) &&
          ((contact_handler && j < model.dof_handler().n_dofs() &&
            contact_handler->contact_dofs().is_element(j)) ||
           j >= model.dof_handler().n_dofs() || j % 7 == 0))
        columns.push_back(j);

    double error = 0, size = 0;
    // The step relative to the displacement, at least 1e-9 of the model's
    // diameter: free of the length unit.
    const double h =
      1e-7 * std::max(0.01 * GridTools::diameter(model.triangulation()),
                      owned_solution.linfty_norm());
    Vector unit(layout.system_owned, mpi_communicator);
    Vector plus(layout.system_owned, mpi_communicator);
    Vector column(layout.system_owned, mpi_communicator);
    for (const auto j : columns)
    {
      unit    = 0;
      unit[j] = 1;
      matrix.vmult(column, unit);
      homogeneous_constraints.distribute(unit);

      reset();
      owned_solution.add(h, unit);
      solution_changed();
      assemble(false, false);
      plus = free_residual;
      reset();
      owned_solution.add(-h, unit);
      solution_changed();
      assemble(false, false);
      // free_residual holds -R: dR/du_j = -(r+ - r-)/(2h) = K e_j.
      for (types::global_dof_index i = 0; i < n_system; ++i)
        if (!homogeneous_constraints.is_constrained(i))
        {
          const double fd = -(plus[i] - free_residual[i]) / (2 * h);
          error += (column[i] - fd) * (column[i] - fd);
          size += column[i] * column[i];
        }
    }
    reset();
    return size > 0 ? std::sqrt(error / size) : 0.;
  }



  template <int dim>
  void
  Problem<dim>::commit(const double)
  {
    material_state->commit();
    if (dynamics_state)
      dynamics_state->commit(
        displacement(),
        full_residual,
        &contact_force_vector,
        external_forces,
        contact_handler ? contact_handler->frictional_dissipation() : 0.,
        time,
        [this]() { return bulk_assembler->stored_energy(displacement()); });
    if (contact_handler)
      contact_handler->commit();
    stabilization_springs.commit();
    committed_counters = counters;
    counters           = ContactCounters();
  }



  template <int dim>
  void
  Problem<dim>::restore()
  {
    material_state->restore();
    if (contact_handler)
      contact_handler->restore();
    stabilization_springs.restore();
    counters = ContactCounters();
  }



  template <int dim>
  bool
  Problem<dim>::outer_update()
  {
    // Augmented Lagrangian: a Uzawa update of the multipliers, then the
    // same increment again, until the penetration is below the tolerance.
    return contact_handler &&
           contact_handler->outer_update(counters.n_augmentations);
  }



  template <int dim>
  IncrementalProblem::ContactChanges
  Problem<dim>::contact_changes() const
  {
    ContactChanges changes;
    if (!contact_handler)
      return changes;
    for (const auto &pair : contact_handler->pairs())
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      {
        // Frictionless nodes (closed) and open ones have no tangential
        // path.
        const ContactStatus now = pair.current[k].result.status;
        if (!pair.owned[k] ||
            (now != ContactStatus::stick && now != ContactStatus::slip))
          continue;
        ++changes.n_active;
        const ContactStatus before = pair.committed[k].result.status;
        if (before == ContactStatus::open ||
            (now == ContactStatus::stick && before != ContactStatus::stick))
          ++changes.n_changed;
      }
    const MPI_Comm comm = contact_handler->communicator();
    changes.n_active    = Utilities::MPI::sum(changes.n_active, comm);
    changes.n_changed   = Utilities::MPI::sum(changes.n_changed, comm);
    return changes;
  }



  template <int dim>
  typename Problem<dim>::State
  Problem<dim>::state()
  {
    return {*material_state,
            contact_handler.get(),
            dynamics_state.get(),
            stabilization_springs,
            ghosted_solution,
            time};
  }



  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
