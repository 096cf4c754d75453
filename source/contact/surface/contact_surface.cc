#include <tribos/contact/surface/contact_surface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/cell_id.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace tribos
{
  template <int dim>
  ContactSurface<dim>::ContactSurface(
    const DoFHandler<dim>              &dof_handler,
    const std::set<types::boundary_id> &boundary_ids,
    const bool                          axisymmetric,
    const Mapping<dim>                 *curved_geometry)
    : ids(boundary_ids)
    , face_shape(FaceShape::for_cells(
        dim,
        dof_handler.get_triangulation().all_reference_cells_are_hyper_cube(),
        dof_handler.get_fe().degree))
    , is_curved(curved_geometry != nullptr)
  {
    // Each process orients the faces of its own cells (the normal of
    // MasterFace must point out of the cell) and every process gathers all
    // of them, in the order of their cells (CellId, the same whatever the
    // partition): the surface is small against the mesh, and the search
    // needs every master face.
    number_nodes(gather_faces(dof_handler, curved_geometry));
    integrate_areas(axisymmetric);
    find_neighbours();
  }



  template <int dim>
  std::vector<typename ContactSurface<dim>::FaceRecord>
  ContactSurface<dim>::gather_faces(const DoFHandler<dim> &dof_handler,
                                    const Mapping<dim> *curved_geometry) const
  {
    std::vector<FaceRecord> own;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
        {
          const auto face = cell->face(f);
          if (!face->at_boundary() || ids.count(face->boundary_id()) == 0)
            continue;

          // A tetrahedron's faces are triangles (TriangleFace).
          const unsigned int n_vertices = face->n_vertices();
          AssertThrow(n_vertices == face_shape.n_vertices(),
                      ExcInternalError());
          std::array<unsigned int, n_face_nodes> order;
          for (unsigned int v = 0; v < n_face_nodes; ++v)
            order[v] = v;
          Vec3<double> x[4];
          for (unsigned int v = 0; v < n_vertices; ++v)
          {
            x[v] = {{0, 0, 0}};
            for (unsigned int d = 0; d < dim; ++d)
              x[v][d] = face->vertex(v)[d];
          }
          // The normal at the face's centre, of its linear face.
          Vec3<double> outward{{0, 0, 0}};
          for (unsigned int d = 0; d < dim; ++d)
            outward[d] = face->center()[d] - cell->center()[d];
          face_shape.template visit<dim>(
            [&](auto kind)
            {
              using Linear = typename decltype(kind)::Linear;
              Vec3<double> xbar, a[2], normal;
              Linear::geometry(x, Linear::centre, xbar, a, normal);
              if (dot(normal, outward) < 0)
                std::swap(order[Linear::flip[0]], order[Linear::flip[1]]);
            });

          FaceRecord record;
          record.cell       = cell->id().template to_binary<dim>();
          record.face       = f;
          record.body       = cell->material_id();
          record.owner      = cell->subdomain_id();
          record.n_vertices = n_vertices;
          for (unsigned int v = 0; v < n_vertices; ++v)
            for (unsigned int d = 0; d < dim; ++d)
            {
              record.dofs[v * dim + d] = face->vertex_dof_index(order[v], d);
              record.x[v * dim + d]    = face->vertex(order[v])[d];
            }
          if (face_shape.n_middles() > 0)
            gather_middles(cell, f, order, curved_geometry, record);
          own.push_back(record);
        }
    std::vector<FaceRecord> records;
    for (auto &part : Utilities::MPI::all_gather(
           dof_handler.get_triangulation().get_communicator(),
           own))
      records.insert(records.end(), part.begin(), part.end());
    std::sort(records.begin(),
              records.end(),
              [](const FaceRecord &a, const FaceRecord &b)
              {
                const CellId ca(a.cell), cb(b.cell);
                return ca < cb || (ca == cb && a.face < b.face);
              });
    return records;
  }



  template <int dim>
  void
  ContactSurface<dim>::gather_middles(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    f,
    const std::array<unsigned int, n_face_nodes>         &order,
    const Mapping<dim>                                   *curved_geometry,
    FaceRecord                                           &record) const
  {
    // A quadratic element has one dof per component on each line and (Q2
    // in 3D) on each face, in component order. Their reference positions:
    // the lines' and the face's centres on straight cells, where the curved
    // geometry puts the quadratic element's support points on curved ones
    // (after one per vertex, one per line, one per face).
    const auto        &base = cell->get_fe().base_element(0);
    const auto         face = cell->face(f);
    const unsigned int n_v  = cell->n_vertices();
    const auto         set  = [&](const unsigned int m,
                         const auto        &object,
                         const unsigned int support_point,
                         const Point<dim>  &straight)
    {
      const Point<dim> x =
        curved_geometry == nullptr ?
          straight :
          curved_geometry->transform_unit_to_real_cell(cell,
                                                       base.unit_support_point(
                                                         support_point));
      for (unsigned int d = 0; d < dim; ++d)
      {
        record.middle_dofs[m * dim + d] = object->dof_index(d);
        record.middle_x[m * dim + d]    = x[d];
      }
    };
    // The middles of the face's edges a-b (oriented order; in 2D the face
    // is the cell's line), then the nine-node quadrilateral's centre.
    face_shape.template visit<dim>(
      [&](auto kind)
      {
        using Kind = decltype(kind);
        if constexpr (Kind::n_middles > 0)
        {
          record.n_middles = Kind::n_middles;
          for (unsigned int e = 0; e < std::size(Kind::middle_edges); ++e)
          {
            const unsigned int a = face->vertex_index(
                                 order[Kind::middle_edges[e][0]]),
                               b = face->vertex_index(
                                 order[Kind::middle_edges[e][1]]);
            bool found = false;
            for (unsigned int l = 0; l < cell->n_lines() && !found; ++l)
            {
              const auto line = cell->line(l);
              if ((line->vertex_index(0) == a && line->vertex_index(1) == b) ||
                  (line->vertex_index(0) == b && line->vertex_index(1) == a))
              {
                set(e, line, n_v + l, line->center());
                found = true;
              }
            }
            AssertThrow(found, ExcInternalError());
          }
          if constexpr (Kind::has_centre)
            set(std::size(Kind::middle_edges),
                face,
                n_v + cell->n_lines() + f,
                face->center());
        }
      });
  }



  template <int dim>
  void
  ContactSurface<dim>::number_nodes(const std::vector<FaceRecord> &records)
  {
    // A node is its vertex's dofs (the first one names it): the number of
    // the node with @p dofs at @p x, made when first seen.
    std::map<types::global_dof_index, unsigned int> node_of_dof;
    const auto node_of = [&](const types::global_dof_index *dofs,
                             const double                  *x) -> unsigned int
    {
      auto it = node_of_dof.find(dofs[0]);
      if (it == node_of_dof.end())
      {
        Node node;
        for (unsigned int d = 0; d < dim; ++d)
        {
          node.dofs[d]      = dofs[d];
          node.reference[d] = x[d];
        }
        it = node_of_dof.emplace(node.dofs[0], node_list.size()).first;
        node_list.push_back(node);
      }
      return it->second;
    };
    for (const auto &record : records)
    {
      Face contact_face;
      contact_face.body       = record.body;
      contact_face.owner      = record.owner;
      contact_face.cell       = record.cell;
      contact_face.n_vertices = record.n_vertices;
      body_ids.insert(record.body);
      for (unsigned int v = 0; v < record.n_vertices; ++v)
        contact_face.nodes[v] =
          node_of(&record.dofs[v * dim], &record.x[v * dim]);
      // Its reference position is the chord's midpoint, where the
      // linear mapping (the mesh's reference geometry) puts the support
      // point. A triangle's middle nodes are shared with the neighbours.
      contact_face.n_middles = record.n_middles;
      for (unsigned int e = 0; e < record.n_middles; ++e)
      {
        const unsigned int n =
          node_of(&record.middle_dofs[e * dim], &record.middle_x[e * dim]);
        contact_face.middles[e] = n;
        face_shape.template visit<dim>(
          [&](auto kind)
          {
            using Kind = decltype(kind);
            if constexpr (Kind::n_middles > 0)
              if constexpr (Kind::middles_as_virtual_points)
                node_list[n].edge = {
                  {static_cast<int>(
                     contact_face.nodes[Kind::middle_edges[e][0]]),
                   static_cast<int>(
                     contact_face.nodes[Kind::middle_edges[e][1]])}};
          });
      }
      face_list.push_back(contact_face);
    }
  }



  template <int dim>
  void
  ContactSurface<dim>::integrate_areas(const bool axisymmetric)
  {
    // Adjacency and tributary areas: the integrals of the faces' functions
    // (e.g. h/6, 2h/3, h/6 on a straight quadratic segment).
    for (unsigned int f = 0; f < face_list.size(); ++f)
    {
      const auto  &face = face_list[f];
      Vec3<double> x[FaceShape::max_nodes];
      for (unsigned int v = 0; v < face.n_nodes(); ++v)
      {
        node_list[face.node(v)].faces.push_back(f);
        x[v] = node_list[face.node(v)].reference;
      }
      face_shape.integrate(x,
                           axisymmetric,
                           is_curved,
                           [&](const unsigned int v,
                               const double       area,
                               const double       measure)
                           {
                             node_list[face.node(v)].area += area;
                             // The face's measure (without the ring),
                             // shared by its nodes.
                             node_list[face.node(v)].size += measure;
                           });
    }
    // Element size at a node: the mean measure of its faces (length in 2D,
    // the square root of the area in 3D). Inside a uniform surface it is
    // the tributary length; at the surface's edge it stays the element
    // size (the tributary length would halve there, and a penalty k E / h
    // would double: a uniform pressure would no longer give a uniform
    // penetration).
    for (auto &node : node_list)
    {
      node.size /= node.faces.size();
      if (dim == 3)
        node.size = std::sqrt(node.size);
    }
  }



  template <int dim>
  bool
  ContactSurface<dim>::continues_across_refinement(const Face        &face,
                                                   const unsigned int p,
                                                   const unsigned int q) const
  {
    const auto midpoint_of =
      [&](const unsigned int m, const unsigned int a, const unsigned int b)
    {
      const auto &xm  = node_list[m].reference;
      const auto &xa  = node_list[a].reference;
      const auto &xb  = node_list[b].reference;
      double      off = 0, length = 0;
      for (unsigned int d = 0; d < 3; ++d)
      {
        off += std::pow(xm[d] - 0.5 * (xa[d] + xb[d]), 2);
        length += std::pow(xa[d] - xb[d], 2);
      }
      return off <= 1e-16 * length;
    };
    // One level between neighbours (p4est's balance): a finer face holds an
    // end of the edge and its midpoint (a hanging node), a coarser one an
    // end and the vertex beyond the other end of which that end is the
    // midpoint.
    for (const unsigned int g : face.neighbours)
    {
      const auto &other    = face_list[g];
      const auto  vertices = other.nodes.begin();
      const auto  end      = other.nodes.begin() + other.n_vertices;
      for (const auto &[e, o] : {std::make_pair(p, q), std::make_pair(q, p)})
        if (std::find(vertices, end, e) != end)
          for (auto r = vertices; r != end; ++r)
            if (*r != e && *r != o &&
                (midpoint_of(*r, e, o) || midpoint_of(o, e, *r)))
              return true;
    }
    return false;
  }



  template <int dim>
  void
  ContactSurface<dim>::find_neighbours()
  {
    // The vertices on each edge of the linear face, per local coordinate
    // and side (-1 where there are none).
    int          edges[3][2][2] = {};
    unsigned int n_c            = 0;
    face_shape.template visit<dim>(
      [&](auto kind)
      {
        using Linear = typename decltype(kind)::Linear;
        n_c          = Linear::n_edge_coordinates;
        for (unsigned int c = 0; c < n_c; ++c)
          for (unsigned int side = 0; side < 2; ++side)
            for (unsigned int i = 0; i < 2; ++i)
              edges[c][side][i] = Linear::edge_nodes[c][side][i];
      });
    for (unsigned int f = 0; f < face_list.size(); ++f)
    {
      auto                  &face = face_list[f];
      std::set<unsigned int> neighbours;
      for (unsigned int v = 0; v < face.n_vertices; ++v)
        for (const unsigned int g : node_list[face.nodes[v]].faces)
          if (g != f)
            neighbours.insert(g);
      face.neighbours.assign(neighbours.begin(), neighbours.end());

      for (unsigned int c = 0; c < n_c; ++c)
        for (unsigned int side = 0; side < 2; ++side)
        {
          if (edges[c][side][0] < 0)
            continue;
          // Another face contains every node of this edge.
          for (const unsigned int g : face.neighbours)
          {
            bool        shares_all = true;
            const auto &other      = face_list[g];
            for (const int local : edges[c][side])
            {
              if (local < 0)
                continue;
              const unsigned int n = face.nodes[local];
              shares_all =
                shares_all &&
                std::find(other.nodes.begin(),
                          other.nodes.begin() + other.n_vertices,
                          n) != other.nodes.begin() + other.n_vertices;
            }
            if (shares_all)
              face.continues[c][side] = true;
          }
          if (!face.continues[c][side] && edges[c][side][1] >= 0)
            face.continues[c][side] =
              continues_across_refinement(face,
                                          face.nodes[edges[c][side][0]],
                                          face.nodes[edges[c][side][1]]);
        }

      if constexpr (dim == 3)
      {
        std::set<unsigned int> ring;
        for (const unsigned int g : face.neighbours)
          for (unsigned int v = 0; v < face_list[g].n_vertices; ++v)
            ring.insert(face_list[g].nodes[v]);
        for (unsigned int v = 0; v < face.n_vertices; ++v)
          ring.erase(face.nodes[v]);
        face.ring.assign(ring.begin(), ring.end());
      }
      if constexpr (dim == 2)
        for (const unsigned int g : face.neighbours)
        {
          const auto &other = face_list[g].nodes;
          if (other[1] == face.nodes[0] && face.beyond[0] < 0)
            face.beyond[0] = other[0];
          if (other[0] == face.nodes[1] && face.beyond[1] < 0)
            face.beyond[1] = other[1];
        }
    }
  }

  template class ContactSurface<2>;
  template class ContactSurface<3>;
} // namespace tribos
