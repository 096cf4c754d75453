#include <tribos/scene/msh_file.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "msh_file_internal.h"

namespace tribos
{
  namespace
  {
    const MshElementType element_types[] = {
      {1, 1, 2, 2, 1, "2-node line"},
      {2, 2, 3, 3, 1, "3-node triangle"},
      {3, 2, 4, 4, 1, "4-node quadrilateral"},
      {4, 3, 4, 4, 1, "4-node tetrahedron"},
      {5, 3, 8, 8, 1, "8-node hexahedron"},
      {6, 3, 6, 6, 1, "6-node prism"},
      {7, 3, 5, 5, 1, "5-node pyramid"},
      {8, 1, 3, 2, 2, "3-node line"},
      {9, 2, 6, 3, 2, "6-node triangle"},
      {10, 2, 9, 4, 2, "9-node quadrilateral"},
      {11, 3, 10, 4, 2, "10-node tetrahedron"},
      {12, 3, 27, 8, 2, "27-node hexahedron"},
      {13, 3, 18, 6, 2, "18-node prism"},
      {14, 3, 14, 5, 2, "14-node pyramid"},
      {15, 0, 1, 1, 0, "point"},
      {16, 2, 8, 4, 2, "8-node quadrilateral"},
      {17, 3, 20, 8, 2, "20-node hexahedron"},
      {18, 3, 15, 6, 2, "15-node prism"},
      {19, 3, 13, 5, 2, "13-node pyramid"},
      {20, 2, 9, 3, 3, "9-node (incomplete cubic) triangle"},
      {21, 2, 10, 3, 3, "10-node triangle"},
      {22, 2, 12, 3, 4, "12-node (incomplete quartic) triangle"},
      {23, 2, 15, 3, 4, "15-node (quartic) triangle"},
      {24, 2, 15, 3, 5, "15-node (incomplete quintic) triangle"},
      {25, 2, 21, 3, 5, "21-node triangle"},
      {26, 1, 4, 2, 3, "4-node line"},
      {27, 1, 5, 2, 4, "5-node line"},
      {28, 1, 6, 2, 5, "6-node line"},
      {29, 3, 20, 4, 3, "20-node tetrahedron"},
      {30, 3, 35, 4, 4, "35-node tetrahedron"},
      {31, 3, 56, 4, 5, "56-node tetrahedron"},
      {92, 3, 64, 8, 3, "64-node hexahedron"},
      {93, 3, 125, 8, 4, "125-node hexahedron"}};
  } // namespace



