#ifndef tribos_base_import_constraints_h
#define tribos_base_import_constraints_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * Make @p constraints (not yet closed, built on this process's cells)
   * hold, for every dof in @p relevant that this process does not own, the
   * line its owner has: the owner's, or none if the owner leaves it free.
   *
   * A process computes constraints only from the cells it has, and for a
   * dof at the edge of its ghost layer that is not enough: a corner node
   * of two symmetry planes whose second plane lies beyond the ghost layer
   * gets one constrained component instead of two, and the outer faces of
   * the ghost layer are boundary faces (id 0) of the local mesh, which a
   * condition on boundary 0 would constrain. The owner of a dof has
   * every cell at it (own or ghost), so its line is the complete one; and
   * contact couples a slave node to master faces anywhere in the mesh, so
   * a process writes matrix entries in rows and columns of dofs whose cells
   * it does not have at all. Each process asks the owners of the dofs it
   * does not own and replaces its lines with theirs. One request and one
   * answer per pair of processes that share dofs (deal.II's some_to_some);
   * the volume is that of the ghost layer and the contact surfaces. (deal.II's
   * AffineConstraints::make_consistent_in_parallel does the same with a
   * search that is quadratic in the number of lines.)
   *
   * @p owned_per_process: every process's locally owned dofs (all_gather).
   */
  void
  import_constraints(AffineConstraints<double>   &constraints,
                     const std::vector<IndexSet> &owned_per_process,
                     const IndexSet              &relevant,
                     const MPI_Comm               communicator);

  /**
   * The hanging node constraints of @p dof_handler on the dofs
   * @p relevant (at least the locally relevant ones), each line its
   * owner's (import_constraints(): a line built from this process's cells
   * alone can miss a parent), closed. @p owned_per_process as there.
   */
  template <int dim>
  AffineConstraints<double>
  hanging_node_constraints(const DoFHandler<dim>       &dof_handler,
                           const IndexSet              &relevant,
                           const std::vector<IndexSet> &owned_per_process);
} // namespace tribos

#endif
