/**
 * read_inp_file(), first stage: the deck read a line at a time into an
 * InpDeck, every number, label and reference checked where it stands;
 * here the files and the keyword lines (the data lines in
 * inp_data_lines.cc).
 */

#include <tribos/scene/inp_file.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "inp_deck.h"

namespace tribos
{
  namespace internal
  {
    namespace
    {
      namespace fs = std::filesystem;

      constexpr std::size_t npos = MshFile::npos;
      /** A longer line is no deck (binary data): refused unheld. */
      constexpr std::size_t max_line_length = std::size_t(1) << 20;
      /** Deeper *INCLUDE nesting is a runaway, not a deck. */
      constexpr std::size_t max_include_depth = 16;
    } // namespace



    bool
    InpParser::next_line(std::istream &input)
    {
      line.clear();
      std::streambuf *buffer = input.rdbuf();
      for (int c = buffer->sbumpc(); c != '\n'; c = buffer->sbumpc())
      {
        if (c == std::char_traits<char>::eof())
        {
          if (line.empty())
            return false;
          break;
        }
        if (line.size() == max_line_length)
          deck.fail({at.file, at.line + 1},
                    "a line longer than 1 MiB: not a text deck (binary "
                    "data?)");
        line += char(c);
      }
      ++at.line;
      if (at.line == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
        line.erase(0, 3); // a UTF-8 byte order mark
      line = std::string(ReaderText::trim(line));
      return true;
    }



    void
    InpParser::read_file(const std::string &name, const InpWhere &from)
    {
      std::error_code error;
      fs::path        path = fs::weakly_canonical(name, error);
      if (error)
        path = fs::absolute(name, error);
      for (std::size_t i = 0; i < reading.size(); ++i)
        if (reading[i] == path)
          deck.fail(from,
                    "*INCLUDE of " + ReaderText::quote(name) +
                      ", which is being "
                      "read already (" +
                      (i == 0 ? "the deck itself" : "an including file") +
                      "): the includes form a cycle");
      if (reading.size() > max_include_depth)
        deck.fail(from,
                  "*INCLUDE nested more than 16 deep: a runaway chain of "
                  "includes?");
      if (!fs::is_regular_file(name, error))
        deck.fail(from,
                  from.line == 0 ?
                    "no such file (or not a regular file)" :
                    "the included file " + ReaderText::quote(name) +
                      " does not exist (or is not a regular file); "
                      "INPUT= is relative to the including file's folder");
      std::ifstream input(name, std::ios::binary);
      if (!input)
        deck.fail(from,
                  "the file " + ReaderText::quote(name) + " cannot be opened");
      deck.files.push_back(name);
      reading.push_back(path);
      const InpWhere outer = at;
      at                   = {deck.files.size() - 1, 0};
      while (next_line(input))
      {
        if (line.empty() || line.compare(0, 2, "**") == 0)
          continue;
        if (line[0] == '*')
          keyword();
        else if (block == InpBlock::none)
          fail(ReaderText::quote(line) +
               " before any keyword line: a deck starts "
               "with a keyword such as *HEADING or *NODE");
        else if (block == InpBlock::node)
          node_line();
        else if (block == InpBlock::element)
          element_line();
        else if (block == InpBlock::elset || block == InpBlock::nset)
          set_line();
        else if (block != InpBlock::skip)
          surface_line();
      }
      if (input.bad())
        fail("reading the file failed");
      if (!pending.empty())
        fail("the file ends inside the data line of element " +
             pending[0].first + " (" + where(pending_at) +
             "), which ends with a comma: its nodes are cut short");
      reading.pop_back();
      at = outer;
    }



    void
    InpParser::keyword()
    {
      if (!pending.empty())
        fail("a keyword line where the data line of element " +
             pending[0].first + " (" + where(pending_at) +
             ") continues: it ends with a comma, but lists fewer nodes "
             "than its type needs");
      std::vector<std::string_view> fields;
      for (std::size_t start = 1;;)
      {
        const std::size_t comma = line.find(',', start);
        fields.push_back(ReaderText::trim(std::string_view(line).substr(
          start,
          comma == std::string::npos ? comma : comma - start)));
        if (comma == std::string::npos)
          break;
        start = comma + 1;
      }
      const std::string name = inp_key(fields[0]);
      if (name.empty())
        fail(ReaderText::quote(line) +
             " where a keyword line (*NODE, *ELEMENT, "
             "...) is expected");
      parameters.clear();
      for (std::size_t i = 1; i < fields.size(); ++i)
      {
        const std::size_t equal = fields[i].find('=');
        std::string_view  value =
          equal == std::string::npos ?
             "" :
             ReaderText::trim(fields[i].substr(equal + 1));
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
          value = value.substr(1, value.size() - 2);
        if (!fields[i].empty())
          parameters.emplace_back(inp_key(fields[i].substr(0, equal)),
                                  std::string(value));
      }
      any_keyword = true;
      if (name == "INCLUDE")
        include(); // textual: the block goes on in the included file
      else
        start_block(name);
    }



    const std::string *
    InpParser::parameter(const char *name) const
    {
      const std::string *found = nullptr;
      for (const auto &[k, value] : parameters)
        if (k == name)
        {
          if (found != nullptr)
            fail(std::string(name) + "= is given twice on the line");
          found = &value;
        }
      return found;
    }



    std::string
    InpParser::name_parameter(const std::string &keyword,
                              const char        *name) const
    {
      const std::string *value = parameter(name);
      if (value == nullptr || value->empty())
        fail("*" + keyword + " without " + name + "=: it needs the name (*" +
             keyword + ", " + name + "=...)");
      return *value;
    }



    void
    InpParser::include()
    {
      const fs::path input(name_parameter("INCLUDE", "INPUT"));
      const fs::path folder = fs::path(deck.files[at.file]).parent_path();
      read_file((input.is_absolute() ? input : folder / input).string(), at);
    }



    void
    InpParser::start_block(const std::string &name)
    {
      block    = InpBlock::skip;
      type     = nullptr;
      set      = npos;
      generate = false;
      for (const char *refused :
           {"PART", "ASSEMBLY", "INSTANCE", "ENDPART", "ENDINSTANCE"})
        if (name == refused)
          fail("*" + name +
               ": Abaqus parts and assemblies are not read; "
               "tribos reads a flat deck (nodes, elements and sets at the "
               "top level): in Abaqus/CAE, check 'Do not use parts and "
               "assemblies in input files' in the model's attributes");
      for (const char *refused :
           {"NGEN", "NFILL", "NCOPY", "NMAP", "ELGEN", "ELCOPY", "SYSTEM"})
        if (name == refused)
          fail("*" + name +
               " generates or moves nodes or elements, which "
               "tribos does not do: list them in *NODE and *ELEMENT data "
               "lines");
      const bool data = name == "NODE" || name == "ELEMENT" || name == "NSET" ||
                        name == "ELSET" || name == "SURFACE";
      if (data && parameter("INPUT") != nullptr)
        fail("*" + name +
             ", INPUT=: not read; put the data lines in a "
             "file read by *INCLUDE, INPUT=");
      if (data && parameter("INSTANCE") != nullptr)
        fail("*" + name +
             ", INSTANCE=: not read; tribos reads a flat "
             "deck, without part instances");
      if (name == "NODE")
      {
        const std::string *system = parameter("SYSTEM");
        if (system != nullptr && inp_key(*system) != "R")
          fail("*NODE, SYSTEM=" + *system +
               ": tribos reads rectangular "
               "coordinates only (SYSTEM=R)");
        if (parameter("NSET") != nullptr)
          set = define(deck.nsets, deck.nset_of, name_parameter(name, "NSET"));
        block = InpBlock::node;
      }
      else if (name == "ELEMENT")
      {
        type_name = inp_key(name_parameter(name, "TYPE"));
        type      = inp_element_type(type_name);
        if (type == nullptr)
          fail("element type " + ReaderText::quote(type_name) +
               " is not one tribos reads" +
               (type_name.compare(0, 5, "C3D27") == 0 ?
                  " (C3D27, whose mid-face nodes may be omitted, is "
                  "not: use C3D20)" :
                  "") +
               "; it reads the solid elements " + inp_element_type_names());
        if (parameter("ELSET") != nullptr)
          set =
            define(deck.elsets, deck.elset_of, name_parameter(name, "ELSET"));
        block = InpBlock::element;
      }
      else if (name == "NSET" || name == "ELSET")
      {
        const bool nodes = name == "NSET";
        if (nodes && parameter("ELSET") != nullptr)
          fail("*NSET, ELSET=: not read; list the nodes or node sets");
        set =
          nodes ?
            define(deck.nsets, deck.nset_of, name_parameter(name, "NSET")) :
            define(deck.elsets, deck.elset_of, name_parameter(name, "ELSET"));
        if (parameter("INTERNAL") != nullptr)
          (nodes ? deck.nsets : deck.elsets)[set].internal = true;
        generate = parameter("GENERATE") != nullptr;
        block    = nodes ? InpBlock::nset : InpBlock::elset;
      }
      else if (name == "SURFACE")
      {
        const std::string  surface = name_parameter(name, "NAME");
        const std::string *kind    = parameter("TYPE");
        const std::string  k = kind == nullptr ? "ELEMENT" : inp_key(*kind);
        if (k != "ELEMENT" && k != "NODE")
          fail("*SURFACE, TYPE=" + *kind +
               ": tribos reads TYPE=ELEMENT "
               "(element faces) and TYPE=NODE surfaces");
        const auto [it, inserted] =
          deck.surface_of.emplace(inp_key(surface), deck.surfaces.size());
        if (!inserted)
          fail("surface " + ReaderText::quote(surface) +
               " is defined twice: at " +
               where(deck.surfaces[it->second].where) + " and here");
        deck.surfaces.push_back(
          {surface, at, n_definitions++, k == "NODE", {}, {}});
        set = it->second;
        block =
          k == "NODE" ? InpBlock::node_surface : InpBlock::element_surface;
      }
    }



    std::size_t
    InpParser::define(std::vector<InpSet>                          &sets,
                      std::unordered_map<std::string, std::size_t> &index,
                      const std::string                            &name)
    {
      const auto [it, inserted] = index.emplace(inp_key(name), sets.size());
      if (inserted) // a repeated name adds to the set, as in Abaqus
        sets.push_back({name, at, n_definitions++, false, {}});
      return it->second;
    }



    InpDeck
    InpParser::read()
    {
      read_file(deck.mesh.file, {0, 0});
      if (!any_keyword)
        deck.fail({0, 0},
                  "the deck has no keyword lines: not an Abaqus or CalculiX "
                  "deck (*NODE, *ELEMENT, ...)");
      if (deck.mesh.nodes.empty())
        deck.fail({0, 0},
                  "the deck defines no nodes: it needs *NODE data lines "
                  "'label, x, y[, z]'");
      if (deck.mesh.elements.empty())
        deck.fail({0, 0},
                  "the deck defines no elements: it needs *ELEMENT, TYPE= "
                  "data lines 'label, node, node, ...'");
      return std::move(deck);
    }



    std::string
    inp_key(const std::string_view s)
    {
      std::string k;
      for (const char c : s)
        if (!ReaderText::is_space(c))
          k += (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c;
      return k;
    }



    InpDeck
    read_inp_deck(const std::string &file)
    {
      return InpParser(file).read();
    }
  } // namespace internal



  MshFile
  read_inp_file(const std::string &file, const InpIds &ids)
  {
    internal::InpDeck deck = internal::read_inp_deck(file);
    internal::assign_inp_ids(deck, ids);
    return std::move(deck.mesh);
  }
} // namespace tribos
