// ctest: labels quick
/**
 * Unit test of the gmsh file reader read_msh_file() (std only, no deal.II:
 * g++ -std=c++17 -Iinclude tests/unit/msh_file.cc source/scene/msh_file*.cc).
 * A 2D mesh of two quadrilaterals with boundary lines and a point, written
 * as MSH 2.2 and as MSH 4.1, must read the same; then the .msh files in
 * tests/, against a plain independent reading; then files written by
 * gmsh, if it is on PATH (else it says "skipped"). The malformed files are
 * msh_file_errors'. Prints each failed check and "N passed, N failed";
 * returns non-zero if any failed. The optional argument is the folder of
 * the .msh files (default: this file's folder).
 */

#include <tribos/scene/msh_file.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "msh_file_cases.h"
#include "reader_check.h"

using namespace tribos;
using namespace reader_check;
using namespace msh_file_cases;
namespace fs = std::filesystem;

namespace
{
  void
  test_good_meshes()
  {
    const MshFile a = read("good22", good22), b = read("good41", good41);
    check(a.version == 2.2 && b.version == 4.1, "versions 2.2 and 4.1");
    check(a.nodes.size() == 6 && a.elements.size() == 6,
          "good22: 6 nodes, 6 elements");
    check(same_mesh(a, b), "good22 and good41 give the same mesh");
    if (a.elements.size() == 6)
    {
      const MshFile::Element &quad = a.elements[4];
      check(quad.tag == 5 && quad.type == 3 && quad.dim == 2 &&
              quad.physical == 1 && quad.entity == 1 &&
              quad.nodes == std::vector<std::size_t>{0, 1, 4, 3} &&
              quad.line == 25,
            "good22: element 5 is the quadrilateral 1 2 5 4 of body 1");
      check(a.elements[0].type == 15 && a.elements[0].dim == 0 &&
              a.elements[0].physical == 0,
            "good22: the point element is kept, physical 0");
      check(a.elements[3].physical == 11 && a.elements[3].entity == 3,
            "good22: the top line has physical 11, entity 3");
    }
    check(a.physical_names.size() == 3 &&
            a.physical_names[1].name == "top side" &&
            a.physical_names[1].tag == 11 && a.physical_names[1].dim == 1,
          "good22: physical names");
    check(a.node_index(5) == 4 && a.node_index(7) == MshFile::npos &&
            a.node_index(0) == MshFile::npos,
          "good22: node_index()");
    check(a.nodes.size() == 6 && a.nodes[5].x[0] == 2 && a.nodes[5].x[1] == 1 &&
            a.nodes[5].line == 17,
          "good22: node 6 at (2, 1, 0), line 17");
    check(b.nodes.size() == 6 && b.nodes[2].line == 26,
          "good41: node 3's coordinates at line 26");

    // CRLF, surrounding whitespace, blank lines between sections, skipped
    // sections, versions 2.0 and 2.1, a UTF-8 byte order mark
    std::string crlf;
    for (const char c : replace(good22, "$EndNodes\n", "$EndNodes\n\n \n"))
      crlf += c == '\n' ? std::string(" \t\r\n") : std::string(1, c);
    check(same_mesh(read("crlf", "\xEF\xBB\xBF" + crlf), a),
          "CRLF, whitespace, blank lines and a byte order mark");
    const std::string skipped =
      replace(good41,
              "$Nodes\n",
              "$Periodic\n1\n1 1 3\n$EndPeriodic\n$Comments\n$Nodes is a word\n"
              "x\n$EndComments\n$NodeData\n1\n\"u\"\n$EndNodeData\n$Nodes\n");
    check(same_mesh(read("skipped", skipped), a),
          "$Periodic, $Comments and $NodeData skipped");
    check(read("v20", replace(good22, "2.2 0 8", "2.0 0 8")).version == 2.0,
          "MSH 2.0 read");
    check(read("v21", replace(good22, "2.2 0 8", "2.1 0 8")).version == 2.1,
          "MSH 2.1 read");

    // no $Entities: physical 0; element lines without tags: 0, 0
    const std::string no_entities =
      replace(good41,
              "$Entities\n1 2 1 0\n1 0 0 0 0\n1 0 0 0 2 0 0 1 10 2 1 -2\n"
              "3 0 1 0 2 1 0 1 11 0\n1 0 0 0 2 1 0 1 1 2 1 3\n$EndEntities\n",
              "");
    const MshFile c = read("no_entities", no_entities);
    check(c.elements.size() == 6 &&
            std::all_of(c.elements.begin(),
                        c.elements.end(),
                        [](const auto &e) { return e.physical == 0; }) &&
            c.elements[5].entity == 1 && c.elements[3].entity == 3,
          "MSH 4.1 without $Entities: physical 0, entity from the block");
    const MshFile d =
      read("no_tags", replace(good22, "5 3 2 1 1 1 2 5 4", "5 3 0 1 2 5 4"));
    check(d.elements.size() == 6 && d.elements[4].physical == 0 &&
            d.elements[4].entity == 0 && d.elements[4].nodes.size() == 4,
          "MSH 2 element without tags: physical 0, entity 0");
    const MshFile e = read("tiny", replace(good22, "6 2 1 0", "6 2 1 1e-400"));
    check(e.nodes.size() == 6 && e.nodes[5].x[2] == 0,
          "an underflowing coordinate (1e-400) reads as 0");

    // tags of 2^31 and more, up to 2^64 - 1
    std::string big = replace(
      replace(replace(replace(good41, "3 6 1 6", "3 6 1 18446744073709551615"),
                      "\n6\n0 1 0",
                      "\n18446744073709551615\n0 1 0"),
              "6 2 3 6 5",
              "3000000000 2 3 18446744073709551615 5"),
      "4 6 1 6",
      "4 6 1 3000000000");
    big             = replace(big, "4 6 5", "4 18446744073709551615 5");
    const MshFile f = read("big_tags", big);
    check(f.nodes.size() == 6 && f.nodes[5].tag == 18446744073709551615ull &&
            f.node_index(18446744073709551615ull) == 5 &&
            f.elements.size() == 6 && f.elements[5].tag == 3000000000ull &&
            f.elements[5].nodes == std::vector<std::size_t>{1, 2, 5, 4},
          "MSH 4.1 tags 3000000000 and 2^64 - 1");
    const MshFile g =
      read("big_tags22",
           replace(replace(replace(good22, "\n3 2 0 0", "\n3000000000 2 0 0"),
                           "3 1 2 10 1 2 3",
                           "3 1 2 10 1 2 3000000000"),
                   "6 3 2 1 1 2 3 6 5",
                   "6 3 2 1 1 2 3000000000 6 5"));
    check(g.elements.size() == 6 && g.node_index(3000000000ull) == 2 &&
            g.elements[5].nodes[1] == 2,
          "MSH 2.2 node tag 3000000000");
  }



