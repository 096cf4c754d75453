// ctest: labels quick
/**
 * Unit test of the gmsh file reader read_msh_file() (std only, no deal.II:
 * g++ -std=c++17 -Iinclude tests/unit/msh_file.cc source/scene/msh_file.cc).
 * A 2D mesh of two quadrilaterals with boundary lines and a point, written
 * as MSH 2.2 and as MSH 4.1, must read the same; then one malformed file
 * per rule of the reader (the cases a fuzz campaign found in the readers
 * tribos used before, and the rest of the format), each of which must give
 * an MshError at the right line with the right message; then the .msh
 * files in tests/, against a plain independent reading; then files written
 * by gmsh, if it is on PATH (else it says "skipped"). Prints each failed check
 * and "N passed, N failed"; returns non-zero if any failed. The optional
 * argument is the folder of the .msh files (default: this file's folder).
 */

#include <tribos/scene/msh_file.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
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

  /** The number of the first line of @p text that is @p line. */
  std::size_t
  line_of(const std::string &text, const std::string &line)
  {
    std::istringstream in(text);
    std::string        l;
    for (std::size_t n = 1; std::getline(in, l); ++n)
      if (l == line || l == line + "\r")
        return n;
    std::cout << "test error: no line '" << line << "'\n";
    std::exit(2);
  }

  std::size_t
  n_lines(const std::string &text)
  {
    return std::count(text.begin(), text.end(), '\n');
  }

  /** Reading @p text must fail at @p line with a message that has @p
   * expected in it. */
  void
  expect_error(const std::string &name,
               const std::string &text,
               const std::size_t  line,
               const std::string &expected)
  {
    const std::string file = write(name + ".msh", text);
    try
    {
      read_msh_file(file);
      check(false,
            name + ": read without error; expected line " +
              std::to_string(line) + ": " + expected);
    }
    catch (const MshError &e)
    {
      const std::string what =
        file + ":" + std::to_string(e.line()) + ": " + e.message();
      check(e.line() == line &&
              e.message().find(expected) != std::string::npos &&
              e.file() == file && e.what() == what,
            name + ": expected line " + std::to_string(line) + " and '" +
              expected + "', got: " + e.what());
    }
    catch (const std::exception &e)
    {
      check(false, name + ": not an MshError: " + e.what());
    }
  }

  MshFile
  read(const std::string &name, const std::string &text)
  {
    try
    {
      return read_msh_file(write(name + ".msh", text));
    }
    catch (const std::exception &e)
    {
      check(false, name + ": " + e.what());
      return MshFile();
    }
  }

  /** Whether @p a and @p b have the same nodes and elements. */
  bool
  same_mesh(const MshFile &a, const MshFile &b)
  {
    if (a.nodes.size() != b.nodes.size() ||
        a.elements.size() != b.elements.size())
      return false;
    for (std::size_t i = 0; i < a.nodes.size(); ++i)
      if (a.nodes[i].tag != b.nodes[i].tag || a.nodes[i].x != b.nodes[i].x)
        return false;
    for (std::size_t i = 0; i < a.elements.size(); ++i)
    {
      const MshFile::Element &e = a.elements[i], &f = b.elements[i];
      if (e.tag != f.tag || e.type != f.type || e.dim != f.dim ||
          e.physical != f.physical || e.entity != f.entity ||
          e.nodes != f.nodes)
        return false;
    }
    return true;
  }

  const std::string good22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
3
1 10 "bottom"
1 11 "top side"
2 1 "body"
$EndPhysicalNames
$Nodes
6
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
$EndNodes
$Elements
6
1 15 2 0 1 1
2 1 2 10 1 1 2
3 1 2 10 1 2 3
4 1 2 11 3 6 5
5 3 2 1 1 1 2 5 4
6 3 2 1 1 2 3 6 5
$EndElements
)";

  const std::string good41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
