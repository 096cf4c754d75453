#include <tribos/scene/gmsh_second_order.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <map>
#include <unordered_map>
#include <utility>

namespace tribos
{
  namespace GmshSecondOrder
  {
    namespace
    {
      /** gmsh's state between open and close, released on every path. */
      struct GmshSession
      {
        GmshSession()
        {
          gmsh::initialize(0, nullptr, false);
          gmsh::option::setNumber("General.Terminal", 0);
        }
        ~GmshSession()
        {
          gmsh::finalize();
        }
      };

      using Edge = std::array<unsigned int, 2>;

      /**
       * A second-order gmsh cell: its corners (gmsh order), the corner pairs
       * of its edges and where the edges' middle nodes are in its node list,
       * the corner quadruples of its quadrilateral faces (hexahedra) and
       * where their centre nodes are (none: serendipity), and where its
       * centre node is (none: serendipity or a simplex).
       */
      struct CellKind
      {
        unsigned int                             n_corners;
        std::vector<Edge>                        edges;
        unsigned int                             first_middle;
        std::vector<std::array<unsigned int, 4>> faces;
        int                                      first_face_centre;
        int                                      centre;
      };

      const std::vector<Edge> triangle_edges = {{{0, 1}}, {{1, 2}}, {{2, 0}}};
      const std::vector<Edge> quad_edges     = {{{0, 1}},
                                                {{1, 2}},
                                                {{2, 3}},
                                                {{3, 0}}};
      const std::vector<Edge> tet_edges =
        {{{0, 1}}, {{1, 2}}, {{2, 0}}, {{3, 0}}, {{3, 2}}, {{3, 1}}};
      const std::vector<Edge>                        hex_edges = {{{0, 1}},
                                                                  {{0, 3}},
                                                                  {{0, 4}},
                                                                  {{1, 2}},
                                                                  {{1, 5}},
                                                                  {{2, 3}},
                                                                  {{2, 6}},
                                                                  {{3, 7}},
                                                                  {{4, 5}},
                                                                  {{4, 7}},
                                                                  {{5, 6}},
                                                                  {{6, 7}}};
      const std::vector<std::array<unsigned int, 4>> hex_faces = {
        {{0, 3, 2, 1}},
        {{0, 1, 5, 4}},
        {{0, 4, 7, 3}},
        {{1, 2, 6, 5}},
        {{2, 3, 7, 6}},
        {{4, 5, 6, 7}}};

      /** The second-order cell of gmsh type @p type (gmsh's node ordering),
       * or null if @p type is none in @p dim dimensions. */
      const CellKind *
      second_order_cell(const int dim, const int type)
      {
        static const CellKind tri6{3, triangle_edges, 3, {}, -1, -1};
        static const CellKind quad8{4, quad_edges, 4, {}, -1, -1};
        static const CellKind quad9{4, quad_edges, 4, {}, -1, 8};
        static const CellKind tet10{4, tet_edges, 4, {}, -1, -1};
        static const CellKind hex20{8, hex_edges, 8, hex_faces, -1, -1};
        static const CellKind hex27{8, hex_edges, 8, hex_faces, 20, 26};
        if (dim == 2)
          return type == 9  ? &tri6 :
                 type == 16 ? &quad8 :
                 type == 10 ? &quad9 :
                              nullptr;
        return type == 11 ? &tet10 :
               type == 17 ? &hex20 :
               type == 12 ? &hex27 :
                            nullptr;
      }

      /** Whether gmsh type @p type is a first-order cell of @p dim
       * dimensions that deal.II's reader takes (prisms and pyramids too:
       * the scene refuses a mesh of several kinds). */
      bool
      first_order_cell(const int dim, const int type)
      {
        return dim == 2 ? (type == 2 || type == 3) :
                          (type == 4 || type == 5 || type == 6 || type == 7);
      }

      /** The number of corners of gmsh face or edge element type @p type
       * (boundary elements), 0 if it is none. */
      unsigned int
      boundary_corners(const int type)
      {
        switch (type)
        {
          case 1: // line
          case 8: // 3-node line
            return 2;
          case 2: // triangle
          case 9: // 6-node triangle
            return 3;
          case 3:  // quadrilateral
          case 10: // 9-node quadrilateral
          case 16: // 8-node quadrilateral
            return 4;
          default:
            return 0;
        }
      }

