#ifndef tribos_scene_scene_h
#define tribos_scene_scene_h

#include <tribos/base/registry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <memory>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The curved geometry of a mesh whose file has second-order cells (tri6,
   * quad8, quad9, tet10, hex20, hex27; GmshSecondOrder): per active cell
   * (by active_cell_index()), where the support points of the quadratic
   * Lagrange element of its kind lie (FE_Q(2) on quadrilaterals and
   * hexahedra, FE_SimplexP(2) on triangles and tetrahedra, in that
   * element's order). A straight mesh has none.
   */
  template <int dim>
  struct CurvedCells
  {
    std::vector<std::vector<Point<dim>>> support_points;

    bool
    empty() const
    {
      return support_points.empty();
    }
  };



  /**
   * A scene: a geometry generator that declares and reads its own
   * parameters (a subsection of Scene, or entries of Scene itself) and
   * builds its bodies into a triangulation. Every scene file in
   * source/scene/ defines one and registers it with a SceneRegistration
   * (ASPECT's plugin shape): adding a scene touches its own file only.
   *
   * All bodies live in one triangulation: the material_id of a cell is its
   * body id, boundary faces carry the boundary ids documented per scene in
   * the README. Separately generated bodies never share vertices, so they
   * interact only through contact (regions of one generated body, like
   * the two ring layers, are bonded). Curved geometry is refined on its
   * exact manifold before the bodies are merged; the merged mesh is then
   * flat (no manifolds needed afterwards).
   */
  class SceneGeometry
  {
  public:
    virtual ~SceneGeometry() = default;

    /** Read the scene's parameters (@p prm inside the subsection Scene). */
    virtual void
    parse_parameters(ParameterHandler &prm) = 0;

    /**
     * Build the scene with Scene/Refinement = @p refinement into the empty
     * @p triangulation; the default refuses: the scene does not exist in
     * that dimension.
     */
    virtual void
    create(const unsigned int refinement,
           Triangulation<2>  &triangulation) const;
    virtual void
    create(const unsigned int refinement,
           Triangulation<3>  &triangulation) const;

    /**
     * As create(), and the curved geometry of the mesh's cells into
     * @p curved: only a second-order mesh file has one. The default leaves
     * @p curved empty (the generators' meshes are flat after their merge).
     */
    virtual void
    create_curved(const unsigned int refinement,
                  Triangulation<2>  &triangulation,
                  CurvedCells<2>    &curved) const;
    virtual void
    create_curved(const unsigned int refinement,
                  Triangulation<3>  &triangulation,
                  CurvedCells<3>    &curved) const;

    /**
     * The order of the mesh's cells in @p dim dimensions: 2 for a
     * second-order mesh file, which Finite element/Polynomial degree = as
     * meshed follows; 1 for every generated scene.
     */
    virtual unsigned int
    mesh_order(const unsigned int dim) const;

    /**
     * Lines for the run's log after its header, once the scene is built:
     * what the user may want to know of an input file read (e.g. the ids
     * an Abaqus deck's sets got). The default: none.
     */
    virtual std::vector<std::string>
    describe() const;

    /**
     * What a message about the mesh the scene made starts with: the
     * parameter of the file it read (the gmsh scene's "Parameter
     * <Scene/Mesh file>", the Abaqus deck's "Parameter <Scene/Input deck>
     * = <file>"); the default names the generated scene by Scene/Name.
     */
    virtual std::string
    mesh_source() const;

    /** The scene's Scene/Name. */
    std::string name;
  };



  /**
   * The registered scenes (the files of source/scene/), by Scene/Name: every
   * scene file defines a static SceneRegistration made by register_scene().
   */
  Registry<SceneGeometry> &
  scene_registry();

  /** The object by which a scene file registers its scene. */
  using SceneRegistration = Registry<SceneGeometry>::Registration;



  /**
   * A scene whose generator is the member template
   * build<dim>(refinement, triangulation) of @p Scene, in 2D and 3D.
   */
  template <class Scene>
  class SceneInBothDimensions : public SceneGeometry
  {
  public:
    void
    create(const unsigned int refinement,
           Triangulation<2>  &triangulation) const override
    {
      static_cast<const Scene &>(*this).build(refinement, triangulation);
    }

    void
    create(const unsigned int refinement,
           Triangulation<3>  &triangulation) const override
    {
      static_cast<const Scene &>(*this).build(refinement, triangulation);
    }
  };



  /** The registration of @p Scene (with a static declare_parameters() and
   * a default constructor) under @p name. */
  template <class Scene>
  SceneRegistration
  register_scene(const std::string &name)
  {
    return register_plugin<Scene>(scene_registry(), name);
  }



  /** The scene called @p name with its parameters from @p prm (inside the
   * subsection Scene). */
  std::shared_ptr<const SceneGeometry>
  parse_scene(const std::string &name, ParameterHandler &prm);

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
