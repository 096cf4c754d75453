#include <tribos/contact/contact_surface.h>

#include <deal.II/base/quadrature_lib.h>

#include <map>

namespace tribos
{
  template <int dim>
  ContactSurface<dim>::ContactSurface(
    const DoFHandler<dim>              &dof_handler,
    const std::set<types::boundary_id> &boundary_ids,
    const bool                          axisymmetric)
    : ids(boundary_ids)
  {
    std::map<unsigned int, unsigned int> node_of_vertex;

    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
      {
        const auto face = cell->face(f);
        if (!face->at_boundary() || ids.count(face->boundary_id()) == 0)
          continue;

        Face contact_face;
        contact_face.body = cell->material_id();
        body_ids.insert(cell->material_id());
        std::array<unsigned int, n_face_nodes> order;
        for (unsigned int v = 0; v < n_face_nodes; ++v)
          order[v] = v;

        // Orient: the MasterFace normal must point out of the cell.
        Vec3<double> x[4];
        for (unsigned int v = 0; v < n_face_nodes; ++v)
        {
          x[v] = {{0, 0, 0}};
          for (unsigned int d = 0; d < dim; ++d)
            x[v][d] = face->vertex(v)[d];
        }
        Vec3<double> xbar, a[2], normal, outward{{0, 0, 0}};
        const double xi[2] = {0, 0};
        MasterFace<dim>::geometry(x, xi, xbar, a, normal);
        for (unsigned int d = 0; d < dim; ++d)
          outward[d] = face->center()[d] - cell->center()[d];
        if (dot(normal, outward) < 0)
        {
          if (dim == 2)
            std::swap(order[0], order[1]);
          else
            std::swap(order[1], order[2]);
        }

        for (unsigned int v = 0; v < n_face_nodes; ++v)
        {
          const unsigned int vertex = face->vertex_index(order[v]);
          auto               it     = node_of_vertex.find(vertex);
          if (it == node_of_vertex.end())
          {
            Node node;
            node.vertex = vertex;
            for (unsigned int d = 0; d < dim; ++d)
            {
              node.dofs[d]      = face->vertex_dof_index(order[v], d);
              node.reference[d] = face->vertex(order[v])[d];
            }
            it = node_of_vertex.emplace(vertex, node_list.size()).first;
            node_list.push_back(node);
          }
          contact_face.nodes[v] = it->second;
        }
        face_list.push_back(contact_face);
      }

    // Adjacency and tributary areas.
    const QGauss<dim - 1> quadrature(2);
    for (unsigned int f = 0; f < face_list.size(); ++f)
    {
      const auto  &face = face_list[f];
      Vec3<double> x[4];
      for (unsigned int v = 0; v < n_face_nodes; ++v)
      {
        node_list[face.nodes[v]].faces.push_back(f);
        x[v] = node_list[face.nodes[v]].reference;
      }
      for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        double xi[2] = {0, 0};
        for (unsigned int c = 0; c < dim - 1; ++c)
          xi[c] = 2 * quadrature.point(q)[c] - 1;
        double N[4], dN[4][2];
        MasterFace<dim>::shape(xi, N, dN);
        Vec3<double> xbar, a[2], normal;
        MasterFace<dim>::geometry(x, xi, xbar, a, normal);
        const double jacobian =
          (dim == 2 ? norm(a[0]) : norm(cross(a[0], a[1])));
        // Weights of [0,1]^(dim-1) times 2^(dim-1) for [-1,1].
        const double weight = quadrature.weight(q) * (dim == 2 ? 2. : 4.);
        const double ring   = axisymmetric ? 2 * numbers::PI * xbar[0] : 1.;
        for (unsigned int v = 0; v < n_face_nodes; ++v)
        {
          node_list[face.nodes[v]].area += N[v] * jacobian * weight * ring;
          // The face's measure (without the ring), shared by its nodes.
          node_list[face.nodes[v]].size += jacobian * weight;
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

    // Local node numbers along each edge: 2D ends; 3D edges of xi_1 = -+1
    // (nodes 0,2 / 1,3) and xi_2 = -+1 (nodes 0,1 / 2,3).
    const std::vector<std::vector<unsigned int>> edge_nodes[2] = {
      (dim == 2 ? std::vector<std::vector<unsigned int>>{{0}, {1}} :
                  std::vector<std::vector<unsigned int>>{{0, 2}, {1, 3}}),
      std::vector<std::vector<unsigned int>>{{0, 1}, {2, 3}}};
    for (unsigned int f = 0; f < face_list.size(); ++f)
    {
      auto                  &face = face_list[f];
      std::set<unsigned int> neighbours;
      for (const unsigned int n : face.nodes)
        for (const unsigned int g : node_list[n].faces)
          if (g != f)
            neighbours.insert(g);
      face.neighbours.assign(neighbours.begin(), neighbours.end());

      for (unsigned int c = 0; c < dim - 1; ++c)
        for (unsigned int side = 0; side < 2; ++side)
        {
          // Another face contains every node of this edge.
          for (const unsigned int g : face.neighbours)
          {
            bool shares_all = true;
            for (const unsigned int local : edge_nodes[c][side])
            {
              const unsigned int n     = face.nodes[local];
              const auto        &other = face_list[g].nodes;
              shares_all =
                shares_all &&
                std::find(other.begin(), other.end(), n) != other.end();
            }
            if (shares_all)
              face.continues[c][side] = true;
          }
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
