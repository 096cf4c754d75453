#ifndef tribos_scene_msh_file_internal_h
#define tribos_scene_msh_file_internal_h

/**
 * The line reader of read_msh_file(), shared by its parts (not an
 * interface: read_msh_file() is): msh_file.cc reads the file's outline
 * ($MeshFormat and which sections follow), msh_file_sections.cc the
 * sections tribos takes.
 */

#include <tribos/scene/msh_file.h>

#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "reader_text.h"

namespace tribos
{
  namespace internal::MshFileImplementation
  {
    using ReaderText::is_space;
    using ReaderText::parse_finite;
    using ReaderText::quote;
    using ReaderText::trim;

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



    inline std::string
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
  } // namespace internal::MshFileImplementation
} // namespace tribos

#endif
