#include <tribos/base/exceptions.h>
#include <tribos/contact/element/mortar_integrals.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "mortar_element_3d_internal.h"

namespace tribos
{
  using namespace internal::Mortar3DImplementation;



  namespace
  {
    /**
     * The AD number of one (slave face, master face) overlap: the 4 + 4
     * nodes' coordinates. Its integrals are carried over to the node's
     * ContactAD afterwards: the quadrature, the clipping and the inverse
     * maps, most of the element's work, run on 24 derivatives instead of
     * the node's 80-150.
     */
    using FaceAD = MortarOverlapCache::FaceAD;

    template <typename Number>
    using Point = std::array<Number, 2>;

    using internal::counter_clockwise;

    /** The pieces of a face of @p n nodes into @p pieces; their number. */
    unsigned int
    face_pieces(const unsigned int n, Piece *pieces)
    {
      if (n == 4)
        pieces[0] = {4, {0, 1, 2, 3}, {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}}};
      else if (n == 3)
        pieces[0] = {3, {0, 1, 2, 0}, {{0, 0}, {1, 0}, {0, 1}, {0, 0}}};
      else if (n == 9)
      {
        // Lexicographic as the face, so their normals are the face's.
        pieces[0] = {4, {0, 4, 6, 8}, {{-1, -1}, {0, -1}, {-1, 0}, {0, 0}}};
        pieces[1] = {4, {4, 1, 8, 7}, {{0, -1}, {1, -1}, {0, 0}, {1, 0}}};
        pieces[2] = {4, {6, 8, 2, 5}, {{-1, 0}, {0, 0}, {-1, 1}, {0, 1}}};
        pieces[3] = {4, {8, 7, 5, 3}, {{0, 0}, {1, 0}, {0, 1}, {1, 1}}};
        return 4;
      }
      else
      {
        // Counter-clockwise as the face: the corners' and the middle one.
        pieces[0] = {3, {0, 3, 5, 0}, {{0, 0}, {.5, 0}, {0, .5}, {0, 0}}};
        pieces[1] = {3, {3, 1, 4, 0}, {{.5, 0}, {1, 0}, {.5, .5}, {0, 0}}};
        pieces[2] = {3, {5, 4, 2, 0}, {{0, .5}, {.5, .5}, {0, 1}, {0, 0}}};
        pieces[3] = {3, {3, 4, 5, 0}, {{.5, 0}, {.5, .5}, {0, .5}, {0, 0}}};
        return 4;
      }
      return 1;
    }

    /**
     * The coordinates xi of the point @p p in the map of the face @p P
     * of @p n nodes (bilinear quadrilateral, lexicographic; or linear
     * triangle) in the plane: Newton from the centre on the values, then one
     * Newton step in AD numbers from the converged values, which gives the
     * derivatives of the exact inverse (at a root, the step's derivative is
     * -J^-1 times that of the residual: the implicit function theorem).
     */
    void
    inverse_map(const Point<FaceAD> *P,
                const unsigned int   n,
                const Point<FaceAD> &p,
                FaceAD              *xi)
    {
      double x[2] = {0., 0.};
      if (n == 3)
        x[0] = x[1] = 1. / 3.;
      double N[4], dN[4][2];
      for (unsigned int iteration = 0; iteration < 30; ++iteration)
      {
        face_shape(n, x, N, dN);
        double r[2], J[2][2];
        for (unsigned int a = 0; a < 2; ++a)
        {
          r[a]    = -p[a].val();
          J[a][0] = J[a][1] = 0.;
          for (unsigned int k = 0; k < n; ++k)
          {
            r[a] += N[k] * P[k][a].val();
            for (unsigned int b = 0; b < 2; ++b)
              J[a][b] += dN[k][b] * P[k][a].val();
          }
        }
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (std::abs(det) < 1e-300)
          break;
        const double d0 = (J[1][1] * r[0] - J[0][1] * r[1]) / det;
        const double d1 = (J[0][0] * r[1] - J[1][0] * r[0]) / det;
        x[0] -= d0;
        x[1] -= d1;
        if (std::max(std::abs(d0), std::abs(d1)) < 1e-14)
          break;
      }
      // The AD step: r's value is zero to round-off, so J^-1 r is the
      // derivative of the root; J is used at its value.
      face_shape(n, x, N, dN);
      FaceAD r[2];
      double J[2][2];
      for (unsigned int a = 0; a < 2; ++a)
      {
        r[a]    = -p[a];
        J[a][0] = J[a][1] = 0.;
        for (unsigned int k = 0; k < n; ++k)
        {
          r[a] += N[k] * P[k][a];
          for (unsigned int b = 0; b < 2; ++b)
            J[a][b] += dN[k][b] * P[k][a].val();
        }
      }
      const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      xi[0]            = x[0];
      xi[1]            = x[1];
      if (std::abs(det) < 1e-300)
        return;
      xi[0] -= (J[1][1] * r[0] - J[0][1] * r[1]) / det;
      xi[1] -= (J[0][0] * r[1] - J[1][0] * r[0]) / det;
    }

