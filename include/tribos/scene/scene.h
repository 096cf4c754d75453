#ifndef tribos_scene_scene_h
#define tribos_scene_scene_h

#include <tribos/parameters/scene.h>

#include <deal.II/grid/tria.h>

#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * Build the scene named in @p parameters into @p triangulation (which
   * must be empty). All bodies live in this one triangulation: the
   * material_id of a cell is its body id, boundary faces carry the boundary
   * ids documented per scene in the README. Separately generated bodies
   * never share vertices, so they interact only through contact (regions
   * of one generated body, like the two ring layers, are bonded).
   *
   * Curved geometry is refined on its exact manifold before the bodies are
   * merged; the merged mesh is then flat (no manifolds needed afterwards).
   */
  template <int dim>
  void
  create_scene(const Parameters::Scene &parameters,
               Triangulation<dim>      &triangulation);

  /**
   * Merge the active cells of @p bodies into @p result without merging any
   * vertices (unlike GridGenerator::merge_triangulations), keeping material
   * ids and boundary ids. Bodies may touch or overlap geometrically.
   */
  template <int dim>
  void
  merge_bodies(const std::vector<const Triangulation<dim> *> &bodies,
               Triangulation<dim>                            &result);
} // namespace tribos

#endif