  /**
   * The meshes in tests/ (all MSH 2.2) against a plain reading with
   * streams: the same nodes and elements, every element line's nodes.
   */
  void
  test_real_meshes(const fs::path &folder)
  {
    std::error_code       error;
    std::vector<fs::path> files;
    for (const auto &entry : fs::directory_iterator(folder, error))
      if (entry.path().extension() == ".msh")
        files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    check(files.size() >= 5, "at least 5 meshes in " + folder.string());
    std::map<std::string, std::vector<int>> types; // by file name
    for (const fs::path &path : files)
    {
      MshFile mesh;
      try
      {
        mesh = read_msh_file(path.string());
      }
      catch (const std::exception &e)
      {
        check(false, path.string() + ": " + e.what());
        continue;
      }
      std::ifstream in(path);
      std::string   word;
      std::size_t   n_nodes = 0, n_elements = 0;
      bool          same = true;
      while (in >> word)
        if (word == "$Nodes")
        {
          in >> n_nodes;
          same = same && n_nodes == mesh.nodes.size();
          for (std::size_t i = 0; same && i < n_nodes; ++i)
          {
            std::uint64_t tag;
            double        x, y, z;
            in >> tag >> x >> y >> z;
            same = mesh.nodes[i].tag == tag && mesh.nodes[i].x[0] == x &&
                   mesh.nodes[i].x[1] == y && mesh.nodes[i].x[2] == z;
          }
        }
        else if (word == "$Elements")
        {
          in >> n_elements;
          same = same && n_elements == mesh.elements.size();
          for (std::size_t i = 0; same && i < n_elements; ++i)
          {
            const MshFile::Element &e = mesh.elements[i];
            std::uint64_t           tag, node;
            int                     type, n_tags, t1 = 0, t2 = 0, t;
            in >> tag >> type >> n_tags;
            for (int k = 0; k < n_tags; ++k)
              in >> (k == 0 ? t1 : k == 1 ? t2 : t);
            same = e.tag == tag && e.type == type && e.physical == t1 &&
                   e.entity == t2 && msh_element_type(type) != nullptr &&
                   e.nodes.size() == msh_element_type(type)->n_nodes;
            for (std::size_t k = 0; same && k < e.nodes.size(); ++k)
              same = (in >> node) && mesh.nodes[e.nodes[k]].tag == node;
            if (same)
              types[path.filename().string()].push_back(type);
          }
        }
      check(same && n_nodes > 0 && n_elements > 0,
            path.string() + ": as a plain reading has it (" +
              std::to_string(mesh.nodes.size()) + " nodes, " +
              std::to_string(mesh.elements.size()) + " elements)");
    }
    const auto has = [&](const std::string &file, const int type)
    {
      const std::vector<int> &t = types[file];
      return std::find(t.begin(), t.end(), type) != t.end();
    };
    check(has("hertz_2d_tri6.msh", 9) && has("ball_octant_tet10.msh", 11) &&
            has("hertz_3d_tet10.msh", 11) && has("mixed_cells.msh", 2) &&
            has("mixed_cells.msh", 3) && has("inclined_square.msh", 3),
          "the real meshes have the cells expected");
  }



