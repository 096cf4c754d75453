/**
 * read_inp_file(), second stage: the body ids of the cells and the boundary
 * elements of the boundary sets, by the rules of read_inp_file()'s
 * documentation; every conflict refused with both sets named.
 */

#include <tribos/scene/inp_file.h>

#include <algorithm>
#include <climits>

#include "inp_deck.h"

namespace tribos
{
  namespace internal
  {
    namespace
    {
      constexpr std::size_t npos = MshFile::npos;

      /** A face's sorted corners, padded with npos: the same for every cell
       * that has the face. */
      using FaceKey = std::array<std::size_t, 4>;

      struct FaceKeyHash
      {
        std::size_t
        operator()(const FaceKey &k) const
        {
          std::size_t h = 0;
          for (const std::size_t v : k)
            h = h * 1000003u ^ std::hash<std::size_t>()(v);
          return h;
        }
      };

      /** The cells that have a face (its first, and its second if any),
       * and the boundary set (a position in the candidates) that took it. */
      struct FaceUse
      {
        std::size_t  element;
        unsigned int face;
        unsigned int n_cells;
        std::size_t  other;
        std::size_t  boundary;
      };

      /** A set that may become a boundary: a surface or a node set. */
      struct Candidate
      {
        bool        surface;
        std::size_t index;
        int         id;
      };

      /** A face as a boundary set gives it: its use, and the line. */
      using BoundaryFace = std::pair<FaceUse *, InpWhere>;

      /** Whether @p members (positions, possibly repeated) hold every
       * position from 0 to @p n - 1: CalculiX's Eall or Nall. */
      bool
      holds_all(const std::vector<std::size_t> &members, const std::size_t n)
      {
        if (members.size() < n) // most sets: no table of n
          return false;
        std::vector<bool> in(n, false);
        for (const std::size_t m : members)
          in[m] = true;
        return std::find(in.begin(), in.end(), false) == in.end();
      }

      class Assigner
      {
      public:
        Assigner(InpDeck &deck, const InpIds &ids)
          : deck(deck)
          , ids(ids)
          , mesh(deck.mesh)
        {
        }

        void
        run();

      private:
        InpDeck                                          &deck;
        const InpIds                                     &ids;
        MshFile                                          &mesh;
        unsigned int                                      dim = 0;
        std::unordered_map<FaceKey, FaceUse, FaceKeyHash> uses;
        /** The boundary faces by their lowest corner (CSR). */
        std::vector<std::size_t> owned_start;
        std::vector<FaceUse *>   owned;
        /** Stamps for the nodes of the node set being turned into faces. */
        std::vector<std::size_t> in_set, visited;

        /** Fail at @p w: an InpIdError if the ids of the @p boundaries
         * (or bodies) are given, for they caused it, else an MshError. */
        [[noreturn]] void
        fail_ids(const InpWhere    &w,
                 const bool         boundaries,
                 const std::string &message) const
        {
          if ((boundaries ? ids.boundaries : ids.bodies).empty())
            deck.fail(w, message);
          throw InpIdError(deck.file_of(w), w.line, message, boundaries);
        }

        /** Refuse @p id for @p name unless it is a valid id. */
        void
        check_id(const int          id,
                 const std::string &name,
                 const bool         boundaries) const
        {
          if (id < 0)
            fail_ids({0, 0},
                     boundaries,
                     "id " + std::to_string(id) + " for " +
                       ReaderText::quote(name) +
                       ": ids are integers from 0 to " +
                       std::to_string(INT_MAX));
        }

        void
        check_dimension();
        FaceKey
        face_key(std::size_t element, unsigned int face) const;
        void
        find_faces();
        void
        add_names(unsigned int                                    d,
                  const std::vector<std::pair<int, std::string>> &named);
        void
        assign_bodies();
        std::vector<Candidate>
        boundary_candidates() const;
        const std::string &
        name_of(const Candidate &c) const
        {
          return c.surface ? deck.surfaces[c.index].name :
                             deck.nsets[c.index].name;
        }

