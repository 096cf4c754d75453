#include <tribos/base/exceptions.h>
#include <tribos/core/stabilization.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tribos
{
  template <int dim>
  Stabilization<dim>::Stabilization(
    const Parameters::AllParameters       &parameters,
    const MPI_Comm                         communicator,
    const IndexSet                        &owned_dofs,
    const std::vector<unsigned char>      &dof_component,
    const std::vector<types::material_id> &dof_body)
    : parameters(parameters)
    , communicator(communicator)
    , owned_dofs(owned_dofs)
    , dof_component(dof_component)
    , dof_body(dof_body)
  {
  }



  template <int dim>
  bool
  Stabilization<dim>::enabled() const
  {
    return parameters.nonlinear_solver.stabilization > 0;
  }



  template <int dim>
  void
  Stabilization<dim>::reinit(const IndexSet &system_owned,
                             const IndexSet &system_relevant,
                             const std::set<types::material_id> &body_ids)
  {
    bodies.assign(body_ids.begin(), body_ids.end());
    anchor_vector.reinit(system_owned, system_relevant, communicator);
    force_vector.reinit(system_owned, communicator);
  }



  template <int dim>
  void
  Stabilization<dim>::begin_solve(const Vector &ghosted_solution)
  {
    anchor_vector = ghosted_solution;
    n_relaxations = 0;
  }



  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  Stabilization<dim>::anchors() const
  {
    return anchor_vector;
  }



  template <int dim>
  TrilinosWrappers::MPI::Vector *
  Stabilization<dim>::forces()
  {
    return enabled() ? &force_vector : nullptr;
  }



  template <int dim>
  NonlinearProblem::Verdict
  Stabilization<dim>::at_convergence(const Vector &ghosted_solution,
                                     const Vector &external_forces,
                                     const std::vector<double> &reactions)
  {
    const auto &p             = parameters.nonlinear_solver;
    const auto [force, ratio] = measure(external_forces, reactions);
    attempt.force             = force;
    attempt.ratio             = ratio;
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
      ++attempt.relaxations;
      anchor_vector = ghosted_solution;
      return NonlinearProblem::Verdict::iterate;
    }
    return NonlinearProblem::Verdict::accept;
  }



  template <int dim>
  std::pair<double, double>
  Stabilization<dim>::measure(const Vector              &external_forces,
                              const std::vector<double> &reactions) const
  {
    // Axisymmetric: radial resultants cancel around the ring; only the
    // axial component is a force.
    const unsigned int first = parameters.finite_element.axisymmetric ? 1 : 0;
    std::vector<Tensor<1, dim>> per_body(bodies.size());
    Tensor<1, dim>              applied;
    for (const auto i : owned_dofs)
    {
      const auto body =
        std::lower_bound(bodies.begin(), bodies.end(), dof_body[i]);
      per_body[body - bodies.begin()][dof_component[i]] += force_vector[i];
      applied[dof_component[i]] += external_forces[i];
    }
    double springs = 0;
    for (auto &f : per_body)
    {
      f = Utilities::MPI::sum(f, communicator);
      for (unsigned int d = 0; d < first; ++d)
        f[d] = 0;
      springs = std::max(springs, f.norm());
    }
    applied = Utilities::MPI::sum(applied, communicator);
    for (unsigned int d = 0; d < first; ++d)
      applied[d] = 0;
    double load = applied.norm();
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
  void
  Stabilization<dim>::commit()
  {
    committed = attempt;
    attempt   = Record();
    largest   = std::max(largest, committed.ratio);
  }



  template <int dim>
  void
  Stabilization<dim>::restore()
  {
    attempt = Record();
  }



  template <int dim>
  const typename Stabilization<dim>::Record &
  Stabilization<dim>::last_increment() const
  {
    return committed;
  }



  template <int dim>
  double
  Stabilization<dim>::largest_ratio() const
  {
    return largest;
  }



  template <int dim>
  void
  Stabilization<dim>::set_largest_ratio(const double ratio)
  {
    largest = ratio;
  }



  template class Stabilization<2>;
  template class Stabilization<3>;
} // namespace tribos