  /** Files written by gmsh, if it is on PATH: MSH 2.2 and 4.1 (with and
   * without parametric coordinates) of the same second-order mesh must
   * read the same. */
  void
  test_gmsh_files()
  {
    if (std::system("command -v gmsh > /dev/null 2>&1") != 0)
    {
      std::cout << "gmsh files: skipped (no gmsh on PATH)" << std::endl;
      return;
    }
    const std::string geo = write("plate.geo", R"(
SetFactory("Built-in");
Point(1) = {0, 0, 0, 0.3}; Point(2) = {1, 0, 0, 0.3};
Point(3) = {1, 0.6, 0, 0.3}; Point(4) = {0, 0.6, 0, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("body", 7) = {1};
Physical Curve("bottom", 3) = {1}; Physical Curve("top", 5) = {3};
Physical Point("corner", 9) = {1};
)");
    const auto mesh = [&](const std::string &name, const std::string &options)
    {
      const std::string file    = (directory / name).string();
      const std::string command = "gmsh -2 -order 2 " + options + " " + geo +
                                  " -o " + file + " > /dev/null 2>&1";
      check(std::system(command.c_str()) == 0, "gmsh ran: " + command);
      try
      {
        return read_msh_file(file);
      }
      catch (const std::exception &e)
      {
        check(false, e.what());
        return MshFile();
      }
    };
    const MshFile a = mesh("plate22.msh", "-format msh22");
    const MshFile b = mesh("plate41.msh", "-format msh41");
    const MshFile c = mesh("plate41p.msh", "-format msh41 -parametric");
    // the same nodes by tag, the same elements as (type, physical, nodes)
    const auto cells = [](const MshFile &m)
    {
      std::vector<std::tuple<int, int, std::vector<std::uint64_t>>> all;
      for (const MshFile::Element &e : m.elements)
      {
        std::vector<std::uint64_t> tags;
        for (const std::size_t n : e.nodes)
          tags.push_back(m.nodes[n].tag);
        all.emplace_back(e.type, e.physical, tags);
      }
      std::sort(all.begin(), all.end());
      return all;
    };
    const auto nodes = [](const MshFile &m)
    {
      std::map<std::uint64_t, std::array<double, 3>> all;
      for (const MshFile::Node &n : m.nodes)
        all[n.tag] = n.x;
      return all;
    };
    check(!a.elements.empty() && cells(a) == cells(b) && cells(a) == cells(c),
          "gmsh's MSH 2.2 and 4.1 files: the same elements (" +
            std::to_string(a.elements.size()) + ")");
    check(!a.nodes.empty() && nodes(a) == nodes(b) && nodes(a) == nodes(c),
          "gmsh's MSH 2.2 and 4.1 files: the same nodes (" +
            std::to_string(a.nodes.size()) + ")");
    const auto count = [&](const int type, const int physical)
    {
      return std::count_if(a.elements.begin(),
                           a.elements.end(),
                           [&](const auto &e) {
                             return e.type == type && e.physical == physical;
                           });
    };
    check(count(9, 7) > 0 && count(8, 3) > 0 && count(8, 5) > 0 &&
            count(15, 9) == 1,
          "gmsh's files: tri6 of body 7, line3 of boundaries 3 and 5, the "
          "corner point 9");
    std::cout << "gmsh files: " << a.nodes.size() << " nodes, "
              << a.elements.size()
              << " elements from gmsh's MSH 2.2, 4.1 and 4.1 with parametric "
                 "coordinates"
              << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  const fs::path folder =
    argc > 1 ? fs::path(argv[1]) : fs::path(__FILE__).parent_path();
  return reader_check::run("msh_file",
                           [&]()
                           {
                             test_good_meshes();
                             test_real_meshes(folder);
                             test_gmsh_files();
                           });
}
