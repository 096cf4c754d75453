/**
 * read_msh_file(), the sections tribos takes: $PhysicalNames, $Entities
 * (MSH 4.1), $Nodes and $Elements, each entry checked as it is read.
 */

#include <tribos/scene/msh_file.h>

#include <algorithm>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "msh_file_internal.h"

namespace tribos
{
  namespace internal::MshFileImplementation
  {
    void
    Parser::read_physical_names(const Section &s)
    {
      data_line(s, {"the number of physical names"}, 1);
      const std::size_t   header = line_no;
      const std::uint64_t n      = unsigned_integer(0, "a count");
      std::map<std::pair<int, int>, std::size_t> named;
      for (std::uint64_t i = 0; i < n; ++i)
      {
        data_line(s, {"'dim tag \"name\"'", "name", i, n, header}, 3, false);
        const int              dim = integer(0, "a dimension", 0, 3);
        const int              tag = integer(1, "a physical tag", 1);
        const std::string_view name =
          trim(line.substr(tokens[1].data() + tokens[1].size() - line.data()));
        if (name.size() < 2 || name.front() != '"' || name.back() != '"')
          fail(quote(name) + " where a name in double quotes is expected");
        const auto [it, inserted] = named.emplace(std::pair(dim, tag), line_no);
        if (!inserted)
          fail("physical group " + std::to_string(tag) + " of dimension " +
               str(dim) + " is named twice: at line " + str(it->second) +
               " and here");
        mesh.physical_names.push_back(
          {unsigned(dim), tag, std::string(name.substr(1, name.size() - 2))});
      }
      end_section(s,
                  "the " + str(n) + " names that line " + str(header) +
                    " announces: more entries than announced?");
    }



    void
    Parser::read_entities(const Section &s)
    {
      data_line(s, {"'numPoints numCurves numSurfaces numVolumes'"}, 4);
      const std::size_t header = line_no;
      std::uint64_t     n[4];
      for (unsigned int d = 0; d < 4; ++d)
        n[d] = unsigned_integer(d, "a number of entities");
      const char *const kind[] = {"point", "curve", "surface", "volume"};
      for (unsigned int d = 0; d < 4; ++d)
        for (std::uint64_t i = 0; i < n[d]; ++i)
        {
          const Expected e{d == 0 ? point_line : entity_line,
                           kind[d],
                           i,
                           n[d],
                           header};
          // a point has its position, the other entities their bounding box
          const std::size_t n_box = d == 0 ? 3 : 6;
          data_line(s, e, n_box + 2 + (d > 0), false);
          const int tag = integer(0, "an entity tag");
          for (std::size_t k = 1; k <= n_box; ++k)
            number(k, "a coordinate");
          const std::size_t n_physical =
            unsigned_integer(n_box + 1, "a count", 0, max_tokens);
          std::size_t n_tokens = n_box + 2 + n_physical;
          if (d > 0)
          {
            expect_tokens(n_tokens + 1, e, false);
            n_tokens +=
              1 + unsigned_integer(n_tokens, "a count", 0, max_tokens);
          }
          expect_tokens(n_tokens, e);
          for (std::size_t k = n_box + 2; k < n_box + 2 + n_physical; ++k)
            physical_tag(k);
          for (std::size_t k = n_box + 3 + n_physical; k < n_tokens; ++k)
            integer(k, "an entity tag");
          const int physical = n_physical > 0 ? physical_tag(n_box + 2) : 0;
          const auto [it, inserted] =
            entities.emplace(std::pair(int(d), tag),
                             Entity{physical, n_physical, line_no});
          if (!inserted)
            fail("entity " + std::to_string(tag) + " of dimension " + str(d) +
                 " is defined twice: at line " + str(it->second.line) +
                 " and here");
        }
      end_section(s, "the entities that line " + str(header) + " announces");
      have_entities = true;
    }



    void
    Parser::read_nodes(const Section &s)
    {
      const ListHeader h =
        read_list_header(s, version4 ? nodes_header : "the number of nodes");
      mesh.nodes.reserve(std::min<std::uint64_t>(h.n, max_reserve));
      std::vector<std::uint64_t> tags;
      std::vector<std::size_t>   tag_lines; // MSH 4.1 lists the tags apart
      std::uint64_t              listed = version4 ? 0 : h.n;
      for (std::uint64_t b = 0; b < h.n_blocks; ++b)
      {
        std::uint64_t size  = h.n;
        std::size_t   block = h.line, n_numbers = 4; // MSH 2: 'tag x y z'
        if (version4)
        {
          data_line(s, {node_block, "node block", b, h.n_blocks, h.line}, 4);
          const int dim = integer(0, "an entity dimension", 0, 3);
          integer(1, "an entity tag");
          n_numbers = 3 + dim * integer(2, "'parametric' (0 or 1)", 0, 1);
          size      = add_block(s, h, listed, "nodes");
          block     = line_no;
          for (std::uint64_t i = 0; i < size; ++i)
          {
            data_line(s, {"the tag", "node", i, size, block}, 1);
            tags.push_back(listed_tag(s, h, "node"));
            tag_lines.push_back(line_no);
          }
        }
        const char *format = !version4      ? "'tag x y z'" :
                             n_numbers == 3 ? "'x y z'" :
                                              "'x y z' and the parametric "
                                              "coordinates";
        for (std::uint64_t i = 0; i < size; ++i)
        {
          data_line(s, {format, "node", i, size, block}, n_numbers);
          if (!version4)
            tags.push_back(listed_tag(s, h, "node"));
          MshFile::Node node{tags[mesh.nodes.size()], {{0, 0, 0}}, line_no};
          for (unsigned int k = 0; k < 3; ++k)
          {
            node.x[k] = number(k + !version4, "a coordinate");
            if (!ReaderText::coordinate_in_range(node.x[k]))
              fail(ReaderText::coordinate_out_of_range(tokens[k + !version4]));
          }
          for (std::size_t k = 3 + !version4; k < n_numbers; ++k)
            number(k, "a parametric coordinate");
          mesh.nodes.push_back(node);
        }
      }
      end_list(s, h, listed, "nodes");
      check_unique(
        mesh.node_tags,
        tags,
        [&](const std::size_t i)
        { return version4 ? tag_lines[i] : mesh.nodes[i].line; },
        "node");
    }



