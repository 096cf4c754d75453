#ifndef tribos_parameters_adaptivity_h
#define tribos_parameters_adaptivity_h

#include <deal.II/base/parameter_handler.h>

namespace tribos
{
  namespace Parameters
  {
    /**
     * Subsection `Adaptivity`: a mesh that refines where the error
     * indicator is large and coarsens where it has gone, during the run
     * (a p4est mesh whose coarse cells are the scene's).
     */
    struct Adaptivity
    {
      /** How the cells to refine and to coarsen are chosen. */
      enum class Strategy
      {
        /** The cells that carry the given fractions of the indicator's
         * sum (GridRefinement::refine_and_coarsen_fixed_fraction). */
        fixed_fraction,
        /** The given fractions of the cells
         * (GridRefinement::refine_and_coarsen_fixed_number). */
        fixed_number
      };

      bool enable;
      /** Times the first increment is solved on the mesh the last
       * solution's indicator asked for, before the run goes on. */
      unsigned int initial_cycles;
      /** Adapt after every this many nominal steps (0: never). */
      unsigned int every;
      Strategy     strategy;
      double       refine_fraction;
      double       coarsen_fraction;
      /** Refinement levels above the scene's mesh at most. */
      unsigned int maximum_level;
      /** Coarsening stops at this many levels above the scene's mesh. */
      unsigned int minimum_level;
      /** No refinement beyond this many dofs (0: no limit of its own;
       * the memory's applies anyway, Model::mark()). */
      unsigned long maximum_dofs;
      /** Kelly's jump of the displacement gradient across faces (or none). */
      bool kelly;
      /** The share of the contact indicator in the combined one. */
      double contact_weight;
      /** A slave node whose gap is below this many of its face's sizes is
       * about to close. */
      double closing_gap_factor;
      /** Redo an increment whose contact zone grew onto cells below
       * Maximum level, on the mesh adapted to its solution. */
      bool redo_on_contact_growth;
      /** The cells within this many widths of a pair's contact zone are
       * refined to the finest level flagged in the zone (0: off). */
      double contact_zone_depth;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace tribos

#endif
