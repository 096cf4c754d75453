/**
 * Scenes "block" and "two blocks" (boxes; the README lists their ids).
 */

#include <tribos/scene/mesh_tools.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>

namespace tribos
{
  using namespace MeshTools;

  namespace
  {
    template <int dim>
    void
    create_block(const Parameters::Scene &p, Triangulation<dim> &tria)
    {
      make_box(tria,
               scaled_counts<dim>(p.block.subdivisions,
                                  p.refinement,
                                  "Scene/Block/Subdivisions"),
               to_point<dim>(p.block.lower_corner, "Scene/Block/Lower corner"),
               to_point<dim>(p.block.upper_corner, "Scene/Block/Upper corner"),
               0,
               0);
    }



    template <int dim>
    void
    create_two_blocks(const Parameters::Scene &p, Triangulation<dim> &tria)
    {
      const auto &s = p.two_blocks;
      const auto  lower_size =
        to_point<dim>(s.lower_size, "Scene/Two blocks/Lower block size");
      const auto upper_size =
        to_point<dim>(s.upper_size, "Scene/Two blocks/Upper block size");

      Triangulation<dim> lower, upper;
      make_box(lower,
               scaled_counts<dim>(s.lower_subdivisions,
                                  p.refinement,
                                  "Scene/Two blocks/Lower subdivisions"),
               Point<dim>(),
               lower_size,
               0,
               0);

      Point<dim> origin;
      origin[0]       = s.upper_offset;
      origin[dim - 1] = lower_size[dim - 1] + s.gap;
      make_box(upper,
               scaled_counts<dim>(s.upper_subdivisions,
                                  p.refinement,
                                  "Scene/Two blocks/Upper subdivisions"),
               origin,
               origin + upper_size,
               1,
               10);
      if (s.upper_bottom_radius > 0)
      {
        // Arc bottom: the lowest point stays at the gap, the corners rise
        // by the sagitta, the top stays flat.
        const double R      = s.upper_bottom_radius;
        const double centre = origin[0] + 0.5 * upper_size[0];
        const double height = upper_size[dim - 1];
        GridTools::transform(
          [&](const Point<dim> &x)
          {
            const double dx     = x[0] - centre;
            const double bottom = R - std::sqrt(R * R - dx * dx);
            Point<dim>   y      = x;
            const double eta    = (x[dim - 1] - origin[dim - 1]) / height;
            y[dim - 1] = origin[dim - 1] + bottom + eta * (height - bottom);
            return y;
          },
          upper);
      }
      merge_bodies<dim>({&lower, &upper}, tria);

      if (!s.box_lower.empty())
      {
        const BoundingBox<dim> box(
          {to_point<dim>(s.box_lower, "Scene/Two blocks/Refinement box"),
           to_point<dim>(s.box_upper, "Scene/Two blocks/Refinement box")});
        for (unsigned int cycle = 0; cycle < s.box_refinements; ++cycle)
        {
          for (const auto &cell : tria.active_cell_iterators())
            if (box.point_inside(cell->center()))
              cell->set_refine_flag();
          tria.execute_coarsening_and_refinement();
        }
      }
    }



    /**
     * The Hertz indenter: lower half disc (2D) or the quarter x, y >= 0 of
     * the lower half ball (3D), lowest point at height @p gap above y/z = 0.
     * Ids: 10 curved surface, 11 flat top, 12 plane x = 0, 13 plane y = 0.
     */
  } // namespace

  const SceneRegistration
    block_scene("block", &create_block<2>, &create_block<3>);
  const SceneRegistration two_blocks_scene("two blocks",
                                           &create_two_blocks<2>,
                                           &create_two_blocks<3>);
} // namespace tribos
