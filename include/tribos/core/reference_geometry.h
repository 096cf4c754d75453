#ifndef tribos_core_reference_geometry_h
#define tribos_core_reference_geometry_h

#include <tribos/core/warnings.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

namespace tribos
{
  using namespace dealii;

  /**
   * The curved cells of a second-order mesh as the reference geometry of
   * the finite element: each dof's reference coordinate (its node's, in the
   * dof's component) and a MappingFEField on them, so that every
   * evaluation on a cell sees its curved shape. Nothing for straight cells.
   */
  template <int dim>
  class ReferenceGeometry
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /**
     * Set the geometry of @p curved (own cells) on the dofs of
     * @p dof_handler with Polynomial degree = 2; with degree 1 warn and
     * clear @p curved (the cells stay straight). Refuses a folded cell
     * (checked at the points of @p quadrature and the nodes), the message
     * starting with @p mesh_source (SceneGeometry::mesh_source()).
     * Collective.
     */
    void
    setup(const DoFHandler<dim> &dof_handler,
          const FESystem<dim>   &fe,
          const Quadrature<dim> &quadrature,
          const IndexSet        &owned_dofs,
          const IndexSet        &relevant_dofs,
          CurvedCells<dim>      &curved,
          const unsigned int     degree,
          Warnings              &warnings,
          const std::string     &mesh_source,
          const MPI_Comm         communicator);

    /** The mapping of the curved cells; null: straight cells. */
    const Mapping<dim> *
    curved_mapping() const;

  private:
    /** Refuse a curved cell whose map folds it (a mid-side node far off
     * its edge): det J <= 0 at a quadrature point or node. Collective. */
    void
    check_curved_cells(const DoFHandler<dim> &dof_handler,
                       const FESystem<dim>   &fe,
                       const Quadrature<dim> &quadrature,
                       const std::string     &mesh_source,
                       const MPI_Comm         communicator) const;

    /** Declared before the mapping, which reads it. */
    Vector                        reference_positions;
    std::unique_ptr<Mapping<dim>> mapping;
  };
} // namespace tribos

#endif
