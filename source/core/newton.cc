#include <tribos/base/exceptions.h>
#include <tribos/core/problem.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribos
{
  template <int dim>
  void
  Problem<dim>::solve_linear_system(Vector &newton_update)
  {
    TimerOutput::Scope t(timer, "linear solve");
    const auto        &p = parameters.linear_solver;
    if (p.type == "direct")
    {
      // KLU's left-looking LU costs least for small systems; the
      // multifrontal MUMPS wins once fill-in dominates (doc/benchmarks.md).
      const std::string name = (p.direct_solver != "auto" ? p.direct_solver :
                                system_matrix.m() > 5000  ? "Amesos_Mumps" :
                                                            "Amesos_Klu");
      SolverControl     control(1, 0);
      TrilinosWrappers::SolverDirect solver(
        control,
        TrilinosWrappers::SolverDirect::AdditionalData(false, name));
      try
      {
        solver.solve(system_matrix, newton_update, system_rhs);
      }
      catch (const std::exception &e)
      {
        // A singular matrix (e.g. an unsupported body, or a degenerate
        // active set) fails this increment; the load stepping cuts back.
        throw NonConvergence("the direct solver " + name +
                             " failed (singular system?)");
      }
    }
    else
    {
      TrilinosWrappers::PreconditionAMG                 amg;
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      std::vector<std::vector<bool>>                    constant_modes;
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(dim, true),
                                       constant_modes);
      data.constant_modes        = constant_modes;
      data.elliptic              = true;
      data.higher_order_elements = parameters.finite_element.degree > 1;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      amg.initialize(system_matrix, data);

      SolverControl       control(p.max_iterations,
                            p.tolerance * system_rhs.l2_norm());
      SolverGMRES<Vector> solver(control,
                                 SolverGMRES<Vector>::AdditionalData(200));
      try
      {
        solver.solve(system_matrix, newton_update, system_rhs, amg);
      }
      catch (const SolverControl::NoConvergence &e)
      {
        throw NonConvergence("GMRES/AMG did not converge in " +
                             std::to_string(e.last_step) +
                             " iterations (Linear solver/Maximum "
                             "iterations); try Type = direct");
      }
    }
  }



  template <int dim>
  void
  Problem<dim>::apply_update(const Vector &update, const double step)
  {
    if (n_multipliers == 0)
    {
      solution.add(step, update);
      return;
    }
    // Multipliers only in serial runs: every entry is owned here.
    const types::global_dof_index n_dofs = dof_handler.n_dofs();
    for (const auto i : locally_owned_dofs)
      solution[i] += step * update[i];
    solution.compress(VectorOperation::insert);
    std::vector<double> lambda = contact->get_multipliers();
    for (types::global_dof_index i = 0; i < n_multipliers; ++i)
      lambda[i] += step * update[n_dofs + i];
    contact->set_multipliers(lambda);
  }



  template <int dim>
  double
  Problem<dim>::displacement_norm(const Vector &v) const
  {
    if (n_multipliers == 0)
      return v.l2_norm();
    double sum = 0;
    for (const auto i : locally_owned_dofs)
      sum += v[i] * v[i];
    return std::sqrt(Utilities::MPI::sum(sum, mpi_communicator));
  }



  template <int dim>
  double
  Problem<dim>::tangent_error(const double time)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(mpi_communicator) == 1,
                ExcMessage("Nonlinear solver/Check tangent works in serial "
                           "runs only."));
    assemble(true, homogeneous_constraints, time);
    const Vector              start = solution;
    const std::vector<double> start_lambda =
      contact ? contact->get_multipliers() : std::vector<double>();
    const auto reset = [&]()
    {
      solution = start;
      if (n_multipliers > 0)
        contact->set_multipliers(start_lambda);
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
                                     solution.linfty_norm());
    Vector       unit(system_owned, mpi_communicator);
    Vector       plus(system_owned, mpi_communicator);
    Vector       column(system_owned, mpi_communicator);
    for (const auto j : columns)
    {
      unit    = 0;
      unit[j] = 1;
      system_matrix.vmult(column, unit);
      homogeneous_constraints.distribute(unit);

      reset();
      apply_update(unit, h);
      ghosted_solution = solution;
      assemble(false, homogeneous_constraints, time);
      plus = free_residual;
      reset();
      apply_update(unit, -h);
      ghosted_solution = solution;
      assemble(false, homogeneous_constraints, time);
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
    ghosted_solution = solution;
    return size > 0 ? std::sqrt(error / size) : 0.;
  }



  template <int dim>
  double
  Problem<dim>::multiplier_norm(const Vector &v) const
  {
    double sum = 0;
    for (types::global_dof_index i = 0; i < n_multipliers; ++i)
      sum += v[dof_handler.n_dofs() + i] * v[dof_handler.n_dofs() + i];
    return std::sqrt(sum);
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
  IncrementReport
  Problem<dim>::solve_increment(const double       time,
                                const unsigned int step,
                                const unsigned int increment)
  {
    const auto &p = parameters.nonlinear_solver;

    const Vector start      = solution;
    ghosted_increment_start = solution;
    const std::vector<double> start_multipliers =
      n_multipliers > 0 ? contact->get_multipliers() : std::vector<double>();
    if (contact)
      contact->begin_increment();
    unsigned int              n_chattering  = 0;
    unsigned int              n_frozen      = 0;
    unsigned int              n_relaxations = 0;
    unsigned int              relaxed_at    = 0;
    unsigned int              n_solves      = 0;
    AffineConstraints<double> increment_constraints;
    make_constraints(time, false, increment_constraints);

    Vector              newton_update(system_owned, mpi_communicator);
    Vector              difference(locally_owned_dofs, mpi_communicator);
    Vector              line_search_base(locally_owned_dofs, mpi_communicator);
    std::vector<double> multiplier_base;

    double reference   = 0;
    double step_length = std::numeric_limits<double>::quiet_NaN();
    double update_norm = std::numeric_limits<double>::quiet_NaN();
    // The undamped Newton correction: a line search shortens the step
    // taken, not the distance to the solution. Displacements and
    // multipliers (tractions) are measured apart: their units differ.
    double       newton_norm = std::numeric_limits<double>::quiet_NaN();
    double       multiplier_newton_norm = 0;
    double       multiplier_update_norm = 0;
    double       previous[2]            = {-1, -1};
    const double nan = std::numeric_limits<double>::quiet_NaN();

    for (unsigned int iteration = 0;; ++iteration)
    {
      const AffineConstraints<double> &constraints =
        (iteration == 0 ? increment_constraints : homogeneous_constraints);
      const double residual = assemble(true, constraints, time);
      if (!std::isfinite(residual))
        throw NonConvergence("the residual is not finite");
      const double force_scale = full_residual.l2_norm();

      // Chattering detector: status changes of each slave node between the
      // iterations of this increment.
      if (contact)
      {
        const auto &cp = parameters.contact;
        const auto  n  = contact->track_status_changes(cp.chattering_flips);
        n_chattering   = std::max(n_chattering, n);
        const std::string what =
          "chattering: " + std::to_string(n) +
          " slave node(s) changed contact status more than " +
          std::to_string(cp.chattering_flips) +
          " times in this increment (Contact/Chattering flips)";
        if (n > 0 && cp.chattering_remedy == "cutback")
          throw NonConvergence(what + "; remedy: cut the increment "
                                      "(Contact/Chattering remedy = cutback)");
        if (n > 0 && cp.chattering_remedy == "freeze" && n > n_frozen)
        {
          n_frozen = contact->freeze_chattering(cp.chattering_flips);
          pcout << "  " << what << ": held closed for the rest of the "
                << "increment (Contact/Chattering remedy = freeze)"
                << std::endl;
        }
      }

      // Observed order of convergence from three successive residuals
      // after the first solve (iteration 0 precedes the Dirichlet
      // increment and says nothing about the rate).
      double order = nan;
      if (iteration >= 3 && previous[0] > 0 && previous[1] > 0 &&
          residual > 0 && previous[0] != previous[1])
        order = std::log(residual / previous[0]) /
                std::log(previous[0] / previous[1]);
      previous[1] = previous[0];
      previous[0] = residual;

      const double scale = std::max(std::max(reference, residual), force_scale);
      convergence_csv->add_row({double(step),
                                double(increment),
                                time,
                                double(iteration),
                                residual,
                                scale > 0 ? residual / scale : 0.,
                                update_norm,
                                step_length,
                                order});

      bool residual_converged = false;
      if (iteration > 0)
      {
        difference = solution;
        difference -= start;
        const double change =
          std::max(difference.l2_norm(), solution.l2_norm());
        residual_converged =
          residual <= p.residual_tolerance * std::max(reference, force_scale) +
                        p.absolute_residual_tolerance;
        // The multipliers' update against their own change in the
        // increment (or their size, if larger).
        double multiplier_change = 0;
        if (n_multipliers > 0)
        {
          const std::vector<double> lambda         = contact->get_multipliers();
          double                    squared_change = 0, squared = 0;
          for (unsigned int i = 0; i < lambda.size(); ++i)
          {
            squared_change += (lambda[i] - start_multipliers[i]) *
                              (lambda[i] - start_multipliers[i]);
            squared += lambda[i] * lambda[i];
          }
          multiplier_change = std::sqrt(std::max(squared_change, squared));
        }
        const bool update_converged =
          (update_norm <= p.increment_tolerance * change || change == 0) &&
          multiplier_update_norm <=
            p.increment_tolerance * multiplier_change + traction_floor;
        // A Newton correction at round-off level of the solution means the
        // residual cannot get smaller in floating point: accept it, but
        // only if the residual is itself at a level no stress of physical
        // meaning leaves (stagnation_residual_bound), so that a small
        // correction against a large displacement (a body moved far) does
        // not pass off an unconverged iterate. The full correction, not
        // the step the line search took: a step cut to 1/32 on a kink is
        // small without the iterate being converged.
        const bool stagnated = newton_norm <= 1e-12 * change &&
                               multiplier_newton_norm <=
                                 1e-12 * multiplier_change + traction_floor &&
                               residual <= stagnation_residual_bound;
        if ((residual_converged && update_converged) || stagnated)
        {
          if (n_frozen > 0)
          {
            const unsigned int n_tension = contact->n_frozen_in_tension();
            if (n_tension > 0)
              throw NonConvergence(
                std::to_string(n_tension) +
                " chattering node(s) held closed ended in tension or off "
                "the master (Contact/Chattering remedy = freeze): cutting "
                "the increment");
          }
          IncrementReport report;
          if (p.stabilization > 0)
          {
            const auto [force, ratio]  = stabilization_measure();
            report.stabilization_force = force;
            report.stabilization_ratio = ratio;
            if (ratio > p.stabilization_limit)
            {
              // The springs still carry part of the load: anchor them at
              // this iterate and go on (pseudo-transient continuation).
              if (n_relaxations >= p.max_stabilization_relaxations)
                throw NonConvergence(
                  "the stabilization springs still carry " +
                  to_scientific(ratio) + " of the load after " +
                  std::to_string(n_relaxations) +
                  " re-anchorings (Nonlinear solver/Stabilization limit = " +
                  to_scientific(p.stabilization_limit) +
                  ", Maximum stabilization relaxations)");
              ++n_relaxations;
              relaxed_at              = iteration;
              ghosted_increment_start = solution;
              reference               = 0;
              continue;
            }
          }
          n_total_newton_iterations += n_solves;
          report.n_iterations  = n_solves;
          report.residual      = residual;
          report.n_chattering  = n_chattering;
          report.n_relaxations = n_relaxations;
          return report;
        }
        if (iteration - relaxed_at >= p.max_iterations)
          throw NonConvergence("Newton did not converge in " +
                               std::to_string(iteration - relaxed_at) +
                               " iterations (|R| = " + to_scientific(residual) +
                               "; Nonlinear solver/Maximum iterations)");
      }
      reference = std::max(reference, residual);

      if (p.check_tangent && iteration > 0)
      {
        pcout << "  tangent check, iteration " << iteration
              << ": relative error " << tangent_error(time) << std::endl;
        assemble(true, constraints, time);
      }

      newton_update = 0;
      ++n_linear_solves;
      ++n_solves;
      solve_linear_system(newton_update);
      constraints.distribute(newton_update);

      step_length = 1;
      // No line search once the residual is at its tolerance (only the
      // update is still too large): there is nothing left to decrease.
      if (p.line_search && iteration > 0 && !residual_converged)
      {
        // Backtracking (Armijo) on the free residual norm. The first
        // iteration carries the Dirichlet increment and is taken whole.
        line_search_base = solution;
        if (n_multipliers > 0)
          multiplier_base = contact->get_multipliers();
        for (unsigned int k = 0;; ++k)
        {
          solution = line_search_base;
          if (n_multipliers > 0)
            contact->set_multipliers(multiplier_base);
          apply_update(newton_update, step_length);
          ghosted_solution = solution;
          double trial     = std::numeric_limits<double>::infinity();
          try
          {
            trial = assemble(false, homogeneous_constraints, time);
          }
          catch (const InvertedElement &)
          {
          }
          if (trial <= (1 - 1e-4 * step_length) * residual ||
              k >= p.max_line_search_steps)
            break;
          step_length *= 0.5;
        }
      }
      else
      {
        apply_update(newton_update, 1.);
        ghosted_solution = solution;
      }
      newton_norm            = displacement_norm(newton_update);
      update_norm            = step_length * newton_norm;
      multiplier_newton_norm = multiplier_norm(newton_update);
      multiplier_update_norm = step_length * multiplier_newton_norm;
    }
  }

  template class Problem<2>;
  template class Problem<3>;
} // namespace tribos
