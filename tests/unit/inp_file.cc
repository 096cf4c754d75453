/**
 * Unit test of the Abaqus/CalculiX deck reader read_inp_file() (std only,
 * no deal.II: g++ -std=c++17 -Iinclude tests/unit/inp_file.cc
 * source/scene/inp_*.cc source/scene/msh_file.cc). A 2D deck of two
 * bodies with surfaces and node sets must give the MshFile a gmsh file of
 * the same mesh gives; each element type's nodes must land in gmsh's order
 * (checked by geometry: a middle node at gmsh's position k is the midpoint
 * of the corners gmsh's edge k joins, from gmsh's documented edge tables,
 * and face S<n>'s nodes lie on the plane of Abaqus's face n); GENERATE,
 * continuation lines, *INCLUDE, explicit ids, CalculiX's Eall (no body
 * beside other sets) and Nall (no boundary), and the errors that given ids
 * cause (InpIdError); then malformed decks, each of which must give an
 * MshError at the right file and line with the right message; then every
 * cut of a good deck (no crash: read or refused); then
 * the example decks of the data folder. Prints each failed check and "N
 * passed, N failed"; returns non-zero if any failed. The optional argument
 * is the data folder (default: ../data from this file).
 */

#include <tribos/scene/inp_file.h>

#include <algorithm>
#include <array>
#include <chrono>
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

using namespace tribos;
namespace fs = std::filesystem;

namespace
{
  unsigned int n_passed = 0, n_failed = 0;
  fs::path     directory; // the temporary files'

  void
  check(const bool ok, const std::string &what)
  {
    if (ok)
      ++n_passed;
    else
    {
      ++n_failed;
      std::cout << "FAILED: " << what << std::endl;
    }
  }

  std::string
  write(const std::string &name, const std::string &text)
  {
    const fs::path path = directory / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  /** @p text with its single occurrence of @p from replaced by @p to. */
  std::string
  replace(std::string text, const std::string &from, const std::string &to)
  {
    const std::size_t at = text.find(from);
    if (at == std::string::npos || text.find(from, at + 1) != std::string::npos)
    {
      std::cout << "test error: '" << from << "' is not in the text once\n";
      std::exit(2);
    }
    return text.replace(at, from.size(), to);
  }

  MshFile
  read(const std::string &name,
       const std::string &text,
       const InpIds      &ids = InpIds())
  {
    try
    {
      return read_inp_file(write(name + ".inp", text), ids);
    }
    catch (const std::exception &e)
    {
      check(false, name + ": " + e.what());
      return MshFile();
    }
  }

  /** Reading @p file must fail in @p in (default: @p file) at @p line with
   * a message that has @p expected in it. */
  void
  expect_error_in(const std::string &name,
                  const std::string &file,
                  const std::size_t  line,
                  const std::string &expected,
                  const InpIds      &ids = InpIds(),
                  std::string        in  = "")
  {
    if (in.empty())
      in = file;
    try
    {
      read_inp_file(file, ids);
      check(false,
            name + ": read without error; expected line " +
              std::to_string(line) + ": " + expected);
    }
    catch (const MshError &e)
    {
      const std::string what =
        in + ":" + std::to_string(e.line()) + ": " + e.message();
      check(e.line() == line &&
              e.message().find(expected) != std::string::npos &&
              e.file() == in && e.what() == what,
            name + ": expected " + in + ":" + std::to_string(line) + " and '" +
              expected + "', got: " + e.what());
    }
    catch (const std::exception &e)
    {
      check(false, name + ": not an MshError: " + e.what());
    }
  }

  void
  expect_error(const std::string &name,
               const std::string &text,
               const std::size_t  line,
               const std::string &expected,
               const InpIds      &ids = InpIds())
  {
    expect_error_in(name, write(name + ".inp", text), line, expected, ids);
  }

  using Point = std::array<double, 3>;

  Point
  position(const MshFile &mesh, const std::size_t node)
  {
    return mesh.nodes[node].x;
  }

  bool
  close(const Point &a, const Point &b)
  {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) +
             std::abs(a[2] - b[2]) <
           1e-12;
  }

  Point
  midpoint(const Point &a, const Point &b)
  {
    return {{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}};
  }

  /** The boundary elements (dim below the cells') of physical @p id. */
  std::vector<const MshFile::Element *>
  boundary(const MshFile &mesh, const unsigned int dim, const int id)
  {
    std::vector<const MshFile::Element *> result;
    for (const auto &e : mesh.elements)
      if (e.dim + 1 == dim && e.physical == id)
        result.push_back(&e);
    return result;
  }

