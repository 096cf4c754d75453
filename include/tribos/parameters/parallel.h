#ifndef tribos_parameters_parallel_h
#define tribos_parameters_parallel_h

#include <deal.II/base/parameter_handler.h>

namespace tribos
{
  namespace Parameters
  {
    /** Subsection `Parallel`: how the mesh is held under MPI. */
    struct Parallel
    {
      enum class Mesh
      {
        /** Every process holds the whole mesh
         * (parallel::shared::Triangulation) and owns a part of it. */
        shared,
        /** Every process holds only its own cells and one layer of ghost
         * cells (parallel::fullydistributed::Triangulation): the scene is
         * built once on the first process, partitioned and handed out. */
        distributed
      };
      Mesh mesh;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
