/**
 * Unit test of the Abaqus/CalculiX deck reader read_inp_file(), its node
 * orders (std only, no deal.II): each element type's nodes must land in
 * gmsh's order, checked by geometry: a middle node at gmsh's position k
 * is the midpoint of the corners gmsh's edge k joins (gmsh's documented
 * edge tables), and face S<n>'s nodes lie on the plane of Abaqus's face n.
 * Prints each failed check and "N passed, N failed"; returns non-zero if
 * any failed.
 */

#include <tribos/scene/inp_file.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "inp_file_cases.h"
#include "reader_check.h"

using namespace tribos;
using namespace reader_check;
using namespace inp_file_cases;
namespace fs = std::filesystem;

namespace
{
  /** A reference element: Abaqus's corners, Abaqus's middle nodes (their
   * edges, from 1, as Abaqus documents them), gmsh's edges (from 0, gmsh's
   * "Node ordering"), and the plane a(x) = 0 of each Abaqus face. */
  struct Reference
  {
    std::string                                       name;
    int                                               gmsh_type;
    std::vector<Point>                                corners;
    std::vector<std::array<int, 2>>                   abaqus_edges;
    std::vector<std::array<int, 2>>                   gmsh_edges;
    std::vector<std::function<double(const Point &)>> faces;
    int                                               face_type;
    unsigned int                                      face_nodes;
  };

