#ifndef tribos_scene_gmsh_second_order_h
#define tribos_scene_gmsh_second_order_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * Second-order gmsh meshes (tri6, quad8, quad9 in 2D; tet10, hex20, hex27
   * in 3D), read with gmsh's own library (libgmsh): deal.II 9.4's reader
   * takes first-order cells only. The triangulation gets the cells' vertices
   * with deal.II's conventions for gmsh files (a cell's body id is the
   * physical tag of its entity, a boundary face's id that of its face
   * element's entity); the mid-side, face and centre nodes give the curved
   * geometry as the support points of the quadratic Lagrange element of
   * the cell's kind (FE_Q(2), FE_SimplexP(2)).
   *
   * The serendipity cells (quad8, hex20) have no face or centre nodes; their
   * geometry lies in the Q2 space (every serendipity function is a Q2
   * function), so the Q2 support points there are the serendipity map's
   * values: the quad8 centre is -1/4 of the corners' sum plus 1/2 of the
   * edge middles' sum, the hex20 centre -1/4 of the corners plus 1/4 of the
   * edge middles.
   */
  namespace GmshSecondOrder
  {
    /**
     * Read @p file (an existing, complete gmsh file) with libgmsh. If its
     * cells are second-order, build them into the empty @p triangulation,
     * put per coarse cell (by index on level 0) the positions of the
     * quadratic element's support points into @p support_points, and
     * return true. If its cells are first-order, leave both untouched and
     * return false (deal.II's reader takes the file). Refuses a file gmsh
     * cannot read, and cells of other kinds or orders, naming them.
     */
    template <int dim>
    bool
    read(const std::string                    &file,
         Triangulation<dim>                   &triangulation,
         std::vector<std::vector<Point<dim>>> &support_points);

    /**
     * Refine @p triangulation, whose coarse cells have the quadratic
     * geometry @p coarse_support_points (as read()), globally
     * @p refinement times and return the support points of the quadratic
     * element per active cell (by active_cell_index()). A refined cell
     * follows its coarse cell's quadratic map: its support points are
     * that map's values at their coarse reference coordinates (from the
     * straight cells, which deal.II refines flat). The new vertices move
     * onto the curved geometry, so that what reads the vertices sees the
     * curved mesh.
     */
    template <int dim>
    std::vector<std::vector<Point<dim>>>
    refine(Triangulation<dim>                         &triangulation,
           const unsigned int                          refinement,
           const std::vector<std::vector<Point<dim>>> &coarse_support_points);
  } // namespace GmshSecondOrder
} // namespace tribos

#endif
