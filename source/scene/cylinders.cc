/**
 * Scenes "cylinder over block" (the Hertz indenter) and "cylinder compression"
 * (the paper's cylinder, structured or split-corner section).
 */

#include <tribos/base/text.h>
#include <tribos/scene/mesh_tools.h>
#include <tribos/scene/scene.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <cmath>
#include <memory>

namespace tribos
{
  using namespace MeshTools;

  namespace
  {
    class CylinderOverBlockScene;
    class CylinderCompressionScene;

    template <int dim>
    void
    create_cylinder_over_block(const CylinderOverBlockScene &s,
                               const unsigned int            refinement,
                               Triangulation<dim>           &tria);

    template <int dim>
    void
    create_cylinder_compression(const CylinderCompressionScene &s,
                                const unsigned int              refinement,
                                Triangulation<dim>             &tria);



    /** Scene "cylinder over block": the lower half of a cylinder (2D) or a
     * quarter of the lower hemisphere (3D) above a block, the Hertz geometry
     * (subsection Scene/Cylinder over block). */
    class CylinderOverBlockScene
      : public SceneInBothDimensions<CylinderOverBlockScene>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Cylinder over block");
        prm.declare_entry("Radius",
                          "1",
                          Text::any_number(),
                          "Indenter radius.");
        prm.declare_entry("Gap",
                          "0",
                          Text::non_negative_number(),
                          "Distance between the indenter's lowest point and "
                          "the block's top.");
        prm.declare_entry("Block width",
                          "4",
                          Text::any_number(),
                          "2D: the block spans x in [-w/2, w/2]; 3D (quarter "
                          "model): x, y in [0, w/2].");
        prm.declare_entry("Block height",
                          "2",
                          Text::any_number(),
                          "Depth of the block below y = 0 (2D) or z = 0 (3D).");
        prm.declare_entry("Block subdivisions",
                          "8, 4",
                          Patterns::Anything(),
                          "Cells in the horizontal and the vertical direction "
                          "(3D: both horizontal directions get the first).");
        prm.declare_entry("Indenter refinements",
                          "3",
                          Patterns::Integer(0, 8),
                          "Global refinements of the indenter's coarse mesh.");
        prm.declare_entry("With block",
                          "true",
                          Patterns::Bool(),
                          "false: the indenter alone (e.g. on a rigid plane).");
        prm.declare_entry(
          "Indenter shape",
          "lower half",
          Patterns::Selection("lower half|whole|meridian"),
          "lower half: the lower half of the cylinder (2D) or a quarter of the "
          "lower hemisphere (3D), loaded on its flat top (boundary 11). whole: "
          "the whole disc (2D only), e.g. a body in flight. meridian: the half "
          "disc x >= 0 (2D only), the meridian section of a whole sphere for "
          "Finite element/Axisymmetric = true, its axis boundary 12. The "
          "curved surface is boundary 10.");
        prm.declare_entry("Contact refinements",
                          "0",
                          Patterns::Integer(0, 10),
                          "Local refinements of the cells near the initial "
                          "contact point (hanging nodes; curved boundary kept "
                          "on its manifold).");
        prm.declare_entry("Refinement radius",
                          "0.25",
                          Text::non_negative_number(),
                          "Cells that reach within this distance of the "
                          "initial contact point (a vertex or the centre "
                          "inside it), relative to the radius, are refined "
                          "in every contact refinement.");
        prm.leave_subsection();
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Cylinder over block");
        radius               = Text::positive(prm, "Radius");
        gap                  = prm.get_double("Gap");
        block_width          = Text::positive(prm, "Block width");
        block_height         = Text::positive(prm, "Block height");
        block_subdivisions   = Text::cell_counts(prm, "Block subdivisions");
        indenter_refinements = prm.get_integer("Indenter refinements");
        with_block           = prm.get_bool("With block");
        indenter_shape       = prm.get("Indenter shape");
        contact_refinements  = prm.get_integer("Contact refinements");
        refinement_radius    = prm.get_double("Refinement radius");
        AssertThrow(block_subdivisions.size() >= 2,
                    dealii::ExcMessage(
                      "Parameter <Scene/Cylinder over block/Block "
                      "subdivisions> needs two values: horizontal, vertical."));
        prm.leave_subsection();
      }

