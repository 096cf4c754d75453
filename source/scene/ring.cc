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
      steps[1].assign(n_circumferential, numbers::PI / n_circumferential);

      // Parameter space (r, theta), theta in [pi, 2 pi]: the lower half.
      Triangulation<2> ring;
      GridGenerator::subdivided_hyper_rectangle(
        ring,
        steps,
        Point<2>(s.inner_radius, numbers::PI),
        Point<2>(s.outer_radius, 2 * numbers::PI),
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

  const SceneRegistration ring_scene("ring on foundation",
                                     &create_ring_on_foundation,
                                     nullptr);
} // namespace tribos