    void
    Parser::read_element_nodes(MshFile::Element &element) const
    {
      const std::size_t n_nodes = msh_element_type(element.type)->n_nodes;
      const std::size_t first   = tokens.size() - n_nodes;
      element.nodes.resize(n_nodes);
      for (std::size_t k = 0; k < n_nodes; ++k)
      {
        const std::uint64_t tag = unsigned_integer(first + k, "a node tag", 1);
        const std::size_t   index = mesh.node_index(tag);
        if (index == MshFile::npos)
          fail("element " + str(element.tag) + " refers to node " + str(tag) +
               ", which $Nodes does not define");
        for (std::size_t j = 0; j < k; ++j)
          if (element.nodes[j] == index)
            fail("element " + str(element.tag) + " lists node " + str(tag) +
                 " twice (as its node " + str(j + 1) + " and " + str(k + 1) +
                 ")");
        element.nodes[k] = index;
      }
    }



    void
    Parser::read_elements(const Section &s)
    {
      const ListHeader h =
        read_list_header(s,
                         version4 ? elements_header : "the number of elements");
      mesh.elements.reserve(std::min<std::uint64_t>(h.n, max_reserve));
      std::vector<std::uint64_t> tags;
      std::uint64_t              listed = version4 ? 0 : h.n;
      for (std::uint64_t b = 0; b < h.n_blocks; ++b)
      {
        const MshElementType *type     = nullptr;
        int                   physical = 0, entity = 0;
        std::uint64_t         size  = h.n;
        std::size_t           block = h.line;
        if (version4)
        {
          data_line(s,
                    {element_block, "element block", b, h.n_blocks, h.line},
                    4);
          const int dim = integer(0, "an entity dimension", 0, 3);
          entity        = integer(1, "an entity tag");
          type          = &element_type(2);
          size          = add_block(s, h, listed, "elements");
          block         = line_no;
          if (int(type->dim) != dim)
            fail("a block of " + std::string(type->name) + "s (dimension " +
                 str(type->dim) + ") on an entity of dimension " + str(dim) +
                 ": the dimensions must agree");
          physical = entity_physical(dim, entity);
        }
        for (std::uint64_t i = 0; i < size; ++i)
        {
          data_line(s,
                    {version4 ? element_line_4 : element_line_2,
                     "element",
                     i,
                     size,
                     block},
                    version4 ? 1 : 3,
                    false);
          MshFile::Element element;
          element.tag        = listed_tag(s, h, "element");
          std::size_t n_tags = 0; // MSH 2
          if (!version4)
          {
            type   = &element_type(1);
            n_tags = unsigned_integer(2, "a number of tags", 0, max_tokens);
          }
          const std::size_t needed = version4 ? 1 : 3 + n_tags;
          if (tokens.size() != needed + type->n_nodes)
            fail("element " + str(element.tag) + " is a " + type->name +
                 " (gmsh type " + str(type->type) + ")" +
                 (version4 ? "" : " with " + str(n_tags) + " tags") +
                 ": its line needs " + str(needed + type->n_nodes) +
                 " numbers (" +
                 (version4 ? "tag" : "tag, type, number of tags, tags") + ", " +
                 str(type->n_nodes) + " nodes), it has " + str(tokens.size()) +
                 (tokens.size() < needed ?
                    "" :
                    " (" + str(tokens.size() - needed) + " nodes)"));
          if (!version4)
          {
            physical = n_tags > 0 ? physical_tag(3) : 0;
            entity   = n_tags > 1 ? integer(4, "an entity tag") : 0;
            for (std::size_t k = 5; k < needed; ++k)
              integer(k, "a tag");
          }
          element.type     = type->type;
          element.dim      = type->dim;
          element.physical = physical;
          element.entity   = entity;
          element.line     = line_no;
          read_element_nodes(element);
          tags.push_back(element.tag);
          mesh.elements.push_back(std::move(element));
        }
      }
      end_list(s, h, listed, "elements");
      MshTagIndex index;
      check_unique(
        index,
        tags,
        [&](const std::size_t i) { return mesh.elements[i].line; },
        "element");
    }
  } // namespace internal::MshFileImplementation
} // namespace tribos
