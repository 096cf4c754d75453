#include <tribos/scene/gmsh_second_order.h>
#include <tribos/scene/msh_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "gmsh_cell_kinds.h"

namespace tribos
{
  namespace GmshSecondOrder
  {
    namespace
    {
      using namespace internal;

      /** The sorted copy of @p indices: the key of an edge, face or cell. */
      template <typename Container>
      std::vector<unsigned int>
      key(const Container &indices)
      {
        std::vector<unsigned int> k(indices.begin(), indices.end());
        std::sort(k.begin(), k.end());
        return k;
      }

      /**
       * A gmsh mesh file (read and checked by read_msh_file()) into
       * deal.II's cell data and, for second-order cells, the positions of
       * their other nodes, kept by the sorted vertex numbers of their edge,
       * face or cell. What the file format allows but tribos cannot mesh
       * is refused here, naming the element's line: cells of other kinds,
       * orders mixed, cells of a higher dimension than Dimension, a 2D mesh
       * off the x-y plane, degenerate, inverted or twisted cells.
       */
      template <int dim>
      class Reader
      {
      public:
        /** @p name starts the messages. */
        Reader(const MshFile &file, const std::string &name)
          : file(file)
          , name(name)
        {
        }

        /** The order of the file's cells (1 or 2); refuses cells of other
         * kinds or orders, first and second order mixed, cells of a
         * dimension above @p dim, and a file without cells. */
        unsigned int
        order() const;

        /** The cells and the boundary elements. */
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
        Point<dim>
        position(const std::size_t node) const;

        /** The message start for the element @p e. */
        std::string
        at(const MshFile::Element &e) const;

        /** Cell @p e of @p kind. */
        void
        add_cell(const CellKind &kind, const MshFile::Element &e);

        /** Refuse cell @p e (its vertices @p corner, deal.II order) if it
         * is degenerate, inverted or twisted. */
        void
        check_shape(const MshFile::Element          &e,
                    const std::vector<unsigned int> &corner) const;

        void
        add_boundary(const MshFile::Element &e);

        const MshFile    &file;
        const std::string name;
        /** First-order meshes number their vertices as deal.II's reader
         * does (in the order of $Nodes), second-order ones as first met. */
        bool                                            second_order = false;
        std::vector<Point<dim>>                         vertices;
        std::vector<unsigned int>                       vertex_of_node;
        std::map<std::vector<unsigned int>, Point<dim>> node_of;
        std::vector<CellData<dim>>                      cells;
        SubCellData                                     boundary;
        bool hyper_cubes = false, simplices = false;
      };



      template <int dim>
      std::string
      Reader<dim>::at(const MshFile::Element &e) const
      {
        return file.file + ":" + std::to_string(e.line) + ": element " +
               std::to_string(e.tag);
      }



      template <int dim>
      unsigned int
      Reader<dim>::order() const
      {
        bool first = false, second = false;
        for (const auto &e : file.elements)
        {
          AssertThrow(e.dim <= dim,
                      ExcMessage(name + " (" + at(e) + "): the mesh has " +
                                 describe(e.type) + " of dimension " +
                                 std::to_string(e.dim) +
                                 ", but Dimension = " + std::to_string(dim) +
                                 ". Set Dimension = 3 for a 3D mesh (a 2D "
                                 "run would take its surface triangles or "
                                 "quadrilaterals as its cells)."));
          if (e.dim != dim)
            continue;
          const CellKind *kind = cell_kind(dim, e.type);
          AssertThrow(
            kind != nullptr,
            ExcMessage(
              name + " (" + at(e) + "): the mesh has " + describe(e.type) +
              ", which tribos does not read. It takes cells of order 1 (" +
              (dim == 2 ? "triangles or quadrilaterals" :
                          "tetrahedra or hexahedra") +
              ") or 2 (" +
              (dim == 2 ? "tri6, quad8, quad9" : "tet10, hex20, hex27") +
              "), one kind per mesh: mesh with 'Mesh.ElementOrder = 1;' or "
              "'= 2;'" +
              (dim == 3 ? ", and without prisms or pyramids ('Mesh."
                          "RecombineAll = 1;' with 'Mesh.SubdivisionAlgorithm "
                          "= 2;' gives hexahedra only)" :
                          std::string()) +
              "."));
          (kind->edges.empty() ? first : second) = true;
        }
        AssertThrow(first || second,
                    ExcMessage(name + ": the mesh has no " +
                               std::string(dim == 2 ? "2D" : "3D") +
                               " cells (with Dimension = " +
                               std::to_string(dim) + ")."));
        AssertThrow(!(first && second),
                    ExcMessage(name +
                               ": the mesh mixes first- and second-order "
                               "cells; tribos takes one order per mesh."));
        return second ? 2 : 1;
      }



