/**
 * The gmsh cells and boundary elements GmshSecondOrder reads
 * (gmsh_cell_kinds.h): gmsh's node ordering of each.
 */

#include "gmsh_cell_kinds.h"

#include <tribos/scene/msh_file.h>

namespace tribos
{
  namespace GmshSecondOrder
  {
    namespace internal
    {
      namespace
      {
        const std::vector<Edge> triangle_edges = {{{0, 1}}, {{1, 2}}, {{2, 0}}};
        const std::vector<Edge> quad_edges     = {{{0, 1}},
                                                  {{1, 2}},
                                                  {{2, 3}},
                                                  {{3, 0}}};
        const std::vector<Edge> tet_edges =
          {{{0, 1}}, {{1, 2}}, {{2, 0}}, {{3, 0}}, {{3, 2}}, {{3, 1}}};
        const std::vector<Edge>                        hex_edges = {{{0, 1}},
                                                                    {{0, 3}},
                                                                    {{0, 4}},
                                                                    {{1, 2}},
                                                                    {{1, 5}},
                                                                    {{2, 3}},
                                                                    {{2, 6}},
                                                                    {{3, 7}},
                                                                    {{4, 5}},
                                                                    {{4, 7}},
                                                                    {{5, 6}},
                                                                    {{6, 7}}};
        const std::vector<std::array<unsigned int, 4>> hex_faces = {
          {{0, 3, 2, 1}},
          {{0, 1, 5, 4}},
          {{0, 4, 7, 3}},
          {{1, 2, 6, 5}},
          {{2, 3, 7, 6}},
          {{4, 5, 6, 7}}};
      } // namespace



      /** The cell of gmsh type @p type (gmsh's node ordering) that tribos
       * reads in @p dim dimensions (first order: corners only), or null. */
      const CellKind *
      cell_kind(const int dim, const int type)
      {
        static const CellKind tri3{3, {}, 3, {}, -1, -1};
        static const CellKind quad4{4, {}, 4, {}, -1, -1};
        static const CellKind tet4{4, {}, 4, {}, -1, -1};
        static const CellKind hex8{8, {}, 8, {}, -1, -1};
        static const CellKind tri6{3, triangle_edges, 3, {}, -1, -1};
        static const CellKind quad8{4, quad_edges, 4, {}, -1, -1};
        static const CellKind quad9{4, quad_edges, 4, {}, -1, 8};
        static const CellKind tet10{4, tet_edges, 4, {}, -1, -1};
        static const CellKind hex20{8, hex_edges, 8, hex_faces, -1, -1};
        static const CellKind hex27{8, hex_edges, 8, hex_faces, 20, 26};
        if (dim == 2)
          return type == 2  ? &tri3 :
                 type == 3  ? &quad4 :
                 type == 9  ? &tri6 :
                 type == 16 ? &quad8 :
                 type == 10 ? &quad9 :
                              nullptr;
        return type == 4  ? &tet4 :
               type == 5  ? &hex8 :
               type == 11 ? &tet10 :
               type == 17 ? &hex20 :
               type == 12 ? &hex27 :
                            nullptr;
      }

      /** The number of corners of gmsh face or edge element type @p type
       * (boundary elements), 0 if it is none. */
      unsigned int
      boundary_corners(const int type)
      {
        switch (type)
        {
          case 1: // line
          case 8: // 3-node line
            return 2;
          case 2: // triangle
          case 9: // 6-node triangle
            return 3;
          case 3:  // quadrilateral
          case 10: // 9-node quadrilateral
          case 16: // 8-node quadrilateral
            return 4;
          default:
            return 0;
        }
      }

      /** What element type @p type is, for messages. */
      std::string
      describe(const int type)
      {
        const MshElementType *kind = msh_element_type(type);
        return "'" + std::string(kind != nullptr ? kind->name : "unknown") +
               "' cells (gmsh element type " + std::to_string(type) +
               (kind != nullptr ? ", order " + std::to_string(kind->order) :
                                  std::string()) +
               ")";
      }
    } // namespace internal
  }   // namespace GmshSecondOrder
} // namespace tribos