      /** gmsh's description of element type @p type. */
      std::string
      describe(const int type)
      {
        std::string         name;
        int                 dim = 0, order = 0, n_nodes = 0, n_primary = 0;
        std::vector<double> coordinates;
        gmsh::model::mesh::getElementProperties(type,
                                                name,
                                                dim,
                                                order,
                                                n_nodes,
                                                coordinates,
                                                n_primary);
        return "'" + name + "' cells (gmsh element type " +
               std::to_string(type) + ", order " + std::to_string(order) + ")";
      }

      /** The sorted copy of @p indices: the key of an edge, face or cell. */
      template <typename Container>
      std::vector<unsigned int>
      key(const Container &indices)
      {
        std::vector<unsigned int> k(indices.begin(), indices.end());
        std::sort(k.begin(), k.end());
        return k;
      }

      /** The physical tag of gmsh entity (@p d, @p tag): 0 without one. */
      int
      physical_tag(const std::string &name, const int d, const int tag)
      {
        std::vector<int> groups;
        gmsh::model::getPhysicalGroupsForEntity(d, tag, groups);
        AssertThrow(groups.size() <= 1,
                    ExcMessage(name + ": the mesh's entity " +
                               std::to_string(tag) + " of dimension " +
                               std::to_string(d) +
                               " is in several physical groups; tribos "
                               "(like deal.II's reader) takes one per "
                               "entity: its body or boundary id."));
        return groups.empty() ? 0 : groups[0];
      }


      /**
       * A second-order gmsh model (open in the session) into deal.II's
       * cell data and the positions of its cells' other nodes, kept by the
       * sorted vertex numbers of their edge, face or cell.
       */
      template <int dim>
      class Reader
      {
      public:
        /** @p name starts the messages. */
        explicit Reader(const std::string &name)
          : name(name)
        {
        }

        /** Whether the model's cells are second-order; refuses cells of
         * other orders or kinds, and first- and second-order mixed. */
        bool
        second_order() const;

        /** The nodes, the cells and the boundary elements. */
        void
        read();

        /** The triangulation of the cells, with deal.II's reader's
         * clean-up (orientation, vertex order). */
        void
        create(Triangulation<dim> &triangulation);

        /** The quadratic element's support points per coarse cell of
         * @p triangulation (create()'s). */
        std::vector<std::vector<Point<dim>>>
        support_points(const Triangulation<dim> &triangulation) const;

      private:
        const Point<dim> &
        position(const std::size_t tag) const;

        /** Cell @p nodes of @p kind, body @p material. */
        void
        add_cell(const CellKind    &kind,
                 const std::size_t *nodes,
                 const unsigned int material);

        void
        read_boundary(const int d);

        const std::string                               name;
        std::unordered_map<std::size_t, Point<dim>>     node;
        std::vector<Point<dim>>                         vertices;
        std::unordered_map<std::size_t, unsigned int>   vertex_of_node;
        std::map<std::vector<unsigned int>, Point<dim>> node_of;
        std::vector<CellData<dim>>                      cells;
        SubCellData                                     boundary;
        bool hyper_cubes = false, simplices = false;
      };



      template <int dim>
      bool
      Reader<dim>::second_order() const
      {
        std::vector<int> types;
        gmsh::model::mesh::getElementTypes(types, dim);
        AssertThrow(!types.empty(),
                    ExcMessage(name + ": the mesh has no " +
                               std::string(dim == 2 ? "2D" : "3D") +
                               " cells (with Dimension = " +
                               std::to_string(dim) + ")."));
        // A first-order mesh is deal.II's reader's.
        if (std::all_of(types.begin(),
                        types.end(),
                        [](const int type)
                        { return first_order_cell(dim, type); }))
          return false;
        bool first_order = false;
        for (const int type : types)
        {
          first_order = first_order || first_order_cell(dim, type);
          AssertThrow(
            first_order_cell(dim, type) || second_order_cell(dim, type),
            ExcMessage(
              name + ": the mesh has " + describe(type) +
              ", which tribos does not read. It takes cells of "
              "order 1 (" +
              (dim == 2 ? "triangles, quadrilaterals" :
                          "tetrahedra, hexahedra") +
              ") or 2 (" +
              (dim == 2 ? "tri6, quad8, quad9" : "tet10, hex20, hex27") +
              "): mesh with 'Mesh.ElementOrder = 1;' or '= 2;'."));
        }
        AssertThrow(!first_order,
                    ExcMessage(name +
                               ": the mesh mixes first- and second-order "
                               "cells; tribos takes one order per mesh."));
        return true;
      }



      template <int dim>
      const Point<dim> &
      Reader<dim>::position(const std::size_t tag) const
      {
        const auto it = node.find(tag);
        AssertThrow(it != node.end(),
                    ExcMessage(name + ": an element refers to node " +
                               std::to_string(tag) +
                               ", which the mesh does not have."));
        return it->second;
      }



