/**
 * Scene "ring on foundation" (the paper's ring, 2D only).
 */

#include <tribos/scene/mesh_tools.h>
#include <tribos/scene/scene.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>

namespace tribos
{
  using namespace MeshTools;

  namespace
  {
    void
    create_ring_on_foundation(const Parameters::Scene &p,
                              Triangulation<2>        &tria)
    {
      const auto        &s        = p.ring_on_foundation;
      const unsigned int n_radial = s.radial_cells_per_layer << p.refinement;
      const unsigned int n_circumferential = s.circumferential_cells
                                             << p.refinement;

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
               {s.foundation_cells[0] << p.refinement,
                s.foundation_cells[1] << p.refinement},
               Point<2>(-0.5 * s.foundation_width, -s.foundation_height),
               Point<2>(0.5 * s.foundation_width, 0),
               2,
               10);
      merge_bodies<2>({&ring, &foundation}, tria);
    }
  } // namespace

  const SceneRegistration
    ring_scene("ring on foundation", &create_ring_on_foundation, nullptr);
} // namespace tribos
