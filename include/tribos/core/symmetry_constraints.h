#ifndef tribos_core_symmetry_constraints_h
#define tribos_core_symmetry_constraints_h

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <set>

namespace tribos
{
  using namespace dealii;

  /**
   * Symmetry conditions (zero normal displacement, the tangential one free)
   * on the boundary faces with ids @p ids of the non-artificial cells of
   * @p dof_handler (a vector Lagrange element, components 0..dim-1) into
   * @p constraints, on the cells' geometry @p mapping.
   *
   * At each support point the normals of its symmetry faces (the faces'
   * normals there, curved faces too) are grouped into directions: normals
   * closer than 18 degrees are one direction (the facets of a curved
   * surface), averaged. One direction: u . n = 0. Two (an edge where two
   * planes meet): u is parallel to their intersection. Three that span
   * space (or two in 2D): u = 0.
   *
   * deal.II 9.4's compute_no_normal_flux_constraints() groups the normals
   * by cell instead: where no cell has a face on both planes of an edge
   * (the fan of cells around an edge of an unstructured mesh, tetrahedra
   * or hexahedra split from them; the corner of triangles), it averages
   * the two planes' normals and leaves the edge free to move in their
   * bisecting plane, and where three planes meet on linear tetrahedra it
   * left one direction free. On structured hexahedra, where every cell at
   * an edge has a face on both planes, the two agree.
   */
  template <int dim>
  void
  make_symmetry_constraints(const Mapping<dim>                 &mapping,
                            const DoFHandler<dim>              &dof_handler,
                            const std::set<types::boundary_id> &ids,
                            AffineConstraints<double>          &constraints);
} // namespace tribos

#endif
