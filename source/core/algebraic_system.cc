#include <tribos/core/algebraic_system.h>

#include <deal.II/base/mpi.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribos
{
  AlgebraicSystem::AlgebraicSystem(const UnknownsLayout            &layout,
                                   const AffineConstraints<double> &homogeneous,
                                   const MPI_Comm mpi_communicator)
    : layout(layout)
    , homogeneous_constraints(homogeneous)
    , mpi_communicator(mpi_communicator)
  {
  }



  void
  AlgebraicSystem::attach(LinearSolver &solver)
  {
    linear_solver = &solver;
  }



  TrilinosWrappers::SparseMatrix &
  AlgebraicSystem::system_matrix()
  {
    return matrix;
  }



  NonlinearProblem::Vector &
  AlgebraicSystem::system_rhs()
  {
    return rhs;
  }



  unsigned long
  AlgebraicSystem::pattern_version() const
  {
    return sparsity_version;
  }



  void
  AlgebraicSystem::distribute(Vector &update, const bool first_iteration) const
  {
    (first_iteration ? increment_constraints : homogeneous_constraints)
      .distribute(update);
  }



  NonlinearProblem::Vector &
  AlgebraicSystem::solution()
  {
    return owned_solution;
  }



  void
  AlgebraicSystem::solution_changed()
  {
    ghosted_solution = owned_solution;
    if (layout.n_multipliers == 0)
      return;
    // The displacement part for the finite element evaluations.
    copy_dof_part(owned_solution, ghosted_displacement);
  }



  void
  AlgebraicSystem::copy_dof_part(const Vector &system, Vector &ghosted) const
  {
    Vector owned(layout.locally_owned_dofs, mpi_communicator);
    for (const auto i : layout.locally_owned_dofs)
      owned[i] = system[i];
    owned.compress(VectorOperation::insert);
    ghosted = owned;
  }



  NonlinearProblem::Norms
  AlgebraicSystem::norms(const Vector &v) const
  {
    if (layout.n_multipliers == 0)
      return {v.l2_norm(), 0};
    double                        squared[2] = {0, 0};
    const types::global_dof_index n_dofs     = layout.locally_owned_dofs.size();
    for (const auto i : layout.system_owned)
      squared[i < n_dofs ? 0 : 1] += v[i] * v[i];
    return {std::sqrt(Utilities::MPI::sum(squared[0], mpi_communicator)),
            std::sqrt(Utilities::MPI::sum(squared[1], mpi_communicator))};
  }



  NonlinearProblem::Norms
  AlgebraicSystem::change_scale() const
  {
    Vector change = owned_solution;
    change -= increment_start;
    const Norms of_change = norms(change), of_size = norms(owned_solution);
    return {std::max(of_change.displacement, of_size.displacement),
            std::max(of_change.multipliers, of_size.multipliers)};
  }



  NonlinearProblem::Norms
  AlgebraicSystem::round_off_floor() const
  {
    return {scales.length_floor, scales.traction_floor};
  }



  double
  AlgebraicSystem::stagnation_residual_bound() const
  {
    return scales.stagnation_bound;
  }



  double
  AlgebraicSystem::residual_round_off() const
  {
    const types::global_dof_index n_dofs = layout.locally_owned_dofs.size();
    const Epetra_CrsMatrix       &A      = matrix.trilinos_matrix();
    int                           length;
    double                       *values;
    int                          *indices;
    double                        squared = 0;
    for (int r = 0; r < A.NumMyRows(); ++r)
    {
      // Constrained rows are no part of the free residual (a row's
      // global index is a dof's below n_dofs, a multiplier's above).
      const types::global_dof_index i = A.RowMap().GID(r);
      if (i < n_dofs && homogeneous_constraints.is_constrained(i))
        continue;
      A.ExtractMyRowView(r, length, values, indices);
      double sum = 0;
      for (int k = 0; k < length; ++k)
        if (types::global_dof_index(A.ColMap().GID(indices[k])) < n_dofs)
          sum += std::abs(values[k]);
      squared += sum * sum;
    }
    const double position = scales.position + displacement().linfty_norm();
    return std::numeric_limits<double>::epsilon() * position *
           std::sqrt(Utilities::MPI::sum(squared, mpi_communicator));
  }



  const NonlinearProblem::Vector &
  AlgebraicSystem::displacement() const
  {
    return layout.n_multipliers == 0 ? ghosted_solution : ghosted_displacement;
  }



  const NonlinearProblem::Vector &
  AlgebraicSystem::unknowns() const
  {
    return owned_solution;
  }



  const NonlinearProblem::Vector &
  AlgebraicSystem::contact_forces() const
  {
    return contact_force_vector;
  }



  void
  AlgebraicSystem::reinit(const Scales &round_off)
  {
    const IndexSet &owned = layout.system_owned;
    rhs.reinit(owned, mpi_communicator);
    free_residual.reinit(owned, mpi_communicator);
    full_residual.reinit(owned, mpi_communicator);
    contact_force_vector.reinit(owned, mpi_communicator);
    owned_solution.reinit(owned, mpi_communicator);
    increment_start.reinit(owned, mpi_communicator);
    ghosted_solution.reinit(owned, layout.system_relevant, mpi_communicator);
    if (layout.n_multipliers > 0)
      ghosted_displacement.reinit(layout.locally_owned_dofs,
                                  layout.locally_relevant_dofs,
                                  mpi_communicator);
    external_forces.reinit(owned, mpi_communicator);
    scales = round_off;
  }



  void
  AlgebraicSystem::reinit_matrix(const DynamicSparsityPattern &dsp)
  {
    // Whatever holds on to the old matrix goes first.
    if (linear_solver != nullptr)
      linear_solver->release_matrix();
    matrix.reinit(layout.system_owned,
                  layout.system_owned,
                  dsp,
                  mpi_communicator);
    ++sparsity_version;
  }
} // namespace tribos