1 10 "bottom"
1 11 "top side"
2 1 "body"
$EndPhysicalNames
$Entities
1 2 1 0
1 0 0 0 0
1 0 0 0 2 0 0 1 10 2 1 -2
3 0 1 0 2 1 0 1 11 0
1 0 0 0 2 1 0 1 1 2 1 3
$EndEntities
$Nodes
3 6 1 6
0 1 0 1
1
0 0 0
1 1 1 2
2
3
1 0 0 0.5
2 0 0 1
2 1 0 3
4
5
6
0 1 0
1 1 0
2 1 0
$EndNodes
$Elements
4 6 1 6
0 1 15 1
1 1
1 1 1 2
2 1 2
3 2 3
1 3 1 1
4 6 5
2 1 3 2
5 1 2 5 4
6 2 3 6 5
$EndElements
)";



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



  void
  test_header_and_sections()
  {
    expect_error("empty", "", 0, "the file is empty");
    expect_error("not_msh", "hello\n" + good22, 1, "not a gmsh mesh file");
    expect_error("msh1", "$NOD\n1\n1 0 0 0\n$ENDNOD\n", 1, "an MSH 1 file");
    for (const char *v : {"3.0", "4.0", "4.2", "1.0", "two"})
      expect_error(std::string("version_") + v,
                   replace(good22, "2.2 0 8", std::string(v) + " 0 8"),
                   2,
                   "tribos reads ASCII MSH 2.0, 2.1, 2.2 and 4.1. Convert "
                   "the file with 'gmsh file.msh -save -format msh2 -o "
                   "new.msh' (or '-format msh41'), or mesh with "
                   "'Mesh.MshFileVersion = 2.2;'");
    expect_error("binary",
                 replace(good41, "4.1 0 8\n", "4.1 1 8\n\x01\n"),
                 2,
                 "a binary gmsh file; tribos reads ASCII ones: save it with "
                 "'gmsh file.msh -save -format msh2 -o new.msh' or mesh with "
                 "'Mesh.Binary = 0;'");
    expect_error("format_tokens",
                 replace(good22, "2.2 0 8", "2.2 0 8 1"),
                 2,
                 "4 numbers on the line where 3 expected: 'version "
                 "file-type data-size'");
    expect_error("no_end_format",
                 replace(good22, "$EndMeshFormat\n", ""),
                 3,
                 "'$PhysicalNames' where $EndMeshFormat is expected");
    const std::string cut = good22.substr(0, good22.find("5 3 2 1"));
    expect_error("cut",
                 cut,
                 n_lines(cut),
                 "the file ends inside its $Elements section opened at line "
                 "19: cut while written or copied?");
    expect_error("cut_header",
                 "$MeshFormat\n",
                 1,
                 "ends inside its $MeshFormat");
    expect_error("no_end_nodes",
                 replace(good22, "$EndNodes\n", ""),
                 18,
                 "'$Elements' where $EndNodes is expected after the 6 nodes "
                 "that line 11 announces");
    expect_error("stray_section",
                 replace(good22, "4 0 1 0\n", "$Foo\n"),
                 15,
                 "'$Foo' inside the $Nodes section opened at line 10, where "
                 "'tag x y z' of node 4 of the 6 that line 11 announces is "
                 "expected");
    expect_error("unended_skipped",
                 good22 + "$NodeData\n1\n2\n",
                 n_lines(good22) + 3,
                 "the file ends inside its $NodeData section opened at line " +
                   std::to_string(n_lines(good22) + 1));
    expect_error("second_nodes",
                 replace(good22,
                         "$Elements\n",
                         "$Nodes\n0\n$EndNodes\n$Elements\n"),
                 19,
                 "a second $Nodes section (the first at line 10)");
    expect_error("second_format",
                 good22 + "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n",
                 n_lines(good22) + 1,
                 "a second $MeshFormat section");
    expect_error("no_elements",
                 good22.substr(0, good22.find("$Elements")),
                 0,
                 "the file has no $Elements section");
    expect_error("no_nodes",
                 "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n",
                 0,
                 "the file has no $Nodes section");
    const std::string elements = good22.substr(good22.find("$Elements"));
    expect_error("elements_first",
                 replace(replace(good22, elements, ""),
                         "$Nodes\n",
                         elements + "$Nodes\n"),
                 10,
                 "$Elements before $Nodes");
    const std::string entities =
      good41.substr(good41.find("$Entities"),
                    good41.find("$Nodes") - good41.find("$Entities"));
    const std::string swapped = replace(replace(good41, entities, ""),
                                        "$Elements\n",
                                        entities + "$Elements\n");
    expect_error("entities_after_nodes",
                 swapped,
                 line_of(swapped, "$Entities"),
                 "$Entities after $Nodes");
    expect_error("junk_between",
                 replace(good22, "$Nodes\n", "hello\n$Nodes\n"),
                 10,
                 "'hello' where a section ($Nodes, $Elements, ...) is "
                 "expected");
    expect_error("stray_end",
                 replace(good22, "$Nodes\n", "$EndFoo\n$Nodes\n"),
                 10,
                 "'$EndFoo' without the section's start before it");
    expect_error("dollar_alone",
                 replace(good22, "$Nodes\n", "$\n$Nodes\n"),
                 10,
                 "'$' where a section line ($ and the section's name alone)");
    expect_error("section_binary",
                 replace(good22,
                         "$Nodes\n",
                         "$N\xff"
                         "des\n$Nodes\n"),
                 10,
                 "'$N?des' where a section line");
    expect_error("section_words",
                 replace(good22, "$Nodes\n", "$Nodes 6\n"),
                 10,
                 "where a section line ($ and the section's name alone)");
    try
    {
      read_msh_file((directory / "does_not_exist.msh").string());
      check(false, "a missing file: no error");
    }
    catch (const MshError &e)
    {
      check(e.line() == 0 && e.message().find("no such file") == 0,
            std::string("a missing file: ") + e.what());
    }
    expect_error("names_unquoted",
                 replace(good22, "\"top side\"", "top side"),
                 7,
                 "'top side' where a name in double quotes is expected");
    expect_error("names_twice",
                 replace(good22, "2 1 \"body\"", "1 10 \"body\""),
                 8,
                 "physical group 10 of dimension 1 is named twice: at line 6 "
                 "and here");
  }



  void
  test_counts_and_tokens()
  {
    // MSH 2 counts
    expect_error("nodes_fewer_announced",
                 replace(good22, "$Nodes\n6\n", "$Nodes\n5\n"),
                 17,
                 "'6 2 1 0' where $EndNodes is expected after the 5 nodes "
                 "that line 11 announces: more entries than announced?");
    expect_error("nodes_more_announced",
                 replace(good22, "$Nodes\n6\n", "$Nodes\n7\n"),
                 18,
                 "$EndNodes where 'tag x y z' of node 7 of the 7 that line "
                 "11 announces is expected: the section lists fewer entries "
                 "than it announces");
    expect_error("elements_fewer_announced",
                 replace(good22, "$Elements\n6\n", "$Elements\n5\n"),
                 26,
                 "where $EndElements is expected after the 5 elements");
    expect_error("elements_more_announced",
                 replace(good22, "$Elements\n6\n", "$Elements\n9\n"),
                 27,
                 "$EndElements where 'tag type numTags tags... nodeTags...' "
                 "of element 7 of the 9 that line 20 announces is expected");
    expect_error("count_1e18",
                 replace(good22,
                         "$Nodes\n6\n",
                         "$Nodes\n1000000000000000000\n"),
                 18,
                 "of node 7 of the 1000000000000000000 that line 11");
    expect_error("count_1e18_41",
                 replace(good41, "3 6 1 6", "3 1000000000000000000 1 6"),
                 18,
                 "the $Nodes header announces 1000000000000000000 nodes, its "
                 "blocks list 6");
    expect_error("block_1e18",
                 replace(good41, "2 1 0 3", "2 1 0 1000000000000000000"),
                 27,
                 "the blocks list more than the 6 nodes");
    expect_error("count_2e64",
                 replace(good22,
                         "$Elements\n6\n",
                         "$Elements\n18446744073709551616\n"),
                 20,
                 "'18446744073709551616' where a count is expected");
    expect_error("entities_1e18",
                 replace(good41, "1 2 1 0", "1 2 1000000000000000000 0"),
                 16,
                 "$EndEntities where 'tag minX minY minZ maxX maxY maxZ "
                 "numPhysicalTags physicalTags... numBoundingEntities "
                 "entityTags...' of surface 2 of the 1000000000000000000 that "
                 "line 11 announces is expected");

    // MSH 4.1 counts
    expect_error("header41_fewer",
                 replace(good41, "3 6 1 6", "3 5 1 6"),
                 27,
                 "the blocks list more than the 5 nodes that the $Nodes "
                 "header (line 18) announces");
    expect_error("header41_more",
                 replace(good41, "3 6 1 6", "3 7 1 6"),
                 18,
                 "the $Nodes header announces 7 nodes, its blocks list 6");
    expect_error("blocks41_fewer",
                 replace(good41, "3 6 1 6", "2 6 1 6"),
                 27,
                 "'2 1 0 3' where $EndNodes is expected after the 2 blocks "
                 "that line 18 announces: more entries than announced?");
    expect_error("blocks41_more",
                 replace(good41, "4 6 1 6", "5 6 1 6"),
                 47,
                 "$EndElements where 'entityDim entityTag elementType "
                 "numElementsInBlock' of element block 5 of the 5 that line "
                 "36 announces is expected");
    expect_error("elements41_sum",
                 replace(good41, "4 6 1 6", "4 7 1 7"),
                 36,
                 "the $Elements header announces 7 elements, its blocks list "
                 "6");
    expect_error("block41_fewer_nodes",
                 replace(good41, "2 1 0 3", "2 1 0 2"),
                 30,
                 "1 numbers on the line where 3 expected: 'x y z' of node 1 "
                 "of the 2 that line 27 announces");
    expect_error("block41_more_nodes",
                 replace(replace(good41, "2 1 0 3", "2 1 0 4"),
                         "3 6 1 6",
                         "3 7 1 6"),
                 31,
                 "3 numbers on the line where 1 expected: the tag of node 4 "
                 "of the 4 that line 27 announces");
    expect_error("block41_more_elements",
                 replace(replace(good41, "2 1 3 2", "2 1 3 3"),
                         "4 6 1 6",
                         "4 7 1 6"),
                 47,
                 "$EndElements where 'elementTag nodeTags...' of element 3 of "
                 "the 3 that line 44 announces");

    // tokens per line: never one of the next line
    expect_error("element_one_more",
                 replace(good22, "5 3 2 1 1 1 2 5 4", "5 3 2 1 1 1 2 5 4 6"),
                 25,
                 "element 5 is a 4-node quadrilateral (gmsh type 3) with 2 "
                 "tags: its line needs 9 numbers (tag, type, number of tags, "
                 "tags, 4 nodes), it has 10 (5 nodes)");
    expect_error("element_one_less",
                 replace(good22, "5 3 2 1 1 1 2 5 4", "5 3 2 1 1 1 2 5"),
                 25,
                 "it has 8 (3 nodes)");
    expect_error("tri6_five_nodes",
                 replace(good22, "5 3 2 1 1 1 2 5 4", "5 9 2 1 1 1 2 5 4 3"),
                 25,
                 "element 5 is a 6-node triangle (gmsh type 9) with 2 tags: "
                 "its line needs 11 numbers (tag, type, number of tags, tags, "
                 "6 nodes), it has 10 (5 nodes)");
    expect_error("tet10_nine_nodes",
                 replace(good22,
                         "5 3 2 1 1 1 2 5 4",
                         "5 11 2 1 1 1 2 3 4 5 6 1 2 3"),
                 25,
                 "10-node tetrahedron (gmsh type 11) with 2 tags: its line "
                 "needs 15 numbers");
    expect_error("element_tags_no_nodes",
                 replace(good22, "5 3 2 1 1 1 2 5 4", "5 3 2"),
                 25,
                 "with 2 tags: its line needs 9 numbers (tag, type, number of "
                 "tags, tags, 4 nodes), it has 3");
    expect_error("element_short",
                 replace(good22, "5 3 2 1 1 1 2 5 4", "5 3"),
                 25,
                 "2 numbers on the line where at least 3 expected");
    expect_error(
      "element_many_tags",
      replace(good22, "5 3 2 1 1 1 2 5 4", "5 3 99 1 1 1 2 5 4"),
      25,
      "with 99 tags: its line needs 106 numbers (tag, type, number of tags, tags, 4 nodes), it has 9");
    expect_error("element41_one_more",
                 replace(good41, "5 1 2 5 4", "5 1 2 5 4 6"),
                 45,
                 "element 5 is a 4-node quadrilateral (gmsh type 3): its line "
                 "needs 5 numbers (tag, 4 nodes), it has 6 (5 nodes)");
    expect_error("element41_one_less",
                 replace(good41, "5 1 2 5 4", "5 1 2 5"),
                 45,
                 "it has 4 (3 nodes)");
    expect_error("node_three_numbers",
                 replace(good22, "3 2 0 0", "3 2 0"),
                 14,
                 "3 numbers on the line where 4 expected: 'tag x y z' of node "
                 "3 of the 6 that line 11 announces");
    expect_error("node_blank_line",
                 replace(good22, "3 2 0 0\n", "\n3 2 0 0\n"),
                 14,
                 "0 numbers on the line where 4 expected");
    expect_error("parametric_missing",
                 replace(good41, "1 0 0 0.5", "1 0 0"),
                 25,
                 "3 numbers on the line where 4 expected: 'x y z' and the "
                 "parametric coordinates of node 1 of the 2 that line 22");
    expect_error("entity_short",
                 replace(good41,
                         "1 0 0 0 2 0 0 1 10 2 1 -2",
                         "1 0 0 0 2 0 0 1 10 2 1"),
                 13,
                 "11 numbers on the line where 12 expected: 'tag minX minY "
                 "minZ maxX maxY maxZ numPhysicalTags physicalTags... "
                 "numBoundingEntities entityTags...' of curve 1 of the 2 that "
                 "line 11 announces");
    expect_error("point_long",
                 replace(good41, "1 0 0 0 0\n", "1 0 0 0 0 7\n"),
                 12,
                 "6 numbers on the line where 5 expected: 'tag x y z "
                 "numPhysicalTags physicalTags...' of point 1");
    expect_error("entity_phys_count",
                 replace(good41,
                         "1 0 0 0 2 0 0 1 10 2 1 -2",
                         "1 0 0 0 2 0 0 70000 10 2 1 -2"),
                 13,
                 "'70000' where a count is expected");
  }



  void
  test_numbers_and_references()
  {
    for (const std::string x :
         {"abc", "nan", "-inf", "inf", "1e999", "1.0x", "0x10", "--1", "+-1"})
      expect_error("coordinate_" + x,
                   replace(good22, "5 1 1 0", "5 1 " + x + " 0"),
                   16,
                   "'" + x +
                     "' where a coordinate is expected (a finite "
                     "number)");
    expect_error("tag_garbage",
                 replace(good22, "3 2 0 0", "3a 2 0 0"),
                 14,
                 "'3a' where a node tag is expected (an integer from 1 to "
                 "18446744073709551615)");
    expect_error("tag_negative",
                 replace(good22, "3 2 0 0", "-3 2 0 0"),
                 14,
                 "'-3' where a node tag");
    expect_error("tag_zero",
                 replace(good22, "3 2 0 0", "0 2 0 0"),
                 14,
                 "'0' where a node tag");
    expect_error("tag_2e64",
                 replace(good41, "\n4\n5\n", "\n18446744073709551616\n5\n"),
                 28,
                 "'18446744073709551616' where a node tag is expected");
    expect_error("tag_outside_range",
                 replace(good41, "\n4\n5\n", "\n7\n5\n"),
                 28,
                 "node tag 7 is outside the range 1 to 6 that the $Nodes "
                 "header (line 18) announces");
    expect_error("element_tag_outside_range",
                 replace(good41, "6 2 3 6 5", "7 2 3 6 5"),
                 46,
                 "element tag 7 is outside the range 1 to 6");
    expect_error("element_type_garbage",
                 replace(good22, "5 3 2 1 1 1 2 5 4", "5 3.0 2 1 1 1 2 5 4"),
                 25,
                 "'3.0' where an element type is expected");

    // uniqueness and references
    expect_error("node_twice",
                 replace(good22, "5 1 1 0", "3 1 1 0"),
                 16,
                 "node tag 3 is defined twice: at line 14 and here");
    expect_error("node_twice_41",
                 replace(good41, "\n5\n6\n", "\n5\n3\n"),
                 30,
                 "node tag 3 is defined twice: at line 24 and here");
    expect_error("node_twice_sparse",
                 replace(replace(good22, "5 1 1 0", "3000000000 1 1 0"),
                         "1 0 0 0",
                         "3000000000 0 0 0"),
                 16,
                 "node tag 3000000000 is defined twice: at line 12 and here");
    expect_error("element_twice",
                 replace(good22, "6 3 2 1 1 2 3 6 5", "2 3 2 1 1 2 3 6 5"),
                 26,
                 "element tag 2 is defined twice: at line 22 and here");
    expect_error("missing_node",
                 replace(good22, "5 3 2 1 1 1 2 5 4", "5 3 2 1 1 1 2 9 4"),
                 25,
                 "element 5 refers to node 9, which $Nodes does not define");
    expect_error("missing_node_41",
                 replace(good41, "5 1 2 5 4", "5 1 2 3000000000 4"),
                 45,
                 "element 5 refers to node 3000000000, which $Nodes does not "
                 "define");
    expect_error("node_repeated",
                 replace(good22, "5 3 2 1 1 1 2 5 4", "5 3 2 1 1 1 2 5 2"),
                 25,
                 "element 5 lists node 2 twice (as its node 2 and 4)");
    expect_error("unknown_type",
                 replace(good22, "5 3 2 1 1 1 2 5 4", "5 99 2 1 1 1 2 5 4"),
                 25,
                 "element type 99 is no gmsh element type tribos knows");
    expect_error("unknown_type_41",
                 replace(good41, "2 1 3 2", "2 1 34 2"),
                 44,
                 "element type 34 is no gmsh element type tribos knows");
    expect_error("block_dimension",
                 replace(good41, "2 1 3 2", "3 1 3 2"),
                 44,
                 "a block of 4-node quadrilaterals (dimension 2) on an entity "
                 "of dimension 3: the dimensions must agree");

    // physical tags of MSH 4.1 entities
    expect_error("several_physicals",
                 replace(good41,
                         "1 0 0 0 2 1 0 1 1 2 1 3",
                         "1 0 0 0 2 1 0 2 1 4 2 1 3"),
                 44,
                 "entity 1 of dimension 2 is in several physical groups; "
                 "tribos takes one per entity: its body or boundary id "
                 "($Entities line 15)");
    const MshFile point =
      read("point_in_two_groups",
           replace(good41, "1 0 0 0 0\n", "1 0 0 0 2 5 6\n"));
    check(point.elements.size() == 6 && point.elements[0].physical == 0,
          "a point entity in two physical groups: physical 0");
    expect_error("entity_missing",
                 replace(good41, "1 3 1 1", "1 4 1 1"),
                 42,
                 "the block's entity 4 of dimension 1 is not in $Entities");
    expect_error("entity_twice",
                 replace(good41,
                         "3 0 1 0 2 1 0 1 11 0",
                         "1 0 1 0 2 1 0 1 11 0"),
                 14,
                 "entity 1 of dimension 1 is defined twice: at line 13 and "
                 "here");
    expect_error("physical_negative_41",
                 replace(good41,
                         "3 0 1 0 2 1 0 1 11 0",
                         "3 0 1 0 2 1 0 1 -11 0"),
                 14,
                 "'-11' where a physical tag is expected (an integer from 0");
    expect_error("physical_negative_22",
                 replace(good22, "4 1 2 11 3 6 5", "4 1 2 -11 3 6 5"),
                 24,
                 "'-11' where a physical tag is expected (an integer from 0");
  }



  /** Inputs that must fail fast, whatever they are. */
  void
  test_hostile_inputs()
  {
    const auto  start   = std::chrono::steady_clock::now();
    std::string dollars = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
    for (unsigned int i = 0; i < 1000000; ++i)
      dollars += "$X\n";
    expect_error("dollars",
                 dollars,
                 1000003,
                 "the file ends inside its $X section opened at line 4");
    std::string  blob = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n";
    std::mt19937 random(7);
    for (unsigned int i = 0; i < 100000; ++i)
      blob += char(random() % 256);
    try
    {
      read_msh_file(write("blob.msh", blob));
      check(false, "a binary blob after the header: no error");
    }
    catch (const MshError &e)
    {
      check(e.line() >= 5, std::string("a binary blob: ") + e.what());
    }
    expect_error("long_line",
                 "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" +
                   std::string(20 << 20, '1'),
                 5,
                 "a line longer than 16 MiB");
    std::string spaced;
    for (unsigned int i = 0; i < 70000; ++i)
      spaced += " 1";
    expect_error("too_many_tokens",
                 replace(good22, "3 2 0 0", "3 2 0 0" + spaced),
                 14,
                 "more than 65536 numbers on the line");
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    check(seconds < 10,
          "hostile inputs read in " + std::to_string(seconds) + " s");
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
  directory =
    fs::temp_directory_path() /
    ("tribos_msh_file_" + std::to_string(std::random_device()()) + "_" +
     std::to_string(
       std::chrono::steady_clock::now().time_since_epoch().count()));
  fs::create_directories(directory);
  const fs::path folder =
    argc > 1 ? fs::path(argv[1]) : fs::path(__FILE__).parent_path();

  test_good_meshes();
  test_header_and_sections();
  test_counts_and_tokens();
  test_numbers_and_references();
  test_hostile_inputs();
  test_real_meshes(folder);
  test_gmsh_files();

  std::error_code error;
  fs::remove_all(directory, error);
  std::cout << n_passed << " passed, " << n_failed << " failed" << std::endl;
  return n_failed == 0 ? 0 : 1;
}