        InpWhere
        where_of(const Candidate &c) const
        {
          return c.surface ? deck.surfaces[c.index].where :
                             deck.nsets[c.index].where;
        }

        std::size_t
        where_order(const Candidate &c) const
        {
          return c.surface ? deck.surfaces[c.index].order :
                             deck.nsets[c.index].order;
        }
        std::vector<BoundaryFace>
        faces_of(const Candidate &c);
        void
        add_boundaries();
      };



      void
      Assigner::check_dimension()
      {
        dim = deck.types[0]->dim;
        for (std::size_t e = 1; e < deck.types.size(); ++e)
          if (deck.types[e]->dim != dim)
            deck.fail(deck.element_where(e),
                      "element " + std::to_string(mesh.elements[e].tag) +
                        " is a " + deck.type_names[e] + " (" +
                        std::to_string(deck.types[e]->dim) + "D), element " +
                        std::to_string(mesh.elements[0].tag) + " (" +
                        deck.place(deck.element_where(0)) + ") a " +
                        deck.type_names[0] +
                        ": a deck is all 2D or all 3D elements");
      }



      FaceKey
      Assigner::face_key(const std::size_t e, const unsigned int f) const
      {
        const InpElementType &type = *deck.types[e];
        FaceKey               k    = {{npos, npos, npos, npos}};
        for (unsigned int c = 0; c < type.n_face_corners; ++c)
          k[c] = mesh.elements[e].nodes[type.faces[f][c]];
        std::sort(k.begin(), k.end());
        return k;
      }



      void
      Assigner::find_faces()
      {
        std::size_t n_faces = 0; // of cells read: no count from the file
        for (const InpElementType *type : deck.types)
          n_faces += type->n_faces;
        uses.reserve(n_faces);
        for (std::size_t e = 0; e < deck.types.size(); ++e)
          for (unsigned int f = 0; f < deck.types[e]->n_faces; ++f)
          {
            const auto [it, inserted] =
              uses.emplace(face_key(e, f), FaceUse{e, f, 0, npos, npos});
            if (++it->second.n_cells == 2)
              it->second.other = e;
          }
        // The boundary faces by lowest corner: a node set's faces are
        // found from its nodes, in time linear in the set.
        owned_start.assign(mesh.nodes.size() + 1, 0);
        for (const auto &[k, use] : uses)
          if (use.n_cells == 1)
            ++owned_start[k[0] + 1];
        for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
          owned_start[n + 1] += owned_start[n];
        owned.resize(owned_start.back());
        std::vector<std::size_t> next(owned_start.begin(),
                                      owned_start.end() - 1);
        for (auto &[k, use] : uses)
          if (use.n_cells == 1)
            owned[next[k[0]]++] = &use;
        in_set.assign(mesh.nodes.size(), npos);
        visited.assign(mesh.nodes.size(), npos);
      }



      void
      Assigner::add_names(const unsigned int                              d,
                          const std::vector<std::pair<int, std::string>> &named)
      {
        // One name per id, as in a gmsh file: sets of one id joined.
        for (std::size_t i = 0; i < named.size(); ++i)
        {
          bool seen = false;
          for (std::size_t j = 0; j < i; ++j)
            seen = seen || named[j].first == named[i].first;
          if (seen)
            continue;
          std::string name = named[i].second;
          for (std::size_t j = i + 1; j < named.size(); ++j)
            if (named[j].first == named[i].first)
              name += ", " + named[j].second;
          mesh.physical_names.push_back({d, named[i].first, name});
        }
      }



