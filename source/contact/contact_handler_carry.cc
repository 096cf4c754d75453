#include <tribos/contact/contact_handler.h>
#include <tribos/contact/surface/master_face.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstring>
#include <limits>

// ContactHandler's part in a change of the mesh (Adaptivity): the
// committed node states are carried from the old slave surfaces to the new
// ones by the nodes' reference positions, which do not depend on the mesh.
namespace tribos
{
  namespace
  {
    /**
     * Where the reference point @p X lies on the face with vertices @p x
     * (MasterFace order; 2D: 2, 3D: 4): the face's shape values there (at
     * the closest point, clamped to the face) into @p N; returns the
     * distance.
     */
    template <int dim>
    double
    locate(const Vec3<double> *x, const Vec3<double> &X, double *N)
    {
      constexpr unsigned int n     = MasterFace<dim>::n_nodes;
      double                 xi[2] = {0, 0}, dN[n][2];
      for (unsigned int iteration = 0; iteration < 20; ++iteration)
      {
        MasterFace<dim>::shape(xi, N, dN);
        double r[3] = {0, 0, 0}, J[3][2] = {};
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int d = 0; d < 3; ++d)
          {
            r[d] += N[a] * x[a][d];
            for (unsigned int c = 0; c < dim - 1; ++c)
              J[d][c] += dN[a][c] * x[a][d];
          }
        for (unsigned int d = 0; d < 3; ++d)
          r[d] -= X[d];
        // Gauss-Newton on |x(xi) - X|^2.
        double A[2][2] = {}, b[2] = {};
        for (unsigned int d = 0; d < 3; ++d)
          for (unsigned int c = 0; c < dim - 1; ++c)
          {
            b[c] -= J[d][c] * r[d];
            for (unsigned int e = 0; e < dim - 1; ++e)
              A[c][e] += J[d][c] * J[d][e];
          }
        double step[2] = {0, 0};
        if (dim == 2)
          step[0] = b[0] / A[0][0];
        else
        {
          const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
          step[0]          = (A[1][1] * b[0] - A[0][1] * b[1]) / det;
          step[1]          = (A[0][0] * b[1] - A[1][0] * b[0]) / det;
        }
        double change = 0;
        for (unsigned int c = 0; c < dim - 1; ++c)
        {
          const double before = xi[c];
          xi[c]               = std::max(-1., std::min(1., xi[c] + step[c]));
          change              = std::max(change, std::abs(xi[c] - before));
        }
        if (!std::isfinite(change) || change < 1e-13)
          break;
      }
      MasterFace<dim>::shape(xi, N, dN);
      double distance = 0;
      for (unsigned int d = 0; d < 3; ++d)
      {
        double y = -X[d];
        for (unsigned int a = 0; a < n; ++a)
          y += N[a] * x[a][d];
        distance += y * y;
      }
      return std::sqrt(distance);
    }



