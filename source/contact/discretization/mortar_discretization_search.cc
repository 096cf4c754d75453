#include <tribos/contact/contact_pair.h>
#include <tribos/contact/discretization/mortar_discretization.h>

#include <algorithm>
#include <cmath>
#include <limits>

// The search of MortarDiscretization: which master faces each slave node's
// element integrates.
namespace tribos
{
  template <int dim>
  bool
  MortarDiscretization<dim>::pair_node(ContactPair<dim>  &pair,
                                       const unsigned int k)
  {
    find_faces(pair, k);
    // The faces of the hanging nodes whose functions this node carries are
    // its element's too. A hanging node has no element of its own (it
    // stays unpaired); its owner may be another process.
    for (const auto &[h, weight] : pair.carried[k])
    {
      find_faces(pair, h);
      pair.current[h].paired = false;
      pair.current[h].face   = -1;
      auto &state            = pair.current[k];
      if (!state.paired && !faces_of_node[h].empty())
      {
        state.paired   = true;
        state.face     = faces_of_node[h][0];
        state.distance = pair.current[h].distance;
      }
    }
    // A smoothed master's element also reads the faces beyond its faces
    // (their normals): a face first coupled as a neighbour needs its own
    // neighbours once it is the element's.
    bool                      new_coupling = false;
    std::vector<unsigned int> faces;
    element_master_faces(pair, k, faces);
    for (const unsigned int face : faces)
      if (pair.couplings.count({k, face}) == 0 ||
          (smoothed_master &&
           std::any_of(pair.master->faces()[face].neighbours.begin(),
                       pair.master->faces()[face].neighbours.end(),
                       [&](const unsigned int g) {
                         return pair.couplings.count({k, g}) == 0;
                       })))
      {
        new_coupling = true;
        this->insert_couplings(pair, k, face, pair.couplings);
      }
    return new_coupling;
  }



  namespace
  {
    /**
     * The walk over the master faces of one slave node's element: from the
     * master faces closest to given slave points through their neighbours,
     * as long as they overlap the slave face or segment in its projection
     * (walk()). Collects the faces taken in @p found, the smallest distance
     * of a start, and whether one of the faces taken lies within reach
     * along the normal. The reach decides whether the node pairs, not
     * which faces its element integrates: a face dropped or taken by its
     * distance while it overlaps would change the weighted gap by its
     * whole share, and Newton cycles where that happens (issue 18).
     */
    template <int dim>
    struct FaceWalk
    {
      const ContactPair<dim>    &pair;
      std::vector<unsigned int> &found;
      double                     closest = std::numeric_limits<double>::max();
      bool                       reached = false;

      /**
       * From the faces closest to @p starts (@p start_face(point, face,
       * distance): false if it finds none); @p classify(m) is 0 for a
       * face that does not overlap, 1 for one that overlaps but is not
       * taken (it faces away, or lies too deep behind), 2 for one taken.
       * The walk goes on through faces not taken, so that faces beyond
       * them are found however the closest faces lie. False if the search
       * found no face at all.
       */
      template <class Classify, class StartFace>
      bool
      walk(const Vec3<double> *starts,
           const unsigned int  n_starts,
           const Classify     &classify,
           const StartFace    &start_face)
      {
        const auto               &faces = pair.master->faces();
        std::vector<unsigned int> queue;
        for (unsigned int s = 0; s < n_starts; ++s)
        {
          unsigned int face;
          double       distance;
          if (!start_face(starts[s], face, distance))
            continue;
          closest = std::min(closest, distance);
          if (std::find(queue.begin(), queue.end(), face) == queue.end())
            queue.push_back(face);
        }
        if (queue.empty())
          return false;
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
      }
    };



