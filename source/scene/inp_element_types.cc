/**
 * The Abaqus solid element types tribos reads, and how their nodes and
 * faces map to gmsh's.
 *
 * Abaqus's numbering, as Abaqus/Standard and CalculiX use it:
 * - corners: those of the gmsh cell, in the same order (the bottom face
 *   1-2-3-4 and the top face 5-6-7-8 of a hexahedron);
 * - middle nodes: triangle 4 on 1-2, 5 on 2-3, 6 on 3-1; quadrilateral 5
 *   on 1-2, 6 on 2-3, 7 on 3-4, 8 on 4-1; tetrahedron 5 on 1-2, 6 on 2-3,
 *   7 on 3-1, 8 on 1-4, 9 on 2-4, 10 on 3-4; hexahedron 9 on 1-2, 10 on
 *   2-3, 11 on 3-4, 12 on 4-1, 13 on 5-6, 14 on 6-7, 15 on 7-8, 16 on 8-5,
 *   17 on 1-5, 18 on 2-6, 19 on 3-7, 20 on 4-8;
 * - faces: triangle S1 1-2, S2 2-3, S3 3-1; quadrilateral S1 1-2, S2 2-3,
 *   S3 3-4, S4 4-1; tetrahedron S1 1-2-3, S2 1-4-2, S3 2-4-3, S4 3-4-1;
 *   hexahedron S1 1-2-3-4, S2 5-8-7-6, S3 1-5-6-2, S4 2-6-7-3, S5 3-7-8-4,
 *   S6 4-8-5-1.
 * Taken from A. Bower's Abaqus-compatible element routines
 * (abq_facenodes_2D/3D, github.com/albower/EN234_FEA,
 * EN234_FEA/user_codes/src/abaqus_uel_*.for), which list each face with its
 * middle nodes, and checked against CalculiX's face tables ifaceq, ifacet
 * (github.com/Dhondtguido/CalculiX, src/normalsoninterface.f: the same
 * faces, S1 reversed, with the same middle nodes).
 *
 * gmsh's numbering (gmsh reference manual, section "Node ordering",
 * manpagez.com/info/gmsh/gmsh-2.2.2/gmsh_65.php): the middle nodes follow
 * the edges, tetrahedron 1-2, 2-3, 3-1, 4-1, 4-3, 4-2; hexahedron 1-2,
 * 1-4, 1-5, 2-3, 2-6, 3-4, 3-7, 4-8, 5-6, 5-8, 6-7, 7-8 (the tables of
 * gmsh_second_order.cc). So the tetrahedron's last two middle nodes swap,
 * and the hexahedron's are reordered.
 *
 * C3D27 is not read: it is a 21- to 27-node element whose mid-face nodes
 * may be left out, and no document at hand gives its node order.
 */

#include <tribos/scene/inp_file.h>

#include <cstring>

namespace tribos
{
  namespace
  {
    using Faces = std::array<std::array<unsigned char, 4>, 6>;
    using Edges = std::array<std::array<unsigned char, 2>, 12>;
    using Order = std::array<unsigned char, 20>;

    // Abaqus's faces (positions from 0).
    constexpr Faces triangle_faces = {{{{0, 1}}, {{1, 2}}, {{2, 0}}}};
    constexpr Faces quad_faces     = {{{{0, 1}}, {{1, 2}}, {{2, 3}}, {{3, 0}}}};
    constexpr Faces tet_faces      = {
           {{{0, 1, 2}}, {{0, 3, 1}}, {{1, 3, 2}}, {{2, 3, 0}}}};
    constexpr Faces hex_faces = {{{{0, 1, 2, 3}},
                                  {{4, 7, 6, 5}},
                                  {{0, 4, 5, 1}},
                                  {{1, 5, 6, 2}},
                                  {{2, 6, 7, 3}},
                                  {{3, 7, 4, 0}}}};

    // gmsh's edges, in the order of their middle nodes.
    constexpr Edges triangle_edges = {{{{0, 1}}, {{1, 2}}, {{2, 0}}}};
    constexpr Edges quad_edges     = {{{{0, 1}}, {{1, 2}}, {{2, 3}}, {{3, 0}}}};
    constexpr Edges tet_edges      = {
           {{{0, 1}}, {{1, 2}}, {{2, 0}}, {{3, 0}}, {{3, 2}}, {{3, 1}}}};
    constexpr Edges hex_edges = {{{{0, 1}},
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
                                  {{6, 7}}}};

