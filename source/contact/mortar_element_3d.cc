#include <tribos/base/exceptions.h>
#include <tribos/contact/mortar_integrals.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace tribos
{



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

    /** Shape functions of a face of @p n nodes: MasterFace<3> (4),
     * TriangleFace (3), or the quadratic triangle (6: vertices, then the
     * middles of the edges 0-1, 1-2, 2-0; no derivatives). */
    template <typename Number>
    void
    face_shape(const unsigned int n,
               const Number      *xi,
               Number            *N,
               Number (*dN)[2])
    {
      if (n == 3)
        TriangleFace::shape(xi, N, dN);
      else if (n == 4)
        MasterFace<3>::shape(xi, N, dN);
      else
      {
        const Number l[3] = {1. - xi[0] - xi[1], xi[0], xi[1]};
        for (unsigned int v = 0; v < 3; ++v)
        {
          N[v]     = l[v] * (2. * l[v] - 1.);
          N[3 + v] = 4. * l[v] * l[(v + 1) % 3];
        }
      }
    }

    /**
     * A flat piece of a face, what the overlaps are clipped and integrated
     * on: a linear face is one piece, itself; a quadratic triangle is four,
     * the triangles of its vertices and edge middles (Popp et al.'s
     * integration on linear sub-elements). The piece's n nodes as positions
     * in its face and their coordinates in the face's map.
     */
    struct Piece
    {
      unsigned int n;
      unsigned int node[4];
      double       xi[4][2];
    };

    /** The pieces of a face of @p n nodes into @p pieces; their number. */
    unsigned int
    face_pieces(const unsigned int n, Piece *pieces)
    {
      if (n == 4)
        pieces[0] = {4, {0, 1, 2, 3}, {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}}};
      else if (n == 3)
        pieces[0] = {3, {0, 1, 2, 0}, {{0, 0}, {1, 0}, {0, 1}, {0, 0}}};
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

    /** The face coordinates of the point with coordinates @p x in
     * @p piece. */
    template <typename Number>
    void
    face_coordinates(const Piece &piece, const Number *x, Number *xi)
    {
      Number N[4], dN[4][2];
      face_shape(piece.n, x, N, dN);
      xi[0] = xi[1] = 0.;
      for (unsigned int v = 0; v < piece.n; ++v)
        for (unsigned int c = 0; c < 2; ++c)
          xi[c] += N[v] * piece.xi[v][c];
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
        for (const TrianglePoint &t : triangle_rule)
        {
          Point<FaceAD> p;
          for (unsigned int d = 0; d < 2; ++d)
            p[d] = t.l[0] * v_0[d] + t.l[1] * v_1[d] + t.l[2] * v_2[d];
          FaceAD x_s[2], x_m[2], xi_s[2], xi_m[2], N_s[6], N_m[6], dN[6][2];
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
      AD           area, slave[6][6], master[6][6];
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
      AD y(integrals.n_out, x.val());
      if (x.size() > 0)
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
     * @p overlaps; returns the area they cover. Each (slave piece, master
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
                  std::vector<Overlap>     &overlaps)
    {
      const MortarInput3D &input = integrals.input;
      const auto          &q     = input.slave_face[f];
      overlaps.clear();
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
            if (input.cache != nullptr)
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
                        FaceAD(24, 3 * k + d, input.xs[q[ps.node[k]]][d]);
                  plane_face = internal::auxiliary_plane(X_face, ps.n);
                }
                Vec3<FaceAD> Y[4];
                for (unsigned int k = 0; k < pm.n; ++k)
                  for (unsigned int d = 0; d < 3; ++d)
                    Y[k][d] = FaceAD(24, 12 + 3 * k + d, Y_value[k][d]);
                entry->overlaps =
                  overlap_integrals(*plane_face, ps, q.n, Y, pm, c.n, *entry);
              }
            }
            if (!entry->overlaps)
              continue;
            if (!found)
            {
              found = true;
              overlaps.emplace_back();
              Overlap &o = overlaps.back();
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
            Overlap &o = overlaps.back();
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
          covered += overlaps.back().area;
      }
      return covered;
    }



    /**
     * The basis the dual functions of a face of @p n nodes are
     * biorthogonal to, as Ntilde = T N: the face's own on a linear face
     * (T = 1); on the quadratic triangle the modified basis of
     * TriangleFace::modified_basis_alpha. The quadratic vertex functions
     * integrate to zero over a flat face, so dual functions biorthogonal to
     * them do not exist; the modified ones are positive on average and
     * still sum to one.
     */
    void
    modified_basis(const unsigned int n, double (&T)[6][6])
    {
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int k = 0; k < 6; ++k)
          T[i][k] = (i == k && i < n) ? 1. : 0.;
      if (n != 6)
        return;
      const double alpha = TriangleFace::modified_basis_alpha;
      for (unsigned int v = 0; v < 3; ++v)
      {
        T[v][3 + v]           = alpha; // edge v, v + 1
        T[v][3 + (v + 2) % 3] = alpha; // edge v - 1, v
        T[3 + v][3 + v]       = 1. - 2. * alpha;
      }
    }



    /**
     * The row @p a (coefficients of the face's functions N) of the
     * functions slave face @p f of @p input carries in Phi = A Ntilde
     * (Ntilde = T N the modified basis, A = D_e M_e^-1 of its mass matrix
     * M_e = int Ntilde Ntilde^T over the face's pieces in their planes
     * @p planes, D_e its row sums), blended with Ntilde by @p theta as in
     * 2D, summed with their weights: node j's row, and those of the
     * hanging nodes it carries.
     */
    void
    carried_row(const MortarInput3D &input,
                const unsigned int   f,
                const Piece         *pieces,
                const unsigned int   n_pieces,
                const Plane<AD>     *planes,
                const AD            &theta,
                AD                  *a)
    {
      const AD           zero(0.);
      const unsigned int n = input.slave_face[f].n;
      double             T[6][6];
      modified_basis(n, T);
      AD coefficients[6]; // of Phi in the modified basis
      for (unsigned int i = 0; i < n; ++i)
        coefficients[i] = zero;
      if (theta.val() <= 0)
        for (unsigned int c = 0; c < input.n_carriers[f]; ++c)
          coefficients[input.carriers[f][c].first] +=
            input.carriers[f][c].second;
      else
      {
        // The mass matrix, exactly on flat pieces: 2 x 2 Gauss on a
        // bilinear quadrilateral, the 7-point rule on a triangle piece
        // (degree 4 on the quadratic triangle).
        AD mass[6][6];
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int k = 0; k < n; ++k)
            mass[i][k] = zero;
        // (xi_1, xi_2, weight) in the piece's coordinates.
        using Rule = std::vector<std::array<double, 3>>;
        static const Rule quadrilateral_rule = []()
        {
          const double g = 1. / std::sqrt(3.);
          return Rule{{{-g, -g, 1.}},
                      {{g, -g, 1.}},
                      {{-g, g, 1.}},
                      {{g, g, 1.}}};
        }();
        static const Rule triangle_piece_rule = []()
        {
          Rule rule;
          for (const TrianglePoint &t : triangle_rule)
            rule.push_back({{t.l[1], t.l[2], 0.5 * t.weight}});
          return rule;
        }();
        for (unsigned int s = 0; s < n_pieces; ++s)
        {
          const Piece &piece = pieces[s];
          const Rule  &rule =
            piece.n == 4 ? quadrilateral_rule : triangle_piece_rule;
          for (const auto &point : rule)
          {
            const double x[2] = {point[0], point[1]};
            double       N_piece[4], dN[6][2], xi[2], N[6], Nt[6];
            face_shape(piece.n, x, N_piece, dN);
            AD J[2][2] = {{zero, zero}, {zero, zero}};
            for (unsigned int k = 0; k < piece.n; ++k)
              for (unsigned int r = 0; r < 2; ++r)
                for (unsigned int c = 0; c < 2; ++c)
                  J[r][c] += dN[k][c] * planes[s].P[k][r];
            const AD det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
            face_coordinates(piece, x, xi);
            face_shape(n, xi, N, dN);
            for (unsigned int i = 0; i < n; ++i)
            {
              Nt[i] = 0.;
              for (unsigned int k = 0; k < n; ++k)
                Nt[i] += T[i][k] * N[k];
            }
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int k = 0; k < n; ++k)
                mass[i][k] += (point[2] * Nt[i] * Nt[k]) * det;
          }
        }
        AD row_sum[6];
        for (unsigned int i = 0; i < n; ++i)
        {
          row_sum[i] = zero;
          for (unsigned int k = 0; k < n; ++k)
            row_sum[i] += mass[i][k];
        }
        // M_e = L U (symmetric positive definite: no pivoting).
        AD lower[6][6];
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
          AD y[6];
          for (unsigned int k = 0; k < n; ++k)
            y[k] = zero;
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
            coefficients[k] += weight * (theta * row_sum[j_local] * y[k] +
                                         (k == j_local ? 1. - theta : zero));
        }
      }
      // From the modified basis to the face's functions: a = T^T c.
      for (unsigned int m = 0; m < n; ++m)
        for (unsigned int k = 0; k < n; ++k)
          if (T[m][k] != 0.)
            a[k] += coefficients[m] * T[m][k];
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
      const auto        &q = input.slave_face[f];
      Piece              pieces[4];
      const unsigned int n_pieces = face_pieces(q.n, pieces);
      // Each piece's auxiliary plane, in the node's numbers and at the
      // values; the face's area and normal (area-weighted) from them.
      Plane<AD>     planes[4];
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
      face_normal = scale(1. / norm(face_normal), face_normal);
      const AD covered =
        find_overlaps(integrals, f, pieces, n_pieces, plane_values, overlaps);
      if (overlaps.empty())
        continue;

      const AD theta = internal::dual_weight(input.dual, covered / area);
      AD       a[6];
      for (unsigned int i = 0; i < q.n; ++i)
        a[i] = zero;
      carried_row(input, f, pieces, n_pieces, planes, theta, a);

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
