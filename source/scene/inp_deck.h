#ifndef tribos_scene_inp_deck_h
#define tribos_scene_inp_deck_h

/**
 * The Abaqus deck reader's internal state, shared by its parts (not an
 * interface: read_inp_file() is): inp_file.cc (keyword lines) and
 * inp_data_lines.cc (data lines) read the deck into an InpDeck,
 * inp_ids.cc gives its cells body ids and adds the boundary elements.
 */

#include <tribos/scene/inp_file.h>

#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "reader_text.h"

namespace tribos
{
  namespace internal
  {
    /** A line of a file: the file (a position in InpDeck::files), the line
     * (0: the whole file). */
    struct InpWhere
    {
      std::size_t file = 0, line = 0;
    };

    /** An *NSET or *ELSET: positions in MshFile::nodes or elements. */
    struct InpSet
    {
      /** As first spelled. */
      std::string name;
      /** Its first keyword line. */
      InpWhere where;
      /** Its place among the sets and surfaces, in order of appearance. */
      std::size_t order;
      /** Marked INTERNAL: Abaqus/CAE's sets for its surfaces. */
      bool internal;
      /** As listed: in order, possibly repeated. */
      std::vector<std::size_t> members;
    };

    /** Face @p face (from 0) of element @p element, as a surface lists it. */
    struct InpFace
    {
      std::size_t  element;
      unsigned int face;
      InpWhere     where;
    };

    /** A *SURFACE: element faces (TYPE=ELEMENT) or nodes (TYPE=NODE). */
    struct InpSurface
    {
      std::string              name;
      InpWhere                 where;
      std::size_t              order;
      bool                     of_nodes;
      std::vector<std::size_t> nodes;
      std::vector<InpFace>     faces;
    };

    /** A deck as read: the mesh without ids or boundary elements, where
     * each node and element is defined, and the sets. */
    struct InpDeck
    {
      /** Nodes and cells; physical 0, no boundary elements yet. */
      MshFile mesh;
      /** Every file read, the deck first, for messages. */
      std::vector<std::string> files;
      /** The file of each node, each element. */
      std::vector<std::size_t> node_files, element_files;
      /** The type of each element, and its name in the deck. */
      std::vector<const InpElementType *> types;
      std::vector<std::string>            type_names;
      std::vector<InpSet>                 nsets, elsets;
      std::vector<InpSurface>             surfaces;
      /** The sets and surfaces by inp_key() of their names. */
      std::unordered_map<std::string, std::size_t> nset_of, elset_of,
        surface_of;

      /** The name of the file of @p w. */
      const std::string &
      file_of(const InpWhere &w) const
      {
        return w.file < files.size() ? files[w.file] : mesh.file;
      }

      [[noreturn]] void
      fail(const InpWhere &w, const std::string &message) const
      {
        throw MshError(file_of(w), w.line, message);
      }

      /** "file:line" of @p w, for a message about another place. */
      std::string
      place(const InpWhere &w) const
      {
        return file_of(w) + ":" + std::to_string(w.line);
      }

      InpWhere
      element_where(const std::size_t e) const
      {
        return {element_files[e], mesh.elements[e].line};
      }
    };

    /** The data lines that follow a keyword line. */
    enum class InpBlock
    {
      none,
      skip,
      node,
      element,
      elset,
      nset,
      element_surface,
      node_surface
    };

    /**
     * One pass over the deck and its includes, a line at a time: keyword
     * lines in inp_file.cc, data lines in inp_data_lines.cc. What a line
     * refers to must be defined above it, so that every reference is
     * checked where it stands and none can be cyclic.
     */
    class InpParser
    {
    public:
      explicit InpParser(const std::string &file)
      {
        deck.mesh.file = file;
      }

      InpDeck
      read();

    private:
      InpDeck                            deck;
      std::vector<std::filesystem::path> reading; // the files open (cycles)
      InpWhere                           at;
      std::string                        line;
      std::vector<std::string_view>      tokens;
      bool                               any_keyword = false;
      // The current keyword's block and parameters.
      InpBlock                                         block = InpBlock::none;
      std::vector<std::pair<std::string, std::string>> parameters;
      const InpElementType                            *type = nullptr;
      std::string                                      type_name;
      std::size_t set      = MshFile::npos; // the set (or surface) lines fill
      bool        generate = false;
      // An element whose data line ended with a comma: its fields so far.
      std::vector<std::pair<std::string, std::size_t>> pending;
      InpWhere                                         pending_at;
      std::unordered_map<std::uint64_t, std::size_t>   node_of, element_of;
      std::size_t n_definitions = 0, n_members = 0;

      [[noreturn]] void
      fail(const std::string &message) const
      {
        deck.fail(at, message);
      }

      /** "line N", or "file:N" if in another file than the current. */
      std::string
      where(const InpWhere &w) const
      {
        return w.file == at.file ? "line " + std::to_string(w.line) :
                                   deck.place(w);
      }

      bool
      next_line(std::istream &input);
      void
      read_file(const std::string &name, const InpWhere &from);
      void
      keyword();
      void
      include();
      void
      start_block(const std::string &name);
      const std::string *
      parameter(const char *name) const;
      std::string
      name_parameter(const std::string &keyword, const char *name) const;
      std::size_t
      define(std::vector<InpSet>                          &sets,
             std::unordered_map<std::string, std::size_t> &index,
             const std::string                            &name);
      void
      split();
      std::uint64_t
      label(std::string_view token, const char *what) const;
      std::size_t
      find(bool node, std::string_view token) const;
      void
      add(std::vector<std::size_t> &to, const std::vector<std::size_t> &from);
      void
      count(std::size_t n);
      bool
      is_name(std::string_view token) const;
      void
      node_line();
      void
      element_line();
      void
      set_line();
      void
      surface_line();
    };



    /** @p s in upper case without blanks: how Abaqus compares keywords,
     * parameters and names. */
    std::string
    inp_key(std::string_view s);

    /** A message's list of the names of @p sets (at most 12): of sets
     * and surfaces, or of (id, name) pairs. */
    template <typename Sets>
    std::string
    inp_names(const Sets &sets)
    {
      std::string list;
      for (std::size_t i = 0; i < sets.size() && i < 12; ++i)
      {
        list += i == 0 ? "" : ", ";
        if constexpr (std::is_same_v<typename Sets::value_type,
                                     std::pair<int, std::string>>)
          list += sets[i].second;
        else
          list += sets[i].name;
      }
      return (sets.empty() ? "none" : list) + (sets.size() > 12 ? ", ..." : "");
    }

    /** The deck @p file read and checked, without ids (inp_file.cc). */
    InpDeck
    read_inp_deck(const std::string &file);

    /** Body ids for the cells, boundary elements for the boundary sets,
     * physical names, node index (inp_ids.cc). */
    void
    assign_inp_ids(InpDeck &deck, const InpIds &ids);
  } // namespace internal
} // namespace tribos

#endif