  /** The name of physical group (@p dim, @p id), "" if none. */
  std::string
  physical_name(const MshFile &mesh, const unsigned int dim, const int id)
  {
    for (const auto &p : mesh.physical_names)
      if (p.dim == dim && p.tag == id)
        return p.name;
    return "";
  }

  // The 2D deck of the first test: a 2 x 1 plate (bodies PLATE, elements
  // 1-2) under a 1 x 1 block (BLOCK, element 3) that shares no node.
  const std::string two_bodies = R"(*HEADING
two bodies
** the plate
*NODE
1, 0., 0.
2, 1., 0.
3, 2., 0.
4, 0., 1.
5, 1., 1.
6, 2., 1.
*node
11, 0.5, 1.0
12, 1.5, 1.0
13, 1.5, 2.0
14, 0.5, 2.0

*Element, type=CPE4R, elset=Plate
1, 1, 2, 5, 4
2, 2, 3, 6, 5
* ELEMENT , TYPE = CPS4 , ELSET = BLOCK
3, 11, 12, 13, 14
*NSET, NSET=BOTTOM
1, 2,
3
*SURFACE, NAME=TOP_OF_PLATE
PLATE, S3
*Surface, name=BLOCK_BOTTOM, type=ELEMENT
3, S1
*MATERIAL, NAME=STEEL
*ELASTIC
210000, 0.3
*STEP
*STATIC
*BOUNDARY
BOTTOM, 1, 2
*END STEP
)";

  void
  test_two_bodies()
  {
    const MshFile mesh = read("two_bodies", two_bodies);
    check(mesh.nodes.size() == 10 && mesh.version == 0,
          "two_bodies: 10 nodes, version 0");
    check(mesh.node_index(13) == 8 && mesh.node_index(7) == MshFile::npos,
          "two_bodies: node_tags built");
    std::size_t n_cells = 0;
    for (const auto &e : mesh.elements)
      if (e.dim == 2)
      {
        ++n_cells;
        check(e.type == 3 && e.entity == 0 && e.nodes.size() == 4,
              "two_bodies: cells are gmsh quadrilaterals of entity 0");
        check(e.physical == (e.tag == 3 ? 2 : 1),
              "two_bodies: element " + std::to_string(e.tag) + " is in body " +
                std::to_string(e.physical));
      }
    check(n_cells == 3, "two_bodies: 3 cells");
    // The same deck with a byte order mark and CRLF line ends.
    std::string crlf = "\xEF\xBB\xBF";
    for (const char c : two_bodies)
      crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const MshFile windows = read("two_bodies_crlf", crlf);
    bool          same    = windows.elements.size() == mesh.elements.size() &&
                windows.nodes.size() == mesh.nodes.size();
    for (std::size_t i = 0; same && i < mesh.elements.size(); ++i)
      same = windows.elements[i].nodes == mesh.elements[i].nodes &&
             windows.elements[i].physical == mesh.elements[i].physical &&
             windows.elements[i].line == mesh.elements[i].line;
    check(same, "two_bodies: the same with a byte order mark and CRLF");
    check(mesh.elements[1].nodes == std::vector<std::size_t>{{1, 2, 5, 4}} &&
            mesh.elements[1].line == 19,
          "two_bodies: element 2's nodes and line");
    check(physical_name(mesh, 2, 1) == "Plate" &&
            physical_name(mesh, 2, 2) == "BLOCK",
          "two_bodies: body names");
    // Boundaries in order of appearance.
    check(physical_name(mesh, 1, 1) == "BOTTOM" &&
            physical_name(mesh, 1, 2) == "TOP_OF_PLATE" &&
            physical_name(mesh, 1, 3) == "BLOCK_BOTTOM" &&
            mesh.physical_names.size() == 5,
          "two_bodies: boundary names in order of appearance");
    const auto bottom = boundary(mesh, 2, 1);
    check(bottom.size() == 2 && bottom[0]->tag == 4 && bottom[1]->tag == 5 &&
            bottom[0]->line == 22,
          "two_bodies: BOTTOM holds the plate's 2 bottom edges, tags 4 and "
          "5, at the *NSET line");
    for (const auto *e : bottom)
      check(position(mesh, e->nodes[0])[1] == 0 &&
              position(mesh, e->nodes[1])[1] == 0,
            "two_bodies: BOTTOM's lines at y = 0");
    const auto top = boundary(mesh, 2, 2);
    check(top.size() == 2 && top[0]->type == 1 && top[0]->nodes.size() == 2,
          "two_bodies: TOP_OF_PLATE is 2 lines");
    for (const auto *e : top)
      check(position(mesh, e->nodes[0])[1] == 1 &&
              position(mesh, e->nodes[1])[1] == 1 && e->line == 26,
            "two_bodies: TOP_OF_PLATE's lines at y = 1, line 26");
    const auto block = boundary(mesh, 2, 3);
    check(block.size() == 1 && block[0]->tag == 8 &&
            position(mesh, block[0]->nodes[0])[0] == 0.5 &&
            position(mesh, block[0]->nodes[1])[0] == 1.5 &&
            position(mesh, block[0]->nodes[1])[1] == 1,
          "two_bodies: BLOCK_BOTTOM is the block's edge 11-12 at y = 1");
  }



  void
  test_ids()
  {
    // A node set of all the plate's nodes: by default a boundary, which
    // overlaps BOTTOM; named, left out.
    const std::string deck =
      replace(two_bodies, "** the plate\n*NODE", "*NODE, NSET=PLATE_NODES");
    expect_error("default_overlap", deck, 21, "a face has one boundary id");
    InpIds ids;
    ids.bodies          = {{"block", 7}, {"PLATE", 0}};
    ids.boundaries      = {{"Bottom", 10},
                           {"top_of_plate", 20},
                           {"BLOCK_BOTTOM", 20}};
    const MshFile named = read("named", deck, ids);
    bool          ok    = true;
    for (const auto &e : named.elements)
      ok = ok && (e.dim == 1 || e.physical == (e.tag == 3 ? 7 : 0));
    check(ok, "ids: named bodies");
    check(boundary(named, 2, 10).size() == 2 &&
            boundary(named, 2, 20).size() == 3 &&
            named.elements.size() == 3 + 5,
          "ids: named boundaries only (PLATE_NODES left out)");
    check(physical_name(named, 1, 20) == "TOP_OF_PLATE, BLOCK_BOTTOM" &&
            physical_name(named, 2, 0) == "Plate",
          "ids: two sets of one id share a name");
    // A surface and a node set of one name.
    const std::string both =
      two_bodies + "*SURFACE, NAME=BOTTOM, TYPE=NODE\nBOTTOM\n";
    ids.bodies             = {};
    ids.boundaries         = {{"nset:bottom", 1}, {"SURFACE: BOTTOM", 1}};
    const MshFile prefixed = read("prefixed", both, ids);
    check(boundary(prefixed, 2, 1).size() == 2 &&
            physical_name(prefixed, 1, 1) == "BOTTOM, BOTTOM",
          "ids: SURFACE: and NSET: prefixes; a face given twice, one id");
  }



  /** What reading @p text with @p ids throws: "" (nothing), "MshError",
   * "InpIdError bodies" or "InpIdError boundaries". */
  std::string
  error_kind(const std::string &name,
             const std::string &text,
             const InpIds      &ids = InpIds())
  {
    try
    {
      read_inp_file(write(name + ".inp", text), ids);
      return "";
    }
    catch (const InpIdError &e)
    {
      return e.boundaries() ? "InpIdError boundaries" : "InpIdError bodies";
    }
    catch (const MshError &)
    {
      return "MshError";
    }
  }



  // A deck as CalculiX's cgx writes it: every node in Nall, every element
  // in Eall, then the parts (two stacked cubes) and the node sets.
  const std::string cgx = R"(*NODE, NSET=Nall