  namespace internal::MshFileImplementation
  {
    MshFile
    Parser::read()
    {
      if (!next_line())
        fail(0, "the file is empty: not a gmsh mesh file");
      if (line.substr(0, 3) == "\xEF\xBB\xBF") // a UTF-8 byte order mark
        line.remove_prefix(3);
      if (line == "$NOD" || line == "$NOE")
        fail("an MSH 1 file; tribos reads MSH 2.2 and 4.1: save it with "
             "'gmsh file.msh -save -format msh2 -o new.msh'");
      if (line != "$MeshFormat")
        fail("not a gmsh mesh file: its first line is " + quote(line) +
             ", not $MeshFormat");
      const Section format{"MeshFormat", 1};
      data_line(format, {version_line}, 3);
      double v = 0;
      if (!parse_finite(tokens[0], v) ||
          (v != 2.0 && v != 2.1 && v != 2.2 && v != 4.1))
        fail("MSH version " + quote(tokens[0]) +
             ": tribos reads ASCII MSH 2.0, 2.1, 2.2 and 4.1. Convert the "
             "file with 'gmsh file.msh -save -format msh2 -o new.msh' (or "
             "'-format msh41'), or mesh with 'Mesh.MshFileVersion = 2.2;' "
             "(or 4.1)");
      mesh.version = v;
      version4     = v == 4.1;
      if (integer(1, "the file type (0: ASCII)", 0, 1) == 1)
        fail("a binary gmsh file; tribos reads ASCII ones: save it with "
             "'gmsh file.msh -save -format msh2 -o new.msh' or mesh with "
             "'Mesh.Binary = 0;'");
      integer(2, "the data size (8)", 1);
      end_section(format, version_line);

      std::map<std::string, std::size_t> seen; // the sections read once
      while (next_line())
      {
        if (line.empty())
          continue; // between sections only: inside, a token count error
        if (line[0] != '$')
          fail(quote(line) + " where a section ($Nodes, $Elements, ...) "
                             "is expected");
        const Section s{std::string(line.substr(1)), line_no};
        if (s.name.empty() || s.name.size() > 64 ||
            std::any_of(s.name.begin(),
                        s.name.end(),
                        [](const char c) { return c < 33 || c > 126; }))
          fail(quote(line) + " where a section line ($ and the section's "
                             "name alone) is expected");
        if (s.name.compare(0, 3, "End") == 0)
          fail(quote(line) + " without the section's start before it");
        if (s.name != "MeshFormat" && s.name != "PhysicalNames" &&
            s.name != "Nodes" && s.name != "Elements" &&
            (s.name != "Entities" || !version4))
        {
          const std::string end_line = "$End" + s.name;
          bool              ended    = false;
          while (!ended && next_line()) // $Periodic, $NodeData, ...
            ended = line == end_line;
          if (!ended)
            fail_cut(s);
          continue;
        }
        const auto [it, first] = seen.emplace(s.name, s.line);
        if (!first || s.name == "MeshFormat")
          fail("a second $" + s.name + " section (the first at line " +
               str(first ? 1 : it->second) + "); a gmsh file has one");
        if (s.name == "Entities" && seen.count("Nodes"))
          fail("$Entities after $Nodes; gmsh writes $Entities first");
        if (s.name == "Elements" && !seen.count("Nodes"))
          fail("$Elements before $Nodes; the elements refer to the nodes, "
               "which gmsh writes first");
        if (s.name == "PhysicalNames")
          read_physical_names(s);
        else if (s.name == "Entities")
          read_entities(s);
        else if (s.name == "Nodes")
          read_nodes(s);
        else
          read_elements(s);
      }
      if (!seen.count("Nodes"))
        fail(0, "the file has no $Nodes section");
      if (!seen.count("Elements"))
        fail(0, "the file has no $Elements section");
      return std::move(mesh);
    }
  } // namespace internal::MshFileImplementation



  const MshElementType *
  msh_element_type(const int type)
  {
    for (const MshElementType &t : element_types)
      if (t.type == type)
        return &t;
    return nullptr;
  }



  std::pair<std::size_t, std::size_t>
  MshTagIndex::build(const std::vector<std::uint64_t> &tags)
  {
    by_tag.clear();
    by_sparse_tag.clear();
    const std::uint64_t max =
      tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
    if (max <= 2 * std::uint64_t(tags.size()) + 1024) // dense: a table
    {
      by_tag.assign(max + 1, npos);
      for (std::size_t i = 0; i < tags.size(); ++i)
      {
        if (by_tag[tags[i]] != npos)
          return {by_tag[tags[i]], i};
        by_tag[tags[i]] = i;
      }
    }
    else
    {
      by_sparse_tag.reserve(tags.size());
      for (std::size_t i = 0; i < tags.size(); ++i)
      {
        const auto [it, inserted] = by_sparse_tag.emplace(tags[i], i);
        if (!inserted)
          return {it->second, i};
      }
    }
    return {npos, npos};
  }



  std::size_t
  MshTagIndex::find(const std::uint64_t tag) const
  {
    if (!by_tag.empty())
      return tag < by_tag.size() ? by_tag[tag] : npos;
    const auto it = by_sparse_tag.find(tag);
    return it == by_sparse_tag.end() ? npos : it->second;
  }



  MshFile
  read_msh_file(const std::string &file)
  {
    return internal::MshFileImplementation::Parser(file).read();
  }
} // namespace tribos