      void
      Assigner::assign_bodies()
      {
        // The body sets, as positions in deck.elsets, and their ids.
        std::vector<std::pair<std::size_t, int>> bodies;
        std::string                              all_cells; // a set left out
        if (ids.bodies.empty())
        {
          // A set of every cell (CalculiX's Eall, which cgx writes beside
          // the parts) is a body only if no other set is.
          std::vector<std::size_t> sets, partial;
          for (std::size_t s = 0; s < deck.elsets.size(); ++s)
            if (!deck.elsets[s].internal && !deck.elsets[s].members.empty())
            {
              sets.push_back(s);
              if (!holds_all(deck.elsets[s].members, deck.types.size()))
                partial.push_back(s);
              else if (all_cells.empty())
                all_cells = deck.elsets[s].name;
            }
          for (const std::size_t s : partial.empty() ? sets : partial)
            bodies.emplace_back(s, int(bodies.size()) + 1);
          if (partial.empty())
            all_cells.clear();
        }
        else
          for (const auto &[name, id] : ids.bodies)
          {
            check_id(id, name, false);
            const auto it = deck.elset_of.find(inp_key(name));
            if (it == deck.elset_of.end())
              fail_ids({0, 0},
                       false,
                       "body set " + ReaderText::quote(name) +
                         " is no element set of the deck (its element sets: " +
                         inp_names(deck.elsets) + ")");
            for (const auto &b : bodies)
              if (b.first == it->second)
                fail_ids({0, 0},
                         false,
                         "element set " + ReaderText::quote(name) +
                           " is given two body ids");
            if (deck.elsets[it->second].members.empty())
              fail_ids(deck.elsets[it->second].where,
                       false,
                       "element set " + ReaderText::quote(name) +
                         ", a body set, has no elements");
            bodies.emplace_back(it->second, id);
          }
        std::vector<std::size_t> body_of(deck.types.size(), npos);
        for (std::size_t b = 0; b < bodies.size(); ++b)
          for (const std::size_t e : deck.elsets[bodies[b].first].members)
          {
            const std::size_t a = body_of[e];
            if (a == npos || bodies[a].second == bodies[b].second)
              body_of[e] = a == npos ? b : a;
            else
            {
              const InpSet &first = deck.elsets[bodies[a].first],
                           &later = deck.elsets[bodies[b].first];
              fail_ids(later.where,
                       false,
                       "element " + std::to_string(mesh.elements[e].tag) +
                         " (" + deck.place(deck.element_where(e)) +
                         ") is in the element sets " + first.name + " (" +
                         deck.place(first.where) + ") and " + later.name +
                         " (here), bodies " + std::to_string(bodies[a].second) +
                         " and " + std::to_string(bodies[b].second) +
                         "; a cell is in one body. " +
                         (ids.bodies.empty() ?
                            "Every element set is a body (but a set of all "
                            "the cells beside others) unless the bodies are "
                            "named: name them with their ids, leaving out "
                            "the sets that overlap them" :
                            "Give the two sets one id, or leave one out"));
            }
          }
        std::vector<std::pair<int, std::string>> named;
        for (const auto &b : bodies)
          named.emplace_back(b.second, deck.elsets[b.first].name);
        for (std::size_t e = 0; e < body_of.size(); ++e)
        {
          if (!bodies.empty() && body_of[e] == npos)
            fail_ids(deck.element_where(e),
                     false,
                     "element " + std::to_string(mesh.elements[e].tag) +
                       " is in none of the element sets that are bodies (" +
                       inp_names(named) +
                       "): every cell must be in one when the deck has "
                       "body sets (cells are body 0 only in a deck without)" +
                       (all_cells.empty() ?
                          std::string() :
                          "; " + all_cells +
                            ", a set of every cell, is a body only when "
                            "no other set is, or when the bodies are named"));
          mesh.elements[e].physical =
            bodies.empty() ? 0 : bodies[body_of[e]].second;
        }
        add_names(dim, named);
      }