    /**
     * How deep behind a master face a slave face of an open node may lie
     * and still be taken: penetrated, not on the far side of the master.
     * Twice the larger face size covers a meshed initial overlap of about
     * an element; the distance both faces moved in the increment covers a
     * slave pushed through the master in one increment (which a bound of
     * one element size missed: the body passed through with zero force,
     * issue 56). The far side of a master body lies farther behind than
     * this on any mesh that resolves the body's thickness.
     */
    inline double
    behind_reach(const double slave_size,
                 const double master_size,
                 const double motion)
    {
      return 2. * std::max(slave_size, master_size) + motion;
    }



    /** The largest distance the first @p n of @p nodes moved since the last
     * converged increment (@p now and @p old: their positions). */
    template <class Nodes>
    double
    largest_motion(const std::vector<Vec3<double>> &now,
                   const std::vector<Vec3<double>> &old,
                   const Nodes                     &nodes,
                   const unsigned int               n)
    {
      double motion = 0;
      for (unsigned int v = 0; v < n; ++v)
        motion = std::max(motion, norm(now[nodes[v]] - old[nodes[v]]));
      return motion;
    }



    /**
     * Self-contact: whether a master face whose farthest point lies
     * @p gap_max from a slave face (of size @p length) along its normal,
     * @p old_gap_max at the start of the increment (size @p old_length),
     * is the far side of the slave's own body: wholly more than half the
     * slave's size behind it, now and at the start. A face the slave was
     * in front of at the start it has gone through in this increment: a
     * penetration (a first iterate carries a fold's sides deep through).
     */
    inline bool
    far_side(const double gap_max,
             const double length,
             const double old_gap_max,
             const double old_length)
    {
      return gap_max < -0.5 * length && old_gap_max < -0.5 * old_length;
    }



    /** The distance from @p x to master face @p f (its vertices' linear
     * face, clamped). */
    template <int dim>
    double
    face_distance(const ContactPair<dim> &pair,
                  const unsigned int      f,
                  const Vec3<double>     &x)
    {
      const auto  &face = pair.master->faces()[f];
      Vec3<double> y[4];
      for (unsigned int v = 0; v < face.n_vertices; ++v)
        y[v] = pair.master_positions[face.nodes[v]];
      return pair.master->shape().template visit<dim>(
        [&](auto kind)
        {
          using Linear = typename decltype(kind)::Linear;
          return Linear::project(x, y, true).distance;
        });
    }



    /** The start faces of a walk for slave node @p k: the tree's closest
     * face, or for self-contact the closest face within the reach of
     * @p self that @p kind takes (class 2). */
    template <int dim, class Kind>
    auto
    start_faces(const ContactPair<dim>       &pair,
                const SelfContactSearch<dim> &self,
                const unsigned int            k,
                const double                  motion,
                const Kind                   &kind)
    {
      return [&pair, &self, k, motion, &kind](const Vec3<double> &point,
                                              unsigned int       &face,
                                              double             &distance)
      {
        if (!self.active())
        {
          double squared_distance;
          if (!pair.search.closest_face(point, face, squared_distance))
            return false;
          distance = std::sqrt(squared_distance);
          return true;
        }
        const int best = self.closest(
          pair,
          k,
          point,
          motion,
          [&](const unsigned int m, double &d)
          {
            double gap_min;
            if (kind(m, gap_min) != 2)
              return false;
            d = face_distance(pair, m, point);
            return true;
          },
          distance);
        face = best;
        return best >= 0;
      };
    }



