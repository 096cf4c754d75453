#ifndef tribos_scene_scene_h
#define tribos_scene_scene_h

#include <tribos/parameters/scene.h>

#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /** A scene generator: builds the scene of @p parameters into an empty
   * triangulation. */
  template <int dim>
  using SceneGenerator = void (*)(const Parameters::Scene &parameters,
                                  Triangulation<dim>      &triangulation);

  /**
   * Registers a scene under its Scene/Name: every scene file defines one
   * such object (static), so adding a scene touches its own file and its
   * parameters (a subsection in parameters/scene.h), nothing else. A null
   * generator: the scene does not exist in that dimension.
   */
  struct SceneRegistration
  {
    SceneRegistration(const std::string      &name,
                      const SceneGenerator<2> two,
                      const SceneGenerator<3> three);
  };

  /** The registered scenes' names, sorted. */
  std::vector<std::string>
  scene_names();

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
