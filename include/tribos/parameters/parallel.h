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
      /**
       * METIS' weight of a cell with a face on a slave surface (a bulk
       * cell weighs 1): the slave nodes' contact work falls to the
       * processes that own them, and where the contact zone lies on one
       * process the others wait for it. summary.txt reports the measured
       * balance and the weight that would even it out.
       */
      unsigned int contact_cell_weight;
      /**
       * Mesh = distributed: at the end of a step whose contact work is
       * this many times larger on the busiest process than on the idlest,
       * the run partitions its mesh again, every cell weighted by the
       * measured work of its slave nodes, and goes on from the step's
       * state (a checkpoint and restart within the run). 0: never.
       */
      double rebalance_threshold;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