      std::vector<Candidate>
      Assigner::boundary_candidates() const
      {
        std::vector<Candidate> candidates;
        if (ids.boundaries.empty())
        {
          // Surfaces and node sets, in order of appearance.
          for (std::size_t s = 0; s < deck.surfaces.size(); ++s)
            candidates.push_back({true, s, 0});
          for (std::size_t s = 0; s < deck.nsets.size(); ++s)
            if (!holds_all(deck.nsets[s].members, mesh.nodes.size()))
              candidates.push_back({false, s, 0}); // not Nall
          std::sort(candidates.begin(),
                    candidates.end(),
                    [&](const Candidate &a, const Candidate &b)
                    { return where_order(a) < where_order(b); });
          return candidates;
        }
        for (const auto &[given, id] : ids.boundaries)
        {
          check_id(id, given, true);
          std::string k = inp_key(given);
          // "SURFACE:name" or "NSET:name" when a surface and a node set
          // share the name.
          const bool only_surface = k.compare(0, 8, "SURFACE:") == 0,
                     only_nset    = k.compare(0, 5, "NSET:") == 0;
          k.erase(0, only_surface ? 8 : only_nset ? 5 : 0);
          const auto s =
            only_nset ? deck.surface_of.end() : deck.surface_of.find(k);
          const auto n =
            only_surface ? deck.nset_of.end() : deck.nset_of.find(k);
          const bool is_s = s != deck.surface_of.end(),
                     is_n = n != deck.nset_of.end();
          if (is_s && is_n)
            fail_ids({0, 0},
                     true,
                     "boundary set " + ReaderText::quote(given) +
                       " is both a surface (" +
                       deck.place(deck.surfaces[s->second].where) +
                       ") and a node set (" +
                       deck.place(deck.nsets[n->second].where) +
                       "): write SURFACE:" + given + " or NSET:" + given);
          if (!is_s && !is_n)
            fail_ids({0, 0},
                     true,
                     "boundary set " + ReaderText::quote(given) +
                       " is no surface or node set of the deck (its "
                       "surfaces: " +
                       inp_names(deck.surfaces) +
                       "; its node sets: " + inp_names(deck.nsets) + ")");
          const Candidate c{is_s, is_s ? s->second : n->second, id};
          for (const Candidate &d : candidates)
            if (d.surface == c.surface && d.index == c.index)
              fail_ids({0, 0},
                       true,
                       "boundary set " + ReaderText::quote(given) +
                         " is given two boundary ids");
          candidates.push_back(c);
        }
        return candidates;
      }



      std::vector<BoundaryFace>
      Assigner::faces_of(const Candidate &c)
      {
        std::vector<BoundaryFace> faces;
        if (c.surface && !deck.surfaces[c.index].of_nodes)
        {
          for (const InpFace &f : deck.surfaces[c.index].faces)
          {
            FaceUse &use = uses.find(face_key(f.element, f.face))->second;
            if (use.n_cells > 1)
              deck.fail(f.where,
                        "face S" + std::to_string(f.face + 1) + " of element " +
                          std::to_string(mesh.elements[f.element].tag) +
                          " is also a face of element " +
                          std::to_string(
                            mesh
                              .elements[use.element == f.element ? use.other :
                                                                   use.element]
                              .tag) +
                          ": it is inside the mesh, and only a face on its "
                          "boundary takes a boundary id");
            faces.emplace_back(&use, f.where);
          }
          return faces;
        }
        // A node set (or TYPE=NODE surface): the boundary faces all of
        // whose nodes it holds, found from their lowest corners.
        const std::vector<std::size_t> &nodes = c.surface ?
                                                  deck.surfaces[c.index].nodes :
                                                  deck.nsets[c.index].members;
        const std::size_t stamp = (c.surface ? 2 * c.index : 2 * c.index + 1);
        for (const std::size_t n : nodes)
          in_set[n] = stamp;
        for (const std::size_t n : nodes)
          if (visited[n] != stamp)
          {
            visited[n] = stamp;
            for (std::size_t i = owned_start[n]; i < owned_start[n + 1]; ++i)
            {
              const FaceUse *use = owned[i];
              const auto     face_nodes =
                inp_face_nodes(*deck.types[use->element],
                               use->face,
                               mesh.elements[use->element].nodes);
              if (std::all_of(face_nodes.begin(),
                              face_nodes.end(),
                              [&](const std::size_t m)
                              { return in_set[m] == stamp; }))
                faces.emplace_back(owned[i], where_of(c));
            }
          }
        std::sort(faces.begin(),
                  faces.end(),
                  [](const BoundaryFace &a, const BoundaryFace &b)
                  {
                    return std::pair(a.first->element, a.first->face) <
                           std::pair(b.first->element, b.first->face);
                  });
        return faces;
      }



