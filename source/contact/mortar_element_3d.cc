#include <tribos/base/exceptions.h>
#include <tribos/contact/mortar_integrals.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace tribos
{
  namespace internal
  {
    namespace
    {
      /** Vertex @p k of a face of @p n vertices, counter-clockwise seen
       * from the side its normal points to, in clockwise order (a master
       * face seen along the slave's normal). */
      unsigned int
      reversed(const unsigned int n, const unsigned int k)
      {
        return n == 3 ? 2 - k : counter_clockwise[3 - k];
      }
    } // namespace



    template <typename Number>
    Number
    polygon_area(const std::array<Number, 2> *polygon, const unsigned int n)
    {
      Number area(0.);
      for (unsigned int i = 0; i < n; ++i)
      {
        const auto &a = polygon[i];
        const auto &b = polygon[(i + 1) % n];
        area += a[0] * b[1] - a[1] * b[0];
      }
      return 0.5 * area;
    }



    template <typename Number>
    unsigned int
    clip_polygon(const std::array<Number, 2> *subject,
                 const unsigned int           n_subject,
                 const std::array<Number, 2> *clip,
                 const unsigned int           n_clip,
                 std::array<Number, 2>       *out)
    {
      using Point = std::array<Number, 2>;
      // Each clip edge adds at most one vertex.
      std::vector<Point> in(subject, subject + n_subject), next;
      next.reserve(n_subject + n_clip);
      for (unsigned int i = 0; i < n_clip && !in.empty(); ++i)
      {
        const Point &a = clip[i];
        const Point &b = clip[(i + 1) % n_clip];
        // Which side of the edge a -> b: 1 inside (left), -1 outside, 0
        // on the line (within 1e-11 of the edge's length, squared).
        // Vertices on the line count as inside and an intersection is
        // computed only between vertices strictly on either side: where
        // the edges of both polygons coincide (non-matching meshes with a
        // common boundary) the intersection of the nearly collinear edges
        // would be anywhere along them, with derivatives of 1e16.
        const auto side = [&](const Point &x)
        {
          return Number((b[0] - a[0]) * (x[1] - a[1]) -
                        (b[1] - a[1]) * (x[0] - a[0]));
        };
        const double tolerance =
          1e-11 * value_of(Number((b[0] - a[0]) * (b[0] - a[0]) +
                                  (b[1] - a[1]) * (b[1] - a[1])));
        const auto where = [&](const Number &d)
        {
          return value_of(d) > tolerance  ? 1 :
                 value_of(d) < -tolerance ? -1 :
                                            0;
        };
        next.clear();
        for (unsigned int k = 0; k < in.size(); ++k)
        {
          const Point &previous = in[(k + in.size() - 1) % in.size()];
          const Point &current  = in[k];
          const Number d_p = side(previous), d_c = side(current);
          const int    w_p = where(d_p), w_c = where(d_c);
          if (w_p * w_c < 0)
          {
            const Number t = d_p / (d_p - d_c);
            next.push_back(
              {{Number(previous[0] + t * (current[0] - previous[0])),
                Number(previous[1] + t * (current[1] - previous[1]))}});
          }
          if (w_c >= 0)
            next.push_back(current);
        }
        std::swap(in, next);
      }
      // More vertices than two convex quadrilaterals can give: a subject
      // that folded over itself (an iterate gone astray) has no overlap.
      if (in.size() > n_subject + n_clip)
        return 0;
      for (unsigned int i = 0; i < in.size(); ++i)
        out[i] = in[i];
      return in.size();
    }

    template double
    polygon_area(const std::array<double, 2> *, const unsigned int);
    template ContactAD
    polygon_area(const std::array<ContactAD, 2> *, const unsigned int);
    template Sacado::Fad::SLFad<double, 24>
    polygon_area(const std::array<Sacado::Fad::SLFad<double, 24>, 2> *,
                 const unsigned int);
    template unsigned int
    clip_polygon(const std::array<Sacado::Fad::SLFad<double, 24>, 2> *,
                 const unsigned int,
                 const std::array<Sacado::Fad::SLFad<double, 24>, 2> *,
                 const unsigned int,
                 std::array<Sacado::Fad::SLFad<double, 24>, 2> *);
    template unsigned int
    clip_polygon(const std::array<double, 2> *,
                 const unsigned int,
                 const std::array<double, 2> *,
                 const unsigned int,
                 std::array<double, 2> *);
    template unsigned int
    clip_polygon(const std::array<ContactAD, 2> *,
                 const unsigned int,
                 const std::array<ContactAD, 2> *,
                 const unsigned int,
                 std::array<ContactAD, 2> *);


    bool
    overlaps_in_plane(const AuxiliaryPlane<double> &plane,
                      const Vec3<double>           *Y,
                      const unsigned int            n_m)
    {
      const double sign_1[4] = {-1, 1, -1, 1}, sign_2[4] = {-1, -1, 1, 1};
      Vec3<double> b_1{{0, 0, 0}}, b_2{{0, 0, 0}};
      if (n_m == 3)
      {
        b_1 = Y[1] - Y[0];
        b_2 = Y[2] - Y[0];
      }
      else
        for (unsigned int k = 0; k < 4; ++k)
        {
          b_1 = b_1 + scale(sign_1[k], Y[k]);
          b_2 = b_2 + scale(sign_2[k], Y[k]);
        }
      const Vec3<double> normal = cross(b_1, b_2);
      if (dot(normal, plane.n0) >= -0.25 * norm(normal))
        return false;
      // The master face's projection, counter-clockwise seen along n0.
      std::array<double, 2> Q[4], clipped[8];
      for (unsigned int k = 0; k < n_m; ++k)
        Q[k] = plane.project(Y[reversed(n_m, k)]);
      if (polygon_area(Q, n_m) <= 0)
        return false;
      const unsigned int n =
        clip_polygon(Q, n_m, plane.P_ccw, plane.n, clipped);
      return n >= 3 && polygon_area(clipped, n) > 1e-12 * plane.area;
    }
  } // namespace internal



  namespace
  {
    using AD = ContactAD;
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
    template <typename Number>
    using Plane = internal::AuxiliaryPlane<Number>;

    /** Shape functions of a face of @p n nodes: MasterFace<3> (4) or
     * TriangleFace (3). */
    template <typename Number>
    void
    face_shape(const unsigned int n,
               const Number      *xi,
               Number            *N,
               Number (*dN)[2])
    {
      if (n == 3)
        TriangleFace::shape(xi, N, dN);
      else
        MasterFace<3>::shape(xi, N, dN);
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

    /** The 7-point rule of degree 5 on a triangle (Dunavant): barycentric
     * coordinates and weights (summing to 1). */
    struct TrianglePoint
    {
      double l[3], weight;
    };
    constexpr double a_1                     = 0.0597158717897698204929,
                     b_1                     = 0.4701420641051150897536,
                     w_1                     = 0.1323941527885061807294,
                     a_2                     = 0.7974269853530873223564,
                     b_2                     = 0.1012865073234563388218,
                     w_2                     = 0.1259391805448271525956;
    constexpr TrianglePoint triangle_rule[7] = {{{1. / 3., 1. / 3., 1. / 3.},
                                                 0.225},
                                                {{a_1, b_1, b_1}, w_1},
                                                {{b_1, a_1, b_1}, w_1},
                                                {{b_1, b_1, a_1}, w_1},
                                                {{a_2, b_2, b_2}, w_2},
                                                {{b_2, a_2, b_2}, w_2},
                                                {{b_2, b_2, a_2}, w_2}};

    /**
     * The overlap of the slave face of @p plane with the master face with
     * the @p n_m nodes @p Y: its area and the integrals of the slave
     * functions against the slave's (@p slave[i][k] = int N_i N_k) and the
     * master's (@p master[i][l] = int N_i N_l) over it. Returns false if
     * they do not overlap.
     */
    bool
    overlap_integrals(const Plane<FaceAD> &plane,
                      const Vec3<FaceAD>  *Y,
                      const unsigned int   n_m,
                      FaceAD              &area,
                      FaceAD (&slave)[4][4],
                      FaceAD (&master)[4][4])
    {
      const unsigned int n_s = plane.n;
      Point<FaceAD>      Q[4], Q_ccw[4], polygon[8];
      for (unsigned int k = 0; k < n_m; ++k)
        Q[k] = plane.project(Y[k]);
      for (unsigned int k = 0; k < n_m; ++k)
        Q_ccw[k] = Q[n_m == 3 ? 2 - k : counter_clockwise[3 - k]];
      if (internal::polygon_area(Q_ccw, n_m).val() <= 0)
        return false;
      const unsigned int n =
        internal::clip_polygon(Q_ccw, n_m, plane.P_ccw, n_s, polygon);
      if (n < 3)
        return false;
      area = internal::polygon_area(polygon, n);
      if (area.val() <= 1e-12 * plane.area.val())
        return false;
      for (unsigned int i = 0; i < 4; ++i)
        for (unsigned int k = 0; k < 4; ++k)
          slave[i][k] = master[i][k] = 0.;
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
        for (const TrianglePoint &t : triangle_rule)
        {
          Point<FaceAD> p;
          for (unsigned int d = 0; d < 2; ++d)
            p[d] = t.l[0] * v_0[d] + t.l[1] * v_1[d] + t.l[2] * v_2[d];
          FaceAD xi_s[2], xi_m[2], N_s[4], N_m[4], dN[4][2];
          inverse_map(plane.P, n_s, p, xi_s);
          inverse_map(Q, n_m, p, xi_m);
          face_shape(n_s, xi_s, N_s, dN);
          face_shape(n_m, xi_m, N_m, dN);
          const FaceAD weight = t.weight * triangle;
          for (unsigned int i = 0; i < n_s; ++i)
          {
            const FaceAD w_i = weight * N_s[i];
            for (unsigned int k = 0; k < n_s; ++k)
              slave[i][k] += w_i * N_s[k];
            for (unsigned int k = 0; k < n_m; ++k)
              master[i][k] += w_i * N_m[k];
          }
        }
      }
      return true;
    }

    /** An overlap's integrals, carried over to the node's AD numbers. */
    struct Overlap
    {
      unsigned int face;
      AD           area, slave[4][4], master[4][4];
    };



    /**
     * An overlap's integral @p x (in its own 24 coordinates: slave face
     * @p q's, then master face @p c's, by their local numbers) in the
     * node's numbers of @p integrals.
     */
    AD
    carry(const FaceAD             &x,
          const MortarIntegrals<3> &integrals,
          const MortarFace3D       &q,
          const MortarFace3D       &c)
    {
      AD y(integrals.n_out, x.val());
      if (x.size() > 0)
      {
        for (unsigned int t = 0; t < 3 * q.n; ++t)
          y.fastAccessDx(3 * q[t / 3] + t % 3) = x.dx(t);
        for (unsigned int t = 0; t < 3 * c.n; ++t)
          y.fastAccessDx(3 * (integrals.n_s + c[t / 3]) + t % 3) = x.dx(12 + t);
      }
      return y;
    }



    /**
     * The master faces of @p integrals' input that overlap its slave face
     * @p f (auxiliary plane @p plane_value at the values), with their
     * integrals in the node's numbers, into @p overlaps; returns the area
     * they cover. From the cache if another node of this face has looked
     * at them in this assembly; otherwise the test on the values first
     * (most faces of the node's list miss this slave face), then the
     * integrals in the overlap's own AD number.
     */
    AD
    find_overlaps(const MortarIntegrals<3> &integrals,
                  const unsigned int        f,
                  const Plane<double>      &plane_value,
                  std::vector<Overlap>     &overlaps)
    {
      const MortarInput3D &input = integrals.input;
      const auto          &q     = input.slave_face[f];
      // In the overlap's own AD number, built when an overlap is first
      // integrated.
      std::optional<Plane<FaceAD>> plane_face;
      overlaps.clear();
      AD covered(0.);
      for (unsigned int m = 0; m < input.n_master_faces; ++m)
      {
        const auto                &c = input.master_face[m];
        MortarOverlapCache::Entry  own;
        MortarOverlapCache::Entry *entry    = &own;
        bool                       computed = false;
        if (input.cache != nullptr)
        {
          const std::uint64_t key =
            (std::uint64_t(input.slave_face_id[f]) << 32) |
            input.master_face_id[m];
          const auto [at, inserted] = input.cache->entries.try_emplace(key);
          entry                     = &at->second;
          computed                  = !inserted;
        }
        if (!computed)
        {
          Vec3<double> Y_value[4];
          for (unsigned int k = 0; k < c.n; ++k)
            Y_value[k] = input.xm[c[k]];
          entry->overlaps =
            internal::overlaps_in_plane(plane_value, Y_value, c.n);
          if (entry->overlaps)
          {
            if (!plane_face)
            {
              Vec3<FaceAD> X_face[4];
              for (unsigned int k = 0; k < q.n; ++k)
                for (unsigned int d = 0; d < 3; ++d)
                  X_face[k][d] = FaceAD(24, 3 * k + d, input.xs[q[k]][d]);
              plane_face = internal::auxiliary_plane(X_face, q.n);
            }
            Vec3<FaceAD> Y[4];
            for (unsigned int k = 0; k < c.n; ++k)
              for (unsigned int d = 0; d < 3; ++d)
                Y[k][d] = FaceAD(24, 12 + 3 * k + d, Y_value[k][d]);
            entry->overlaps = overlap_integrals(*plane_face,
                                                Y,
                                                c.n,
                                                entry->area,
                                                entry->slave,
                                                entry->master);
          }
        }
        if (!entry->overlaps)
          continue;
        overlaps.emplace_back();
        Overlap &o = overlaps.back();
        o.face     = m;
        o.area     = carry(entry->area, integrals, q, c);
        for (unsigned int i = 0; i < q.n; ++i)
        {
          for (unsigned int k = 0; k < q.n; ++k)
            o.slave[i][k] = carry(entry->slave[i][k], integrals, q, c);
          for (unsigned int k = 0; k < c.n; ++k)
            o.master[i][k] = carry(entry->master[i][k], integrals, q, c);
        }
        covered += o.area;
      }
      return covered;
    }



    /**
     * The row @p a of the functions slave face @p f of @p input carries in
     * Phi = A N (A = D_e M_e^-1 of the face's mass matrix in the plane
     * @p plane, blended with the identity by @p theta as in 2D), summed
     * with their weights: node j's row, and those of the hanging nodes it
     * carries.
     */
    void
    carried_row(const MortarInput3D &input,
                const unsigned int   f,
                const Plane<AD>     &plane,
                const AD            &theta,
                AD                  *a)
    {
      const AD zero(0.);
      if (theta.val() <= 0)
      {
        for (unsigned int c = 0; c < input.n_carriers[f]; ++c)
          a[input.carriers[f][c].first] += input.carriers[f][c].second;
        return;
      }
      // The face's mass matrix, exactly: 2 x 2 Gauss on the bilinear
      // quadrilateral, the 3-point rule of degree 2 on the triangle.
      const unsigned int n = plane.n;
      AD                 mass[4][4];
      for (unsigned int i = 0; i < 4; ++i)
        for (unsigned int k = 0; k < 4; ++k)
          mass[i][k] = zero;
      const double g = 1. / std::sqrt(3.);
      using Rule     = std::vector<std::array<double, 3>>;
      const Rule rule =
        n == 3 ?
          Rule{{{1. / 6, 1. / 6, 1. / 6}},
               {{2. / 3, 1. / 6, 1. / 6}},
               {{1. / 6, 2. / 3, 1. / 6}}} :
          Rule{{{-g, -g, 1.}}, {{g, -g, 1.}}, {{-g, g, 1.}}, {{g, g, 1.}}};
      for (const auto &point : rule)
      {
        const double xi[2] = {point[0], point[1]};
        double       N[4], dN[4][2];
        face_shape(n, xi, N, dN);
        AD J[2][2] = {{zero, zero}, {zero, zero}};
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int r = 0; r < 2; ++r)
            for (unsigned int s = 0; s < 2; ++s)
              J[r][s] += dN[k][s] * plane.P[k][r];
        const AD det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int k = 0; k < n; ++k)
            mass[i][k] += (point[2] * N[i] * N[k]) * det;
      }
      AD row_sum[4];
      for (unsigned int i = 0; i < n; ++i)
      {
        row_sum[i] = zero;
        for (unsigned int k = 0; k < n; ++k)
          row_sum[i] += mass[i][k];
      }
      // M_e = L U (symmetric positive definite: no pivoting).
      AD lower[4][4];
      for (unsigned int p = 0; p < n; ++p)
        for (unsigned int i = p + 1; i < n; ++i)
        {
          lower[i][p] = mass[i][p] / mass[p][p];
          for (unsigned int k = p; k < n; ++k)
            mass[i][k] -= lower[i][p] * mass[p][k];
        }
      for (unsigned int c = 0; c < input.n_carriers[f]; ++c)
      {
        const auto [j_local, weight] = input.carriers[f][c];
        // y = M_e^-1 e_j.
        AD y[4]    = {zero, zero, zero, zero};
        y[j_local] = 1.;
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int i = p + 1; i < n; ++i)
            y[i] -= lower[i][p] * y[p];
        for (unsigned int p = n; p-- > 0;)
        {
          for (unsigned int k = p + 1; k < n; ++k)
            y[p] -= mass[p][k] * y[k];
          y[p] /= mass[p][p];
        }
        for (unsigned int k = 0; k < n; ++k)
          a[k] += weight * (theta * row_sum[j_local] * y[k] +
                            (k == j_local ? 1. - theta : zero));
      }
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
    MortarIntegrals<3> integrals(input, enforcement.n_node_unknowns());
    const AD           zero(0.);
    static thread_local std::vector<Overlap> overlaps;
    for (unsigned int f = 0; f < input.n_slave_faces; ++f)
    {
      const auto  &q = input.slave_face[f];
      Vec3<AD>     X[4];
      Vec3<double> X_value[4];
      for (unsigned int k = 0; k < q.n; ++k)
      {
        X[k]       = integrals.xs[q[k]];
        X_value[k] = input.xs[q[k]];
      }
      const Plane<AD> plane = internal::auxiliary_plane(X, q.n);
      if (plane.area.val() <= 0)
        continue;
      const AD covered = find_overlaps(integrals,
                                       f,
                                       internal::auxiliary_plane(X_value, q.n),
                                       overlaps);
      if (overlaps.empty())
        continue;

      const AD theta = internal::dual_weight(input.dual, covered / plane.area);
      AD       a[4]  = {zero, zero, zero, zero};
      carried_row(input, f, plane, theta, a);

      AD face_weight = zero;
      for (const Overlap &o : overlaps)
      {
        const auto &c = input.master_face[o.face];
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
      integrals.normal_j = integrals.normal_j + scale(face_weight, plane.n0);
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