1,0.,0.,0.
2,1.,0.,0.
3,1.,1.,0.
4,0.,1.,0.
5,0.,0.,1.
6,1.,0.,1.
7,1.,1.,1.
8,0.,1.,1.
9,0.,0.,2.
10,1.,0.,2.
11,1.,1.,2.
12,0.,1.,2.
*ELEMENT, TYPE=C3D8, ELSET=Eall
1,1,2,3,4,5,6,7,8
2,5,6,7,8,9,10,11,12
*ELSET,ELSET=PART1
1,
*ELSET,ELSET=PART2
2,
*NSET,NSET=BOTTOM
1,2,3,4,
*NSET,NSET=TOP
9,10,11,12,
)";

  void
  test_calculix_sets()
  {
    // Eall beside the parts is no body, Nall no boundary.
    const MshFile parts   = read("cgx_parts", cgx);
    std::size_t   n_cells = 0;
    bool          bodies  = true;
    for (const auto &e : parts.elements)
      if (e.dim == 3)
      {
        ++n_cells;
        bodies = bodies && e.physical == int(e.tag);
      }
    check(n_cells == 2 && bodies && physical_name(parts, 3, 1) == "PART1" &&
            physical_name(parts, 3, 2) == "PART2",
          "cgx: 2 bodies, PART1 (1) and PART2 (2); Eall is none");
    check(boundary(parts, 3, 1).size() == 1 &&
            boundary(parts, 3, 2).size() == 1 &&
            physical_name(parts, 2, 1) == "BOTTOM" &&
            physical_name(parts, 2, 2) == "TOP" &&
            parts.physical_names.size() == 4 && parts.elements.size() == 4,
          "cgx: Nall is no boundary; BOTTOM (1) and TOP (2) one face each");
    // Eall alone is the one body.
    const std::string alone =
      replace(cgx, "*ELSET,ELSET=PART1\n1,\n*ELSET,ELSET=PART2\n2,\n", "");
    const MshFile all = read("cgx_eall", alone);
    bool          one = all.elements.size() == 4;
    for (const auto &e : all.elements)
      one = one && (e.dim != 3 || e.physical == 1);
    check(one && physical_name(all, 3, 1) == "Eall" &&
            all.physical_names.size() == 3,
          "cgx: Eall alone is 1 body");
    // A part that leaves a cell out: refused, Eall named.
    expect_error("cgx_part_missing",
                 replace(cgx, "*ELSET,ELSET=PART2\n2,\n", ""),
                 16,
                 "element 2 is in none of the element sets that are bodies "
                 "(PART1): every cell must be in one when the deck has body "
                 "sets (cells are body 0 only in a deck without); Eall, a set "
                 "of every cell, is a body only");
    // Named, Eall and Nall are sets as any other.
    InpIds ids;
    ids.bodies          = {{"EALL", 5}};
    ids.boundaries      = {{"nall", 3}};
    const MshFile named = read("cgx_named", cgx, ids);
    bool          five  = true;
    for (const auto &e : named.elements)
      five = five && (e.dim != 3 || e.physical == 5);
    check(five && boundary(named, 3, 3).size() == 10 &&
            named.elements.size() == 12,
          "cgx: named, Eall is body 5 and Nall holds the 10 boundary faces");
  }



  void
  test_id_errors()
  {
    // The errors the given ids cause are InpIdErrors, of the list that
    // caused them; the deck's and the default ids' are not.
    const std::string deck =
      replace(two_bodies, "** the plate\n*NODE", "*NODE, NSET=PLATE_NODES");
    check(error_kind("kind_default_overlap", deck) == "MshError",
          "id errors: a default overlap is an MshError");
    check(error_kind("kind_deck",
                     replace(two_bodies, "type=CPE4R", "type=S4R")) ==
            "MshError",
          "id errors: an unknown element type is an MshError");
    InpIds ids;
    ids.bodies = {{"NOWHERE", 1}};
    check(error_kind("kind_body", two_bodies, ids) == "InpIdError bodies",
          "id errors: an unknown body set");
    ids.bodies = {{"PLATE", 1}};
    check(error_kind("kind_body_missing", two_bodies, ids) ==
            "InpIdError bodies",
          "id errors: the block in no body set given");
    ids.bodies     = {};
    ids.boundaries = {{"BOTTOM", 1}, {"PLATE_NODES", 2}};
    check(error_kind("kind_boundary_overlap", deck, ids) ==
            "InpIdError boundaries",
          "id errors: given boundary sets that overlap");
    ids.boundaries = {{"BOTTOM", -1}};
    check(error_kind("kind_boundary_id", two_bodies, ids) ==
            "InpIdError boundaries",
          "id errors: a negative boundary id");
  }



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



  void
  test_generate_continuation_include()
  {
    // GENERATE (with an increment), a set of a set, a set repeated (it
    // adds), a C3D8R line continued after 7 nodes, lower case.
    std::ostringstream deck;
    deck << "*node\n";
    for (int i = 0; i < 27; ++i)
      deck << i + 1 << ", " << i % 3 << ", " << (i / 3) % 3 << ", " << i / 9
           << "\n";
    deck << "*Element, Type=C3D8R\n";
    for (int e = 0; e < 8; ++e)
    {
      const int i = e % 2, j = (e / 2) % 2, k = e / 4;
      const int n = 1 + i + 3 * j + 9 * k;
      deck << 10 + e << ", " << n << ", " << n + 1 << ", " << n + 4 << ", "
           << n + 3 << ", " << n + 9 << ", " << n + 10 << ", " << n + 13
           << ",\n " << n + 12 << "\n";
    }
    deck << "*ELSET, ELSET=LOWER, GENERATE\n10, 13\n"
         << "*ELSET, ELSET=ODD, GENERATE\n11, 17, 2\n"
         << "*ELSET, ELSET=UPPER\n14, 15\n*ELSET, ELSET=UPPER\n16, 17\n"
         << "*NSET, NSET=Z0, generate\n1, 9\n"
         << "*NSET, NSET=Z0_AGAIN\nZ0\n";
    InpIds ids;
    ids.bodies              = {{"LOWER", 1}, {"UPPER", 2}};
    ids.boundaries          = {{"Z0_AGAIN", 5}};
    const MshFile mesh      = read("generate", deck.str(), ids);
    std::size_t   n_body[3] = {0, 0, 0};
    for (const auto &e : mesh.elements)
      if (e.dim == 3 && e.physical >= 0 && e.physical < 3)
        ++n_body[e.physical];
    check(n_body[1] == 4 && n_body[2] == 4, "generate: 4 cells in each body");
    check(boundary(mesh, 3, 5).size() == 4,
          "generate: Z0_AGAIN (a copy of Z0) holds the 4 bottom faces");
    check(mesh.elements[0].nodes.size() == 8 && mesh.elements[0].line == 30,
          "continuation: an element over two lines, at its first line");
    // By default, LOWER, ODD and UPPER overlap.
    expect_error("generate_overlap", deck.str(), 48, "element 11 (");

    // *INCLUDE: relative to the including file, nested, textual (the
    // nodes' data lines in a file of their own).
    write("include/mesh/nodes.inp", "1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n");
    write("include/mesh/elements.inp",
          "*NODE\n*INCLUDE, INPUT=nodes.inp\n"
          "*ELEMENT, TYPE=CPE3, ELSET=ALL\n1, 1, 2, 3\n2, 1, 3, 4\n");
    const std::string top =
      write("include/deck.inp",
            "*HEADING\n*INCLUDE, INPUT=mesh/elements.inp\n*NSET, NSET=LEFT\n"
            "1, 4\n");
    try
    {
      const MshFile m = read_inp_file(top);
      check(m.nodes.size() == 4 && m.elements.size() == 3 &&
              m.elements[2].physical == 1 && m.elements[0].physical == 1 &&
              m.nodes[3].line == 4,
            "include: nodes and elements from the included files");
    }
    catch (const std::exception &e)
    {
      check(false, std::string("include: ") + e.what());
    }
    // An error in an included file names that file.
    const std::string bad =
      write("include/mesh/bad.inp", "*NODE\n1, 0, 0\n1, 1, 0\n");
    expect_error_in("include_error",
                    write("include/bad_deck.inp",
                          "*HEADING\n*INCLUDE, INPUT=mesh/bad.inp\n"),
                    3,
                    "node 1 is defined twice: at line 2",
                    InpIds(),
                    bad);
    const std::string a = write("cycle/a.inp", "*INCLUDE, INPUT=b.inp\n");
    write("cycle/b.inp", "*NODE\n1, 0, 0\n*INCLUDE, INPUT=a.inp\n");
    expect_error_in("include_cycle",
                    a,
                    3,
                    "form a cycle",
                    InpIds(),
                    (directory / "cycle/b.inp").string());
    // 18 files deep.
    for (int i = 0; i < 18; ++i)
      write("deep/" + std::to_string(i) + ".inp",
            "*INCLUDE, INPUT=" + std::to_string(i + 1) + ".inp\n");
    expect_error_in("include_depth",
                    (directory / "deep/0.inp").string(),
                    1,
                    "more than 16 deep",
                    InpIds(),
                    (directory / "deep/16.inp").string());
  }



  // A small valid deck that the malformed ones change.
  const std::string base = R"(*HEADING