      void
      Assigner::add_boundaries()
      {
        std::vector<Candidate> candidates = boundary_candidates();
        std::uint64_t          tag        = 0;
        for (const auto &e : mesh.elements)
          tag = std::max(tag, e.tag);
        std::vector<std::pair<int, std::string>> named;
        int                                      next_id = 0;
        for (std::size_t b = 0; b < candidates.size(); ++b)
        {
          Candidate                      &c     = candidates[b];
          const std::vector<BoundaryFace> faces = faces_of(c);
          const std::string kind = c.surface ? "surface " : "node set ";
          if (faces.empty() && !ids.boundaries.empty())
            fail_ids(where_of(c),
                     true,
                     kind + ReaderText::quote(name_of(c)) +
                       ", a boundary set, holds no face of the mesh "
                       "boundary" +
                       (c.surface ? "" :
                                    " (a face is in a node set if all its "
                                    "nodes, corners and middles, are)"));
          if (faces.empty())
            continue; // by default, a set of no face is no boundary
          if (ids.boundaries.empty())
            c.id = ++next_id;
          named.emplace_back(c.id, name_of(c));
          for (const auto &[use, where] : faces)
          {
            if (use->boundary != npos)
            {
              const Candidate &d = candidates[use->boundary];
              if (d.id == c.id)
                continue; // given once already
              fail_ids(where,
                       true,
                       "face S" + std::to_string(use->face + 1) +
                         " of element " +
                         std::to_string(mesh.elements[use->element].tag) +
                         " is in the " +
                         (d.surface ? "surface " : "node set ") + name_of(d) +
                         " (" + deck.place(where_of(d)) + ") and the " + kind +
                         name_of(c) + ", boundaries " + std::to_string(d.id) +
                         " and " + std::to_string(c.id) +
                         "; a face has one boundary id. " +
                         (ids.boundaries.empty() ?
                            "Every surface and node set (but one of all the "
                            "nodes) is a boundary unless the boundaries are "
                            "named: name them with their ids, leaving out "
                            "the sets that overlap them" :
                            "Give the two sets one id, or leave one out"));
            }
            use->boundary = b;
            if (++tag == 0)
              deck.fail({0, 0},
                        "the element labels leave no tags for the boundary "
                        "elements (they come after the largest label)");
            const InpElementType &type = *deck.types[use->element];
            mesh.elements.push_back(
              {tag,
               type.face_type,
               dim - 1,
               c.id,
               0,
               inp_face_nodes(type,
                              use->face,
                              mesh.elements[use->element].nodes),
               where.line});
          }
        }
        add_names(dim - 1, named);
      }



      void
      Assigner::run()
      {
        check_dimension();
        find_faces();
        assign_bodies();
        add_boundaries();
        std::vector<std::uint64_t> tags;
        for (const auto &node : mesh.nodes)
          tags.push_back(node.tag);
        mesh.node_tags.build(tags); // unique: the parser checked
      }
    } // namespace



    void
    assign_inp_ids(InpDeck &deck, const InpIds &ids)
    {
      Assigner(deck, ids).run();
    }
  } // namespace internal
} // namespace tribos
