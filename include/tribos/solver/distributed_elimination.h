#ifndef tribos_solver_distributed_elimination_h
#define tribos_solver_distributed_elimination_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_Import.h>

#include <functional>
#include <memory>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * MultiplierElimination on a distributed saddle-point matrix: the
   * preconditioner of the iterative multiplier solve on any number of
   * processes.
   *
   * A node's multipliers belong to the process that owns the node, so
   * the rows H_k and D_k of its block are that process's own rows; the
   * block's columns G_k lie in the rows of the node's slave and master
   * dofs, which other processes may own. Each process sends the entries of
   * its displacement rows in multiplier columns to the owners of those
   * multipliers (with the rows' diagonal entries, which scale the
   * regularization); the owner regularizes and inverts the block as the
   * serial elimination does (regularized_block_inverse) and adds - G_k
   * D~_k^-1 H_k to the eliminated matrix, in rows other processes may own.
   * The volume sent is that of the contact interface, not the mesh.
   *
   * The eliminated matrix has the displacement rows of the system, in the
   * same order on each process (the system's own rows are its dofs, then
   * its multipliers), so the near-null space of the system's rows serves
   * AMG on it unchanged.
   */
  class DistributedElimination
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /** Solves the eliminated system, or approximates its solution: y
     * (overwritten), right-hand side (displacement rows). */
    using ReducedSolve = std::function<void(Vector &, const Vector &)>;

    /**
     * Prepare for @p A's pattern, whose unknowns from @p first on are
     * multipliers in blocks of @p size, and build the eliminated matrix's
     * pattern. False (on every process) where the elimination does not
     * apply: a multiplier row coupled to another node's multipliers.
     */
    bool
    prepare(const TrilinosWrappers::SparseMatrix &A,
            const types::global_dof_index         first,
            const unsigned int                    size);

    /** The values of K - G D~^-1 H, with the regularization @p alpha. */
    void
    eliminate(const TrilinosWrappers::SparseMatrix &A, const double alpha);

    /** The eliminated matrix (displacement rows and columns). */
    const TrilinosWrappers::SparseMatrix &
    matrix() const
    {
      return reduced;
    }

    /** @p y = P^-1 @p z (system vectors), the eliminated system solved by
     * @p solve. */
    void
    apply(const Vector &z, Vector &y, const ReducedSolve &solve);

  private:
    /** A block of this process: its rows and columns (global indices) and
     * the values of G, H and D~^-1 as in regularized_block_inverse. */
    struct Block
    {
      types::global_dof_index              first = 0;
      std::vector<types::global_dof_index> rows, columns;
      std::vector<double>                  g, row_diagonal, h, d, inverse;
    };

    /** Receive every block's G (and its rows' diagonal entries) from the
     * processes owning its rows; @p pattern: the rows are new. */
    void
    gather_columns(const TrilinosWrappers::SparseMatrix &A, const bool pattern);

    /** Read the rows H and D of the blocks from @p A; false if one couples
     * to another block. */
    bool
    read_rows(const TrilinosWrappers::SparseMatrix &A, const bool pattern);

    types::global_dof_index first = 0;
    unsigned int            size  = 0;
    MPI_Comm                communicator;
    /** This process's displacement rows; the columns of H of its blocks
     * (the ghosts of the vectors apply() and eliminate() read). */
    IndexSet owned, h_columns;
    /**
     * Per local column of the system matrix, its local column in the
     * eliminated matrix (-1: a multiplier); per owned row, the position of
     * its diagonal entry in the system matrix's row; the owned rows with
     * entries in multiplier columns. The system's own rows are its dofs
     * first, so a dof's local row is the same in both matrices.
     */
    std::vector<int> column_in_reduced, diagonal_position, coupled_rows;
    /** y_reduced's values into y_ghosted (owned and H's columns). */
    std::unique_ptr<Epetra_Import> import;
    /** Per block of the whole system (global number), its process. */
    std::vector<unsigned int>      block_owner;
    std::vector<Block>             blocks;
    TrilinosWrappers::SparseMatrix reduced;
    Vector                         f, y_reduced, y_ghosted, diagonal;
  };
} // namespace tribos

#endif
