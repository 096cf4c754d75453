#ifndef tribos_core_unknowns_layout_h
#define tribos_core_unknowns_layout_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/types.h>

namespace tribos
{
  using namespace dealii;

  /**
   * Who holds which unknowns: the displacement dofs, then the contact
   * multipliers (none unless a pair uses them), in one vector. The matrix,
   * right-hand side, residuals and Newton update live on the system's
   * index sets. Model builds it; everything that makes vectors reads it.
   */
  struct UnknownsLayout
  {
    IndexSet locally_owned_dofs;
    /** The dofs the ghosted vectors hold: those of the own and ghost
     * cells, and the slave nodes this process reads (contact). */
    IndexSet locally_relevant_dofs;
    /** The dofs the constraints and the sparsity pattern know: the
     * relevant ones and every contact dof (contact writes rows and columns
     * of master dofs anywhere). */
    IndexSet coupled_dofs;
    /** The system's unknowns: own, ghosted, and coupled_dofs with the
     * multipliers. */
    IndexSet                system_owned;
    IndexSet                system_relevant;
    IndexSet                system_coupled;
    types::global_dof_index n_multipliers = 0;
    /** Dofs ghosted on this process only because of contact (slave nodes
     * beyond its cells): the contact's share of every ghost update. */
    types::global_dof_index n_contact_ghosts = 0;
  };



  /** What the contact adds to the unknowns (Problem builds it from its
   * ContactHandler, Model::set_unknowns() takes it). */
  struct ContactUnknowns
  {
    /** Dofs beyond the own and ghost cells' that this process reads. */
    IndexSet ghost_dofs;
    /** Every contact dof (coupled anywhere). */
    IndexSet                contact_dofs;
    types::global_dof_index n_multipliers = 0;
    /** This process's multipliers, numbered after the dofs. */
    IndexSet owned_multipliers;
  };
} // namespace tribos

#endif