    /**
     * A rule on the triangle exact to degree 8, for the products of two
     * biquadratic functions (degree 4 in each direction): 5 x 5 Gauss
     * points on the square collapsed onto the triangle (Duffy: x = u (1 -
     * v), y = v, dx dy = (1 - v) du dv takes degree 8 to degree 8 in u and
     * 9 in v, which 5 points integrate exactly).
     */
    const std::vector<TrianglePoint> &
    biquadratic_triangle_rule()
    {
      static const std::vector<TrianglePoint> rule = []()
      {
        const double               x[5] = {-0.9061798459386639927976,
                                           -0.5384693101056830910363,
                                           0.,
                                           0.5384693101056830910363,
                                           0.9061798459386639927976};
        const double               w[5] = {0.2369268850561890875143,
                                           0.4786286704993664680413,
                                           0.5688888888888888888889,
                                           0.4786286704993664680413,
                                           0.2369268850561890875143};
        std::vector<TrianglePoint> points;
        for (unsigned int a = 0; a < 5; ++a)
          for (unsigned int b = 0; b < 5; ++b)
          {
            const double u = 0.5 * (1. + x[a]), v = 0.5 * (1. + x[b]);
            // Weights on [0, 1]^2 (1/4 w_a w_b), Jacobian 1 - v, over the
            // triangle's area 1/2.
            points.push_back({{(1. - u) * (1. - v), u * (1. - v), v},
                              0.5 * w[a] * w[b] * (1. - v)});
          }
        return points;
      }();
      return rule;
    }