    /**
     * 2D: the master segments that overlap slave node @p k's segments in
     * the projection onto their lines, face them and are not too deep
     * behind them (within @p search_distance: reached). False if the
     * search found no face. For self-contact (@p self active) not the
     * node's own neighbourhood nor the far side of its own body.
     */
    bool
    walk_segments(FaceWalk<2>                &walker,
                  const SelfContactSearch<2> &self,
                  const unsigned int          k,
                  const double                search_distance)
    {
      const ContactPair<2> &pair        = walker.pair;
      const auto           &faces       = pair.master->faces();
      const auto           &slave_faces = pair.slave->faces();
      const Vec3<double>    ez{{0., 0., 1.}};
      // A node closed at the last converged step keeps faces however deep
      // an iterate pushes it (it must meet the contact force, not lose the
      // master); an open one only sees faces within behind_reach() behind
      // it (the far side of the master body lies beyond).
      const bool was_closed = pair.committed[k].closed();
      const bool quadratic  = pair.slave->quadratic();
      bool       searched   = false;
      for (const unsigned int f : pair.slave->nodes()[k].faces)
      {
        const Vec3<double> &x_a = pair.slave_positions[slave_faces[f].nodes[0]];
        const Vec3<double> &x_b = pair.slave_positions[slave_faces[f].nodes[1]];
        const Vec3<double>  e   = x_b - x_a;
        const double        length_squared = dot(e, e);
        const Vec3<double>  n_s =
          scale(1. / std::sqrt(length_squared), cross(ez, e));
        const double slave_motion = largest_motion(pair.slave_positions,
                                                   pair.old_slave_positions,
                                                   slave_faces[f].nodes,
                                                   2);
        // Whether master face m overlaps this slave segment in the
        // projection onto its line, faces it and is not too deep behind
        // it (walk's classes); @p gap_min: its closest point along the
        // normal.
        const auto kind = [&](const unsigned int m, double &gap_min)
        {
          const Vec3<double> &y_c = pair.master_positions[faces[m].nodes[0]];
          const Vec3<double> &y_d = pair.master_positions[faces[m].nodes[1]];
          // Self-contact: not the node's own faces, nor their neighbours
          // but across a crease (SelfContactSearch::own()).
          if (self.active() && self.own(k, m) &&
              (self.of_node(pair, k, m) ||
               dot(cross(ez, y_d - y_c), n_s) >
                 SelfContactSearch<2>::crease * norm(y_d - y_c)))
            return 0;
          const double s_c = dot(y_c - x_a, e) / length_squared;
          const double s_d = dot(y_d - x_a, e) / length_squared;
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
          gap_min        = std::numeric_limits<double>::max();
          double gap_max = -gap_min;
          for (const double t : {lo, hi})
          {
            const Vec3<double> y =
              y_c + scale((t - s_c) / (s_d - s_c), y_d - y_c);
            const double gap = dot(y - (x_a + scale(t, e)), n_s);
            gap_min          = std::min(gap_min, gap);
            gap_max          = std::max(gap_max, gap);
          }
          const double length = std::sqrt(length_squared);
          if (self.active())
          {
            // The slave segment and the face at the start of the increment.
            const Vec3<double> &a_old =
              pair.old_slave_positions[slave_faces[f].nodes[0]];
            const Vec3<double> e_old =
              pair.old_slave_positions[slave_faces[f].nodes[1]] - a_old;
            const Vec3<double> n_old =
              scale(1. / norm(e_old), cross(ez, e_old));
            double old_gap_max = -std::numeric_limits<double>::max();
            for (unsigned int v = 0; v < 2; ++v)
              old_gap_max =
                std::max(old_gap_max,
                         dot(pair.old_master_positions[faces[m].nodes[v]] -
                               a_old,
                             n_old));
            return far_side(gap_max, length, old_gap_max, norm(e_old)) ? 1 : 2;
          }
          // Deeper than the reach (at least twice the length: the cheap
          // test first).
          if (!was_closed && gap_max < -2. * length &&
              gap_max <
                -behind_reach(length,
                              norm(y_d - y_c),
                              slave_motion +
                                largest_motion(pair.master_positions,
                                               pair.old_master_positions,
                                               faces[m].nodes,
                                               faces[m].n_vertices)))
            return 1;
          return 2;
        };
        const auto classify = [&](const unsigned int m)
        {
          double    gap_min;
          const int c = kind(m, gap_min);
          if (c == 2)
            walker.reached |=
              gap_min <= std::min(search_distance, std::sqrt(length_squared));
          return c;
        };

        // From the faces closest to the segment's ends and middle through
        // their neighbours, as long as they overlap.
        const Vec3<double> starts[3] = {x_a, x_b, scale(0.5, x_a + x_b)};
        searched |= walker.walk(starts,
                                3,
                                classify,
                                start_faces(pair, self, k, slave_motion, kind));
        if (!searched && !self.active())
          return false;
      }
      return searched;
    }



