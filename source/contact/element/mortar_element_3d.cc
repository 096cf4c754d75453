#include <tribos/base/exceptions.h>
#include <tribos/contact/element/mortar_integrals.h>

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

    /** The most nodes of a face (the nine-node quadrilateral). */
    constexpr unsigned int max_face_nodes = MortarFace3D::max_nodes;

    using internal::counter_clockwise;
    template <typename Number>
    using Plane = internal::AuxiliaryPlane<Number>;

    /** Shape functions of a face of @p n nodes: MasterFace<3> (4),
     * TriangleFace (3), the quadratic triangle (6: vertices, then the
     * middles of the edges 0-1, 1-2, 2-0) or the biquadratic
     * quadrilateral (9: MortarFace3D's order); no derivatives of the
     * quadratic ones. */
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
      else if (n == 9)
      {
        // The 1D functions of the nodes at -1, 1 and 0, in each direction;
        // node i sits at (at_1[i], at_2[i]).
        Number l[2][3], dl[3];
        for (unsigned int d = 0; d < 2; ++d)
          quadratic_segment_shape(xi[d], l[d], dl);
        constexpr unsigned int at_1[9] = {0, 1, 0, 1, 2, 2, 0, 1, 2},
                               at_2[9] = {0, 0, 1, 1, 0, 1, 2, 2, 2};
        for (unsigned int i = 0; i < 9; ++i)
          N[i] = l[0][at_1[i]] * l[1][at_2[i]];
      }
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
     * integration on linear sub-elements); a nine-node quadrilateral four
     * bilinear quadrilaterals, each with a vertex, two edge middles and
     * the centre. The piece's n nodes as positions
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



    /**
     * The basis the dual functions of a face of @p n nodes are
     * biorthogonal to, as Ntilde = T N: the face's own on a linear face
     * (T = 1); on the quadratic triangle the modified basis of
     * TriangleFace::modified_basis_alpha, on the nine-node quadrilateral
     * the tensor product of the quadratic segment's with that alpha. The
     * quadratic vertex functions integrate to zero over a flat face, so dual
     * functions biorthogonal to them do not exist; the modified ones are
     * positive on average and still sum to one.
     */
    void
    modified_basis(const unsigned int n,
                   double (&T)[max_face_nodes][max_face_nodes])
    {
      for (unsigned int i = 0; i < max_face_nodes; ++i)
        for (unsigned int k = 0; k < max_face_nodes; ++k)
          T[i][k] = (i == k && i < n) ? 1. : 0.;
      if (n == 9)
      {
        // The tensor product of the quadratic segment's modified functions
        // (ends N_e + alpha N_m, middle (1 - 2 alpha) N_m) with the same
        // alpha: the biquadratic vertex functions integrate to only A/36
        // (the centre's 4A/9), and the vertices' multipliers, divided by so
        // little, scatter on distorted faces (the 3D press fit of
        // tests/verification/curved_meshes.py: 8.2 % RMS at the vertices, 2.6 %
        // with this basis, whose integrals are 9A/100 at the vertices, 3A/25 at
        // the edge middles and 4A/25 at the centre of a flat face of area
        // A).
        const double           alpha     = TriangleFace::modified_basis_alpha;
        const double           T_1[3][3] = {{1., 0., alpha},
                                            {0., 1., alpha},
                                            {0., 0., 1. - 2. * alpha}};
        constexpr unsigned int at_1[9]   = {0, 1, 0, 1, 2, 2, 0, 1, 2},
                               at_2[9]   = {0, 0, 1, 1, 0, 1, 2, 2, 2};
        for (unsigned int i = 0; i < 9; ++i)
          for (unsigned int k = 0; k < 9; ++k)
            T[i][k] = T_1[at_1[i]][at_1[k]] * T_1[at_2[i]][at_2[k]];
        return;
      }
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
      double             T[max_face_nodes][max_face_nodes];
      modified_basis(n, T);
      // Scratch of this thread (AD numbers zero their derivatives when
      // constructed: some 200 of them per call).
      static thread_local struct
      {
        AD coefficients[max_face_nodes]; // of Phi in the modified basis
        AD mass[max_face_nodes][max_face_nodes];
        AD row_sum[max_face_nodes];
        AD lower[max_face_nodes][max_face_nodes];
        AD y[max_face_nodes];
      } scratch;
      auto &coefficients = scratch.coefficients;
      for (unsigned int i = 0; i < n; ++i)
        coefficients[i] = zero;
      if (theta.val() <= 0)
        for (unsigned int c = 0; c < input.n_carriers[f]; ++c)
          coefficients[input.carriers[f][c].first] +=
            input.carriers[f][c].second;
      else
      {
        // The mass matrix, exactly on flat pieces: 2 x 2 Gauss on a
        // bilinear quadrilateral, 3 x 3 on the pieces of a nine-node one
        // (degree 4 in each direction, 5 with the Jacobian), the 7-point
        // rule on a triangle piece (degree 4 on the quadratic triangle).
        auto &mass = scratch.mass;
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
        static const Rule biquadratic_rule = []()
        {
          const double g    = std::sqrt(0.6);
          const double x[3] = {-g, 0., g}, w[3] = {5. / 9., 8. / 9., 5. / 9.};
          Rule         rule;
          for (unsigned int b = 0; b < 3; ++b)
            for (unsigned int a = 0; a < 3; ++a)
              rule.push_back({{x[a], x[b], w[a] * w[b]}});
          return rule;
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
          const Rule  &rule  = piece.n == 3 ? triangle_piece_rule :
                               n == 9       ? biquadratic_rule :
                                              quadrilateral_rule;
          for (const auto &point : rule)
          {
            const double x[2] = {point[0], point[1]};
            double N_piece[4], dN[max_face_nodes][2], xi[2], N[max_face_nodes],
              Nt[max_face_nodes];
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
        auto &row_sum = scratch.row_sum;
        for (unsigned int i = 0; i < n; ++i)
        {
          row_sum[i] = zero;
          for (unsigned int k = 0; k < n; ++k)
            row_sum[i] += mass[i][k];
        }
        // M_e = L U (symmetric positive definite: no pivoting).
        auto &lower = scratch.lower;
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
          auto &y = scratch.y;
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
    MortarIntegrals<3> &integrals =
      MortarIntegrals<3>::for_element(input, enforcement.n_node_unknowns());
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