    /**
     * The overlap of the slave piece @p ps (of a face of @p n_s nodes) of
     * @p plane with the master piece @p pm (of a face of @p n_m nodes) with
     * nodes @p Y: its area and the integrals of the slave face's functions
     * against the slave face's (@p entry.slave[i n_s + k] = int N_i N_k)
     * and the master face's (@p entry.master[i n_m + l] = int N_i N_l)
     * over it. Returns false if they do not overlap.
     */
    bool
    overlap_integrals(const Plane<FaceAD>       &plane,
                      const Piece               &ps,
                      const unsigned int         n_s,
                      const Vec3<FaceAD>        *Y,
                      const Piece               &pm,
                      const unsigned int         n_m,
                      MortarOverlapCache::Entry &entry)
    {
      Point<FaceAD> Q[4], Q_ccw[4], polygon[8];
      for (unsigned int k = 0; k < pm.n; ++k)
        Q[k] = plane.project(Y[k]);
      for (unsigned int k = 0; k < pm.n; ++k)
        Q_ccw[k] = Q[internal::clockwise(pm.n, k)];
      if (internal::polygon_area(Q_ccw, pm.n).val() <= 0)
        return false;
      const unsigned int n =
        internal::clip_polygon(Q_ccw, pm.n, plane.P_ccw, ps.n, polygon);
      if (n < 3)
        return false;
      entry.area = internal::polygon_area(polygon, n);
      if (entry.area.val() <= 1e-12 * plane.area.val())
        return false;
      entry.slave.assign(n_s * n_s, FaceAD(0.));
      entry.master.assign(n_s * n_m, FaceAD(0.));
      // The clip polygon is convex: a fan of triangles from its first
      // vertex.
      const Point<FaceAD> &v_0 = polygon[0];
      for (unsigned int i = 1; i + 1 < n; ++i)
      {
        const Point<FaceAD> &v_1 = polygon[i];
        const Point<FaceAD> &v_2 = polygon[i + 1];
        const FaceAD triangle = 0.5 * ((v_1[0] - v_0[0]) * (v_2[1] - v_0[1]) -
                                       (v_1[1] - v_0[1]) * (v_2[0] - v_0[0]));
        if (triangle.val() <= 0)
          continue;
        // The 7-point rule integrates the products of linear and of
        // six-node triangle functions exactly on flat faces (degree <= 4),
        // nine-node quadrilaterals' need degree 8.
        static const std::vector<TrianglePoint> seven_points(
          std::begin(triangle_rule),
          std::end(triangle_rule));
        const std::vector<TrianglePoint> &rule =
          (n_s == 9 || n_m == 9) ? biquadratic_triangle_rule() : seven_points;
        for (const TrianglePoint &t : rule)
        {
          Point<FaceAD> p;
          for (unsigned int d = 0; d < 2; ++d)
            p[d] = t.l[0] * v_0[d] + t.l[1] * v_1[d] + t.l[2] * v_2[d];
          FaceAD x_s[2], x_m[2], xi_s[2], xi_m[2], N_s[max_face_nodes],
            N_m[max_face_nodes], dN[max_face_nodes][2];
          inverse_map(plane.P, ps.n, p, x_s);
          inverse_map(Q, pm.n, p, x_m);
          face_coordinates(ps, x_s, xi_s);
          face_coordinates(pm, x_m, xi_m);
          face_shape(n_s, xi_s, N_s, dN);
          face_shape(n_m, xi_m, N_m, dN);
          const FaceAD weight = t.weight * triangle;
          for (unsigned int i = 0; i < n_s; ++i)
          {
            const FaceAD w_i = weight * N_s[i];
            for (unsigned int k = 0; k < n_s; ++k)
              entry.slave[i * n_s + k] += w_i * N_s[k];
            for (unsigned int k = 0; k < n_m; ++k)
              entry.master[i * n_m + k] += w_i * N_m[k];
          }
        }
      }
      return true;
    }

    /** A master face's overlaps with a slave face, their integrals summed
     * and carried over to the node's AD numbers. */
    struct Overlap
    {
      unsigned int face;
      AD           area, slave[max_face_nodes][max_face_nodes],
        master[max_face_nodes][max_face_nodes];
    };



    /**
     * An overlap's integral @p x (in its own 24 coordinates: slave piece
     * @p ps's nodes, then from 12 on master piece @p pm's, by their
     * positions in faces @p q and @p c) in the node's numbers of
     * @p integrals.
     */
    AD
    carry(const FaceAD             &x,
          const MortarIntegrals<3> &integrals,
          const MortarFace3D       &q,
          const Piece              &ps,
          const MortarFace3D       &c,
          const Piece              &pm)
    {
      AD y(integrals.derivatives ? integrals.n_out : 0, x.val());
      if (integrals.derivatives && x.size() > 0)
      {
        for (unsigned int t = 0; t < 3 * ps.n; ++t)
          y.fastAccessDx(3 * q[ps.node[t / 3]] + t % 3) = x.dx(t);
        for (unsigned int t = 0; t < 3 * pm.n; ++t)
          y.fastAccessDx(3 * (integrals.n_s + c[pm.node[t / 3]]) + t % 3) =
            x.dx(12 + t);
      }
      return y;
    }



