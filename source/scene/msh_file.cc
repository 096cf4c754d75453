#include <tribos/scene/msh_file.h>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string_view>

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

    // The lines of the format, in gmsh's words, for the messages.
    const char *const version_line = "'version file-type data-size'";
    const char *const point_line =
      "'tag x y z numPhysicalTags physicalTags...'";
    const char *const entity_line =
      "'tag minX minY minZ maxX maxY maxZ numPhysicalTags physicalTags... "
      "numBoundingEntities entityTags...'";
    const char *const nodes_header =
      "'numEntityBlocks numNodes minNodeTag maxNodeTag'";
    const char *const node_block =
      "'entityDim entityTag parametric numNodesInBlock'";
    const char *const elements_header =
      "'numEntityBlocks numElements minElementTag maxElementTag'";
    const char *const element_block =
      "'entityDim entityTag elementType numElementsInBlock'";
    const char *const element_line_2 = "'tag type numTags tags... nodeTags...'";
    const char *const element_line_4 = "'elementTag nodeTags...'";

    /** No more is reserved from a count that a file announces before the
     * file has listed the entries: a wrong count must not exhaust memory. */
    constexpr std::size_t max_reserve = std::size_t(1) << 20;
    /** A longer line is no text mesh (a binary blob): refused unbuffered. */
    constexpr std::size_t max_line_length = std::size_t(1) << 24;
    /** More numbers than any gmsh line has (an entity's bounding list). */
    constexpr std::size_t max_tokens = std::size_t(1) << 16;

    bool
    is_space(const char c)
    {
      return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
    }

    std::string_view
    trim(std::string_view s)
    {
      while (!s.empty() && is_space(s.back()))
        s.remove_suffix(1);
      while (!s.empty() && is_space(s.front()))
        s.remove_prefix(1);
      return s;
    }

    /** @p s quoted for a message: its start, with non-printing bytes as
     * '?', since the file may be binary. */
    std::string
    quote(const std::string_view s)
    {
      std::string q = "'";
      for (std::size_t i = 0; i < s.size() && i < 40; ++i)
        q += (s[i] < 32 || s[i] > 126) ? '?' : s[i];
      return q + (s.size() > 40 ? "...'" : "'");
    }

    std::string
    str(const std::uint64_t n)
    {
      return std::to_string(n);
    }

    /** Whole-token parses: no sign for unsigned, no trailing garbage. */
    template <typename Integer>
    bool
    parse(const std::string_view s, Integer &value)
    {
      const auto r = std::from_chars(s.data(), s.data() + s.size(), value);
      return r.ec == std::errc() && r.ptr == s.data() + s.size();
    }

    /** A finite double (a leading '+' allowed, as strtod has it). */
    bool
    parse_finite(std::string_view s, double &value)
    {
      if (s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+')
        s.remove_prefix(1);
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
      const char *end = s.data() + s.size();
      const auto  r   = std::from_chars(s.data(), end, value);
      if (r.ptr != end)
        return false;
      if (r.ec == std::errc::result_out_of_range) // 1e999 refused, 1e-400 0
        value = std::strtod(std::string(s).c_str(), nullptr);
      else if (r.ec != std::errc())
        return false;
#else
      const std::string copy(s);
      char             *end = nullptr;
      value                 = std::strtod(copy.c_str(), &end);
      if (copy.empty() || end != copy.c_str() + copy.size() ||
          copy.find_first_of("xXnN") != std::string::npos)
        return false;
#endif
      return std::isfinite(value);
    }

    struct Section
    {
      std::string name;
      std::size_t line;
    };

    /**
     * What a line should hold, for the message if it does not: its format
     * and, for an entry of a list, which of how many the header at which
     * line announces. Cheap to make for every line: the text is built for
     * a message only.
     */
    struct Expected
    {
      const char   *format;
      const char   *entry  = nullptr;
      std::uint64_t index  = 0;
      std::uint64_t count  = 0;
      std::size_t   header = 0;

      std::string
      text() const
      {
        if (entry == nullptr)
          return format;
        return std::string(format) + " of " + entry + " " + str(index + 1) +
               " of the " + str(count) + " that line " + str(header) +
               " announces";
      }
    };

    /** The header of $Nodes or $Elements: in MSH 2 a count, one block. */
    struct ListHeader
    {
      std::size_t   line;
      std::uint64_t n_blocks, n, min, max;
    };

    /** What an element block needs of an entry of $Entities. */
    struct Entity
    {
      int         physical;
      std::size_t n_physical;
      std::size_t line;
    };

    /** One pass over the file, a line at a time, from a bounded buffer. */
    class Parser
    {
    public:
      explicit Parser(const std::string &file)
      {
        mesh.file = file;
        std::error_code error;
        if (!std::filesystem::is_regular_file(file, error))
          fail(0, "no such file (or not a regular file)");
        input.open(file, std::ios::binary);
        if (!input)
          fail(0, "the file cannot be opened for reading");
      }

      MshFile
      read();

    private:
      std::ifstream                 input;
      std::vector<char>             buffer = std::vector<char>(1 << 20);
      std::size_t                   begin = 0, end = 0;
      bool                          at_eof  = false;
      std::size_t                   line_no = 0;
      std::string_view              line; // without surrounding whitespace
      std::vector<std::string_view> tokens;
      MshFile                       mesh;
      bool                          version4      = false;
      bool                          have_entities = false;
      std::map<std::pair<int, int>, Entity> entities;

      [[noreturn]] void
      fail(const std::size_t at, const std::string &message) const
      {
        throw MshError(mesh.file, at, message);
      }

      [[noreturn]] void
      fail(const std::string &message) const
      {
        fail(line_no, message);
      }

      [[noreturn]] void
      fail_cut(const Section &s) const
      {
        fail("the file ends inside its $" + s.name +
             " section opened at line " + str(s.line) +
             ": cut while written or copied?");
      }

      /** The next line into @p line; false at the end of the file. */
      bool
      next_line()
      {
        while (true)
        {
          const char *data = buffer.data();
          const char *nl   = static_cast<const char *>(
            std::memchr(data + begin, '\n', end - begin));
          if (nl != nullptr || (at_eof && begin < end))
          {
            const std::size_t stop = nl != nullptr ? nl - data : end;
            line  = trim(std::string_view(data + begin, stop - begin));
            begin = nl != nullptr ? stop + 1 : end;
            ++line_no;
            return true;
          }
          if (at_eof)
            return false;
          if (end - begin >= max_line_length)
            fail(line_no + 1,
                 "a line longer than 16 MiB: not a text mesh file (binary "
                 "data?)");
          std::memmove(buffer.data(), data + begin, end - begin);
          end -= begin;
          begin = 0;
          if (end == buffer.size())
            buffer.resize(2 * buffer.size());
          input.read(buffer.data() + end, buffer.size() - end);
          if (input.bad())
            fail(line_no + 1, "reading the file failed");
          end += input.gcount();
          at_eof = input.gcount() == 0;
        }
      }

      /** The next line of @p s, split into tokens, which must be @p n (at
       * least @p n unless @p exact). */
      void
      data_line(const Section    &s,
                const Expected   &e,
                const std::size_t n,
                const bool        exact = true)
      {
        if (!next_line())
          fail_cut(s);
        if (!line.empty() && line[0] == '$')
        {
          if (line == "$End" + s.name)
            fail("$End" + s.name + " where " + e.text() +
                 " is expected: the section lists fewer entries than it "
                 "announces");
          fail(quote(line) + " inside the $" + s.name +
               " section opened at line " + str(s.line) + ", where " +
               e.text() + " is expected");
        }
        tokens.clear();
        for (const char *p = line.data(), *stop = p + line.size(); p < stop;)
        {
          const char *q = p;
          while (q < stop && !is_space(*q))
            ++q;
          if (tokens.size() == max_tokens)
            fail("more than 65536 numbers on the line; no gmsh line has as "
                 "many");
          tokens.emplace_back(p, q - p);
          for (p = q; p < stop && is_space(*p);)
            ++p;
        }
        expect_tokens(n, e, exact);
      }

      void
      expect_tokens(const std::size_t n,
                    const Expected   &e,
                    const bool        exact = true) const
      {
        if (exact ? tokens.size() != n : tokens.size() < n)
          fail(str(tokens.size()) + " numbers on the line where " +
               (exact ? "" : "at least ") + str(n) + " expected: " + e.text());
      }

      /** The line after the last entry of @p s must end it. */
      void
      end_section(const Section &s, const std::string &after)
      {
        if (!next_line())
          fail_cut(s);
        if (line != "$End" + s.name)
          fail(quote(line) + " where $End" + s.name + " is expected after " +
               after);
      }

      std::uint64_t
      unsigned_integer(const std::size_t   i,
                       const char         *what,
                       const std::uint64_t min = 0,
                       const std::uint64_t max = UINT64_MAX) const
      {
        std::uint64_t value = 0;
        if (!parse(tokens[i], value) || value < min || value > max)
          fail(quote(tokens[i]) + " where " + what +
               " is expected (an integer from " + str(min) + " to " + str(max) +
               ")");
        return value;
      }

      int
      integer(const std::size_t i,
              const char       *what,
              const int         min = INT_MIN,
              const int         max = INT_MAX) const
      {
        int value = 0;
        if (!parse(tokens[i], value) || value < min || value > max)
          fail(quote(tokens[i]) + " where " + what +
               " is expected (an integer from " + std::to_string(min) + " to " +
               std::to_string(max) + ")");
        return value;
      }

      double
      number(const std::size_t i, const char *what) const
      {
        double value = 0;
        if (!parse_finite(tokens[i], value))
          fail(quote(tokens[i]) + " where " + what +
               " is expected (a finite number)");
        return value;
      }

      /** gmsh writes no negative physical tag; one is refused rather than
       * taken as its absolute value, which could merge two groups. */
      int
      physical_tag(const std::size_t i) const
      {
        return integer(i, "a physical tag", 0);
      }

      const MshElementType &
      element_type(const std::size_t i) const
      {
        const int type = integer(i, "an element type");
        if (msh_element_type(type) == nullptr)
          fail("element type " + std::to_string(type) +
               " is no gmsh element type tribos knows (it reads types "
               "1-31, 92 and 93)");
        return *msh_element_type(type);
      }

      ListHeader
      read_list_header(const Section &s, const char *format)
      {
        data_line(s, {format}, version4 ? 4 : 1);
        if (!version4)
          return {line_no, 1, unsigned_integer(0, "a count"), 1, UINT64_MAX};
        return {line_no,
                unsigned_integer(0, "a number of blocks"),
                unsigned_integer(1, "a count"),
                unsigned_integer(2, "a tag"),
                unsigned_integer(3, "a tag")};
      }

      /** Count the block whose header is the current line into @p listed,
       * which must stay within the section header's count; its size. */
      std::uint64_t
      add_block(const Section    &s,
                const ListHeader &h,
                std::uint64_t    &listed,
                const char       *noun) const
      {
        const std::uint64_t size = unsigned_integer(3, "a number of entries");
        if (size > h.n - listed)
          fail("the blocks list more than the " + str(h.n) + " " + noun +
               " that the $" + s.name + " header (line " + str(h.line) +
               ") announces");
        listed += size;
        return size;
      }

      /** The tag that starts the current line, in the header's range. */
      std::uint64_t
      listed_tag(const Section &s, const ListHeader &h, const char *noun) const
      {
        const std::uint64_t tag =
          unsigned_integer(0,
                           noun[0] == 'n' ? "a node tag" : "an element tag",
                           1);
        if (tag < h.min || tag > h.max)
          fail(std::string(noun) + " tag " + str(tag) +
               " is outside the range " + str(h.min) + " to " + str(h.max) +
               " that the $" + s.name + " header (line " + str(h.line) +
               ") announces");
        return tag;
      }

      /** The section's end, after as many entries as its header says. */
      void
      end_list(const Section      &s,
               const ListHeader   &h,
               const std::uint64_t listed,
               const char         *noun)
      {
        end_section(s,
                    "the " + str(version4 ? h.n_blocks : h.n) + " " +
                      (version4 ? "blocks" : noun) + " that line " +
                      str(h.line) + " announces: more entries than announced?");
        if (listed != h.n)
          fail(h.line,
               "the $" + s.name + " header announces " + str(h.n) + " " + noun +
                 ", its blocks list " + str(listed));
      }

      template <typename LineOf>
      void
      check_unique(MshTagIndex                      &index,
                   const std::vector<std::uint64_t> &tags,
                   const LineOf                     &line_of,
                   const char                       *noun) const
      {
        const auto repeat = index.build(tags);
        if (repeat.first != MshTagIndex::npos)
          fail(line_of(repeat.second),
               std::string(noun) + " tag " + str(tags[repeat.first]) +
                 " is defined twice: at line " + str(line_of(repeat.first)) +
                 " and here");
      }

      /** The physical tag of the elements of entity @p tag. */
      int
      entity_physical(const int dim, const int tag) const
      {
        if (!have_entities)
          return 0;
        const auto it = entities.find(std::pair(dim, tag));
        if (it == entities.end())
          fail("the block's entity " + std::to_string(tag) + " of dimension " +
               str(dim) + " is not in $Entities");
        if (it->second.n_physical > 1 && dim > 0)
          fail("entity " + std::to_string(tag) + " of dimension " + str(dim) +
               " is in several physical groups; tribos takes one per "
               "entity: its body or boundary id ($Entities line " +
               str(it->second.line) + ")");
        return it->second.n_physical == 1 ? it->second.physical : 0;
      }

      void
      read_physical_names(const Section &s);
      void
      read_entities(const Section &s);
      void
      read_nodes(const Section &s);
      void
      read_elements(const Section &s);
      void
      read_element_nodes(MshFile::Element &element) const;
    };



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
            node.x[k] = number(k + !version4, "a coordinate");
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
  } // namespace



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
    return Parser(file).read();
  }
} // namespace tribos
