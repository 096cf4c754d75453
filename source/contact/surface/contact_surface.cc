#include <tribos/contact/surface/contact_surface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/cell_id.h>

#include <algorithm>
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
  {
    // Each process orients the faces of its own cells (the normal of
    // MasterFace must point out of the cell) and every process gathers all
    // of them, in the order of their cells (CellId, the same whatever the
    // partition): the surface is small against the mesh, and the search
    // needs every master face.
    const auto        &fe     = dof_handler.get_fe();
    const unsigned int degree = fe.degree;
    AssertThrow(degree == 1 || degree == 2,
                ExcMessage("Contact surfaces are built for Finite element/"
                           "Polynomial degree = 1 or 2; this mesh has "
                           "degree " +
                           std::to_string(degree) + "."));
    is_quadratic = (degree == 2);
    is_quadratic_quads =
      is_quadratic && dim == 3 &&
      dof_handler.get_triangulation().all_reference_cells_are_hyper_cube();
    is_curved = (curved_geometry != nullptr);
    number_nodes(gather_faces(dof_handler, curved_geometry));
    if (is_curved || is_quadratic_quads)
      integrate_quadratic_areas(axisymmetric);
    else
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
          Vec3<double> xbar, a[2], normal, outward{{0, 0, 0}};
          if (n_vertices == 3)
          {
            const double xi[2] = {1. / 3, 1. / 3};
            TriangleFace::geometry(x, xi, xbar, a, normal);
          }
          else
          {
            const double xi[2] = {0, 0};
            MasterFace<dim>::geometry(x, xi, xbar, a, normal);
          }
          for (unsigned int d = 0; d < dim; ++d)
            outward[d] = face->center()[d] - cell->center()[d];
          if (dot(normal, outward) < 0)
          {
            if (dim == 2)
              std::swap(order[0], order[1]);
            else
              std::swap(order[1], order[2]);
          }

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
          if (is_quadratic)
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
    if constexpr (dim == 2)
    {
      // The segment's middle: its line's dofs.
      record.n_middles = 1;
      set(0, face, n_v + f, face->center());
      return;
    }
    // The middles of the face's edges a-b (oriented order): the six-node
    // triangle's 0-1, 1-2, 2-0; the nine-node quadrilateral's (lexicographic
    // like MasterFace) 0-1, 2-3, 0-2, 1-3, then its centre.
    const bool         triangle    = face->n_vertices() == 3;
    const unsigned int edges[4][2] = {{0, 1},
                                      {triangle ? 1u : 2u, triangle ? 2u : 3u},
                                      {triangle ? 2u : 0u, triangle ? 0u : 2u},
                                      {1, 3}};
    const unsigned int n_edges     = triangle ? 3 : 4;
    record.n_middles               = triangle ? 3 : 5;
    for (unsigned int e = 0; e < n_edges; ++e)
    {
      const unsigned int a = face->vertex_index(order[edges[e][0]]),
                         b = face->vertex_index(order[edges[e][1]]);
      bool found           = false;
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
    if (!triangle)
      set(4, face, n_v + cell->n_lines() + f, face->center());
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
        if (dim == 3 && record.n_vertices == 3)
          node_list[n].edge = {
            {static_cast<int>(contact_face.nodes[e]),
             static_cast<int>(contact_face.nodes[(e + 1) % 3])}};
      }
      face_list.push_back(contact_face);
    }
  }



  template <int dim>
  void
  ContactSurface<dim>::integrate_areas(const bool axisymmetric)
  {
    // Adjacency and tributary areas (of the faces' shape functions, the
    // quadratic ones on Q2: h/6, 2h/3, h/6 on a straight face).
    const QGauss<dim - 1> quadrature(is_quadratic ? 3 : 2);
    for (unsigned int f = 0; f < face_list.size(); ++f)
    {
      const auto  &face = face_list[f];
      Vec3<double> x[4];
      for (unsigned int v = 0; v < face.n_nodes(); ++v)
        node_list[face.node(v)].faces.push_back(f);
      for (unsigned int v = 0; v < face.n_vertices; ++v)
        x[v] = node_list[face.nodes[v]].reference;
      if (face.triangle())
      {
        // A flat triangle: each vertex's shape function integrates to a
        // third of its area. On the six-node triangle the vertex functions
        // integrate to zero: the areas are those of the modified basis of
        // the mortar element (Mortar3D), 2 A / 15 and A / 5.
        const double area  = 0.5 * norm(cross(x[1] - x[0], x[2] - x[0]));
        const double alpha = TriangleFace::modified_basis_alpha;
        for (unsigned int v = 0; v < face.n_nodes(); ++v)
        {
          const double share = face.n_middles == 0 ? 1. / 3. :
                               v < 3               ? 2. * alpha / 3. :
                                                     (1. - 2. * alpha) / 3.;
          node_list[face.node(v)].area += share * area;
          node_list[face.node(v)].size += area;
        }
        continue;
      }
      for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        double xi[2] = {0, 0};
        for (unsigned int c = 0; c < dim - 1; ++c)
          xi[c] = 2 * quadrature.point(q)[c] - 1;
        double N[4] = {}, dN[4][2] = {};
        MasterFace<dim>::shape(xi, N, dN);
        if (is_quadratic)
        {
          N[0] = 0.5 * xi[0] * (xi[0] - 1.);
          N[1] = 0.5 * xi[0] * (xi[0] + 1.);
          N[2] = 1. - xi[0] * xi[0];
        }
        Vec3<double> xbar, a[2], normal;
        MasterFace<dim>::geometry(x, xi, xbar, a, normal);
        const double jacobian =
          (dim == 2 ? norm(a[0]) : norm(cross(a[0], a[1])));
        // Weights of [0,1]^(dim-1) times 2^(dim-1) for [-1,1].
        const double weight = quadrature.weight(q) * (dim == 2 ? 2. : 4.);
        const double ring   = axisymmetric ? 2 * numbers::PI * xbar[0] : 1.;
        for (unsigned int v = 0; v < face.n_nodes(); ++v)
        {
          node_list[face.node(v)].area += N[v] * jacobian * weight * ring;
          // The face's measure (without the ring), shared by its nodes.
          node_list[face.node(v)].size += jacobian * weight;
        }
      }
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



  namespace
  {
    const QGauss<1> &
    line_rule()
    {
      static const QGauss<1> rule(4);
      return rule;
    }

    const QGauss<2> &
    square_rule()
    {
      static const QGauss<2> rule(4);
      return rule;
    }

    const QGaussSimplex<2> &
    triangle_rule()
    {
      static const QGaussSimplex<2> rule(4);
      return rule;
    }

    /** The number of points of quadratic_face_point()'s rule. */
    unsigned int
    n_quadratic_face_points(const unsigned int n_nodes)
    {
      return n_nodes == 3 ? line_rule().size() :
             n_nodes == 6 ? triangle_rule().size() :
                            square_rule().size();
    }

    /**
     * At point @p q of the reference face of @p n_nodes nodes (3: the
     * segment through nodes 0, middle, 1; 6: the six-node triangle; 9: the
     * nine-node quadrilateral), the nodes' functions @p N (the six-node
     * triangle's modified basis), the position @p xq on the face through
     * @p x and the measure of the face there times the rule's weight
     * (returned). Rules: 4-point Gauss on segments and per direction on
     * quadrilaterals, the 4-point-per-direction simplex rule on triangles.
     */
    double
    quadratic_face_point(const unsigned int  n_nodes,
                         const Vec3<double> *x,
                         const unsigned int  q,
                         double             *N,
                         Vec3<double>       &xq)
    {
      double dN[9][2]     = {};
      xq                  = {{0, 0, 0}};
      Vec3<double> a[2]   = {{{0, 0, 0}}, {{0, 0, 0}}};
      double       weight = 0;
      if (n_nodes == 3)
      {
        double dL[3];
        quadratic_segment_shape(2 * line_rule().point(q)[0] - 1, N, dL);
        for (unsigned int i = 0; i < 3; ++i)
          dN[i][0] = dL[i];
        weight = 2 * line_rule().weight(q);
      }
      else if (n_nodes == 6)
      {
        const Point<2> &p        = triangle_rule().point(q);
        const double    L[3]     = {1 - p[0] - p[1], p[0], p[1]};
        const double    dL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
        for (unsigned int v = 0; v < 3; ++v)
        {
          const unsigned int w = (v + 1) % 3;
          N[v]                 = L[v] * (2 * L[v] - 1);
          N[3 + v]             = 4 * L[v] * L[w];
          for (unsigned int k = 0; k < 2; ++k)
          {
            dN[v][k]     = (4 * L[v] - 1) * dL[v][k];
            dN[3 + v][k] = 4 * (dL[v][k] * L[w] + L[v] * dL[w][k]);
          }
        }
        weight = triangle_rule().weight(q);
      }
      else
      {
        // Node i is the product of the 1D functions a(i) in xi_1 and b(i)
        // in xi_2 (0: -1, 1: +1, 2: middle): vertices (lexicographic),
        // middles of 0-1, 2-3, 0-2, 1-3, centre.
        const unsigned int a_of[9] = {0, 1, 0, 1, 2, 2, 0, 1, 2};
        const unsigned int b_of[9] = {0, 0, 1, 1, 0, 1, 2, 2, 2};
        double             L1[3], dL1[3], L2[3], dL2[3];
        quadratic_segment_shape(2 * square_rule().point(q)[0] - 1, L1, dL1);
        quadratic_segment_shape(2 * square_rule().point(q)[1] - 1, L2, dL2);
        for (unsigned int i = 0; i < 9; ++i)
        {
          N[i]     = L1[a_of[i]] * L2[b_of[i]];
          dN[i][0] = dL1[a_of[i]] * L2[b_of[i]];
          dN[i][1] = L1[a_of[i]] * dL2[b_of[i]];
        }
        weight = 4 * square_rule().weight(q);
      }
      for (unsigned int i = 0; i < n_nodes; ++i)
      {
        xq = xq + scale(N[i], x[i]);
        for (unsigned int k = 0; k < 2; ++k)
          a[k] = a[k] + scale(dN[i][k], x[i]);
      }
      if (n_nodes == 6)
      {
        // The modified basis: a vertex takes alpha of both its edges'
        // middle functions.
        const double alpha = TriangleFace::modified_basis_alpha;
        double       P2[6];
        std::copy(N, N + 6, P2);
        for (unsigned int v = 0; v < 3; ++v)
          N[v] = P2[v] + alpha * (P2[3 + v] + P2[3 + (v + 2) % 3]);
        for (unsigned int e = 0; e < 3; ++e)
          N[3 + e] = (1 - 2 * alpha) * P2[3 + e];
      }
      return weight * (n_nodes == 3 ? norm(a[0]) : norm(cross(a[0], a[1])));
    }
  } // namespace



  template <int dim>
  void
  ContactSurface<dim>::integrate_quadratic_areas(const bool axisymmetric)
  {
    // Quadratic faces only (the constructor builds no other curved ones,
    // and nine-node quadrilaterals have no other path).
    for (unsigned int f = 0; f < face_list.size(); ++f)
    {
      const auto        &face    = face_list[f];
      const unsigned int n_nodes = face.n_nodes();
      Vec3<double>       x[9];
      for (unsigned int v = 0; v < n_nodes; ++v)
      {
        node_list[face.node(v)].faces.push_back(f);
        x[v] = node_list[face.node(v)].reference;
      }
      const unsigned int n_points = n_quadratic_face_points(n_nodes);
      for (unsigned int q = 0; q < n_points; ++q)
      {
        double       N[9];
        Vec3<double> xq;
        const double weight = quadratic_face_point(n_nodes, x, q, N, xq);
        const double ring   = axisymmetric ? 2 * numbers::PI * xq[0] : 1.;
        for (unsigned int v = 0; v < n_nodes; ++v)
        {
          node_list[face.node(v)].area += N[v] * weight * ring;
          node_list[face.node(v)].size += weight;
        }
      }
    }
    for (auto &node : node_list)
    {
      node.size /= node.faces.size();
      if (dim == 3)
        node.size = std::sqrt(node.size);
    }
  }



  template <int dim>
  void
  ContactSurface<dim>::find_neighbours()
  {
    // Local node numbers along each edge: 2D ends; 3D edges of xi_1 = -+1
    // (nodes 0,2 / 1,3) and xi_2 = -+1 (nodes 0,1 / 2,3); triangles: xi_1 =
    // 0 (nodes 0,2), xi_2 = 0 (nodes 0,1), xi_1 + xi_2 = 1 (nodes 1,2).
    using Edges                   = std::vector<std::vector<unsigned int>>;
    const Edges edge_nodes[3]     = {(dim == 2 ? Edges{{0}, {1}} :
                                                 Edges{{0, 2}, {1, 3}}),
                                     Edges{{0, 1}, {2, 3}},
                                     Edges{}};
    const Edges triangle_edges[3] = {Edges{{0, 2}, {}},
                                     Edges{{0, 1}, {}},
                                     Edges{{}, {1, 2}}};
    for (unsigned int f = 0; f < face_list.size(); ++f)
    {
      auto                  &face = face_list[f];
      std::set<unsigned int> neighbours;
      for (unsigned int v = 0; v < face.n_vertices; ++v)
        for (const unsigned int g : node_list[face.nodes[v]].faces)
          if (g != f)
            neighbours.insert(g);
      face.neighbours.assign(neighbours.begin(), neighbours.end());

      const Edges       *edges = face.triangle() ? triangle_edges : edge_nodes;
      const unsigned int n_c   = face.triangle() ? 3 : dim - 1;
      for (unsigned int c = 0; c < n_c; ++c)
        for (unsigned int side = 0; side < 2; ++side)
        {
          if (side >= edges[c].size() || edges[c][side].empty())
            continue;
          // Another face contains every node of this edge.
          for (const unsigned int g : face.neighbours)
          {
            bool        shares_all = true;
            const auto &other      = face_list[g];
            for (const unsigned int local : edges[c][side])
            {
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