      template <int dim>
      void
      Reader<dim>::read()
      {
        std::vector<std::size_t> node_tags;
        std::vector<double>      coordinates, parametric;
        gmsh::model::mesh::getNodes(node_tags,
                                    coordinates,
                                    parametric,
                                    -1,
                                    -1,
                                    false,
                                    false);
        for (std::size_t i = 0; i < node_tags.size(); ++i)
        {
          Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = coordinates[3 * i + d];
          node[node_tags[i]] = x;
        }

        gmsh::vectorpair entities;
        gmsh::model::getEntities(entities, dim);
        for (const auto &[d, tag] : entities)
        {
          const int        material = physical_tag(name, d, tag);
          std::vector<int> types;
          std::vector<std::vector<std::size_t>> tags, nodes;
          gmsh::model::mesh::getElements(types, tags, nodes, d, tag);
          for (unsigned int b = 0; b < types.size(); ++b)
          {
            const std::size_t n_nodes = nodes[b].size() / tags[b].size();
            for (std::size_t e = 0; e < tags[b].size(); ++e)
              add_cell(*second_order_cell(dim, types[b]),
                       &nodes[b][e * n_nodes],
                       material);
          }
        }
        // The boundary elements: lines in 2D, faces (and lines) in 3D.
        for (int d = 1; d < dim; ++d)
          read_boundary(d);
      }



      template <int dim>
      void
      Reader<dim>::add_cell(const CellKind    &kind,
                            const std::size_t *nodes,
                            const unsigned int material)
      {
        // The corners become the vertices, numbered when first seen.
        const bool hyper_cube = (kind.n_corners == (dim == 2 ? 4u : 8u));
        hyper_cubes           = hyper_cubes || hyper_cube;
        simplices             = simplices || !hyper_cube;
        std::vector<unsigned int> corner(kind.n_corners);
        for (unsigned int c = 0; c < kind.n_corners; ++c)
        {
          const auto [it, is_new] =
            vertex_of_node.emplace(nodes[c], vertices.size());
          if (is_new)
            vertices.push_back(position(nodes[c]));
          corner[c] = it->second;
        }
        CellData<dim> cell(kind.n_corners);
        for (unsigned int c = 0; c < kind.n_corners; ++c)
          cell.vertices[hyper_cube ? GeometryInfo<dim>::ucd_to_deal[c] : c] =
            corner[c];
        cell.material_id = material;
        cells.push_back(cell);

        Point<dim> sum_corners, sum_middles;
        for (unsigned int c = 0; c < kind.n_corners; ++c)
          sum_corners += position(nodes[c]);
        for (unsigned int m = 0; m < kind.edges.size(); ++m)
        {
          const Point<dim> &x = position(nodes[kind.first_middle + m]);
          sum_middles += x;
          node_of.emplace(key(Edge{{corner[kind.edges[m][0]],
                                    corner[kind.edges[m][1]]}}),
                          x);
        }
        // Faces of hexahedra: their centre nodes, or the serendipity map's
        // value at the centre.
        for (unsigned int f = 0; f < kind.faces.size(); ++f)
        {
          std::array<unsigned int, 4> face;
          for (unsigned int c = 0; c < 4; ++c)
            face[c] = corner[kind.faces[f][c]];
          Point<dim> x;
          if (kind.first_face_centre >= 0)
            x = position(nodes[kind.first_face_centre + f]);
          else
            for (unsigned int c = 0; c < 4; ++c)
            {
              const unsigned int a = kind.faces[f][c],
                                 z = kind.faces[f][(c + 1) % 4];
              x += -0.25 * position(nodes[a]);
              for (unsigned int m = 0; m < kind.edges.size(); ++m)
                if ((kind.edges[m][0] == a && kind.edges[m][1] == z) ||
                    (kind.edges[m][0] == z && kind.edges[m][1] == a))
                  x += 0.5 * position(nodes[kind.first_middle + m]);
            }
          node_of.emplace(key(face), x);
        }
        if (hyper_cube)
          node_of.emplace(key(corner),
                          kind.centre >= 0 ?
                            position(nodes[kind.centre]) :
                            Point<dim>(-0.25 * sum_corners +
                                       (dim == 2 ? 0.5 : 0.25) * sum_middles));
      }



