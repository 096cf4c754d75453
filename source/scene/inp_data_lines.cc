/**
 * read_inp_file(), first stage, the data lines of *NODE, *ELEMENT, *NSET,
 * *ELSET and *SURFACE: each field parsed whole, each label and name
 * looked up among what is defined above.
 */

#include <tribos/scene/inp_file.h>

#include <cctype>
#include <charconv>

#include "inp_deck.h"

namespace tribos
{
  namespace internal
  {
    namespace
    {
      constexpr std::size_t npos = MshFile::npos;

      std::string
      str(const std::uint64_t n)
      {
        return std::to_string(n);
      }
    } // namespace



    void
    InpParser::split()
    {
      tokens.clear();
      for (std::size_t start = 0;;)
      {
        const std::size_t comma = line.find(',', start);
        tokens.push_back(ReaderText::trim(std::string_view(line).substr(
          start,
          comma == std::string::npos ? comma : comma - start)));
        if (comma == std::string::npos)
          break;
        start = comma + 1;
      }
      if (tokens.size() > 1 && tokens.back().empty())
        tokens.pop_back(); // a line may end with a comma
    }



    std::uint64_t
    InpParser::label(const std::string_view token, const char *what) const
    {
      std::uint64_t value = 0;
      const auto    r =
        std::from_chars(token.data(), token.data() + token.size(), value);
      if (r.ec != std::errc() || r.ptr != token.data() + token.size() ||
          value == 0)
        fail(ReaderText::quote(token) + " where " + what +
             " is expected (an integer from 1 to " + str(UINT64_MAX) + ")");
      return value;
    }



    std::size_t
    InpParser::find(const bool node, const std::string_view token) const
    {
      const std::uint64_t l     = label(token, node ? "a node" : "an element");
      const auto         &index = node ? node_of : element_of;
      const auto          it    = index.find(l);
      if (it == index.end())
        fail(std::string(node ? "node " : "element ") + str(l) + ", which no " +
             (node ? "*NODE" : "*ELEMENT") +
             " data line above defines (a deck defines what it refers to "
             "first)");
      return it->second;
    }



    void
    InpParser::count(const std::size_t n)
    {
      // Copies of sets into sets could grow without end: a bound linear
      // in the mesh, far above any real deck's.
      n_members += n;
      if (n_members > 64 * (deck.mesh.nodes.size() + deck.types.size()) +
                        (std::size_t(1) << 22))
        fail("the sets and surfaces list more than 64 members per node and "
             "element: sets copied into sets over and over?");
    }



    void
    InpParser::add(std::vector<std::size_t>       &to,
                   const std::vector<std::size_t> &from)
    {
      count(from.size());
      to.insert(to.end(), from.begin(), from.end());
    }



    bool
    InpParser::is_name(const std::string_view token) const
    {
      if (token.empty())
        fail("an empty field where a label or a set name is expected");
      // Abaqus names start with a letter, labels are digits.
      return std::isalpha(static_cast<unsigned char>(token[0])) ||
             token[0] == '_';
    }



    void
    InpParser::node_line()
    {
      split();
      if (tokens.size() < 2 || tokens.size() > 4)
        fail(str(tokens.size()) + " fields on a *NODE data line where "
                                  "'label, x, y[, z]' is expected");
      MshFile::Node node{label(tokens[0], "a node label"), {{0, 0, 0}}, 0};
      node.line = at.line;
      for (std::size_t k = 1; k < tokens.size(); ++k)
        if (!tokens[k].empty())
        {
          if (!ReaderText::parse_finite(tokens[k], node.x[k - 1]))
            fail(ReaderText::quote(tokens[k]) +
                 " where a coordinate is expected (a finite number)");
          if (!ReaderText::coordinate_in_range(node.x[k - 1]))
            fail(ReaderText::coordinate_out_of_range(tokens[k]));
        }
      const auto [it, inserted] =
        node_of.emplace(node.tag, deck.mesh.nodes.size());
      if (!inserted)
        fail("node " + str(node.tag) + " is defined twice: at " +
             where({deck.node_files[it->second],
                    deck.mesh.nodes[it->second].line}) +
             " and here");
      deck.mesh.nodes.push_back(node);
      deck.node_files.push_back(at.file);
      if (set != npos)
      {
        count(1);
        deck.nsets[set].members.push_back(deck.mesh.nodes.size() - 1);
      }
    }



    void
    InpParser::element_line()
    {
      const bool more = line.back() == ',';
      split();
      if (pending.empty())
        pending_at = at;
      for (const std::string_view t : tokens)
        pending.emplace_back(std::string(t), at.line);
      const std::size_t needed = 1 + type->n_nodes;
      if (pending.size() < needed && more)
        return; // continued on the next line
      const auto field_fail = [&](const std::size_t i, const std::string &m)
      {
        deck.fail({at.file, pending[i].second}, m);
      };
      const std::string &tag = pending[0].first;
      if (pending.size() != needed)
        fail("element " + tag + " is a " + type_name + " (" +
             msh_element_type(type->gmsh_type)->name + "): its data " +
             (pending_at.line == at.line ? "line lists " : "lines list ") +
             str(pending.size() - 1) + " nodes where " + str(type->n_nodes) +
             " are expected" +
             (pending.size() < needed ? " (a line that ends with a comma "
                                        "continues on the next)" :
                                        ""));
      MshFile::Element element;
      at.line     = pending_at.line;
      element.tag = label(tag, "an element label");
      std::vector<std::size_t> nodes(type->n_nodes);
      for (std::size_t k = 0; k < nodes.size(); ++k)
      {
        at.line  = pending[k + 1].second; // for find()'s message
        nodes[k] = find(true, pending[k + 1].first);
        for (std::size_t j = 0; j < k; ++j)
          if (nodes[j] == nodes[k])
            field_fail(k + 1,
                       "element " + tag + " lists node " +
                         pending[k + 1].first + " twice (as its node " +
                         str(j + 1) + " and " + str(k + 1) + ")");
      }
      at.line          = pending.back().second;
      element.type     = type->gmsh_type;
      element.dim      = type->dim;
      element.physical = 0;
      element.entity   = 0;
      element.line     = pending_at.line;
      for (std::size_t k = 0; k < nodes.size(); ++k)
        element.nodes.push_back(nodes[type->to_gmsh[k]]);
      const auto [it, inserted] =
        element_of.emplace(element.tag, deck.mesh.elements.size());
      if (!inserted)
        deck.fail(pending_at,
                  "element " + tag + " is defined twice: at " +
                    where(deck.element_where(it->second)) + " and here");
      deck.mesh.elements.push_back(std::move(element));
      deck.element_files.push_back(at.file);
      deck.types.push_back(type);
      deck.type_names.push_back(type_name);
      pending.clear();
      if (set != npos)
      {
        count(1);
        deck.elsets[set].members.push_back(deck.mesh.elements.size() - 1);
      }
    }



