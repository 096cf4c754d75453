/**
 * The gmsh files and helpers the unit tests msh_file and msh_file_errors
 * share: two good meshes (MSH 2.2 and 4.1 of the same two quadrilaterals
 * with boundary lines and a point), reading a text, the expected failure
 * of reading one, and the comparison of two meshes.
 */

#ifndef tribos_tests_msh_file_cases_h
#define tribos_tests_msh_file_cases_h

#include <tribos/scene/msh_file.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

#include "reader_check.h"

namespace msh_file_cases
{
  /** The number of the first line of @p text that is @p line. */
  inline std::size_t
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

  inline std::size_t
  n_lines(const std::string &text)
  {
    return std::count(text.begin(), text.end(), '\n');
  }

  /** Reading @p text must fail at @p line with a message that has @p
   * expected in it. */
  inline void
  expect_error(const std::string &name,
               const std::string &text,
               const std::size_t  line,
               const std::string &expected)
  {
    const std::string file = reader_check::write(name + ".msh", text);
    reader_check::expect_error_in(
      name,
      [&]() { tribos::read_msh_file(file); },
      file,
      line,
      expected);
  }

  inline tribos::MshFile
  read(const std::string &name, const std::string &text)
  {
    try
    {
      return tribos::read_msh_file(reader_check::write(name + ".msh", text));
    }
    catch (const std::exception &e)
    {
      reader_check::check(false, name + ": " + e.what());
      return tribos::MshFile();
    }
  }

  /** Whether @p a and @p b have the same nodes and elements. */
  inline bool
  same_mesh(const tribos::MshFile &a, const tribos::MshFile &b)
  {
    if (a.nodes.size() != b.nodes.size() ||
        a.elements.size() != b.elements.size())
      return false;
    for (std::size_t i = 0; i < a.nodes.size(); ++i)
      if (a.nodes[i].tag != b.nodes[i].tag || a.nodes[i].x != b.nodes[i].x)
        return false;
    for (std::size_t i = 0; i < a.elements.size(); ++i)
    {
      const tribos::MshFile::Element &e = a.elements[i], &f = b.elements[i];
      if (e.tag != f.tag || e.type != f.type || e.dim != f.dim ||
          e.physical != f.physical || e.entity != f.entity ||
          e.nodes != f.nodes)
        return false;
    }
    return true;
  }

  inline const std::string good22 = R"($MeshFormat
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

  inline const std::string good41 = R"($MeshFormat
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
} // namespace msh_file_cases

#endif
