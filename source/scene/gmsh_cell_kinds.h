#ifndef tribos_scene_gmsh_cell_kinds_h
#define tribos_scene_gmsh_cell_kinds_h

/**
 * The gmsh cells that GmshSecondOrder's reader builds triangulations of,
 * and the boundary elements it reads (private to gmsh_second_order.cc,
 * whose Reader uses them, not an interface).
 */

#include <array>
#include <string>
#include <vector>

namespace tribos
{
  namespace GmshSecondOrder
  {
    namespace internal
    {
      using Edge = std::array<unsigned int, 2>;

      /**
       * A second-order gmsh cell: its corners (gmsh order), the corner pairs
       * of its edges and where the edges' middle nodes are in its node list,
       * the corner quadruples of its quadrilateral faces (hexahedra) and
       * where their centre nodes are (none: serendipity), and where its
       * centre node is (none: serendipity or a simplex).
       */
      struct CellKind
      {
        unsigned int                             n_corners;
        std::vector<Edge>                        edges;
        unsigned int                             first_middle;
        std::vector<std::array<unsigned int, 4>> faces;
        int                                      first_face_centre;
        int                                      centre;
      };

      /** The cell of gmsh type @p type (gmsh's node ordering) that tribos
       * reads in @p dim dimensions (first order: corners only), or null. */
      const CellKind *
      cell_kind(int dim, int type);

      /** The number of corners of gmsh face or edge element type @p type
       * (boundary elements), 0 if it is none. */
      unsigned int
      boundary_corners(int type);

      /** What element type @p type is, for messages. */
      std::string
      describe(int type);
    } // namespace internal
  }   // namespace GmshSecondOrder
} // namespace tribos

#endif
