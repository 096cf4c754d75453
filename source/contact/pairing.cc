#include <tribos/base/timing.h>
#include <tribos/contact/master_exchange.h>
#include <tribos/contact/mortar_element_3d.h>
#include <tribos/contact/pairing.h>
#include <tribos/contact/smoothed_segment.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace tribos
{
  namespace
  {
    /**
     * Width, in local coordinates, of the band beyond the end of a master
     * surface in which a slave node still sees the end face's extension.
     */
    constexpr double edge_band = 0.1;
  } // namespace



  template <int dim>
  void
  smoothed_stencil(const ContactPair<dim>          &pair,
                   const unsigned int               face,
                   const std::vector<Vec3<double>> &positions,
                   Vec3<double>                    *x,
                   bool                            *has)
  {
    const auto &f = pair.master->faces()[face];
    x[0]          = positions[f.nodes[0]];
    x[1]          = positions[f.nodes[1]];
    for (unsigned int side = 0; side < 2; ++side)
    {
      has[side]   = f.beyond[side] >= 0;
      x[2 + side] = has[side] ? positions[f.beyond[side]] : x[side];
    }
  }



  template <int dim>
  Pairing<dim>::Pairing(const Parameters::Contact &parameters,
                        const MPI_Comm             communicator)
    : parameters(parameters)
    , communicator(communicator)
  {
  }



  template <int dim>
  bool
  Pairing<dim>::update(ContactPair<dim>                    &pair,
                       const TrilinosWrappers::MPI::Vector &solution)
  {
    const auto &slave_nodes = pair.slave->nodes();
    for (const unsigned int k : pair.read_slave_nodes)
    {
      pair.slave_positions[k] = slave_nodes[k].reference;
      for (unsigned int d = 0; d < dim; ++d)
        pair.slave_positions[k][d] += solution[slave_nodes[k].dofs[d]];
    }
    const unsigned int n_unknowns = pair.enforcement->n_node_unknowns();
    // The enforcement's unknowns are unknowns of the system: read those
    // of the own nodes (only their elements use them).
    if (n_unknowns > 0)
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        for (unsigned int d = 0; d < n_unknowns && pair.owned[k]; ++d)
          pair.current[k].lambda[d] =
            solution[pair.first_unknown + n_unknowns * k + d];

    if (pair.rigid)
    {
      for (unsigned int k = 0; k < pair.n_nodes(); ++k)
        pair.current[k].paired = pair.owned[k] && !pair.excluded[k];
      return false;
    }
    const auto start = std::chrono::steady_clock::now();
    exchanged.values += exchange_master_nodes(pair,
                                              solution,
                                              parameters.search_distance,
                                              communicator);
    exchanged.seconds += seconds_since(start);

    bool                      new_coupling = false;
    std::vector<unsigned int> faces;
    for (unsigned int k = 0; k < pair.n_nodes(); ++k)
    {
      if (!pair.owned[k] || pair.excluded[k])
        continue;
      if (pair.mortar)
      {
        pair_mortar(pair, k);
        // The faces of the hanging nodes whose functions this node carries
        // are its element's too. A hanging node has no element of its own
        // (it stays unpaired); its owner may be another process.
        for (const auto &[h, weight] : pair.carried[k])
        {
          pair_mortar(pair, h);
          pair.current[h].paired = false;
          pair.current[h].face   = -1;
          auto &state            = pair.current[k];
          if (!state.paired && !pair.mortar_faces[h].empty())
          {
            state.paired   = true;
            state.face     = pair.mortar_faces[h][0];
            state.distance = pair.current[h].distance;
          }
        }
        // A smoothed master's element also reads the faces beyond its
        // faces (their normals): a face first coupled as a neighbour needs
        // its own neighbours once it is the element's.
        pair.mortar_master_faces(k, faces);
        for (const unsigned int face : faces)
          if (pair.couplings.count({k, face}) == 0 ||
              (pair.smoothed &&
               std::any_of(pair.master->faces()[face].neighbours.begin(),
                           pair.master->faces()[face].neighbours.end(),
                           [&](const unsigned int g) {
                             return pair.couplings.count({k, g}) == 0;
                           })))
          {
            new_coupling = true;
            pair.insert_couplings(k, face, pair.couplings);
          }
        continue;
      }
      if (pair.smoothed)
        pair_smoothed(pair, k);
      else
        pair_faceted(pair, k);

      const int face = pair.current[k].face;
      if (face >= 0 && pair.couplings.count({k, face}) == 0)
      {
        new_coupling = true;
        pair.insert_couplings(k, face, pair.couplings);
      }
    }
    return new_coupling;
  }



  template <int dim>
  void
  Pairing<dim>::pair_faceted(ContactPair<dim> &pair, const unsigned int k) const
  {
    NodeState          &state = pair.current[k];
    const Vec3<double> &x     = pair.slave_positions[k];
    const auto         &faces = pair.master->faces();
    const auto project_onto   = [&](const unsigned int f, const bool clamp)
    {
      Vec3<double> xm[4];
      for (unsigned int v = 0; v < MasterFace<dim>::n_nodes; ++v)
        xm[v] = pair.master_positions[faces[f].nodes[v]];
      return project<dim>(x, xm, clamp);
    };

    // Keep the face of the last evaluation while the node projects onto it
    // or onto its extension within a small band: over a master vertex (a
    // concave kink of the deformed master) the closest face would otherwise
    // flip between iterations and Newton would cycle between two smooth
    // residuals.
    // A face that is not known lies beyond the search distance.
    if (state.paired && pair.face_known[state.face])
    {
      const Projection kept = project_onto(state.face, false);
      bool             near = kept.distance <= parameters.search_distance;
      for (unsigned int c = 0; c < dim - 1; ++c)
        near = near && std::abs(kept.xi[c]) <= 1. + edge_band;
      if (near)
      {
        state.projection = kept;
        return;
      }
    }
    state.paired   = false;
    state.face     = -1;
    state.distance = std::numeric_limits<double>::quiet_NaN();
    const std::vector<unsigned int> candidates =
      candidate_faces(pair, x, state);
    if (candidates.empty())
      return;

    // Exact projection on the candidate and its neighbours: prefer a
    // projection inside a face (the closest such), else the closest clamped
    // one.
    bool   best_inside   = false;
    double best_distance = std::numeric_limits<double>::max();
    for (const unsigned int f : candidates)
    {
      const Projection p      = project_onto(f, true);
      const bool       inside = p.inside();
      if ((inside && !best_inside) ||
          (inside == best_inside && p.distance < best_distance))
      {
        best_inside      = inside;
        best_distance    = p.distance;
        state.face       = f;
        state.projection = p;
      }
    }
    // A projection clamped at an edge where the master surface ends: within
    // a small band beyond the edge the node sees the face's extension (a
    // smooth residual for nodes flush with the end of the master); farther
    // out it has slid off: no contact.
    state.paired = true;
    bool at_end  = false;
    for (unsigned int c = 0; c < dim - 1; ++c)
      if (state.projection.clamped[c] != 0 &&
          !faces[state.face].continues[c][state.projection.clamped[c] > 0])
        at_end = true;
    if (at_end)
    {
      const Projection extended = project_onto(state.face, false);
      for (unsigned int c = 0; c < dim - 1; ++c)
        if (std::abs(extended.xi[c]) > 1. + edge_band)
          state.paired = false;
      state.projection = extended;
    }
  }



  template <int dim>
  std::vector<unsigned int>
  Pairing<dim>::candidate_faces(const ContactPair<dim> &pair,
                                const Vec3<double>     &x,
                                NodeState              &state) const
  {
    unsigned int closest;
    double       squared_distance;
    if (!pair.search.closest_face(x, closest, squared_distance))
      return {};
    // Beyond the search distance the master is not looked for (the faces
    // there are not all known under MPI): no gap either.
    state.distance = std::sqrt(squared_distance);
    if (state.distance > parameters.search_distance)
    {
      state.distance = std::numeric_limits<double>::quiet_NaN();
      return {};
    }
    std::vector<unsigned int> candidates(1, closest);
    for (const unsigned int g : pair.master->faces()[closest].neighbours)
      if (pair.face_known[g])
        candidates.push_back(g);
    return candidates;
  }



  template <int dim>
  void
  Pairing<dim>::pair_smoothed(ContactPair<dim>  &pair,
                              const unsigned int k) const
  {
    NodeState          &state = pair.current[k];
    const Vec3<double> &x     = pair.slave_positions[k];
    const auto         &faces = pair.master->faces();

    // The smoothed projection onto one face: inside, or on the extension
    // beyond a free end of the master within the edge band.
    const auto try_face = [&](const unsigned int f, Projection &p) -> int
    {
      Vec3<double> xm[4];
      bool         has[2];
      smoothed_stencil(pair, f, pair.master_positions, xm, has);
      double xi;
      if (!SmoothedSegment::project(x, xm, has, xi))
        return 0;
      const double xbar[2] = {0.5 * (1 - xi) * xm[0][0] +
                                0.5 * (1 + xi) * xm[1][0],
                              0.5 * (1 - xi) * xm[0][1] +
                                0.5 * (1 + xi) * xm[1][1]};
      p                    = Projection();
      p.xi[0]              = xi;
      p.distance           = std::hypot(x[0] - xbar[0], x[1] - xbar[1]);
      if (std::abs(xi) <= 1.)
        return 2;
      const int side = xi > 0 ? 1 : 0;
      p.clamped[0]   = xi > 0 ? 1 : -1;
      if (!faces[f].continues[0][side] && std::abs(xi) <= 1. + edge_band)
        return 1;
      return 0;
    };

    // The face of the last evaluation while the node still projects onto
    // it: the projection is continuous across vertices, so this only saves
    // the search.
    if (state.paired && pair.face_known[state.face])
    {
      Projection p;
      const int  kind = try_face(state.face, p);
      if (kind > 0 && p.distance <= parameters.search_distance)
      {
        state.projection = p;
        return;
      }
    }
    state.paired         = false;
    state.face           = -1;
    state.distance       = std::numeric_limits<double>::quiet_NaN();
    int    best_kind     = 0;
    double best_distance = std::numeric_limits<double>::max();
    for (const unsigned int f : candidate_faces(pair, x, state))
    {
      Projection p;
      const int  kind = try_face(f, p);
      if (kind > best_kind ||
          (kind == best_kind && kind > 0 && p.distance < best_distance))
      {
        best_kind        = kind;
        best_distance    = p.distance;
        state.face       = f;
        state.projection = p;
      }
    }
    state.paired = best_kind > 0;
  }

  template <int dim>
  void
  Pairing<dim>::pair_mortar(ContactPair<dim> &pair, const unsigned int k) const
  {
    NodeState &state = pair.current[k];
    auto      &found = pair.mortar_faces[k];
    found.clear();
    state.paired        = false;
    state.face          = -1;
    state.distance      = std::numeric_limits<double>::quiet_NaN();
    const auto &faces   = pair.master->faces();
    double      closest = std::numeric_limits<double>::max();
    // Whether one of the faces found lies within reach along the normal.
    // The reach decides whether the node pairs, not which faces its
    // element integrates: a face dropped or taken by its distance while
    // it overlaps would change the weighted gap by its whole share, and
    // Newton cycles where that happens (issue 18).
    bool reached = false;
    // From the master faces closest to the slave points @p starts through
    // their neighbours, as long as they overlap the slave face or segment
    // in its projection; @p classify(m) is 0 for a face that does not
    // overlap, 1 for one that overlaps but is not taken (it faces away, or
    // lies too deep behind), 2 for one taken. The walk goes on through
    // faces not taken, so that faces beyond them are found however the
    // closest faces lie. False if the search found no face at all.
    const auto walk = [&](const std::initializer_list<Vec3<double>> starts,
                          const auto                               &classify)
    {
      std::vector<unsigned int> queue;
      for (const Vec3<double> &point : starts)
      {
        unsigned int face;
        double       squared_distance;
        if (!pair.search.closest_face(point, face, squared_distance))
          return false;
        closest = std::min(closest, std::sqrt(squared_distance));
        if (std::find(queue.begin(), queue.end(), face) == queue.end())
          queue.push_back(face);
      }
      const unsigned int n_start = queue.size();
      for (unsigned int i = 0; i < queue.size(); ++i)
      {
        const unsigned int m       = queue[i];
        const int          class_m = classify(m);
        if (class_m == 2 &&
            std::find(found.begin(), found.end(), m) == found.end())
          found.push_back(m);
        if (class_m > 0 || i < n_start)
          for (const unsigned int g : faces[m].neighbours)
            if (pair.face_known[g] &&
                std::find(queue.begin(), queue.end(), g) == queue.end())
              queue.push_back(g);
      }
      return true;
    };
    if constexpr (dim == 2)
    {
      const auto        &slave_faces = pair.slave->faces();
      const Vec3<double> ez{{0., 0., 1.}};
      // A node closed at the last converged step keeps faces however deep
      // an iterate pushes it (it must meet the contact force, not lose the
      // master); an open one only sees faces less than a segment length
      // behind it (steep slave segments would otherwise pair with faces
      // beside them).
      const bool was_closed = pair.committed[k].closed();
      const bool quadratic  = pair.slave->quadratic();
      for (const unsigned int f : pair.slave->nodes()[k].faces)
      {
        const Vec3<double> &x_a = pair.slave_positions[slave_faces[f].nodes[0]];
        const Vec3<double> &x_b = pair.slave_positions[slave_faces[f].nodes[1]];
        const Vec3<double>  e   = x_b - x_a;
        const double        length_squared = dot(e, e);
        const Vec3<double>  n_s =
          scale(1. / std::sqrt(length_squared), cross(ez, e));

        // Whether master face m overlaps this slave segment in the
        // projection onto its line, faces it and is not too deep behind
        // it (walk's classes).
        const auto classify = [&](const unsigned int m)
        {
          const Vec3<double> &y_c = pair.master_positions[faces[m].nodes[0]];
          const Vec3<double> &y_d = pair.master_positions[faces[m].nodes[1]];
          const double        s_c = dot(y_c - x_a, e) / length_squared;
          const double        s_d = dot(y_d - x_a, e) / length_squared;
          if (std::abs(s_c - s_d) < 1e-12)
            return 0;
          // Quadratic segments are curves, the chords only approximate
          // where they overlap: a face found late (or lost) would change
          // the element's weights by a jump. Faces a quarter of the
          // segment beyond its chord are taken as well; the element skips
          // those that do not overlap.
          const double margin = quadratic ? 0.25 : 0.;
          const double lo     = std::max(-margin, std::min(s_c, s_d));
          const double hi     = std::min(1. + margin, std::max(s_c, s_d));
          if (hi <= lo)
            return 0;
          // Faces steeper than 75 degrees to the slave segment cannot
          // carry its contact (the sides of a body above the slave).
          const Vec3<double> n_m = cross(ez, y_d - y_c);
          if (dot(n_m, n_s) >= -0.25 * norm(n_m))
            return 1;
          // Within reach: closer than the search distance and the
          // segment's length (a node whose faces are all farther cannot
          // close within an increment; it is paired again when it comes
          // near). Not wholly more than that behind the slave (the far
          // side of a thin master).
          double gap_min = std::numeric_limits<double>::max(),
                 gap_max = -gap_min;
          for (const double t : {lo, hi})
          {
            const Vec3<double> y =
              y_c + scale((t - s_c) / (s_d - s_c), y_d - y_c);
            const double gap = dot(y - (x_a + scale(t, e)), n_s);
            gap_min          = std::min(gap_min, gap);
            gap_max          = std::max(gap_max, gap);
          }
          const double length = std::sqrt(length_squared);
          if (gap_max < -length && !was_closed)
            return 1;
          reached |= gap_min <= std::min(parameters.search_distance, length);
          return 2;
        };

        // From the faces closest to the segment's ends and middle through
        // their neighbours, as long as they overlap.
        if (!walk({x_a, x_b, scale(0.5, x_a + x_b)}, classify))
          return;
      }
    }
    else
    {
      const auto &slave_faces = pair.slave->faces();
      const bool  was_closed  = pair.committed[k].closed();
      for (const unsigned int f : pair.slave->nodes()[k].faces)
      {
        // The face's auxiliary plane, as in the element (Mortar3D).
        Vec3<double> x[4];
        for (unsigned int v = 0; v < 4; ++v)
          x[v] = pair.slave_positions[slave_faces[f].nodes[v]];
        const internal::AuxiliaryPlane<double> plane =
          internal::auxiliary_plane(x);
        double height_min = std::numeric_limits<double>::max(),
               height_max = -height_min;
        for (unsigned int v = 0; v < 4; ++v)
        {
          height_min = std::min(height_min, dot(x[v] - plane.x0, plane.n0));
          height_max = std::max(height_max, dot(x[v] - plane.x0, plane.n0));
        }
        const double length = std::sqrt(std::abs(plane.area));

        // Whether master face m overlaps this slave face in the plane and
        // is not too deep behind it (as in 2D).
        const auto classify = [&](const unsigned int m)
        {
          Vec3<double> y[4];
          double       gap_min = std::numeric_limits<double>::max(),
                 gap_max       = -gap_min;
          for (unsigned int v = 0; v < 4; ++v)
          {
            y[v]               = pair.master_positions[faces[m].nodes[v]];
            const double above = dot(y[v] - plane.x0, plane.n0);
            gap_min            = std::min(gap_min, above - height_max);
            gap_max            = std::max(gap_max, above - height_min);
          }
          if (!internal::overlaps_in_plane(plane, y))
            return 0;
          if (gap_max < -length && !was_closed)
            return 1;
          reached |= gap_min <= std::min(parameters.search_distance, length);
          return 2;
        };

        if (!walk({x[0], x[1], x[2], x[3], plane.x0}, classify))
          return;
      }
    }
    // Beyond the search distance no gap is known (see candidate_faces()).
    state.distance = closest <= parameters.search_distance ?
                       closest :
                       std::numeric_limits<double>::quiet_NaN();
    if (!reached)
      found.clear();
    if (!found.empty())
    {
      state.paired = true;
      state.face   = found[0];
    }
  }

  template class Pairing<2>;
  template class Pairing<3>;
  template void
  smoothed_stencil(const ContactPair<2> &,
                   const unsigned int,
                   const std::vector<Vec3<double>> &,
                   Vec3<double> *,
                   bool *);
  template void
  smoothed_stencil(const ContactPair<3> &,
                   const unsigned int,
                   const std::vector<Vec3<double>> &,
                   Vec3<double> *,
                   bool *);
} // namespace tribos