base
*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
*ELEMENT, TYPE=CPE4, ELSET=A
1, 1, 2, 3, 4
*NSET, NSET=N
1, 2
*SURFACE, NAME=S
1, S3
)";

  void
  test_malformed()
  {
    const auto with = [](const std::string &from, const std::string &to)
    {
      return replace(base, from, to);
    };
    expect_error("empty", "", 0, "no keyword lines");
    expect_error("comments_only", "** nothing\n\n", 0, "no keyword lines");
    expect_error("data_first", "1, 0, 0\n*NODE\n", 1, "before any keyword");
    expect_error("binary",
                 "\x01\x02\xff\x00garbage\n",
                 1,
                 "before any keyword");
    expect_error("keyword_alone", "*HEADING\n*\n", 2, "where a keyword line");
    expect_error("no_nodes",
                 "*HEADING\nx\n*MATERIAL, NAME=M\n",
                 0,
                 "defines no nodes");
    expect_error("no_elements",
                 base.substr(0, base.find("*ELEMENT")),
                 0,
                 "defines no elements");
    expect_error("label_zero",
                 with("1, 0, 0", "0, 0, 0"),
                 4,
                 "'0' where a node label");
    expect_error("label_too_big",
                 with("1, 0, 0", "18446744073709551616, 0, 0"),
                 4,
                 "an integer from 1 to 18446744073709551615");
    expect_error("label_negative",
                 with("1, 0, 0", "-1, 0, 0"),
                 4,
                 "where a node label");
    expect_error("coordinate_nan",
                 with("2, 1, 0", "2, nan, 0"),
                 5,
                 "'nan' where a coordinate");
    expect_error("coordinate_inf",
                 with("2, 1, 0", "2, 1e999, 0"),
                 5,
                 "a finite number");
    expect_error("node_fields",
                 with("3, 1, 1", "3, 1, 1, 0, 7"),
                 6,
                 "5 fields on a *NODE data line");
    expect_error("node_twice",
                 with("4, 0, 1", "1, 0, 1"),
                 7,
                 "node 1 is defined twice: at line 4 and here");
    expect_error("type_unknown",
                 with("TYPE=CPE4", "TYPE=S4R"),
                 8,
                 "element type 'S4R' is not one tribos reads");
    expect_error("type_c3d27",
                 with("TYPE=CPE4", "type=c3d27"),
                 8,
                 "C3D27, whose mid-face nodes");
    expect_error("type_missing",
                 with("TYPE=CPE4, ", ""),
                 8,
                 "*ELEMENT without TYPE=");
    expect_error("param_twice",
                 with("ELSET=A", "ELSET=A, Type=CPE4"),
                 8,
                 "TYPE= is given twice");
    expect_error("element_short",
                 with("1, 1, 2, 3, 4", "1, 1, 2, 3"),
                 9,
                 "line lists 3 nodes where 4 are expected");
    expect_error("element_long",
                 with("1, 1, 2, 3, 4", "1, 1, 2, 3, 4, 5"),
                 9,
                 "lists 5 nodes");
    expect_error("element_node_undefined",
                 with("1, 1, 2, 3, 4", "1, 1, 2, 3, 9"),
                 9,
                 "node 9, which no *NODE data line above defines");
    expect_error("element_node_twice",
                 with("1, 1, 2, 3, 4", "1, 1, 2, 3, 1"),
                 9,
                 "lists node 1 twice (as its node 1 and 4)");
    expect_error("element_empty_field",
                 with("1, 1, 2, 3, 4", "1, 1, , 3, 4"),
                 9,
                 "'' where a node is expected");
    expect_error("element_twice",
                 with("1, 1, 2, 3, 4", "1, 1, 2, 3, 4\n1, 4, 3, 2, 1"),
                 10,
                 "element 1 is defined twice: at line 9");
    expect_error("continuation_keyword",
                 with("1, 1, 2, 3, 4", "1, 1, 2,"),
                 10,
                 "where the data line of element 1 (line 9) continues");
    expect_error("continuation_eof",
                 base.substr(0, base.find("1, 1, 2, 3, 4")) + "1, 1, 2,\n",
                 9,
                 "the file ends inside the data line of element 1");
    expect_error("continuation_node",
                 with("1, 1, 2, 3, 4", "1, 1, 2,\n3, 8"),
                 10,
                 "node 8, which no");
    expect_error("set_unknown_name",
                 with("1, 2\n", "1, B\n"),
                 11,
                 "'B' is no node set defined above");
    expect_error("set_undefined_label",
                 with("1, 2\n", "1, 7\n"),
                 11,
                 "node 7, which no *NODE");
    expect_error("generate_reverse",
                 base + "*ELSET, ELSET=G, GENERATE\n4, 1\n",
                 15,
                 "must not exceed the last");
    expect_error("generate_undefined",
                 base + "*ELSET, ELSET=G, GENERATE\n1, 3\n",
                 15,
                 "element 2, which no *ELEMENT");
    expect_error("generate_fields",
                 base + "*NSET, NSET=G, GENERATE\n1\n",
                 15,
                 "1 fields on a GENERATE line");
    expect_error("generate_step_zero",
                 base + "*NSET, NSET=G, GENERATE\n1, 4, 0\n",
                 15,
                 "'0' where an increment");
    expect_error("face_bad",
                 with("1, S3", "1, S7"),
                 13,
                 "'S7' where a face identifier S1 to S6");
    expect_error("face_missing",
                 with("1, S3", "1, S5"),
                 13,
                 "whose faces are S1 to S4: it has no face S5");
    expect_error("face_without",
                 with("1, S3", "1"),
                 13,
                 "'element or element set, S<n>'");
    expect_error("face_unknown_set",
                 with("1, S3", "B, S3"),
                 13,
                 "'B' is no element set defined above");
    expect_error("surface_twice",
                 base + "*SURFACE, NAME=s\n1, S1\n",
                 14,
                 "surface 's' is defined twice: at line 12");
    expect_error("surface_type",
                 with("NAME=S", "NAME=S, TYPE=CUTTING SURFACE"),
                 12,
                 "tribos reads TYPE=ELEMENT");
    expect_error("surface_interior",
                 "*NODE\n1, 0, 0\n2, 1, 0\n3, 2, 0\n4, 0, 1\n5, 1, 1\n6, 2, 1\n"
                 "*ELEMENT, TYPE=CPE4\n1, 1, 2, 5, 4\n2, 2, 3, 6, 5\n"
                 "*SURFACE, NAME=MIDDLE\n1, S2\n",
                 12,
                 "is also a face of element 2: it is inside the mesh");
    expect_error("mixed_dims",
                 base + "*ELEMENT, TYPE=C3D4\n2, 1, 2, 3, 4\n",
                 15,
                 "a deck is all 2D or all 3D");
    expect_error(
      "body_none",
      base + "*ELEMENT, TYPE=CPE3\n2, 1, 2, 3\n",
      15,
      "element 2 is in none of the element sets that are bodies (A)");
    expect_error("part",
                 with("*HEADING", "*Part, name=P"),
                 1,
                 "parts and assemblies are not read");
    expect_error("ngen",
                 base + "*NGEN, NSET=X\n1, 4\n",
                 14,
                 "generates or moves nodes");
    expect_error("system",
                 with("*NODE", "*NODE, SYSTEM=C"),
                 3,
                 "rectangular coordinates only");
    expect_error("input_parameter",
                 with("*NODE", "*NODE, INPUT=nodes.txt"),
                 3,
                 "INPUT=: not read");
    expect_error("include_missing",
                 base + "*INCLUDE, INPUT=nowhere.inp\n",
                 14,
                 "does not exist");
    expect_error("long_line",
                 base + "** " + std::string(std::size_t(2) << 20, 'x') + "\n",
                 14,
                 "longer than 1 MiB");
    expect_error_in("not_a_file", directory.string(), 0, "no such file");

    // The ids, refused at line 0 (the whole deck) or at the set.
    InpIds ids;
    ids.bodies = {{"Q", 1}};
    expect_error(
      "ids_unknown_body",
      base,
      0,
      "body set 'Q' is no element set of the deck (its element sets: A)",
      ids);
    ids.bodies = {{"A", -1}};
    expect_error("ids_negative", base, 0, "ids are integers from 0 to", ids);
    ids.bodies = {{"A", 1}, {"a", 2}};
    expect_error("ids_twice", base, 0, "is given two body ids", ids);
    ids.bodies     = {};
    ids.boundaries = {{"Q", 1}};
    expect_error("ids_unknown_boundary",
                 base,
                 0,
                 "is no surface or node set of the deck",
                 ids);
    ids.boundaries = {{"N", 1}};
    expect_error("ids_ambiguous",
                 base + "*SURFACE, NAME=N\n1, S1\n",
                 0,
                 "write SURFACE:N or NSET:N",
                 ids);
    ids.boundaries = {{"P", 1}};
    expect_error("ids_no_faces",
                 base + "*NSET, NSET=P\n3\n",
                 14,
                 "holds no face of the mesh boundary",
                 ids);
    ids.boundaries = {{"N", 1}, {"S", 2}};
    expect_error("ids_overlap",
                 base + "*NSET, NSET=N\n3, 4\n",
                 13,
                 "boundaries 1 and 2; a face has one boundary id",
                 ids);
    ids.boundaries = {{"N", 1}, {"S", 1}};
    check(read("ids_merge", base + "*NSET, NSET=N\n3, 4\n", ids)
              .elements.size() == 5,
          "ids: a face in two boundary sets of one id is one element (1 "
          "cell, 4 edges)");
  }



  /** Every cut of @p text at a line end or mid-line must read or give an
   * MshError: no crash, no other exception. */
  void
  test_cuts(const std::string &name, const std::string &text)
  {
    std::size_t n_cuts = 0, n_read = 0;
    for (std::size_t at = 0; at < text.size(); at += 1 + at % 7)
    {
      const std::string file = write("cut.inp", text.substr(0, at));
      try
      {
        read_inp_file(file);
        ++n_read;
      }
      catch (const MshError &)
      {
      }
      catch (const std::exception &e)
      {
        check(false, name + " cut at " + std::to_string(at) + ": " + e.what());
      }
      ++n_cuts;
    }
    check(n_cuts > 50 && n_read > 0,
          name + ": " + std::to_string(n_cuts) + " cuts, " +
            std::to_string(n_read) + " read");
  }



  /** The deck two_bodies must give what read_msh_file() gives for the same
   * mesh in MSH 2.2 (but the lines). */
  void
  test_same_as_gmsh()
  {
    const std::string msh  = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
5
2 1 "Plate"
2 2 "BLOCK"
1 1 "BOTTOM"
1 2 "TOP_OF_PLATE"
1 3 "BLOCK_BOTTOM"
$EndPhysicalNames
$Nodes
10
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
11 0.5 1 0
12 1.5 1 0
13 1.5 2 0
14 0.5 2 0
$EndNodes
$Elements
8
1 3 2 1 0 1 2 5 4
2 3 2 1 0 2 3 6 5
3 3 2 2 0 11 12 13 14
4 1 2 1 0 1 2
5 1 2 1 0 2 3
6 1 2 2 0 5 4
7 1 2 2 0 6 5
8 1 2 3 0 11 12
$EndElements
)";
    const fs::path    path = directory / "two_bodies.msh";
    std::ofstream(path) << msh;
    const MshFile g    = read_msh_file(path.string());
    const MshFile a    = read("same_as_gmsh", two_bodies);
    bool          same = g.nodes.size() == a.nodes.size() &&
                g.elements.size() == a.elements.size() &&
                g.physical_names.size() == a.physical_names.size();
    for (std::size_t i = 0; same && i < g.nodes.size(); ++i)
      same = g.nodes[i].tag == a.nodes[i].tag && g.nodes[i].x == a.nodes[i].x;
    for (std::size_t i = 0; same && i < g.elements.size(); ++i)
    {
      const MshFile::Element &e = g.elements[i], &f = a.elements[i];
      same = e.tag == f.tag && e.type == f.type && e.dim == f.dim &&
             e.physical == f.physical && e.entity == f.entity &&
             e.nodes == f.nodes;
    }
    for (std::size_t i = 0; same && i < g.physical_names.size(); ++i)
      same = g.physical_names[i].dim == a.physical_names[i].dim &&
             g.physical_names[i].tag == a.physical_names[i].tag &&
             g.physical_names[i].name == a.physical_names[i].name;
    check(same, "same_as_gmsh: the deck reads as its gmsh file");
  }



  /** The example decks of the data folder. */
  void
  test_examples(const fs::path &folder)
  {
    for (const unsigned int dim : {2u, 3u})
    {
      const std::string name =
        dim == 2 ? "blocks_on_plate.inp" : "blocks_on_plate_3d.inp";
      MshFile mesh;
      try
      {
        mesh = read_inp_file((folder / name).string());
      }
      catch (const std::exception &e)
      {
        check(false, name + ": " + e.what());
        continue;
      }
      std::size_t plate = 0, block = 0;
      for (const auto &e : mesh.elements)
        if (e.dim == dim)
          (e.physical == 1 ? plate : block) += 1;
      check(plate == (dim == 2 ? 8 : 4) && block == (dim == 2 ? 4 : 1) &&
              mesh.nodes.size() == (dim == 2 ? 24 : 26),
            name + ": PLATE (body 1) and BLOCK (body 2)");
      // BOTTOM, TOP, BLOCK_BOTTOM, PLATE_TOP: their faces' heights.
      const double      height[] = {0, 2, 1, 1};
      const std::size_t count2[] = {4, 2, 2, 4}, count3[] = {4, 1, 1, 4};
      const std::vector<const char *> names = {"BOTTOM",
                                               "TOP",
                                               "BLOCK_BOTTOM",
                                               "PLATE_TOP"};
      for (int b = 0; b < 4; ++b)
      {
        const auto faces = boundary(mesh, dim, b + 1);
        bool       flat  = faces.size() == (dim == 2 ? count2 : count3)[b] &&
                    physical_name(mesh, dim - 1, b + 1) == names[b];
        for (const auto *f : faces)
          for (const std::size_t n : f->nodes)
            flat = flat && position(mesh, n)[dim - 1] == height[b];
        check(flat,
              name + ": boundary " + std::to_string(b + 1) + " " + names[b]);
      }
      test_cuts(name,
                [&]
                {
                  std::ifstream      in(folder / name);
                  std::ostringstream text;
                  text << in.rdbuf();
                  return text.str();
                }());
    }
  }
} // namespace



int
main(int argc, char **argv)
{
  directory =
    fs::temp_directory_path() /
    ("tribos_inp_file_" + std::to_string(std::random_device()()) + "_" +
     std::to_string(
       std::chrono::steady_clock::now().time_since_epoch().count()));
  fs::create_directories(directory);
  const fs::path folder =
    argc > 1 ? fs::path(argv[1]) :
               fs::path(__FILE__).parent_path().parent_path() / "data";

  test_two_bodies();
  test_ids();
  test_calculix_sets();
  test_id_errors();
  for (const Reference &r : references())
    test_node_order(r);
  test_generate_continuation_include();
  test_malformed();
  test_cuts("two_bodies", two_bodies);
  test_same_as_gmsh();
  test_examples(folder);

  std::error_code error;
  fs::remove_all(directory, error);
  std::cout << n_passed << " passed, " << n_failed << " failed" << std::endl;
  return n_failed == 0 ? 0 : 1;
}
