/**
 * Scene "ring on foundation" (the paper's ring, 2D only).
 */

#include <tribos/base/text.h>
#include <tribos/scene/mesh_tools.h>
#include <tribos/scene/scene.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <memory>

namespace tribos
{
  using namespace MeshTools;

  namespace
  {
    class RingOnFoundationScene;

    void
    create_ring_on_foundation(const RingOnFoundationScene &s,
                              const unsigned int           refinement,
                              Triangulation<2>            &tria);



    /** Scene "ring on foundation": the lower half of a two-layer ring above a
     * foundation block, the paper's section 4.2, 2D only (subsection Scene/Ring
     * on foundation). */
    class RingOnFoundationScene : public SceneGeometry
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Ring on foundation");
        prm.declare_entry("Inner radius", "90", Text::any_number(), "");
        prm.declare_entry("Interface radius",
                          "95",
                          Text::any_number(),
                          "Radius between the inner (body 0) and the outer "
                          "(body 1) layer.");
        prm.declare_entry("Outer radius", "100", Text::any_number(), "");
        prm.declare_entry("Circumferential cells",
                          "64",
                          Patterns::Integer(2),
                          "Cells along the half circumference.");
        prm.declare_entry("Radial cells per layer", "1", Patterns::Integer(1));
        prm.declare_entry("Foundation width", "260", Text::any_number(), "");
        prm.declare_entry("Foundation height", "50", Text::any_number(), "");
        prm.declare_entry("Foundation cells",
                          "52, 10",
                          Patterns::Anything(),
                          "Cells in x and y of the foundation.");
        prm.declare_entry("Gap",
                          "20",
                          Text::non_negative_number(),
                          "Distance between the ring's bottom and the "
                          "foundation's top (y = 0).");
        prm.declare_entry("Whole ring",
                          "false",
                          Patterns::Bool(),
                          "false: the lower half ring of the paper (its ends, "
                          "the cut at the centre height, are boundaries 2 and "
                          "3); true: the whole ring, 2 x Circumferential cells "
                          "around (no ends), e.g. for a ring dropped in "
                          "dynamics.");
        prm.leave_subsection();
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Ring on foundation");
        inner_radius           = Text::positive(prm, "Inner radius");
        interface_radius       = Text::positive(prm, "Interface radius");
        outer_radius           = Text::positive(prm, "Outer radius");
        circumferential_cells  = prm.get_integer("Circumferential cells");
        radial_cells_per_layer = prm.get_integer("Radial cells per layer");
        foundation_width       = Text::positive(prm, "Foundation width");
        foundation_height      = Text::positive(prm, "Foundation height");
        foundation_cells       = Text::cell_counts(prm, "Foundation cells");
        gap                    = prm.get_double("Gap");
        whole_ring             = prm.get_bool("Whole ring");
        AssertThrow(inner_radius < interface_radius &&
                      interface_radius < outer_radius,
                    dealii::ExcMessage(
                      "Scene/Ring on foundation: need Inner radius < Interface "
                      "radius < Outer radius."));
        AssertThrow(foundation_cells.size() == 2,
                    dealii::ExcMessage("Parameter <Scene/Ring on foundation/"
                                       "Foundation cells> needs two values."));
        prm.leave_subsection();
      }

      /** 2D only: the 3D one refuses. */
      using SceneGeometry::create;
      void
      create(const unsigned int refinement,
             Triangulation<2>  &tria) const override
      {
        create_ring_on_foundation(*this, refinement, tria);
      }

      double                    inner_radius;
      double                    interface_radius;
      double                    outer_radius;
      unsigned int              circumferential_cells;
      unsigned int              radial_cells_per_layer;
      double                    foundation_width;
      double                    foundation_height;
      std::vector<unsigned int> foundation_cells;
      double                    gap;
      /** The whole ring instead of its lower half (dynamics: a ring in
       * flight). */
      bool whole_ring;
    };



    void
    create_ring_on_foundation(const RingOnFoundationScene &s,
                              const unsigned int           refinement,
                              Triangulation<2>            &tria)
    {
      const unsigned int n_radial = s.radial_cells_per_layer << refinement;
      const unsigned int n_circumferential = s.circumferential_cells
                                             << refinement;

      std::vector<std::vector<double>> steps(2);
      for (unsigned int i = 0; i < n_radial; ++i)
        steps[0].push_back((s.interface_radius - s.inner_radius) / n_radial);
      for (unsigned int i = 0; i < n_radial; ++i)
        steps[0].push_back((s.outer_radius - s.interface_radius) / n_radial);
      // Parameter space (r, theta), theta in [pi, 2 pi]: the lower half;
      // the whole ring from the top, theta in [pi/2, 5 pi/2], its seam
      // closed below.
      const bool   whole   = s.whole_ring;
      const double theta_0 = whole ? 0.5 * numbers::PI : numbers::PI;
      const double theta_1 = whole ? 2.5 * numbers::PI : 2 * numbers::PI;
      steps[1].assign((whole ? 2 : 1) * n_circumferential,
                      numbers::PI / n_circumferential);
      Triangulation<2> ring;
      GridGenerator::subdivided_hyper_rectangle(
        ring,
        steps,
        Point<2>(s.inner_radius, theta_0),
        Point<2>(s.outer_radius, theta_1),
        true);
      for (const auto &cell : ring.active_cell_iterators())
        cell->set_material_id(cell->center()[0] < s.interface_radius ? 0 : 1);

      const double centre_height = s.outer_radius + s.gap;
      GridTools::transform(
        [centre_height](const Point<2> &q)
        {
          return Point<2>(q[0] * std::cos(q[1]),
                          centre_height + q[0] * std::sin(q[1]));
        },
        ring);
      if (whole)
      {
        // The seam's two vertex columns coincide: one closed ring, inner
        // surface 0, outer surface 1.
        std::vector<Point<2>>    vertices = ring.get_vertices();
        std::vector<CellData<2>> cells;
        for (const auto &cell : ring.active_cell_iterators())
        {
          CellData<2> data(cell->n_vertices());
          for (const unsigned int v : cell->vertex_indices())
            data.vertices[v] = cell->vertex_index(v);
          data.material_id = cell->material_id();
          cells.push_back(data);
        }
        SubCellData               none;
        std::vector<unsigned int> all;
        GridTools::delete_duplicated_vertices(vertices,
                                              cells,
                                              none,
                                              all,
                                              1e-8 * s.outer_radius);
        GridTools::delete_unused_vertices(vertices, cells, none);
        ring.clear();
        ring.create_triangulation(vertices, cells, none);
        const Point<2> centre(0, centre_height);
        for (const auto &face : ring.active_face_iterators())
          if (face->at_boundary())
            face->set_boundary_id(
              face->center().distance(centre) > s.interface_radius ? 1 : 0);
      }

      Triangulation<2> foundation;
      make_box(foundation,
               {s.foundation_cells[0] << refinement,
                s.foundation_cells[1] << refinement},
               Point<2>(-0.5 * s.foundation_width, -s.foundation_height),
               Point<2>(0.5 * s.foundation_width, 0),
               2,
               10);
      merge_bodies<2>({&ring, &foundation}, tria);
    }
  } // namespace

  const SceneRegistration ring_scene =
    register_scene<RingOnFoundationScene>("ring on foundation");
} // namespace tribos