    constexpr Order identity = {
      {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19}};
    // gmsh's edges 4-3 and 4-2 are Abaqus's nodes 10 and 9.
    constexpr Order tet10_order = {{0, 1, 2, 3, 4, 5, 6, 7, 9, 8}};
    // gmsh's edge e: 1-2 is Abaqus's 9, 1-4 12, 1-5 17, 2-3 10, 2-6 18,
    // 3-4 11, 3-7 19, 4-8 20, 5-6 13, 5-8 16, 6-7 14, 7-8 15.
    constexpr Order hex20_order = {
      {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 16, 9, 17, 10, 18, 19, 12, 15, 13, 14}};

    constexpr InpElementType
      tri3{2, 2, 3, identity, 3, 2, triangle_faces, 0, {}, 1};
    constexpr InpElementType
      tri6{9, 2, 6, identity, 3, 2, triangle_faces, 3, triangle_edges, 8};
    constexpr InpElementType
      quad4{3, 2, 4, identity, 4, 2, quad_faces, 0, {}, 1};
    constexpr InpElementType
      quad8{16, 2, 8, identity, 4, 2, quad_faces, 4, quad_edges, 8};
    constexpr InpElementType tet4{4, 3, 4, identity, 4, 3, tet_faces, 0, {}, 2};
    constexpr InpElementType
      tet10{11, 3, 10, tet10_order, 4, 3, tet_faces, 6, tet_edges, 9};
    constexpr InpElementType hex8{5, 3, 8, identity, 6, 4, hex_faces, 0, {}, 3};
    constexpr InpElementType
      hex20{17, 3, 20, hex20_order, 6, 4, hex_faces, 12, hex_edges, 16};

    /** A family of names: the base, the formulation letters that may follow
     * (one of them, then an optional H for hybrid), and its cell. */
    struct Family
    {
      const char           *base;
      const char           *letters;
      const InpElementType *type;
    };

    const Family families[] = {{"CPE3", "", &tri3},
                               {"CPS3", "", &tri3},
                               {"CAX3", "", &tri3},
                               {"CPE6", "M", &tri6},
                               {"CPS6", "M", &tri6},
                               {"CAX6", "M", &tri6},
                               {"CPE4", "RI", &quad4},
                               {"CPS4", "RI", &quad4},
                               {"CAX4", "RI", &quad4},
                               {"CPE8", "R", &quad8},
                               {"CPS8", "R", &quad8},
                               {"CAX8", "R", &quad8},
                               {"C3D4", "", &tet4},
                               {"C3D10", "MI", &tet10},
                               {"C3D8", "RI", &hex8},
                               {"C3D20", "R", &hex20}};

    /** Whether @p rest is a suffix the family allows: "", a letter of
     * @p letters, then optionally "H". */
    bool
    allowed_suffix(std::string_view rest, const char *letters)
    {
      if (!rest.empty() && rest.back() == 'H')
        rest.remove_suffix(1);
      return rest.empty() ||
             (rest.size() == 1 && std::strchr(letters, rest[0]) != nullptr);
    }
  } // namespace



  const InpElementType *
  inp_element_type(const std::string_view name)
  {
    for (const Family &f : families)
    {
      const std::string_view base(f.base);
      if (name.substr(0, base.size()) == base &&
          allowed_suffix(name.substr(base.size()), f.letters))
        return f.type;
    }
    return nullptr;
  }



  std::string
  inp_element_type_names()
  {
    std::string names;
    for (const Family &f : families)
    {
      names += names.empty() ? "" : ", ";
      names += f.base;
      if (f.letters[0] != '\0')
        names += std::string("[") + f.letters + "]";
      names += "[H]";
    }
    return names + " (in brackets: optional, at most one of its letters)";
  }



  std::vector<std::size_t>
  inp_face_nodes(const InpElementType           &type,
                 const unsigned int              face,
                 const std::vector<std::size_t> &nodes)
  {
    const auto              &corners = type.faces[face];
    const unsigned int       n       = type.n_face_corners;
    std::vector<std::size_t> result;
    for (unsigned int c = 0; c < n; ++c)
      result.push_back(nodes[corners[c]]);
    const unsigned int n_cell_corners = type.n_nodes - type.n_edges;
    // A line has one edge, a triangle or quadrilateral as many as corners.
    for (unsigned int c = 0; type.n_edges > 0 && c < (n == 2 ? 1 : n); ++c)
    {
      const unsigned int a = corners[c], b = corners[(c + 1) % n];
      for (unsigned int e = 0; e < type.n_edges; ++e)
        if ((type.edges[e][0] == a && type.edges[e][1] == b) ||
            (type.edges[e][0] == b && type.edges[e][1] == a))
          result.push_back(nodes[n_cell_corners + e]);
    }
    return result;
  }
} // namespace tribos
