#include <tribos/contact/search/master_exchange.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>

namespace tribos
{
  template <int dim>
  std::size_t
  exchange_master_nodes(ContactPair<dim>                    &pair,
                        const TrilinosWrappers::MPI::Vector &solution,
                        const double                         search_distance,
                        const MPI_Comm                       communicator)
  {
    const auto        &nodes = pair.master->nodes();
    const auto        &faces = pair.master->faces();
    const unsigned int rank  = Utilities::MPI::this_mpi_process(communicator);
    const auto         position = [&](const unsigned int n)
    {
      Vec3<double> x = nodes[n].reference;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] += solution[nodes[n].dofs[d]];
      return x;
    };

    // The own master nodes now (their committed positions are kept by the
    // commit) and their box. The largest face diameter, measured from the
    // own nodes (the other nodes of their faces are on cells at an own
    // vertex: own or ghost cells).
    std::fill(pair.master_known.begin(), pair.master_known.end(), false);
    constexpr double inf = std::numeric_limits<double>::infinity();
    // A box: lower corner, upper corner (empty: lower > upper), h, and the
    // reach beyond the search distance and 3 h that its process asks.
    using Box         = std::array<double, 8>;
    Box        own    = {{inf, inf, inf, -inf, -inf, -inf, 0, 0}};
    double     h      = 0;
    const auto extend = [](Box &box, const Vec3<double> &x)
    {
      for (unsigned int d = 0; d < dim; ++d)
      {
        box[d]     = std::min(box[d], x[d]);
        box[3 + d] = std::max(box[3 + d], x[d]);
      }
    };
    for (const unsigned int n : pair.owned_master_nodes)
    {
      pair.master_positions[n] = position(n);
      pair.master_known[n]     = true;
      extend(own, pair.master_positions[n]);
      for (const unsigned int f : nodes[n].faces)
        for (unsigned int i = 0; i < faces[f].n_nodes(); ++i)
          h = std::max(h,
                       norm(pair.master_positions[n] -
                            position(faces[f].node(i))));
    }

    // The box of the slave nodes this process reads, and h, from all; the
    // box asks for the reach of the elements beyond it too (mortar: 5 slave
    // face sizes, ContactDiscretization::exchange_reach()).
    Box box = {{inf, inf, inf, -inf, -inf, -inf, h, 0}};
    for (const unsigned int k : pair.read_slave_nodes)
    {
      extend(box, pair.slave_positions[k]);
      box[7] = std::max(box[7], pair.discretization->exchange_reach(pair, k));
    }
    const auto boxes = Utilities::MPI::all_gather(communicator, box);
    for (const auto &other : boxes)
      h = std::max(h, other[6]);

    // Whether the box from x to y (a point: x = y) meets the box other
    // widened by its reach.
    const auto within =
      [&](const Box &other, const Vec3<double> &x, const Vec3<double> &y)
    {
      const double reach  = search_distance + 3 * h + other[7];
      bool         inside = true;
      for (unsigned int d = 0; d < dim && inside; ++d)
        inside = y[d] >= other[d] - reach && x[d] <= other[3 + d] + reach;
      return inside;
    };

    // To every other process, the own nodes within its box widened by the
    // reach: number, position now, position at the last commit. A process
    // whose box misses the own nodes' box gets nothing.
    const Vec3<double> own_lo{{own[0], own[1], own[2]}},
      own_hi{{own[3], own[4], own[5]}};
    std::map<unsigned int, std::vector<double>> send;
    for (unsigned int r = 0; r < boxes.size(); ++r)
    {
      if (r == rank || boxes[r][0] > boxes[r][3] ||
          pair.owned_master_nodes.empty() || !within(boxes[r], own_lo, own_hi))
        continue;
      std::vector<double> *records = nullptr;
      for (const unsigned int n : pair.owned_master_nodes)
      {
        const Vec3<double> &x = pair.master_positions[n];
        if (!within(boxes[r], x, x))
          continue;
        if (records == nullptr)
          records = &send[r];
        records->push_back(n);
        for (unsigned int d = 0; d < dim; ++d)
          records->push_back(x[d]);
        for (unsigned int d = 0; d < dim; ++d)
          records->push_back(pair.old_master_positions[n][d]);
      }
    }
    std::size_t n_received = 0;
    for (const auto &[from, records] :
         Utilities::MPI::some_to_some(communicator, send))
    {
      n_received += records.size();
      for (std::size_t i = 0; i < records.size(); i += 1 + 2 * dim)
      {
        const auto n = static_cast<unsigned int>(records[i]);
        for (unsigned int d = 0; d < dim; ++d)
        {
          pair.master_positions[n][d]     = records[i + 1 + d];
          pair.old_master_positions[n][d] = records[i + 1 + dim + d];
        }
        pair.master_known[n] = true;
      }
    }

    // The faces whose nodes are known (a smoothed master: and the nodes
    // beyond its ends, 2D, or around its vertices, 3D), in the order of
    // the surface.
    pair.known_faces.clear();
    for (unsigned int f = 0; f < faces.size(); ++f)
    {
      bool known = true;
      for (unsigned int i = 0; i < faces[f].n_nodes() && known; ++i)
        known = pair.master_known[faces[f].node(i)];
      if (pair.discretization->needs_nodes_beyond())
      {
        for (const int m : faces[f].beyond)
          known = known && (m < 0 || pair.master_known[m]);
        for (const unsigned int m : faces[f].ring)
          known = known && pair.master_known[m];
      }
      pair.face_known[f] = known;
      if (known)
        pair.known_faces.push_back(f);
    }
    pair.search.build(*pair.master, pair.known_faces, pair.master_positions);
    return n_received;
  }

  template std::size_t
  exchange_master_nodes(ContactPair<2> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const double,
                        const MPI_Comm);
  template std::size_t
  exchange_master_nodes(ContactPair<3> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const double,
                        const MPI_Comm);
} // namespace tribos