      /** The scene in dim dimensions. */
      template <int dim>
      void
      build(const unsigned int refinement, Triangulation<dim> &tria) const
      {
        create_cylinder_over_block(*this, refinement, tria);
      }

      double                    radius;
      double                    gap;
      double                    block_width;
      double                    block_height;
      std::vector<unsigned int> block_subdivisions;
      unsigned int              indenter_refinements;
      bool                      with_block;
      /** "lower half", "whole" or "meridian". */
      std::string  indenter_shape;
      unsigned int contact_refinements;
      double       refinement_radius;
    };



    /** Scene "cylinder compression": one eighth of a cylinder (3D) or a quarter
     * of its meridian section (2D), the paper's section 4.1 (subsection
     * Scene/Cylinder compression). */
    class CylinderCompressionScene
      : public SceneInBothDimensions<CylinderCompressionScene>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Cylinder compression");
        prm.declare_entry("Radius", "6.35", Text::any_number(), "");
        prm.declare_entry("Height",
                          "12.7",
                          Text::any_number(),
                          "Full height; the model holds the upper half.");
        prm.declare_entry("Radial refinements",
                          "2",
                          Patterns::Integer(0, 8),
                          "Refinements of the quarter-disc cross section.");
        prm.declare_entry("Axial cells",
                          "4",
                          Patterns::Integer(1),
                          "Cells over the half height before refinement "
                          "(structured mesh only).");
        prm.declare_entry(
          "Mesh",
          "structured",
          Patterns::Selection("structured|split corner"),
          "structured: the meridian section is a grid (2D: 2^r x axial "
          "cells; 3D: quarter disc extruded), and the rim corner (top face "
          "meets lateral face) is the corner of one cell, which goes flat "
          "when the side folds onto the plate. split corner: the meridian "
          "section is three blocks, each refined r times, two of which meet "
          "at the rim corner along its bisector, so a fold opens each of "
          "them to about 90 degrees; in 3D the outer 3/4 of the radius is "
          "this section swept around the axis, the inner 1/4 a quarter disc "
          "extruded (Axial cells unused).");
        prm.declare_entry("Imperfection",
                          "0",
                          Patterns::Double(0, 0.5),
                          "Relative reduction of the radius at the mid plane "
                          "z = 0, decreasing linearly to 0 at z = h/2 (the "
                          "necking bar's trigger: 0.018).");
        prm.leave_subsection();
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Cylinder compression");
        radius             = Text::positive(prm, "Radius");
        height             = Text::positive(prm, "Height");
        radial_refinements = prm.get_integer("Radial refinements");
        axial_cells        = prm.get_integer("Axial cells");
        split_corner       = (prm.get("Mesh") == "split corner");
        imperfection       = prm.get_double("Imperfection");
        prm.leave_subsection();
      }

      /** The scene in dim dimensions. */
      template <int dim>
      void
      build(const unsigned int refinement, Triangulation<dim> &tria) const
      {
        create_cylinder_compression(*this, refinement, tria);
      }

      double       radius;
      double       height;
      unsigned int radial_refinements;
      unsigned int axial_cells;
      /** Meridian section of three blocks, the rim corner split. */
      bool split_corner;
      /** Relative radius reduction at the mid plane (linear taper). */
      double imperfection;
    };



    template <int dim>
    void
    make_indenter(Triangulation<dim> &tria,
                  const double        radius,
                  const double        gap,
                  const unsigned int  n_refinements,
                  const std::string  &shape)
    {
      AssertThrow(shape == "lower half" || dim == 2,
                  ExcMessage("Parameter <Scene/Cylinder over block/Indenter "
                             "shape> = <" +
                             shape +
                             "> is available in 2D only (in 3D: lower half; "
                             "a whole sphere is the axisymmetric meridian)."));
      if (shape == "whole")
      {
        GridGenerator::hyper_ball(tria, Point<dim>(), radius);
        tria.refine_global(n_refinements);
      }
      else if (shape == "meridian")
      {
        // Half disc x >= 0: the (r, z) section of a sphere.
        GridGenerator::half_hyper_ball(tria, Point<dim>(), radius);
        tria.refine_global(n_refinements);
      }
      else if (dim == 2)
      {
        // Half disc x >= 0, then rotate by -90 degrees: y <= 0.
        GridGenerator::half_hyper_ball(tria, Point<dim>(), radius);
        tria.refine_global(n_refinements);
        GridTools::transform(
          [](const Point<dim> &x)
          {
            Point<dim> y;
            y[0] = x[1];
            y[1] = -x[0];
            return y;
          },
          tria);
      }
      else
      {
        // Octant x, y, z >= 0, then rotate by -90 degrees about x.
        GridGenerator::quarter_hyper_ball(tria, Point<dim>(), radius);
        tria.refine_global(n_refinements);
        GridTools::transform(
          [](const Point<dim> &x)
          {
            Point<dim> y;
            y[0] = x[0];
            y[1] = x[dim - 1];
            y[2] = -x[1];
            return y;
          },
          tria);
      }
      Tensor<1, dim> shift;
      shift[dim - 1] = radius + gap;
      GridTools::shift(shift, tria);

      const double tolerance = 1e-10 * radius;
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
        {
          const Point<dim> c = face->center();
          if (shape == "meridian" && std::abs(c[0]) < tolerance)
            face->set_boundary_id(12);
          else if (shape != "lower half")
            face->set_boundary_id(10);
          else if (std::abs(c[dim - 1] - (radius + gap)) < tolerance)
            face->set_boundary_id(11);
          else if (dim == 3 && std::abs(c[0]) < tolerance)
            face->set_boundary_id(12);
          else if (dim == 3 && std::abs(c[1]) < tolerance)
            face->set_boundary_id(13);
          else
            face->set_boundary_id(10);
        }
      set_material_id(tria, 1);
    }



    template <int dim>
    void
    create_cylinder_over_block(const CylinderOverBlockScene &s,
                               const unsigned int            refinement,
                               Triangulation<dim>           &tria)
    {
      Triangulation<dim> block, indenter;

      std::vector<unsigned int> counts(dim, s.block_subdivisions[0]);
      counts[dim - 1] = s.block_subdivisions[1];
      for (auto &n : counts)
        n <<= refinement;
      Point<dim> p1, p2;
      for (unsigned int d = 0; d < dim - 1; ++d)
      {
        p1[d] = (dim == 2 ? -0.5 * s.block_width : 0.);
        p2[d] = 0.5 * s.block_width;
      }
      p1[dim - 1] = -s.block_height;
      make_box(block, counts, p1, p2, 0, 0);

      make_indenter(indenter,
                    s.radius,
                    s.gap,
                    s.indenter_refinements + refinement,
                    s.indenter_shape);
      if (s.with_block)
        merge_bodies<dim>({&block, &indenter}, tria);
      else
        merge_bodies<dim>({&indenter}, tria);

      // Local refinement at the contact point: the curved surface goes
      // back on its exact manifold so that new vertices lie on the sphere.
      Point<dim> centre, contact_point;
      centre[dim - 1]        = s.radius + s.gap;
      contact_point[dim - 1] = 0.5 * s.gap;
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == 10)
          face->set_all_manifold_ids(1);
      tria.set_manifold(1, SphericalManifold<dim>(centre));
      for (unsigned int cycle = 0; cycle < s.contact_refinements; ++cycle)
      {
        for (const auto &cell : tria.active_cell_iterators())
        {
          // Refine every cell that reaches into the refinement disc.
          double distance = cell->center().distance(contact_point);
          for (const unsigned int v : cell->vertex_indices())
            distance =
              std::min(distance, cell->vertex(v).distance(contact_point));
          if (distance < s.refinement_radius * s.radius)
            cell->set_refine_flag();
        }
        tria.execute_coarsening_and_refinement();
      }
    }



    /**
     * Meridian section [r0, R] x [0, z_top] in three blocks, each refined
     * @p n_refinements times: one at the inner bottom corner and two that
     * meet along the line from the section's centre to the rim corner
     * (R, z_top). The rim corner is then a vertex of two cells: when the
     * lateral face folds onto the plate, the corner's 180 degrees are
     * shared by two cells instead of flattening one.
     */
    void
    create_split_corner_section(Triangulation<2>  &section,
                                const double       r0,
                                const double       R,
                                const double       z_top,
                                const unsigned int n_refinements)
    {
      const double                rm = 0.5 * (r0 + R), zm = 0.5 * z_top;
      const std::vector<Point<2>> vertices = {Point<2>(r0, 0),
                                              Point<2>(rm, 0),
                                              Point<2>(R, 0),
                                              Point<2>(r0, zm),
                                              Point<2>(rm, zm),
                                              Point<2>(r0, z_top),
                                              Point<2>(R, z_top)};
      std::vector<CellData<2>>    cells(3);
      cells[0].vertices = {0, 1, 3, 4};
      cells[1].vertices = {1, 2, 4, 6};
      cells[2].vertices = {3, 4, 5, 6};
      section.create_triangulation(vertices, cells, SubCellData());
      section.refine_global(n_refinements);
    }



    /**
     * The section (r, z) swept over the quarter turn x, y >= 0 in
     * @p n_angles equal angles: hexahedra r x z x angle.
     */
    void
    sweep_section(const Triangulation<2> &section,
                  const unsigned int      n_angles,
                  Triangulation<3>       &result)
    {
      const std::vector<Point<2>> &points     = section.get_vertices();
      const unsigned int           n_vertices = points.size();
      std::vector<Point<3>>        vertices;
      for (unsigned int j = 0; j <= n_angles; ++j)
      {
        const double angle = 0.5 * numbers::PI * j / n_angles;
        for (const Point<2> &p : points)
          vertices.emplace_back(p[0] * std::cos(angle),
                                p[0] * std::sin(angle),
                                p[1]);
      }
      std::vector<CellData<3>> cells;
      for (const auto &cell : section.active_cell_iterators())
        for (unsigned int j = 0; j < n_angles; ++j)
        {
          // (r, z, -angle) is right-handed: the later angle comes first.
          CellData<3> hex;
          hex.vertices.resize(8);
          for (unsigned int v = 0; v < 4; ++v)
          {
            hex.vertices[v]     = (j + 1) * n_vertices + cell->vertex_index(v);
            hex.vertices[v + 4] = j * n_vertices + cell->vertex_index(v);
          }
          cells.push_back(hex);
        }
      result.create_triangulation(vertices, cells, SubCellData());
    }



    /**
     * One eighth of the cylinder (3D): quarter disc x, y >= 0 extruded over
     * the upper half height z in [0, h/2]. 2D: the meridian section
     * [0, r] x [0, h/2]. Ids: 0 plane x = 0, 1 plane y = 0, 2 mid plane,
     * 3 top (plate), 4 lateral surface.
     */
    template <int dim>
    void
    create_cylinder_compression(const CylinderCompressionScene &s,
                                const unsigned int              refinement,
                                Triangulation<dim>             &tria)
    {
      const unsigned int axial_cells = s.axial_cells << refinement;
      const double       tolerance   = 1e-10 * s.radius;

      const unsigned int n_refinements = s.radial_refinements + refinement;
      if (s.split_corner)
      {
        if constexpr (dim == 2)
          create_split_corner_section(tria,
                                      0.,
                                      s.radius,
                                      0.5 * s.height,
                                      n_refinements);
        else
        {
          // Inner quarter of the radius: a quarter disc extruded in the
          // section's layers at r0; outside: the section swept around in
          // the disc's arc segments. The disc is refined once less than
          // the section: the fold-over is axisymmetric and needs its
          // resolution in the section, while each refinement of the
          // angles doubles the ring's cells (r = 3: 2304 cells).
          const double     r0 = 0.25 * s.radius;
          Triangulation<2> section;
          create_split_corner_section(section,
                                      r0,
                                      s.radius,
                                      0.5 * s.height,
                                      n_refinements);
          std::vector<double> layers;
          for (const Point<2> &v : section.get_vertices())
            if (std::abs(v[0] - r0) < tolerance)
              layers.push_back(v[1]);
          std::sort(layers.begin(), layers.end());
          Triangulation<2> disc, flat;
          GridGenerator::quarter_hyper_ball(disc, Point<2>(), r0);
          disc.refine_global(std::max(n_refinements, 1u) - 1);
          GridGenerator::flatten_triangulation(disc, flat);
          Triangulation<3> core, ring;
          GridGenerator::extrude_triangulation(flat, layers, core);
          sweep_section(section, 1u << std::max(n_refinements, 1u), ring);
          GridGenerator::merge_triangulations(core,
                                              ring,
                                              tria,
                                              1e-8 * s.radius);
        }
      }
      else if constexpr (dim == 2)
      {
        GridGenerator::subdivided_hyper_rectangle(
          tria,
          {(1u << n_refinements), axial_cells},
          Point<2>(),
          Point<2>(s.radius, 0.5 * s.height));
      }
      else
      {
        Triangulation<2> disc;
        GridGenerator::quarter_hyper_ball(disc, Point<2>(), s.radius);
        disc.refine_global(n_refinements);
        Triangulation<2> flat;
        GridGenerator::flatten_triangulation(disc, flat);
        GridGenerator::extrude_triangulation(flat,
                                             axial_cells + 1,
                                             0.5 * s.height,
                                             tria);
      }

      if (s.imperfection > 0)
        GridTools::transform(
          [&s](const Point<dim> &x)
          {
            const double factor =
              1. - s.imperfection * (1. - 2. * x[dim - 1] / s.height);
            Point<dim> y = x;
            for (unsigned int d = 0; d < dim - 1; ++d)
              y[d] *= factor;
            return y;
          },
          tria);

      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
        {
          const Point<dim> c = face->center();
          if (std::abs(c[dim - 1] - 0.5 * s.height) < tolerance)
            face->set_boundary_id(3);
          else if (std::abs(c[dim - 1]) < tolerance)
            face->set_boundary_id(2);
          else if (std::abs(c[0]) < tolerance)
            face->set_boundary_id(0);
          else if (dim == 3 && std::abs(c[1]) < tolerance)
            face->set_boundary_id(1);
          else
            face->set_boundary_id(4);
        }
      set_material_id(tria, 0);
    }



    /**
     * Lower half of a two-layer ring (inner layer body 0, outer layer body
     * 1) with its bottom at y = gap, over a foundation (body 2) with its top
     * at y = 0. Ids: 0 inner surface, 1 outer surface, 2 left end, 3 right
     * end; foundation 10 left, 11 right, 12 bottom, 13 top.
     */
  } // namespace

  const SceneRegistration cylinder_over_block_scene =
    register_scene<CylinderOverBlockScene>("cylinder over block");
  const SceneRegistration cylinder_compression_scene =
    register_scene<CylinderCompressionScene>("cylinder compression");
} // namespace tribos
