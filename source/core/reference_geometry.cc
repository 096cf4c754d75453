/**
 * The reference geometry of a second-order mesh's curved cells on the dofs,
 * checked, and the mapping every evaluation on the cells takes.
 */

#include <tribos/core/reference_geometry.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe_field.h>

#include <sstream>
#include <string>

namespace tribos
{
  template <int dim>
  void
  ReferenceGeometry<dim>::setup(const DoFHandler<dim> &dof_handler,
                                const FESystem<dim>   &fe,
                                const Quadrature<dim> &quadrature,
                                const IndexSet        &locally_owned_dofs,
                                const IndexSet        &locally_relevant_dofs,
                                CurvedCells<dim>      &curved_cells,
                                const unsigned int     degree,
                                Warnings              &warnings,
                                const std::string     &mesh_source,
                                const MPI_Comm         mpi_communicator)
  {
    mapping.reset();
    if (curved_cells.empty())
      return;
    if (degree == 1)
    {
      warnings.warn(
        "the mesh's cells are second-order (curved), and Finite "
        "element/Polynomial degree = 1 takes their vertices only: the "
        "cells are straight, a curved boundary is faceted. Polynomial "
        "degree = 2 keeps the curved geometry.");
      curved_cells = {};
      return;
    }
    // Each dof's reference coordinate is its node's: the support point of
    // the quadratic element (FE_Q(2), FE_SimplexP(2)) the dof's base
    // function belongs to, in the dof's component.
    Vector owned(locally_owned_dofs, mpi_communicator);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const auto &points =
          curved_cells.support_points[cell->active_cell_index()];
        AssertThrow(points.size() == fe.base_element(0).n_dofs_per_cell(),
                    ExcInternalError());
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (locally_owned_dofs.is_element(dofs[i]))
          {
            const auto [component, base] = fe.system_to_component_index(i);
            owned[dofs[i]]               = points[base][component];
          }
      }
    owned.compress(VectorOperation::insert);
    reference_positions.reinit(locally_owned_dofs,
                               locally_relevant_dofs,
                               mpi_communicator);
    reference_positions = owned;
    mapping =
      std::make_unique<MappingFEField<dim, dim, Vector>>(dof_handler,
                                                         reference_positions);
    check_curved_cells(dof_handler,
                       fe,
                       quadrature,
                       mesh_source,
                       mpi_communicator);
  }



  template <int dim>
  void
  ReferenceGeometry<dim>::check_curved_cells(
    const DoFHandler<dim> &dof_handler,
    const FESystem<dim>   &fe,
    const Quadrature<dim> &quadrature,
    const std::string     &mesh_source,
    const MPI_Comm         mpi_communicator) const
  {
    // The Jacobian of the curved map at the quadrature points and at the
    // nodes: a mid-side node far off its edge folds the cell (det J <= 0),
    // and nothing after this would say so.
    std::vector<Point<dim>> points = quadrature.get_points();
    for (const auto &p : fe.base_element(0).get_unit_support_points())
      points.push_back(p);
    FEValues<dim> fe_values(*mapping,
                            fe,
                            Quadrature<dim>(points),
                            update_jacobians | update_quadrature_points);
    std::string   folded;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && folded.empty())
      {
        fe_values.reinit(cell);
        for (unsigned int q = 0; q < points.size() && folded.empty(); ++q)
          if (determinant(Tensor<2, dim>(fe_values.jacobian(q))) <= 0)
          {
            std::ostringstream where;
            where << "the curved cell of body " << cell->material_id()
                  << " with vertex 0 at (" << cell->vertex(0)
                  << ") is folded (its map's Jacobian is not positive at ("
                  << fe_values.quadrature_point(q) << "))";
            folded = where.str();
          }
      }
    for (const auto &message :
         Utilities::MPI::all_gather(mpi_communicator, folded))
      AssertThrow(message.empty(),
                  ExcMessage(mesh_source + ": " + message +
                             ": a mid-side node lies too far from the middle "
                             "of its edge. Mesh again (in gmsh, "
                             "'Mesh.HighOrderOptimize = 2;' untangles "
                             "curved cells), or mesh with "
                             "'Mesh.ElementOrder = 1;'."));
  }



  template <int dim>
  const Mapping<dim> *
  ReferenceGeometry<dim>::curved_mapping() const
  {
    return mapping.get();
  }



  template class ReferenceGeometry<2>;
  template class ReferenceGeometry<3>;
} // namespace tribos