    /** 3D: as walk_segments(), the overlaps clipped in each slave face's
     * auxiliary plane (as in the element, Mortar3D). */
    bool
    walk_faces(FaceWalk<3>                &walker,
               const SelfContactSearch<3> &self,
               const unsigned int          k,
               const double                search_distance)
    {
      const ContactPair<3> &pair        = walker.pair;
      const auto           &faces       = pair.master->faces();
      const auto           &slave_faces = pair.slave->faces();
      const bool            was_closed  = pair.committed[k].closed();
      bool                  searched    = false;
      for (const unsigned int f : pair.slave->nodes()[k].faces)
      {
        const unsigned int n_s = slave_faces[f].n_vertices;
        Vec3<double>       x[4];
        for (unsigned int v = 0; v < n_s; ++v)
          x[v] = pair.slave_positions[slave_faces[f].nodes[v]];
        const internal::AuxiliaryPlane<double> plane =
          internal::auxiliary_plane(x, n_s);
        double height_min = std::numeric_limits<double>::max(),
               height_max = -height_min;
        for (unsigned int v = 0; v < n_s; ++v)
        {
          height_min = std::min(height_min, dot(x[v] - plane.x0, plane.n0));
          height_max = std::max(height_max, dot(x[v] - plane.x0, plane.n0));
        }
        const double length       = std::sqrt(std::abs(plane.area));
        const double slave_motion = largest_motion(pair.slave_positions,
                                                   pair.old_slave_positions,
                                                   slave_faces[f].nodes,
                                                   n_s);
        // Self-contact: the slave face at the start of the increment.
        double                           old_height_min = 0, old_length = 0;
        internal::AuxiliaryPlane<double> old_plane;
        if (self.active())
        {
          Vec3<double> x_old[4];
          for (unsigned int v = 0; v < n_s; ++v)
            x_old[v] = pair.old_slave_positions[slave_faces[f].nodes[v]];
          old_plane      = internal::auxiliary_plane(x_old, n_s);
          old_length     = std::sqrt(std::abs(old_plane.area));
          old_height_min = std::numeric_limits<double>::max();
          for (unsigned int v = 0; v < n_s; ++v)
            old_height_min =
              std::min(old_height_min,
                       dot(x_old[v] - old_plane.x0, old_plane.n0));
        }

        // Whether master face m overlaps this slave face in the plane and
        // is not too deep behind it (as in 2D).
        const auto kind = [&](const unsigned int m, double &gap_min)
        {
          const unsigned int n_m = faces[m].n_vertices;
          Vec3<double>       y[4];
          gap_min        = std::numeric_limits<double>::max();
          double gap_max = -gap_min;
          for (unsigned int v = 0; v < n_m; ++v)
          {
            y[v]               = pair.master_positions[faces[m].nodes[v]];
            const double above = dot(y[v] - plane.x0, plane.n0);
            gap_min            = std::min(gap_min, above - height_max);
            gap_max            = std::max(gap_max, above - height_min);
          }
          // Self-contact: as in 2D.
          if (self.active() && self.own(k, m) &&
              (self.of_node(pair, k, m) ||
               dot(internal::auxiliary_plane(y, n_m).n0, plane.n0) >
                 SelfContactSearch<3>::crease))
            return 0;
          if (!internal::overlaps_in_plane(plane, y, n_m))
            return 0;
          if (self.active())
          {
            double old_gap_max = -std::numeric_limits<double>::max();
            for (unsigned int v = 0; v < n_m; ++v)
              old_gap_max =
                std::max(old_gap_max,
                         dot(pair.old_master_positions[faces[m].nodes[v]] -
                               old_plane.x0,
                             old_plane.n0) -
                           old_height_min);
            return far_side(gap_max, length, old_gap_max, old_length) ? 1 : 2;
          }
          if (!was_closed && gap_max < -2. * length &&
              gap_max <
                -behind_reach(
                  length,
                  std::sqrt(std::abs(internal::auxiliary_plane(y, n_m).area)),
                  slave_motion + largest_motion(pair.master_positions,
                                                pair.old_master_positions,
                                                faces[m].nodes,
                                                n_m)))
            return 1;
          return 2;
        };
        const auto classify = [&](const unsigned int m)
        {
          double    gap_min;
          const int c = kind(m, gap_min);
          if (c == 2)
            walker.reached |= gap_min <= std::min(search_distance, length);
          return c;
        };

        // From the faces closest to its vertices and its centre.
        Vec3<double> starts[5];
        std::copy(x, x + n_s, starts);
        starts[n_s] = plane.x0;
        searched |= walker.walk(starts,
                                n_s + 1,
                                classify,
                                start_faces(pair, self, k, slave_motion, kind));
        if (!searched && !self.active())
          return false;
      }
      return searched;
    }



