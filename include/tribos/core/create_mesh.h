#ifndef tribos_core_create_mesh_h
#define tribos_core_create_mesh_h

#include <tribos/core/warnings.h>
#include <tribos/parameters/all_parameters.h>
#include <tribos/scene/scene.h>

#include <deal.II/distributed/tria_base.h>
#include <deal.II/grid/cell_id.h>

#include <memory>
#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /** Per cell (CellId), its measured contact work: a rebalanced run's
   * partition weights. */
  using CellWeights = std::vector<std::pair<CellId::binary_type, unsigned int>>;

  /** The empty mesh of Parallel/Mesh: parallel::shared (every process holds
   * all of it) or parallel::fullydistributed. */
  template <int dim>
  std::unique_ptr<parallel::TriangulationBase<dim>>
  make_triangulation(const Parameters::AllParameters &parameters,
                     const MPI_Comm                   mpi_communicator);

  /**
   * Build the scene of @p parameters into the empty @p triangulation: the
   * whole mesh (shared), or the first process's mesh partitioned by METIS
   * (with @p weights if given) and this process's cells (distributed). A
   * second-order mesh's curved cells (own cells) into @p curved_cells.
   * Refuses a refinement that would not fit in memory, a simplex model it
   * cannot run, and a boundary id in a condition that the mesh does not
   * have. Collective.
   */
  template <int dim>
  void
  create_mesh(const Parameters::AllParameters  &parameters,
              parallel::TriangulationBase<dim> &triangulation,
              CurvedCells<dim>                 &curved_cells,
              const CellWeights                *weights,
              Warnings                         &warnings);
} // namespace tribos

#endif