      template <int dim>
      Point<dim>
      Reader<dim>::position(const std::size_t node) const
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = file.nodes[node].x[d];
        return x;
      }



      template <int dim>
      void
      Reader<dim>::read()
      {
        second_order = order() == 2;
        vertex_of_node.assign(file.nodes.size(), numbers::invalid_unsigned_int);
        // A 2D mesh must lie in the x-y plane: deal.II would drop z.
        if (dim == 2)
        {
          double extent = 0;
          for (const auto &node : file.nodes)
            for (unsigned int d = 0; d < 3; ++d)
              extent = std::max(extent, std::abs(node.x[d]));
          for (const auto &e : file.elements)
            if (e.dim == dim)
              for (const std::size_t n : e.nodes)
                AssertThrow(std::abs(file.nodes[n].x[2]) <= 1e-10 * extent,
                            ExcMessage(
                              name + " (" + file.file + ":" +
                              std::to_string(file.nodes[n].line) +
                              "): a node of the 2D mesh has z = " +
                              std::to_string(file.nodes[n].x[2]) +
                              "; with Dimension = 2 the mesh must lie in the "
                              "x-y plane (z = 0)."));
        }
        if (!second_order)
          for (std::size_t n = 0; n < file.nodes.size(); ++n)
          {
            vertex_of_node[n] = vertices.size();
            vertices.push_back(position(n));
          }
        for (const auto &e : file.elements)
          if (e.dim == dim)
            add_cell(*cell_kind(dim, e.type), e);
        // The boundary elements: lines in 2D, faces (and lines) in 3D.
        for (const auto &e : file.elements)
          if (e.dim >= 1 && e.dim < dim)
            add_boundary(e);
      }



