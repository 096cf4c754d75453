#ifndef tribos_scene_gmsh_second_order_h
#define tribos_scene_gmsh_second_order_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  struct MshFile;

  /**
   * gmsh meshes, first- or second-order, read by tribos's own reader
   * (read_msh_file(): every count, tag and reference checked, the line
   * named in every message) and built into a triangulation here, where
   * what tribos cannot mesh is refused (other kinds of cells, a 3D mesh
   * with Dimension = 2, a 2D mesh off the x-y plane, degenerate, inverted
   * or twisted cells). Neither deal.II's reader nor libgmsh is used: both
   * crash or hang on some malformed files (issue 56). A cell's body id is
   * the physical tag of its element, a boundary face's id that of its face
   * element. First-order meshes get deal.II's reader's vertex numbering
   * (the $Nodes order) and clean-up. Second-order ones (tri6, quad8, quad9
   * in 2D; tet10, hex20, hex27 in 3D) also give the curved geometry: the
   * mid-side, face and centre nodes as the support points of the quadratic
   * Lagrange element of the cell's kind (FE_Q(2), FE_SimplexP(2)).
   *
   * The serendipity cells (quad8, hex20) have no face or centre nodes; their
   * geometry lies in the Q2 space (every serendipity function is a Q2
   * function), so the Q2 support points there are the serendipity map's
   * values: the quad8 centre is -1/4 of the corners' sum plus 1/2 of the
   * edge middles' sum, the hex20 centre -1/4 of the corners plus 1/4 of the
   * edge middles.
   *
   * The reader takes any MshFile, so that a mesh of another format
   * converted to one (an Abaqus deck, read_inp_file()) is built the same
   * way: the overloads of an MshFile start their messages with a given
   * name; the element lines they name are those of MshFile::file.
   */
  namespace GmshSecondOrder
  {
    /**
     * Read @p file and build its cells into the empty @p triangulation. If
     * they are second-order, put per coarse cell (by index on level 0) the
     * positions of the quadratic element's support points into
     * @p support_points and return true; return false for first-order
     * cells. Refuses a malformed file or cells tribos cannot mesh, naming
     * the file's line.
     */
    template <int dim>
    bool
    read(const std::string                    &file,
         Triangulation<dim>                   &triangulation,
         std::vector<std::vector<Point<dim>>> &support_points);

    /**
     * As read(file, ...), of the already read @p mesh (what read() reads
     * the file into), its messages starting with @p name (read() gives
     * "Parameter <Scene/Mesh file> = <file>").
     */
    template <int dim>
    bool
    read(const MshFile                        &mesh,
         const std::string                    &name,
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

    /** The order (1 or 2) of the @p dim dimensional cells of @p file; the
     * same refusals as read(). */
    template <int dim>
    unsigned int
    order(const std::string &file);

    /** The order of the already read @p mesh, as order(file); messages
     * start with @p name. */
    template <int dim>
    unsigned int
    order(const MshFile &mesh, const std::string &name);
  } // namespace GmshSecondOrder
} // namespace tribos

#endif