    /** A carried node's state: the pairing (of the old master surface)
     * forgotten, so the search pairs it again. */
    void
    unpair(NodeState &state)
    {
      state.paired     = false;
      state.face       = -1;
      state.projection = Projection();
      state.distance   = std::numeric_limits<double>::quiet_NaN();
    }
  } // namespace



  template <int dim>
  typename ContactHandler<dim>::CarriedState
  ContactHandler<dim>::carried_state() const
  {
    // committed_state()'s layout: number of pairs; per pair the number of
    // nodes, ever_near and the states (of every node, gathered).
    const std::vector<char> bytes  = committed_state();
    size_t                  offset = sizeof(unsigned int);
    CarriedState            carried;
    for (const auto &pair : contact_pairs)
    {
      typename CarriedState::Pair p;
      unsigned int                n;
      std::memcpy(&n, bytes.data() + offset, sizeof(n));
      offset += sizeof(n);
      p.ever_near = bytes[offset] != 0;
      offset += 1;
      p.states.resize(n);
      std::memcpy(p.states.data(),
                  bytes.data() + offset,
                  n * sizeof(NodeState));
      offset += n * sizeof(NodeState);
      for (const auto &node : pair.slave->nodes())
        p.reference.push_back(node.reference);
      for (const auto &face : pair.slave->faces())
      {
        std::array<unsigned int, 4> vertices{};
        for (unsigned int v = 0; v < MasterFace<dim>::n_nodes; ++v)
          vertices[v] = face.nodes[v];
        p.faces.push_back(vertices);
      }
      carried.pairs.push_back(std::move(p));
    }
    return carried;
  }



  template <int dim>
  void
  ContactHandler<dim>::carry_over(const CarriedState &carried)
  {
    AssertThrow(carried.pairs.size() == contact_pairs.size(),
                ExcInternalError());
    constexpr unsigned int n_vertices = MasterFace<dim>::n_nodes;
    for (unsigned int p = 0; p < contact_pairs.size(); ++p)
    {
      auto       &pair = contact_pairs[p];
      const auto &old  = carried.pairs[p];
      pair.ever_near   = old.ever_near;
      // The surface's size scale (its largest element): a node within
      // 1e-8 of it from an old node is that node.
      double size = 0;
      for (const auto &node : pair.slave->nodes())
        size = std::max(size, node.size);
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
      {
        const Vec3<double> &X     = pair.slave->nodes()[k].reference;
        NodeState          &state = pair.committed[k];
        // The old node at the same place (a vertex kept), or the old face
        // the new node lies on (the middle of a refined face), or the
        // nearest old face (a node of a coarsened face: a vertex kept too).
        double       best = std::numeric_limits<double>::max();
        unsigned int same = 0;
        for (unsigned int j = 0; j < old.reference.size(); ++j)
        {
          double d = 0;
          for (unsigned int c = 0; c < 3; ++c)
            d += (X[c] - old.reference[j][c]) * (X[c] - old.reference[j][c]);
          if (d < best)
          {
            best = d;
            same = j;
          }
        }
        if (std::sqrt(best) <= 1e-8 * size)
        {
          state = old.states[same];
          unpair(state);
          continue;
        }
        double       weights[4], nearest = std::numeric_limits<double>::max();
        unsigned int face = 0;
        for (unsigned int f = 0; f < old.faces.size(); ++f)
        {
          Vec3<double> x[4];
          double       N[4];
          for (unsigned int v = 0; v < n_vertices; ++v)
            x[v] = old.reference[old.faces[f][v]];
          const double d = locate<dim>(x, X, N);
          if (d < nearest)
          {
            nearest = d;
            face    = f;
            std::copy(N, N + n_vertices, weights);
          }
        }
        // The state of the face's nearest vertex (status, flags), its
        // fields interpolated.
        unsigned int main = 0;
        for (unsigned int v = 1; v < n_vertices; ++v)
          if (weights[v] > weights[main])
            main = v;
        state = old.states[old.faces[face][main]];
        unpair(state);
        state.slip = state.multiplier = 0;
        state.result.pressure = state.result.gap = 0;
        for (unsigned int c = 0; c < 3; ++c)
          state.point[c] = state.lambda[c] = state.result.traction[c] =
            state.result.normal[c]         = 0;
        for (unsigned int v = 0; v < n_vertices; ++v)
        {
          const NodeState &s = old.states[old.faces[face][v]];
          const double     w = weights[v];
          state.slip += w * s.slip;
          state.multiplier += w * s.multiplier;
          state.result.pressure += w * s.result.pressure;
          state.result.gap += w * s.result.gap;
          for (unsigned int c = 0; c < 3; ++c)
          {
            state.point[c] += w * s.point[c];
            state.lambda[c] += w * s.lambda[c];
            state.result.traction[c] += w * s.result.traction[c];
            state.result.normal[c] += w * s.result.normal[c];
          }
        }
        const double length = norm(state.result.normal);
        if (length > 0)
          state.result.normal = scale(1. / length, state.result.normal);
      }
      pair.current = pair.committed;
    }
  }



  template <int dim>
  void
  ContactHandler<dim>::write_multipliers(
    TrilinosWrappers::MPI::Vector &unknowns) const
  {
    for (const auto &pair : contact_pairs)
    {
      const unsigned int n = pair.enforcement->n_node_unknowns();
      for (unsigned int k = 0; k < pair.n_nodes() && n > 0; ++k)
        if (pair.owned[k])
          for (unsigned int d = 0; d < n; ++d)
            unknowns[pair.first_unknown + n * k + d] =
              pair.committed[k].lambda[d];
    }
    unknowns.compress(VectorOperation::insert);
  }



  template class ContactHandler<2>;
  template class ContactHandler<3>;
} // namespace tribos
