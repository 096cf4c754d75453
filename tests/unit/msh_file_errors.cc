// ctest: labels quick
/**
 * Unit test of the gmsh file reader read_msh_file(), its refusals (std
 * only, no deal.II): one malformed file per rule of the reader (the cases
 * a fuzz campaign found in the readers tribos used before, and the rest of
 * the format), each of which must give an MshError at the right line with
 * the right message. The good files are msh_file's. Prints each failed
 * check and "N passed, N failed"; returns non-zero if any failed.
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
} // namespace



int
main()
{
  return reader_check::run("msh_file_errors",
                           []()
                           {
                             test_header_and_sections();
                             test_counts_and_tokens();
                             test_numbers_and_references();
                             test_hostile_inputs();
                           });
}
