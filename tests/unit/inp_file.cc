/**
 * Unit test of the Abaqus/CalculiX deck reader read_inp_file() (std only,
 * no deal.II: g++ -std=c++17 -Iinclude tests/unit/inp_file.cc
 * source/scene/inp_*.cc source/scene/msh_file.cc). A 2D deck of two
 * bodies with surfaces and node sets must give the MshFile a gmsh file of
 * the same mesh gives; GENERATE,
 * continuation lines, *INCLUDE, explicit ids, CalculiX's Eall (no body
 * beside other sets) and Nall (no boundary); then the example decks of the
 * data folder (each also cut everywhere: read or refused, no crash). The
 * node orders are inp_file_node_order's, the errors inp_file_errors'. Prints
 * each failed check and "N passed, N failed"; returns non-zero if any failed.
 * The optional argument is the data folder (default: ../data from this file).
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
  const fs::path folder =
    argc > 1 ? fs::path(argv[1]) :
               fs::path(__FILE__).parent_path().parent_path() / "data";
  return reader_check::run("inp_file",
                           [&]()
                           {
                             test_two_bodies();
                             test_ids();
                             test_calculix_sets();
                             test_generate_continuation_include();
                             test_same_as_gmsh();
                             test_examples(folder);
                           });
}
