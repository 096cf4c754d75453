/**
 * Unit test of the Abaqus/CalculiX deck reader read_inp_file(), its
 * refusals (std only, no deal.II): the errors that given ids cause
 * (InpIdError) and the deck's own (MshError); malformed decks, each of
 * which must give an MshError at the right file and line with the right
 * message; every cut of a good deck (no crash: read or refused). The good
 * decks are inp_file's. Prints each failed check and "N passed, N
 * failed"; returns non-zero if any failed.
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
} // namespace



int
main()
{
  return reader_check::run("inp_file_errors",
                           []()
                           {
                             test_id_errors();
                             test_malformed();
                             test_cuts("two_bodies", two_bodies);
                           });
}
