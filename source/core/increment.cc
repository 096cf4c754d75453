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
  Problem<dim>::solution_changed()
  {
    ghosted_solution = owned_solution;
    if (n_multipliers == 0)
      return;
    // The displacement part for the finite element evaluations.
    Vector owned(locally_owned_dofs, mpi_communicator);
    for (const auto i : locally_owned_dofs)
      owned[i] = owned_solution[i];
    owned.compress(VectorOperation::insert);
    displacement = owned;
  }



  template <int dim>
  void
  Problem<dim>::begin_increment(const double end_time, const Vector *predictor)
  {
    time            = end_time;
    increment_start = owned_solution;
    ghosted_anchors = ghosted_solution;
    // The start is the converged state (the update test measures the
    // increment's change from it, the stabilization springs hold to it);
    // the first iterate is the predicted one, and the increment's
    // constraints below take it to the Dirichlet values.
    if (predictor != nullptr)
    {
      owned_solution.add(1., *predictor);
      solution_changed();
    }
    n_relaxations = 0;
    if (contact)
      contact->begin_increment();
    if (integrator)
      integrator->set_step(time - committed_time);
    make_constraints(time, false, increment_constraints);
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
    if (integrator)
      r.force_scale = std::max(r.force_scale, inertia_forces.l2_norm());
    return r;
  }



  template <int dim>
  void
  Problem<dim>::distribute(Vector &update, const bool first_iteration) const
  {
    (first_iteration ? increment_constraints : homogeneous_constraints)
      .distribute(update);
  }



  template <int dim>
  NonlinearProblem::Norms
  Problem<dim>::norms(const Vector &v) const
  {
    if (n_multipliers == 0)
      return {v.l2_norm(), 0};
    double                        squared[2] = {0, 0};
    const types::global_dof_index n_dofs     = dof_handler.n_dofs();
    for (const auto i : system_owned)
      squared[i < n_dofs ? 0 : 1] += v[i] * v[i];
    return {std::sqrt(Utilities::MPI::sum(squared[0], mpi_communicator)),
            std::sqrt(Utilities::MPI::sum(squared[1], mpi_communicator))};
  }



  template <int dim>
  NonlinearProblem::Norms
  Problem<dim>::change_scale() const
  {
    Vector change = owned_solution;
    change -= increment_start;
    const Norms of_change = norms(change), of_size = norms(owned_solution);
    return {std::max(of_change.displacement, of_size.displacement),
            std::max(of_change.multipliers, of_size.multipliers)};
  }



  template <int dim>
  void
  Problem<dim>::after_assembly(const unsigned int iteration,
                               const double       residual)
  {
    if (contact)
      contact->watch_iteration(iteration,
                               residual,
                               [this](const std::string &text)
                               { message(text); });
  }



  template <int dim>
  NonlinearProblem::Verdict
  Problem<dim>::at_convergence(IncrementReport &report)
  {
    const auto &p = parameters.nonlinear_solver;
    if (contact && !contact->accept_iterate([this](const std::string &text)
                                            { message(text); }))
      return Verdict::iterate;
    report.n_chattering  = contact ? contact->n_chattering() : 0;
    report.n_relaxations = n_relaxations;
    if (p.stabilization > 0)
    {
      const auto [force, ratio]  = stabilization_measure();
      report.stabilization_force = force;
      report.stabilization_ratio = ratio;
      if (ratio > p.stabilization_limit)
      {
        // The springs still carry part of the load: anchor them at this
        // iterate and go on (pseudo-transient continuation).
        if (n_relaxations >= p.max_stabilization_relaxations)
          throw NonConvergence(
            "the stabilization springs still carry " + to_scientific(ratio) +
            " of the load after " + std::to_string(n_relaxations) +
            " re-anchorings (Nonlinear solver/Stabilization limit = " +
            to_scientific(p.stabilization_limit) +
            ", Maximum stabilization relaxations)");
        ++n_relaxations;
        ghosted_anchors = ghosted_solution;
        return Verdict::iterate;
      }
    }
    return Verdict::accept;
  }



  template <int dim>
  std::pair<double, double>
  Problem<dim>::stabilization_measure() const
  {
    // Axisymmetric: radial resultants cancel around the ring; only the
    // axial component is a force.
    const unsigned int first = parameters.finite_element.axisymmetric ? 1 : 0;
    std::vector<Tensor<1, dim>> per_body(materials.size());
    Tensor<1, dim>              applied;
    for (const auto i : locally_owned_dofs)
    {
      per_body[dof_body[i]][dof_component[i]] += stabilization_forces[i];
      applied[dof_component[i]] += external_forces[i];
    }
    double springs = 0;
    for (auto &f : per_body)
    {
      f = Utilities::MPI::sum(f, mpi_communicator);
      for (unsigned int d = 0; d < first; ++d)
        f[d] = 0;
      springs = std::max(springs, f.norm());
    }
    applied = Utilities::MPI::sum(applied, mpi_communicator);
    for (unsigned int d = 0; d < first; ++d)
      applied[d] = 0;
    double     load      = applied.norm();
    const auto reactions = reaction_forces();
    for (unsigned int c = 0; c + dim <= reactions.size(); c += dim)
    {
      double squared = 0;
      for (unsigned int d = first; d < dim; ++d)
        squared += reactions[c + d] * reactions[c + d];
      load = std::max(load, std::sqrt(squared));
    }
    const double floor =
      parameters.nonlinear_solver.absolute_residual_tolerance;
    if (springs <= floor)
      return {springs, 0.};
    return {springs,
            load > 0 ? springs / load :
                       std::numeric_limits<double>::infinity()};
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
    const types::global_dof_index n_system = system_owned.size();

    // Columns: every free contact dof, every multiplier and every 7th free
    // dof.
    std::vector<types::global_dof_index> columns;
    for (types::global_dof_index j = 0; j < n_system; ++j)
      if (!homogeneous_constraints.is_constrained(j) &&
          ((contact && j < dof_handler.n_dofs() &&
            contact->contact_dofs().is_element(j)) ||
           j >= dof_handler.n_dofs() || j % 7 == 0))
        columns.push_back(j);

    double error = 0, size = 0;
    // The step relative to the displacement, at least 1e-9 of the model's
    // diameter: free of the length unit.
    const double h = 1e-7 * std::max(0.01 * GridTools::diameter(triangulation),
                                     owned_solution.linfty_norm());
    Vector       unit(system_owned, mpi_communicator);
    Vector       plus(system_owned, mpi_communicator);
    Vector       column(system_owned, mpi_communicator);
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
  Problem<dim>::log_iteration(const unsigned int iteration,
                              const double       residual,
                              const double       relative_residual,
                              const double       update_norm,
                              const double       step_length,
                              const double       order)
  {
    convergence_csv->add_row({double(current_step),
                              double(current_increment),
                              time,
                              double(iteration),
                              residual,
                              relative_residual,
                              update_norm,
                              step_length,
                              order});
  }



  template <int dim>
  void
  Problem<dim>::message(const std::string &text)
  {
    pcout << text << std::endl;
  }



  template <int dim>
  void
  Problem<dim>::commit(const double)
  {
    history_old = history_new;
    if (integrator)
      commit_dynamics();
    if (contact)
      contact->commit();
  }



  template <int dim>
  void
  Problem<dim>::restore()
  {
    history_new = history_old;
    if (contact)
      contact->restore();
  }



  template <int dim>
  bool
  Problem<dim>::outer_update(IncrementReport &report)
  {
    // Augmented Lagrangian: a Uzawa update of the multipliers, then the
    // same increment again, until the penetration is below the tolerance.
    return contact && contact->outer_update(report.n_augmentations);
  }



  template <int dim>
  std::string
  Problem<dim>::step_status() const
  {
    if (!contact)
      return "";
    const ContactStatistics s = contact_output->statistics();
    return "  active/stick/slip " + std::to_string(s.n_active) + "/" +
           std::to_string(s.n_stick) + "/" + std::to_string(s.n_slip);
  }



  template <int dim>
  void
  Problem<dim>::end_step(const unsigned int step, const double end_time)
  {
    if (parameters.output.is_output_step(step,
                                         parameters.time_stepping.n_steps))
      write_vtu(step, end_time);
    const unsigned int every = parameters.output.checkpoint_every;
    if (every > 0 &&
        (step % every == 0 || step == parameters.time_stepping.n_steps))
      write_checkpoint(step);
    check_balance(step);
  }



  template <int dim>
  void
  Problem<dim>::failed(const std::string &message)
  {
    if (contact)
      for (const auto &w : contact->run_warnings())
        warn(w);
    write_summary("FAILED: " + message);
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