      template <int dim>
      void
      Reader<dim>::read_boundary(const int d)
      {
        gmsh::vectorpair entities;
        gmsh::model::getEntities(entities, d);
        for (const auto &[entity_dim, tag] : entities)
        {
          const int        id = physical_tag(name, entity_dim, tag);
          std::vector<int> types;
          std::vector<std::vector<std::size_t>> tags, nodes;
          gmsh::model::mesh::getElements(types, tags, nodes, entity_dim, tag);
          for (unsigned int b = 0; b < types.size(); ++b)
          {
            const unsigned int n_corners = boundary_corners(types[b]);
            AssertThrow(n_corners > 0 && (n_corners == 2) == (d == 1),
                        ExcMessage(name + ": the mesh's boundary has " +
                                   describe(types[b]) +
                                   ", which tribos does not read."));
            const std::size_t n_nodes = nodes[b].size() / tags[b].size();
            for (std::size_t e = 0; e < tags[b].size(); ++e)
            {
              CellData<1> line;
              CellData<2> face(n_corners);
              for (unsigned int c = 0; c < n_corners; ++c)
              {
                const std::size_t tag_c = nodes[b][e * n_nodes + c];
                const auto        it    = vertex_of_node.find(tag_c);
                AssertThrow(it != vertex_of_node.end(),
                            ExcMessage(name +
                                       ": a boundary element's corner is "
                                       "no corner of a cell (node " +
                                       std::to_string(tag_c) + ")."));
                (d == 1 ? line.vertices[c] : face.vertices[c]) = it->second;
              }
              if (d == 1)
              {
                line.boundary_id = id;
                boundary.boundary_lines.push_back(line);
              }
              else
              {
                face.boundary_id = id;
                boundary.boundary_quads.push_back(face);
              }
            }
          }
        }
      }



      template <int dim>
      void
      Reader<dim>::create(Triangulation<dim> &triangulation)
      {
        if (hyper_cubes && !simplices)
        {
          GridTools::invert_cells_with_negative_measure(vertices, cells);
          GridTools::consistently_order_cells(cells);
        }
        else if (simplices)
          GridTools::invert_cells_with_negative_measure(vertices, cells);
        triangulation.create_triangulation(vertices, cells, boundary);
      }



      template <int dim>
      std::vector<std::vector<Point<dim>>>
      Reader<dim>::support_points(const Triangulation<dim> &triangulation) const
      {
        // Vertices, lines' middles, (hexahedra) faces' centres,
        // (quadrilaterals and hexahedra) the centre: the dof order of FE_Q(2)
        // and FE_SimplexP(2).
        std::vector<std::vector<Point<dim>>> support_points(
          triangulation.n_cells(0));
        const auto find = [&](const std::vector<unsigned int> &k)
        {
          const auto it = node_of.find(k);
          AssertThrow(it != node_of.end(), ExcInternalError());
          return it->second;
        };
        for (const auto &cell : triangulation.cell_iterators_on_level(0))
        {
          auto &points = support_points[cell->index()];
          for (const unsigned int v : cell->vertex_indices())
            points.push_back(cell->vertex(v));
          for (unsigned int l = 0; l < cell->n_lines(); ++l)
            points.push_back(find(key(Edge{{cell->line(l)->vertex_index(0),
                                            cell->line(l)->vertex_index(1)}})));
          if (!cell->reference_cell().is_hyper_cube())
            continue;
          if (dim == 3)
            for (const auto &face : cell->face_iterators())
            {
              std::vector<unsigned int> corners;
              for (const unsigned int v : face->vertex_indices())
                corners.push_back(face->vertex_index(v));
              points.push_back(find(key(corners)));
            }
          std::vector<unsigned int> corners;
          for (const unsigned int v : cell->vertex_indices())
            corners.push_back(cell->vertex_index(v));
          points.push_back(find(key(corners)));
        }
        return support_points;
      }
    } // namespace



    template <int dim>
    bool
    read(const std::string                    &file,
         Triangulation<dim>                   &triangulation,
         std::vector<std::vector<Point<dim>>> &support_points)
    {
      const std::string name = "Parameter <Scene/Mesh file> = <" + file + ">";
      GmshSession       session;
      gmsh::open(file);
      std::string error;
      gmsh::logger::getLastError(error);
      AssertThrow(error.empty(),
                  ExcMessage(name + ": gmsh cannot read the mesh: " + error));
      Reader<dim> reader(name);
      if (!reader.second_order())
        return false;
      reader.read();
      reader.create(triangulation);
      support_points = reader.support_points(triangulation);
      return true;
    }



    template bool
    read(const std::string &,
         Triangulation<2> &,
         std::vector<std::vector<Point<2>>> &);
    template bool
    read(const std::string &,
         Triangulation<3> &,
         std::vector<std::vector<Point<3>>> &);
  } // namespace GmshSecondOrder
} // namespace tribos