      template <int dim>
      void
      Reader<dim>::add_cell(const CellKind &kind, const MshFile::Element &e)
      {
        const std::vector<std::size_t> &nodes = e.nodes;
        // The corners become the vertices (second order: numbered when
        // first met).
        const bool hyper_cube = (kind.n_corners == (dim == 2 ? 4u : 8u));
        hyper_cubes           = hyper_cubes || hyper_cube;
        simplices             = simplices || !hyper_cube;
        std::vector<unsigned int> corner(kind.n_corners);
        for (unsigned int c = 0; c < kind.n_corners; ++c)
        {
          unsigned int &vertex = vertex_of_node[nodes[c]];
          if (vertex == numbers::invalid_unsigned_int)
          {
            vertex = vertices.size();
            vertices.push_back(position(nodes[c]));
          }
          corner[c] = vertex;
        }
        CellData<dim> cell(kind.n_corners);
        for (unsigned int c = 0; c < kind.n_corners; ++c)
          cell.vertices[hyper_cube ? GeometryInfo<dim>::ucd_to_deal[c] : c] =
            corner[c];
        cell.material_id = e.physical;
        check_shape(e, cell.vertices);
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
      Reader<dim>::add_boundary(const MshFile::Element &e)
      {
        const unsigned int n_corners = boundary_corners(e.type);
        AssertThrow(n_corners > 0 && (n_corners == 2) == (e.dim == 1),
                    ExcMessage(name + " (" + at(e) +
                               "): the mesh's boundary "
                               "has " +
                               describe(e.type) +
                               ", which tribos does not read."));
        CellData<1> line;
        CellData<2> face(n_corners);
        for (unsigned int c = 0; c < n_corners; ++c)
        {
          const unsigned int vertex = vertex_of_node[e.nodes[c]];
          AssertThrow(vertex != numbers::invalid_unsigned_int,
                      ExcMessage(name + " (" + at(e) +
                                 "): a boundary element's corner is no "
                                 "corner of a cell (node " +
                                 std::to_string(file.nodes[e.nodes[c]].tag) +
                                 ")."));
          (e.dim == 1 ? line.vertices[c] : face.vertices[c]) = vertex;
        }
        if (e.dim == 1)
        {
          line.boundary_id = e.physical;
          boundary.boundary_lines.push_back(line);
        }
        else
        {
          face.boundary_id = e.physical;
          boundary.boundary_quads.push_back(face);
        }
      }



      template <int dim>
      void
      Reader<dim>::check_shape(const MshFile::Element          &e,
                               const std::vector<unsigned int> &corner) const
      {
        // Simplices: the signed volume; hyper cubes: the Jacobian at each
        // corner (its edges to the neighbours in deal.II's lexicographic
        // order, signed by the corner's parity): all of one sign and none
        // near zero. The sign itself is free (deal.II turns inverted cells
        // over).
        double h = 0;
        for (const unsigned int a : corner)
          for (const unsigned int b : corner)
            h = std::max(h, vertices[a].distance(vertices[b]));
        const auto det =
          [&](const unsigned int v, const std::array<unsigned int, dim> &to)
        {
          Tensor<2, dim> J;
          for (unsigned int d = 0; d < dim; ++d)
            for (unsigned int i = 0; i < dim; ++i)
              J[i][d] = vertices[corner[to[d]]][i] - vertices[corner[v]][i];
          return determinant(J);
        };
        std::vector<double> dets;
        if (corner.size() == dim + 1)
        {
          std::array<unsigned int, dim> to;
          for (unsigned int d = 0; d < dim; ++d)
            to[d] = d + 1;
          dets.push_back(det(0, to));
        }
        else
          for (unsigned int v = 0; v < corner.size(); ++v)
          {
            std::array<unsigned int, dim> to;
            int                           parity = 1;
            for (unsigned int d = 0; d < dim; ++d)
            {
              to[d] = v ^ (1u << d);
              parity *= (v & (1u << d)) ? -1 : 1;
            }
            dets.push_back(parity * det(v, to));
          }
        double smallest_size = std::numeric_limits<double>::max();
        for (const double d : dets)
          smallest_size = std::min(smallest_size, std::abs(d));
        const bool degenerate =
          !(h > 0) || smallest_size <= 1e-12 * std::pow(h, dim);
        const bool one_sign =
          std::all_of(dets.begin(),
                      dets.end(),
                      [&](const double d) { return (d > 0) == (dets[0] > 0); });
        AssertThrow(!degenerate && one_sign,
                    ExcMessage(
                      name + " (" + at(e) + "): the " +
                      msh_element_type(e.type)->name + " is " +
                      (degenerate ?
                         std::string("degenerate (zero ") +
                           (dim == 2 ? "area" : "volume") + " at a corner)" :
                         std::string("inverted or twisted at some of its "
                                     "corners (the Jacobian changes sign)")) +
                      ". Mesh it again."));
      }



      template <int dim>
      void
      Reader<dim>::create(Triangulation<dim> &triangulation)
      {
        if (!second_order)
          GridTools::delete_unused_vertices(vertices, cells, boundary);
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
    read(const MshFile                        &mesh,
         const std::string                    &name,
         Triangulation<dim>                   &triangulation,
         std::vector<std::vector<Point<dim>>> &support_points)
    {
      Reader<dim> reader(mesh, name);
      reader.read();
      reader.create(triangulation);
      if (reader.order() == 1)
        return false;
      support_points = reader.support_points(triangulation);
      return true;
    }



    template <int dim>
    unsigned int
    order(const MshFile &mesh, const std::string &name)
    {
      return Reader<dim>(mesh, name).order();
    }



    namespace
    {
      /** The messages' start for the gmsh file @p file. */
      std::string
      mesh_file_name(const std::string &file)
      {
        return "Parameter <Scene/Mesh file> = <" + file + ">";
      }

      /** @p file read, its MshError a deal.II exception after @p name. */
      MshFile
      read_file(const std::string &file, const std::string &name)
      {
        try
        {
          return read_msh_file(file);
        }
        catch (const MshError &error)
        {
          AssertThrow(false, ExcMessage(name + ": " + error.what()));
        }
        return MshFile();
      }
    } // namespace



    template <int dim>
    bool
    read(const std::string                    &file,
         Triangulation<dim>                   &triangulation,
         std::vector<std::vector<Point<dim>>> &support_points)
    {
      const std::string name = mesh_file_name(file);
      return read(read_file(file, name), name, triangulation, support_points);
    }



    template <int dim>
    unsigned int
    order(const std::string &file)
    {
      const std::string name = mesh_file_name(file);
      return order<dim>(read_file(file, name), name);
    }



    template bool
    read(const MshFile &,
         const std::string &,
         Triangulation<2> &,
         std::vector<std::vector<Point<2>>> &);
    template bool
    read(const MshFile &,
         const std::string &,
         Triangulation<3> &,
         std::vector<std::vector<Point<3>>> &);
    template unsigned int
    order<2>(const MshFile &, const std::string &);
    template unsigned int
    order<3>(const MshFile &, const std::string &);
    template bool
    read(const std::string &,
         Triangulation<2> &,
         std::vector<std::vector<Point<2>>> &);
    template bool
    read(const std::string &,
         Triangulation<3> &,
         std::vector<std::vector<Point<3>>> &);
    template unsigned int
    order<2>(const std::string &);
    template unsigned int
    order<3>(const std::string &);
  } // namespace GmshSecondOrder
} // namespace tribos
