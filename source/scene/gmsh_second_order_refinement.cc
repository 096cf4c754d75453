#include <tribos/scene/gmsh_second_order.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_q1.h>

#include <memory>

namespace tribos
{
  namespace GmshSecondOrder
  {
    template <int dim>
    std::vector<std::vector<Point<dim>>>
    refine(Triangulation<dim>                         &triangulation,
           const unsigned int                          refinement,
           const std::vector<std::vector<Point<dim>>> &coarse_support_points)
    {
      triangulation.refine_global(refinement);
      std::vector<std::vector<Point<dim>>> points(
        triangulation.n_active_cells());
      std::unique_ptr<FiniteElement<dim>> quadratic;
      const bool                          hyper_cube =
        triangulation.all_reference_cells_are_hyper_cube();
      if (hyper_cube)
        quadratic = std::make_unique<FE_Q<dim>>(2);
      else
        quadratic = std::make_unique<FE_SimplexP<dim>>(2);
      const auto &unit_points = quadratic->get_unit_support_points();
      const auto &linear      = StaticMappingQ1<dim>::mapping;

      for (const auto &cell : triangulation.active_cell_iterators())
      {
        auto coarse = cell;
        while (coarse->level() > 0)
          coarse = coarse->parent();
        const auto &coarse_points = coarse_support_points[coarse->index()];
        if (cell->level() == 0)
        {
          points[cell->active_cell_index()] = coarse_points;
          continue;
        }
        // The refined cell is straight inside its straight coarse cell:
        // a point's coarse reference coordinates come from the straight
        // maps (multilinear, or affine on simplices), its position from
        // the coarse quadratic map.
        Tensor<2, dim> jacobian;
        if (!hyper_cube)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              jacobian[d][k] = coarse->vertex(k + 1)[d] - coarse->vertex(0)[d];
        const Tensor<2, dim> inverse = hyper_cube ? jacobian : invert(jacobian);
        for (const auto &unit : unit_points)
        {
          Point<dim> straight, reference;
          if (hyper_cube)
          {
            straight  = linear.transform_unit_to_real_cell(cell, unit);
            reference = linear.transform_real_to_unit_cell(coarse, straight);
          }
          else
          {
            straight = cell->vertex(0);
            for (unsigned int k = 0; k < dim; ++k)
              straight += unit[k] * (cell->vertex(k + 1) - cell->vertex(0));
            reference = Point<dim>(inverse * (straight - coarse->vertex(0)));
          }
          Point<dim> x;
          for (unsigned int i = 0; i < coarse_points.size(); ++i)
            x += quadratic->shape_value(i, reference) * coarse_points[i];
          points[cell->active_cell_index()].push_back(x);
        }
      }
      // deal.II put the new vertices on the straight cells' edges, faces
      // and centres: onto the curved geometry with them (each vertex is
      // its cells' first support points), so that what reads vertices (the
      // contact surfaces) sees the curved mesh.
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = points[cell->active_cell_index()][v];
      return points;
    }



    template std::vector<std::vector<Point<2>>>
    refine(Triangulation<2> &,
           const unsigned int,
           const std::vector<std::vector<Point<2>>> &);
    template std::vector<std::vector<Point<3>>>
    refine(Triangulation<3> &,
           const unsigned int,
           const std::vector<std::vector<Point<3>>> &);
  } // namespace GmshSecondOrder
} // namespace tribos