    void
    InpParser::set_line()
    {
      const bool nodes = block == InpBlock::nset;
      InpSet    &s     = (nodes ? deck.nsets : deck.elsets)[set];
      split();
      std::vector<std::size_t> members;
      if (generate)
      {
        if (tokens.size() < 2 || tokens.size() > 3)
          fail(str(tokens.size()) + " fields on a GENERATE line where "
                                    "'first, last[, increment]' is expected");
        const char   *what  = nodes ? "a node label" : "an element label";
        std::uint64_t first = label(tokens[0], what),
                      last  = label(tokens[1], what),
                      step  = tokens.size() == 3 ?
                                label(tokens[2], "an increment") :
                                1;
        if (last < first)
          fail("GENERATE from " + str(first) + " to " + str(last) +
               ": the first label must not exceed the last");
        // An increment beyond the range generates the first label alone:
        // the set lost the rest silently, and a boundary set of no face
        // shifted the default ids of the sets after it, reported as a
        // Contact/Pairs or Dirichlet id that the scene does not have.
        if (step > last - first && last > first)
          fail("GENERATE from " + str(first) + " to " + str(last) + " by " +
               str(step) + ": the increment exceeds the range, so the set " +
               "would hold label " + str(first) + " alone (the increment " +
               "steps from the first label to the last)");
        // Each label must be defined, so that the loop ends within as
        // many steps as there are nodes or elements.
        for (std::uint64_t l = first;; l += step)
        {
          members.push_back(find(nodes, str(l)));
          if (last - l < step)
            break;
        }
      }
      else
        for (const std::string_view t : tokens)
        {
          if (t.empty())
            continue; // ", ," as Abaqus allows
          if (!is_name(t))
            members.push_back(find(nodes, t)); // a label
          else
          {
            const auto &index = nodes ? deck.nset_of : deck.elset_of;
            const auto  it    = index.find(inp_key(t));
            if (it == index.end())
              fail(ReaderText::quote(t) + " is no " +
                   (nodes ? "node set" : "element set") +
                   " defined above (a set lists labels and the names of "
                   "sets defined before it)");
            add(members,
                (nodes ? deck.nsets : deck.elsets)[it->second].members);
          }
        }
      add(s.members, members);
    }



    void
    InpParser::surface_line()
    {
      InpSurface &s = deck.surfaces[set];
      split();
      if (s.of_nodes)
      {
        double weight = 0;
        if (tokens.size() > 2 || (tokens.size() == 2 &&
                                  !ReaderText::parse_finite(tokens[1], weight)))
          fail("a TYPE=NODE surface's data line is 'node or node set[, "
               "area]'");
        if (is_name(tokens[0]))
        {
          const auto it = deck.nset_of.find(inp_key(tokens[0]));
          if (it == deck.nset_of.end())
            fail(ReaderText::quote(tokens[0]) +
                 " is no node set defined above");
          add(s.nodes, deck.nsets[it->second].members);
        }
        else
        {
          count(1);
          s.nodes.push_back(find(true, tokens[0]));
        }
        return;
      }
      if (tokens.size() != 2)
        fail(str(tokens.size()) + " fields where 'element or element set, "
                                  "S<n>' is expected (the face identifier "
                                  "S1, S2, ... is needed)");
      const std::string face = inp_key(tokens[1]);
      std::uint64_t     f    = 0;
      if (face.size() < 2 || face[0] != 'S' ||
          std::from_chars(face.data() + 1, face.data() + face.size(), f).ptr !=
            face.data() + face.size() ||
          f == 0 || f > 6)
        fail(ReaderText::quote(tokens[1]) +
             " where a face identifier S1 to S6 is "
             "expected");
      std::vector<std::size_t> elements;
      if (is_name(tokens[0]))
      {
        const auto it = deck.elset_of.find(inp_key(tokens[0]));
        if (it == deck.elset_of.end())
          fail(ReaderText::quote(tokens[0]) +
               " is no element set defined above");
        add(elements, deck.elsets[it->second].members);
      }
      else
        elements.push_back(find(false, tokens[0]));
      for (const std::size_t e : elements)
      {
        if (f > deck.types[e]->n_faces)
          fail("element " + str(deck.mesh.elements[e].tag) + " is a " +
               deck.type_names[e] + ", whose faces are S1 to S" +
               str(deck.types[e]->n_faces) + ": it has no face " + face);
        count(1);
        s.faces.push_back({e, static_cast<unsigned int>(f - 1), at});
      }
    }
  } // namespace internal
} // namespace tribos