    /**
     * How deep slave node @p k lies inside the master: its distance to the
     * closest master point if it lies behind the face there (within 25
     * degrees of the inward normal: beside the end of a master surface is
     * not inside), else 0.
     */
    template <int dim>
    double
    depth_inside(const ContactPair<dim> &pair, const unsigned int k)
    {
      const Vec3<double> &x = pair.slave_positions[k];
      unsigned int        m;
      double              squared_distance;
      Vec3<double>        closest;
      if (!pair.search.closest_face(x, m, squared_distance, &closest) ||
          squared_distance == 0)
        return 0;
      const auto  &face = pair.master->faces()[m];
      Vec3<double> y[4];
      for (unsigned int v = 0; v < face.n_vertices; ++v)
        y[v] = pair.master_positions[face.nodes[v]];
      Vec3<double> normal;
      if constexpr (dim == 2)
        normal = cross(Vec3<double>{{0., 0., 1.}}, y[1] - y[0]);
      else
        normal = internal::auxiliary_plane(y, face.n_vertices).n0;
      const double distance = std::sqrt(squared_distance);
      return dot(x - closest, normal) < -0.9 * distance * norm(normal) ?
               distance :
               0;
    }
  } // namespace



  template <int dim>
  void
  MortarDiscretization<dim>::find_faces(ContactPair<dim>  &pair,
                                        const unsigned int k)
  {
    NodeState &state = pair.current[k];
    auto      &found = faces_of_node[k];
    found.clear();
    state.paired   = false;
    state.face     = -1;
    state.distance = std::numeric_limits<double>::quiet_NaN();
    FaceWalk<dim> walker{pair, found};
    bool          searched;
    if constexpr (dim == 2)
      searched =
        walk_segments(walker, self_search, k, parameters.search_distance);
    else
      searched = walk_faces(walker, self_search, k, parameters.search_distance);
    if (!searched)
      return;
    // Beyond the search distance no gap is known (see candidate_faces()).
    state.distance = walker.closest <= parameters.search_distance ?
                       walker.closest :
                       std::numeric_limits<double>::quiet_NaN();
    // A node inside the master has a negative distance: reported as an open
    // gap of +0.29 it read as clear of a master it had passed into. Its
    // depth is at least walker.closest: beyond the search distance the
    // query is skipped. (A self pair's closest face is the node's own.)
    if (std::isfinite(state.distance) && !self_search.active())
    {
      const double depth = depth_inside(pair, k);
      if (depth > 0 && depth <= parameters.search_distance)
        state.distance = -depth;
    }
    if (!walker.reached)
      found.clear();
    if (!found.empty())
    {
      state.paired = true;
      state.face   = found[0];
    }
  }



  template class MortarDiscretization<2>;
  template class MortarDiscretization<3>;
} // namespace tribos