    /**
     * The master faces of @p integrals' input that overlap its slave face
     * @p f (its pieces @p pieces, their auxiliary planes @p planes at the
     * values), with their integrals in the node's numbers, into
     * the first @p n_overlaps of @p overlaps (kept between calls: an
     * Overlap holds 163 AD numbers, whose construction zeroes 0.5 MB);
     * returns the area they cover. Each (slave piece, master
     * piece) pair from the cache if another node of this face has looked
     * at it in this assembly; otherwise the test on the values first
     * (most faces of the node's list miss this slave face), then the
     * integrals in the pair's own AD number.
     */
    AD
    find_overlaps(const MortarIntegrals<3> &integrals,
                  const unsigned int        f,
                  const Piece              *pieces,
                  const unsigned int        n_pieces,
                  const Plane<double>      *planes,
                  std::vector<Overlap>     &overlaps,
                  unsigned int             &n_overlaps)
    {
      const MortarInput3D &input = *integrals.input;
      const auto          &q     = input.slave_face[f];
      n_overlaps                 = 0;
      AD covered(0.);
      for (unsigned int m = 0; m < input.n_master_faces; ++m)
      {
        const auto        &c = input.master_face[m];
        Piece              master_pieces[4];
        const unsigned int n_master_pieces = face_pieces(c.n, master_pieces);
        bool               found           = false;
        for (unsigned int s = 0; s < n_pieces; ++s)
        {
          const Piece &ps = pieces[s];
          // In the pair's own AD number, built when it is first integrated.
          std::optional<Plane<FaceAD>> plane_face;
          for (unsigned int h = 0; h < n_master_pieces; ++h)
          {
            const Piece               &pm = master_pieces[h];
            MortarOverlapCache::Entry  own;
            MortarOverlapCache::Entry *entry    = &own;
            bool                       computed = false;
            // (A residual only is not kept: its numbers have no
            // derivatives.)
            if (input.cache != nullptr && integrals.derivatives)
            {
              const std::uint64_t key =
                (std::uint64_t(4 * input.slave_face_id[f] + s) << 32) |
                (4 * input.master_face_id[m] + h);
              const auto [at, inserted] = input.cache->entries.try_emplace(key);
              entry                     = &at->second;
              computed                  = !inserted;
            }
            if (!computed)
            {
              Vec3<double> Y_value[4];
              for (unsigned int k = 0; k < pm.n; ++k)
                Y_value[k] = input.xm[c[pm.node[k]]];
              entry->overlaps =
                internal::overlaps_in_plane(planes[s], Y_value, pm.n);
              if (entry->overlaps)
              {
                if (!plane_face)
                {
                  Vec3<FaceAD> X_face[4];
                  for (unsigned int k = 0; k < ps.n; ++k)
                    for (unsigned int d = 0; d < 3; ++d)
                      X_face[k][d] =
                        integrals.derivatives ?
                          FaceAD(24, 3 * k + d, input.xs[q[ps.node[k]]][d]) :
                          FaceAD(input.xs[q[ps.node[k]]][d]);
                  plane_face = internal::auxiliary_plane(X_face, ps.n);
                }
                Vec3<FaceAD> Y[4];
                for (unsigned int k = 0; k < pm.n; ++k)
                  for (unsigned int d = 0; d < 3; ++d)
                    Y[k][d] = integrals.derivatives ?
                                FaceAD(24, 12 + 3 * k + d, Y_value[k][d]) :
                                FaceAD(Y_value[k][d]);
                entry->overlaps =
                  overlap_integrals(*plane_face, ps, q.n, Y, pm, c.n, *entry);
              }
            }
            if (!entry->overlaps)
              continue;
            if (!found)
            {
              found = true;
              if (n_overlaps == overlaps.size())
                overlaps.emplace_back();
              Overlap &o = overlaps[n_overlaps++];
              o.face     = m;
              o.area     = AD(0.);
              for (unsigned int i = 0; i < q.n; ++i)
              {
                for (unsigned int k = 0; k < q.n; ++k)
                  o.slave[i][k] = AD(0.);
                for (unsigned int k = 0; k < c.n; ++k)
                  o.master[i][k] = AD(0.);
              }
            }
            Overlap &o = overlaps[n_overlaps - 1];
            o.area += carry(entry->area, integrals, q, ps, c, pm);
            for (unsigned int i = 0; i < q.n; ++i)
            {
              for (unsigned int k = 0; k < q.n; ++k)
                o.slave[i][k] +=
                  carry(entry->slave[i * q.n + k], integrals, q, ps, c, pm);
              for (unsigned int k = 0; k < c.n; ++k)
                o.master[i][k] +=
                  carry(entry->master[i * c.n + k], integrals, q, ps, c, pm);
            }
          }
        }
        if (found)
          covered += overlaps[n_overlaps - 1].area;
      }
      return covered;
    }


  } // namespace



  ContactPointResult
  Mortar3D::evaluate(const SlaveInput     &slave,
                     const MortarInput3D  &input,
                     const Enforcement<3> &enforcement,
                     double               *R,
                     double               *K,
                     bool                 &paired,
                     Vec3<double>         &weighted_point)
  {
    MortarIntegrals<3> &integrals =
      MortarIntegrals<3>::for_element(input,
                                      enforcement.n_node_unknowns(),
                                      K != nullptr);
    const AD                                 zero(0.);
    static thread_local std::vector<Overlap> overlaps;
    unsigned int                             n_overlaps = 0;
    // The pieces' planes and the face's row, kept as the overlaps are.
    static thread_local Plane<AD> planes[4];
    static thread_local AD        a[max_face_nodes];
    for (unsigned int f = 0; f < input.n_slave_faces; ++f)
    {
      const auto        &q = input.slave_face[f];
      Piece              pieces[4];
      const unsigned int n_pieces = face_pieces(q.n, pieces);
      // Each piece's auxiliary plane, in the node's numbers and at the
      // values; the face's area and normal (area-weighted) from them.
      Plane<double> plane_values[4];
      AD            area = zero;
      Vec3<AD>      face_normal{{zero, zero, zero}};
      bool          degenerate = false;
      for (unsigned int s = 0; s < n_pieces; ++s)
      {
        Vec3<AD>     X[4];
        Vec3<double> X_value[4];
        for (unsigned int k = 0; k < pieces[s].n; ++k)
        {
          X[k]       = integrals.xs[q[pieces[s].node[k]]];
          X_value[k] = input.xs[q[pieces[s].node[k]]];
        }
        planes[s]       = internal::auxiliary_plane(X, pieces[s].n);
        plane_values[s] = internal::auxiliary_plane(X_value, pieces[s].n);
        degenerate      = degenerate || planes[s].area.val() <= 0;
        area += planes[s].area;
        face_normal = face_normal + scale(planes[s].area, planes[s].n0);
      }
      if (degenerate)
        continue;
      face_normal      = scale(1. / norm(face_normal), face_normal);
      const AD covered = find_overlaps(integrals,
                                       f,
                                       pieces,
                                       n_pieces,
                                       plane_values,
                                       overlaps,
                                       n_overlaps);
      if (n_overlaps == 0)
        continue;

      const AD theta = internal::dual_weight(input.dual, covered / area);
      for (unsigned int i = 0; i < q.n; ++i)
        a[i] = zero;
      carried_row(input, f, pieces, n_pieces, planes, theta, a);

      AD face_weight = zero;
      for (unsigned int v = 0; v < n_overlaps; ++v)
      {
        const Overlap &o = overlaps[v];
        const auto    &c = input.master_face[o.face];
        for (unsigned int i = 0; i < q.n; ++i)
        {
          if (a[i].val() == 0 && a[i].size() == 0)
            continue;
          for (unsigned int k = 0; k < q.n; ++k)
          {
            const AD w_s = a[i] * o.slave[i][k];
            integrals.D[q[k]] += w_s;
            face_weight += w_s;
          }
          for (unsigned int k = 0; k < c.n; ++k)
            integrals.M[c[k]] += a[i] * o.master[i][k];
        }
      }
      integrals.normal_j = integrals.normal_j + scale(face_weight, face_normal);
    }
    return internal::finish_mortar<3>(slave,
                                      enforcement,
                                      integrals,
                                      R,
                                      K,
                                      paired,
                                      weighted_point);
  }
} // namespace tribos