  std::vector<Reference>
  references()
  {
    const std::vector<Point> triangle = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}};
    const std::vector<Point> square   = {{{0, 0, 0}},
                                         {{1, 0, 0}},
                                         {{1, 1, 0}},
                                         {{0, 1, 0}}};
    const std::vector<Point> tet      = {{{0, 0, 0}},
                                         {{1, 0, 0}},
                                         {{0, 1, 0}},
                                         {{0, 0, 1}}};
    std::vector<Point>       cube     = square;
    for (const Point &p : square)
      cube.push_back({{p[0], p[1], 1}});
    using F                             = std::function<double(const Point &)>;
    const std::vector<F> triangle_faces = {[](const Point &x) { return x[1]; },
                                           [](const Point &x)
                                           { return x[0] + x[1] - 1; },
                                           [](const Point &x)
                                           {
                                             return x[0];
                                           }};
    const std::vector<F> square_faces   = {[](const Point &x) { return x[1]; },
                                           [](const Point &x)
                                           { return x[0] - 1; },
                                           [](const Point &x)
                                           { return x[1] - 1; },
                                           [](const Point &x)
                                           {
                                           return x[0];
                                         }};
    const std::vector<F> tet_faces      = {[](const Point &x) { return x[2]; },
                                           [](const Point &x) { return x[1]; },
                                           [](const Point &x)
                                           { return x[0] + x[1] + x[2] - 1; },
                                           [](const Point &x)
                                           {
                                        return x[0];
                                      }};
    const std::vector<F> cube_faces     = {[](const Point &x) { return x[2]; },
                                           [](const Point &x) { return x[2] - 1; },
                                           [](const Point &x) { return x[1]; },
                                           [](const Point &x) { return x[0] - 1; },
                                           [](const Point &x) { return x[1] - 1; },
                                           [](const Point &x)
                                           {
                                         return x[0];
                                       }};
    const std::vector<std::array<int, 2>> triangle_edges = {{{1, 2}},
                                                            {{2, 3}},
                                                            {{3, 1}}};
    const std::vector<std::array<int, 2>> square_edges   = {{{1, 2}},
                                                            {{2, 3}},
                                                            {{3, 4}},
                                                            {{4, 1}}};
    const std::vector<std::array<int, 2>> gmsh_triangle  = {{{0, 1}},
                                                            {{1, 2}},
                                                            {{2, 0}}};
    const std::vector<std::array<int, 2>> gmsh_square    = {{{0, 1}},
                                                            {{1, 2}},
                                                            {{2, 3}},
                                                            {{3, 0}}};
    const std::vector<std::array<int, 2>> abaqus_tet =
      {{{1, 2}}, {{2, 3}}, {{3, 1}}, {{1, 4}}, {{2, 4}}, {{3, 4}}};
    const std::vector<std::array<int, 2>> gmsh_tet =
      {{{0, 1}}, {{1, 2}}, {{2, 0}}, {{3, 0}}, {{3, 2}}, {{3, 1}}};
    const std::vector<std::array<int, 2>> abaqus_hex = {{{1, 2}},
                                                        {{2, 3}},
                                                        {{3, 4}},
                                                        {{4, 1}},
                                                        {{5, 6}},
                                                        {{6, 7}},
                                                        {{7, 8}},
                                                        {{8, 5}},
                                                        {{1, 5}},
                                                        {{2, 6}},
                                                        {{3, 7}},
                                                        {{4, 8}}};
    const std::vector<std::array<int, 2>> gmsh_hex   = {{{0, 1}},
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
    return {
      {"CPE3", 2, triangle, {}, {}, triangle_faces, 1, 2},
      {"CPS6M",
       9,
       triangle,
       triangle_edges,
       gmsh_triangle,
       triangle_faces,
       8,
       3},
      {"CAX4R", 3, square, {}, {}, square_faces, 1, 2},
      {"CPE8RH", 16, square, square_edges, gmsh_square, square_faces, 8, 3},
      {"C3D4", 4, tet, {}, {}, tet_faces, 2, 3},
      {"C3D10M", 11, tet, abaqus_tet, gmsh_tet, tet_faces, 9, 6},
      {"C3D8I", 5, cube, {}, {}, cube_faces, 3, 4},
      {"C3D20R", 17, cube, abaqus_hex, gmsh_hex, cube_faces, 16, 8}};
  }



  bool
  is_2d(const Reference &r)
  {
    return r.gmsh_type == 2 || r.gmsh_type == 9 || r.gmsh_type == 3 ||
           r.gmsh_type == 16;
  }



  void
  test_node_order(const Reference &r)
  {
    // Nodes 101, 102, ...: the corners, then Abaqus's middles; the element
    // line continues after 15 nodes with a trailing comma, as CalculiX
    // writes it.
    std::vector<Point> x = r.corners;
    for (const auto &e : r.abaqus_edges)
      x.push_back(midpoint(r.corners[e[0] - 1], r.corners[e[1] - 1]));
    std::ostringstream deck;
    deck.precision(17);
    deck << "*NODE\n";
    for (std::size_t i = 0; i < x.size(); ++i)
      deck << 101 + i << ", " << x[i][0] << ", " << x[i][1]
           << (is_2d(r) ? "" : ", " + std::to_string(x[i][2])) << "\n";
    deck << "*ELEMENT, TYPE=" << r.name << "\n7";
    for (std::size_t i = 0; i < x.size(); ++i)
      deck << (i == 15 ? ",\n" : ", ") << 101 + i;
    deck << "\n";
    for (std::size_t f = 0; f < r.faces.size(); ++f)
      deck << "*SURFACE, NAME=F" << f + 1 << "\n7, S" << f + 1 << "\n";
    const MshFile mesh = read("order_" + r.name, deck.str());
    if (mesh.elements.empty())
      return;
    const MshFile::Element &cell = mesh.elements[0];
    const unsigned int      dim  = is_2d(r) ? 2 : 3;
    check(cell.type == r.gmsh_type && cell.dim == dim &&
            cell.nodes.size() == x.size(),
          r.name + ": gmsh type " + std::to_string(cell.type));
    for (std::size_t c = 0; c < r.corners.size(); ++c)
      check(close(position(mesh, cell.nodes[c]), r.corners[c]),
            r.name + ": corner " + std::to_string(c) + " in place");
    for (std::size_t e = 0; e < r.gmsh_edges.size(); ++e)
      check(close(position(mesh, cell.nodes[r.corners.size() + e]),
                  midpoint(r.corners[r.gmsh_edges[e][0]],
                           r.corners[r.gmsh_edges[e][1]])),
            r.name + ": gmsh node " + std::to_string(r.corners.size() + e) +
              " is the middle of gmsh's edge " + std::to_string(e));
    for (std::size_t f = 0; f < r.faces.size(); ++f)
    {
      const auto        faces = boundary(mesh, dim, int(f) + 1);
      const std::string what  = r.name + ": face S" + std::to_string(f + 1);
      check(faces.size() == 1 && physical_name(mesh, dim - 1, int(f) + 1) ==
                                   "F" + std::to_string(f + 1),
            what + " is one boundary element");
      if (faces.size() != 1)
        continue;
      const MshFile::Element &face = *faces[0];
      check(face.type == r.face_type && face.nodes.size() == r.face_nodes &&
              face.line == x.size() + 5 + (x.size() > 15) + 2 * f,
            what + ": gmsh type " + std::to_string(face.type) + ", line " +
              std::to_string(face.line));
      for (const std::size_t n : face.nodes)
        check(std::abs(r.faces[f](position(mesh, n))) < 1e-12,
              what + ": its nodes on the face's plane");
      // Middles as gmsh's boundary elements have them: of the edges from
      // corner 0 to 1, 1 to 2, ... (a line: its one middle).
      const std::size_t n_corners = msh_element_type(face.type)->n_corners;
      for (std::size_t m = n_corners; m < face.nodes.size(); ++m)
        check(close(position(mesh, face.nodes[m]),
                    midpoint(
                      position(mesh, face.nodes[m - n_corners]),
                      position(mesh,
                               face.nodes[(m - n_corners + 1) % n_corners]))),
              what + ": its node " + std::to_string(m) +
                " the middle of its corners");
    }
  }
} // namespace



int
main()
{
  return reader_check::run("inp_file_node_order",
                           []()
                           {
                             for (const Reference &r : references())
                               test_node_order(r);
                           });
}
