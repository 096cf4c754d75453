/**
 * Scenes "block" and "two blocks" (boxes; the README lists their ids).
 */

#include <tribos/base/text.h>
#include <tribos/scene/mesh_tools.h>
#include <tribos/scene/scene.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace tribos
{
  using namespace MeshTools;

  namespace
  {
    /**
     * Scene "block": one body, an axis-parallel box (subsection
     * Scene/Block).
     */
    class BlockScene : public SceneInBothDimensions<BlockScene>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Block");
        prm.declare_entry("Lower corner",
                          "0, 0, 0",
                          Patterns::Anything(),
                          "Coordinates x, y(, z); the first dim are used.");
        prm.declare_entry("Upper corner",
                          "1, 1, 1",
                          Patterns::Anything(),
                          "Coordinates x, y(, z); the first dim are used.");
        prm.declare_entry("Subdivisions",
                          "4, 4, 4",
                          Patterns::Anything(),
                          "Cells per direction before refinement.");
        prm.leave_subsection();
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Block");
        lower_corner = Text::parse_doubles(prm.get("Lower corner"),
                                           "Scene/Block/Lower corner");
        upper_corner = Text::parse_doubles(prm.get("Upper corner"),
                                           "Scene/Block/Upper corner");
        // A box of zero or negative width has no volume to mesh.
        for (unsigned int d = 0;
             d < std::min(lower_corner.size(), upper_corner.size());
             ++d)
          AssertThrow(upper_corner[d] > lower_corner[d],
                      ExcMessage("Parameters <Scene/Block/Lower corner> = <" +
                                 prm.get("Lower corner") +
                                 "> and <Scene/Block/Upper corner> = <" +
                                 prm.get("Upper corner") +
                                 ">: every coordinate of the upper corner "
                                 "must exceed the lower corner's (the box "
                                 "has no width in coordinate " +
                                 std::to_string(d) + ")."));
        subdivisions = Text::cell_counts(prm, "Subdivisions");
        prm.leave_subsection();
      }

      /** The scene in dim dimensions. */
      template <int dim>
      void
      build(const unsigned int refinement, Triangulation<dim> &tria) const;

    private:
      std::vector<double>       lower_corner;
      std::vector<double>       upper_corner;
      std::vector<unsigned int> subdivisions;
    };



    /**
     * Scene "two blocks": a lower and an upper box with independent
     * (non-matching) meshes, the upper one above the lower one (subsection
     * Scene/Two blocks).
     */
    class TwoBlocksScene : public SceneInBothDimensions<TwoBlocksScene>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Two blocks");
        prm.declare_entry("Lower block size",
                          "1, 0.5, 1",
                          Patterns::Anything(),
                          "Extent per direction; the last used one (y in 2D, "
                          "z in 3D) is the height.");
        prm.declare_entry("Upper block size",
                          "1, 0.5, 1",
                          Patterns::Anything(),
                          "Extent per direction of the upper block.");
        prm.declare_entry("Lower subdivisions",
                          "4, 2, 4",
                          Patterns::Anything(),
                          "Cells per direction of the lower block.");
        prm.declare_entry("Upper subdivisions",
                          "3, 2, 3",
                          Patterns::Anything(),
                          "Cells per direction of the upper block; choose "
                          "counts different from the lower block for "
                          "non-matching interfaces.");
        prm.declare_entry("Gap",
                          "0",
                          Text::non_negative_number(),
                          "Vertical distance between the blocks.");
        prm.declare_entry("Upper block offset",
                          "0",
                          Patterns::Anything(),
                          "Shift of the upper block in x, or in x and y "
                          "(3D: 'x, y'; a punch narrower than the lower block "
                          "placed inside its width).");
        prm.declare_entry("Upper bottom radius",
                          "0",
                          Text::non_negative_number(),
                          "0: flat. Otherwise the bottom of the upper block "
                          "is a circular arc (a cylinder in 3D, axis along "
                          "y) of this radius through the bottom corners, "
                          "lowest in the middle (the ironing punch); the "
                          "block keeps its height at the corners and the gap "
                          "is measured at the lowest point.");
        prm.declare_entry(
          "Refinement box",
          "",
          Patterns::Anything(),
          "Empty: none. Otherwise 'x0, y0(, z0) : x1, y1(, z1)', "
          "the lower and upper corner of a box: the cells of "
          "both blocks whose centre lies inside are refined "
          "<Box refinements> times (hanging nodes where the "
          "box ends).");
        prm.declare_entry("Box refinements",
                          "1",
                          Patterns::Integer(0, 6),
                          "Refinements of the cells in <Refinement box>.");
        prm.leave_subsection();
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Two blocks");
        lower_size         = Text::positive_list(prm, "Lower block size");
        upper_size         = Text::positive_list(prm, "Upper block size");
        lower_subdivisions = Text::cell_counts(prm, "Lower subdivisions");
        upper_subdivisions = Text::cell_counts(prm, "Upper subdivisions");
        gap                = prm.get_double("Gap");
        upper_offset =
          Text::parse_doubles(prm.get("Upper block offset"),
                              "Scene/Two blocks/Upper block offset");
        AssertThrow(upper_offset.size() == 1 || upper_offset.size() == 2,
                    dealii::ExcMessage(
                      "Parameter <Scene/Two blocks/Upper block offset> = <" +
                      prm.get("Upper block offset") +
                      ">: expected one number (x) or two (x, y)."));
        // The blocks' coordinates must resolve their sizes: at an offset
        // of 1e150 the upper block's faces coincide in floating point and
        // lose their boundary ids.
        double extent = gap;
        for (unsigned int d = 0; d < lower_size.size(); ++d)
          extent = std::max(extent, lower_size[d]);
        for (const double offset : upper_offset)
          AssertThrow(std::abs(offset) <= 1e6 * extent,
                      dealii::ExcMessage(
                        "Parameter <Scene/Two blocks/Upper block offset> = <" +
                        prm.get("Upper block offset") +
                        ">: an offset beyond 1e6 times the blocks' size puts "
                        "the upper block out of any reach (and beyond what "
                        "its coordinates resolve)."));
        upper_bottom_radius = prm.get_double("Upper bottom radius");
        AssertThrow(upper_bottom_radius == 0 ||
                      upper_bottom_radius > 0.5 * upper_size[0],
                    dealii::ExcMessage(
                      "Parameter <Scene/Two blocks/Upper bottom radius> = " +
                      std::to_string(upper_bottom_radius) +
                      " must be 0 or larger than half the upper block width."));
        box_refinements = prm.get_integer("Box refinements");
        const auto corners =
          dealii::Utilities::split_string_list(prm.get("Refinement box"), ':');
        AssertThrow(corners.empty() || corners.size() == 2,
                    dealii::ExcMessage(
                      "Parameter <Scene/Two blocks/Refinement box> = <" +
                      prm.get("Refinement box") +
                      ">: expected 'lower corner : upper corner', e.g. "
                      "'0, 0, 0 : 0.5, 1, 1'."));
        box_lower.clear();
        box_upper.clear();
        if (corners.size() == 2)
        {
          box_lower =
            Text::parse_doubles(corners[0], "Scene/Two blocks/Refinement box");
          box_upper =
            Text::parse_doubles(corners[1], "Scene/Two blocks/Refinement box");
          AssertThrow(
            box_lower.size() == box_upper.size(),
            dealii::ExcMessage(
              "Parameter <Scene/Two blocks/Refinement box> = <" +
              prm.get("Refinement box") +
              ">: both corners need the same number of coordinates."));
        }
        prm.leave_subsection();
      }


      std::vector<double>       lower_size;
      std::vector<double>       upper_size;
      std::vector<unsigned int> lower_subdivisions;
      std::vector<unsigned int> upper_subdivisions;
      double                    gap;
      /** Shift of the upper block in x (and y). */
      std::vector<double> upper_offset;
      /** Radius of the upper block's arc-shaped bottom; 0: flat. */
      double upper_bottom_radius;
      /** Lower and upper corner of the box whose cells are refined
       * box_refinements times after the merge (empty: none). */
      std::vector<double> box_lower, box_upper;
      unsigned int        box_refinements;

      /** The scene in dim dimensions. */
      template <int dim>
      void
      build(const unsigned int refinement, Triangulation<dim> &tria) const;
    };



    template <int dim>
    void
    BlockScene::build(const unsigned int  refinement,
                      Triangulation<dim> &tria) const
    {
      make_box(tria,
               scaled_counts<dim>(subdivisions,
                                  refinement,
                                  "Scene/Block/Subdivisions"),
               to_point<dim>(lower_corner, "Scene/Block/Lower corner"),
               to_point<dim>(upper_corner, "Scene/Block/Upper corner"),
               0,
               0);
    }



    template <int dim>
    void
    TwoBlocksScene::build(const unsigned int  refinement,
                          Triangulation<dim> &tria) const
    {
      const auto &s = *this;
      const auto  lower_size =
        to_point<dim>(s.lower_size, "Scene/Two blocks/Lower block size");
      const auto upper_size =
        to_point<dim>(s.upper_size, "Scene/Two blocks/Upper block size");

      Triangulation<dim> lower, upper;
      make_box(lower,
               scaled_counts<dim>(s.lower_subdivisions,
                                  refinement,
                                  "Scene/Two blocks/Lower subdivisions"),
               Point<dim>(),
               lower_size,
               0,
               0);

      Point<dim> origin;
      origin[0] = s.upper_offset[0];
      if (s.upper_offset.size() > 1)
      {
        AssertThrow(dim == 3,
                    dealii::ExcMessage(
                      "Parameter <Scene/Two blocks/Upper block offset>: a "
                      "shift in y needs Dimension = 3; give one number in "
                      "2D."));
        origin[1] = s.upper_offset[1];
      }
      origin[dim - 1] = lower_size[dim - 1] + s.gap;
      make_box(upper,
               scaled_counts<dim>(s.upper_subdivisions,
                                  refinement,
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
      // The arc bottom on its exact manifold, for a mesh refined after
      // this (Adaptivity): set last, so the scene's own refinement above
      // is as it always was.
      if (s.upper_bottom_radius > 0)
      {
        Point<dim> centre;
        centre[0]       = origin[0] + 0.5 * upper_size[0];
        centre[dim - 1] = origin[dim - 1] + s.upper_bottom_radius;
        const types::boundary_id bottom = 10 + 2 * (dim - 1);
        for (const auto &face : tria.active_face_iterators())
          if (face->at_boundary() && face->boundary_id() == bottom)
            face->set_manifold_id(2);
        if constexpr (dim == 2)
          tria.set_manifold(2, SphericalManifold<dim>(centre));
        else
        {
          Tensor<1, dim> axis;
          axis[1] = 1;
          tria.set_manifold(2, CylindricalManifold<dim>(axis, centre));
        }
      }
    }

  } // namespace

  const SceneRegistration block_scene = register_scene<BlockScene>("block");
  const SceneRegistration two_blocks_scene =
    register_scene<TwoBlocksScene>("two blocks");
} // namespace tribos
