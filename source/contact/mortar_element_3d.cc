#include <tribos/base/exceptions.h>
#include <tribos/contact/contact_pair.h>
#include <tribos/contact/mortar_element.h>
#include <tribos/contact/mortar_element_3d.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

namespace tribos
{
  namespace internal
  {
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
  } // namespace internal



  namespace
  {
    using AD    = ContactAD;
    using Point = std::array<AD, 2>;

    /** @p x as a Number: its value for double, itself for AD. */
    template <typename Number>
    Number
    value_or_ad(const AD &x)
    {
      if constexpr (std::is_same_v<Number, double>)
        return x.val();
      else
        return x;
    }

    /** Lexicographic vertex numbers in counter-clockwise order. */
    constexpr unsigned int counter_clockwise[4] = {0, 1, 3, 2};

    /**
     * The coordinates xi of the point @p p in the bilinear map of the
     * quadrilateral @p P (lexicographic) in the plane: Newton from the
     * centre on the values, then one Newton step in AD numbers from the
     * converged values, which gives the derivatives of the exact inverse
     * (at a root, the step's derivative is -J^-1 times that of the
     * residual: the implicit function theorem).
     */
    void
    inverse_map(const Point *P, const Point &p, AD *xi)
    {
      const auto residual = [&](const auto *x, auto *r, auto(*J)[2])
      {
        using Number = std::remove_cv_t<std::remove_pointer_t<decltype(x)>>;
        Number N[4], dN[4][2];
        MasterFace<3>::shape(x, N, dN);
        for (unsigned int a = 0; a < 2; ++a)
        {
          r[a] = -Number(value_or_ad<Number>(p[a]));
          for (unsigned int b = 0; b < 2; ++b)
            J[a][b] = 0.;
          for (unsigned int k = 0; k < 4; ++k)
          {
            const Number x_k = value_or_ad<Number>(P[k][a]);
            r[a] += N[k] * x_k;
            for (unsigned int b = 0; b < 2; ++b)
              J[a][b] += dN[k][b] * x_k;
          }
        }
      };
      double x[2] = {0., 0.};
      for (unsigned int iteration = 0; iteration < 30; ++iteration)
      {
        double r[2], J[2][2];
        residual(x, r, J);
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
      xi[0] = x[0];
      xi[1] = x[1];
      AD r[2], J[2][2];
      residual(xi, r, J);
      const AD det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      if (std::abs(det.val()) < 1e-300)
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

    /** A master face's clipped overlap with a slave face in the plane. */
    struct Overlap
    {
      unsigned int face;
      Point        master[4];
      Point        polygon[8]; // at most 4 + 4 vertices
      unsigned int n_vertices;
    };
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
    const unsigned int n_s             = input.n_slave_nodes;
    const unsigned int n_m             = input.n_master_nodes;
    const unsigned int n_displacements = 3 * (n_s + n_m);
    const unsigned int n_out = n_displacements + enforcement.n_node_unknowns();

    Vec3<AD> xs[MortarInput3D::max_slave_nodes], xm[max_mortar_master_nodes_3d];
    for (unsigned int i = 0; i < n_s; ++i)
      xs[i] = internal::seed<3>(input.xs[i], 3 * i, n_out);
    for (unsigned int l = 0; l < n_m; ++l)
      xm[l] = internal::seed<3>(input.xm[l], 3 * (n_s + l), n_out);

    const AD zero(0.);
    AD       D[MortarInput3D::max_slave_nodes], M[max_mortar_master_nodes_3d];
    for (unsigned int i = 0; i < n_s; ++i)
      D[i] = zero;
    for (unsigned int l = 0; l < n_m; ++l)
      M[l] = zero;
    Vec3<AD> normal_j = {{zero, zero, zero}};

    static thread_local std::vector<Overlap> overlaps;
    for (unsigned int f = 0; f < input.n_slave_faces; ++f)
    {
      const auto  &q       = input.slave_face[f];
      unsigned int j_local = 0;
      while (q[j_local] != 0)
        ++j_local;

      // The auxiliary plane: the face's centre and unit normal there, an
      // orthonormal basis e_1, e_2 in it (e_1 along the face's a_1).
      Vec3<AD>     x0 = {{zero, zero, zero}}, a_1 = x0, a_2 = x0;
      const double sign_1[4] = {-1, 1, -1, 1}, sign_2[4] = {-1, -1, 1, 1};
      for (unsigned int k = 0; k < 4; ++k)
      {
        x0  = x0 + scale(0.25, xs[q[k]]);
        a_1 = a_1 + scale(0.25 * sign_1[k], xs[q[k]]);
        a_2 = a_2 + scale(0.25 * sign_2[k], xs[q[k]]);
      }
      Vec3<AD> n0             = cross(a_1, a_2);
      n0                      = scale(1. / norm(n0), n0);
      const Vec3<AD> e1       = scale(1. / norm(a_1), a_1);
      const Vec3<AD> e2       = cross(n0, e1);
      const auto     in_plane = [&](const Vec3<AD> &x)
      {
        const Vec3<AD> d = x - x0;
        return Point{{dot(d, e1), dot(d, e2)}};
      };
      Point P[4], P_ccw[4];
      for (unsigned int k = 0; k < 4; ++k)
        P[k] = in_plane(xs[q[k]]);
      for (unsigned int k = 0; k < 4; ++k)
        P_ccw[k] = P[counter_clockwise[k]];
      const AD slave_area = internal::polygon_area(P_ccw, 4);
      if (slave_area.val() <= 0)
        continue;

      // The master faces facing this one, clipped against it in the plane.
      overlaps.clear();
      AD covered = zero;
      for (unsigned int m = 0; m < input.n_master_faces; ++m)
      {
        const auto  &c = input.master_face[m];
        Vec3<double> b_1{{0, 0, 0}}, b_2{{0, 0, 0}};
        for (unsigned int k = 0; k < 4; ++k)
        {
          b_1 = b_1 + scale(sign_1[k], input.xm[c[k]]);
          b_2 = b_2 + scale(sign_2[k], input.xm[c[k]]);
        }
        const Vec3<double> n_m = cross(b_1, b_2);
        Vec3<double>       n_0;
        for (unsigned int d = 0; d < 3; ++d)
          n_0[d] = n0[d].val();
        if (dot(n_m, n_0) >= -0.25 * norm(n_m))
          continue;
        Overlap o;
        o.face = m;
        Point Q_ccw[4];
        for (unsigned int k = 0; k < 4; ++k)
          o.master[k] = in_plane(xm[c[k]]);
        for (unsigned int k = 0; k < 4; ++k)
          Q_ccw[k] = o.master[counter_clockwise[3 - k]];
        // On the values first: most faces of the node's list miss this
        // slave face, and the clipping in AD numbers is the costly part.
        {
          std::array<double, 2> q[4], p[4], clipped[8];
          for (unsigned int k = 0; k < 4; ++k)
            for (unsigned int d = 0; d < 2; ++d)
            {
              q[k][d] = Q_ccw[k][d].val();
              p[k][d] = P_ccw[k][d].val();
            }
          if (internal::polygon_area(q, 4) <= 0)
            continue;
          const unsigned int n = internal::clip_polygon(q, 4, p, 4, clipped);
          if (n < 3 ||
              internal::polygon_area(clipped, n) <= 1e-12 * slave_area.val())
            continue;
        }
        o.n_vertices = internal::clip_polygon(Q_ccw, 4, P_ccw, 4, o.polygon);
        if (o.n_vertices < 3)
          continue;
        const AD area = internal::polygon_area(o.polygon, o.n_vertices);
        if (area.val() <= 1e-12 * slave_area.val())
          continue;
        covered += area;
        overlaps.push_back(o);
      }
      if (overlaps.empty())
        continue;

      // The row of node j in Phi = A N (A = D_e M_e^-1, blended with the
      // identity by theta as in 2D).
      const AD fraction = covered / slave_area;
      const AD theta    = !input.dual || fraction.val() <= 0.5 ? zero :
                          fraction.val() >= 1.                 ? AD(1.) :
                                                 2. * fraction - 1.;
      AD       a[4]     = {zero, zero, zero, zero};
      a[j_local]        = 1.;
      if (theta.val() > 0)
      {
        AD           mass[4][4];
        const double g = 1. / std::sqrt(3.);
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int k = 0; k < 4; ++k)
            mass[i][k] = zero;
        for (const double g_1 : {-g, g})
          for (const double g_2 : {-g, g})
          {
            const AD xi[2] = {g_1, g_2};
            AD       N[4], dN[4][2];
            MasterFace<3>::shape(xi, N, dN);
            AD J[2][2] = {{zero, zero}, {zero, zero}};
            for (unsigned int k = 0; k < 4; ++k)
              for (unsigned int r = 0; r < 2; ++r)
                for (unsigned int s = 0; s < 2; ++s)
                  J[r][s] += dN[k][s] * P[k][r];
            const AD det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
            for (unsigned int i = 0; i < 4; ++i)
              for (unsigned int k = 0; k < 4; ++k)
                mass[i][k] += det * N[i] * N[k];
          }
        AD d_j = zero;
        for (unsigned int k = 0; k < 4; ++k)
          d_j += mass[j_local][k];
        // y = M_e^-1 e_j (M_e symmetric positive definite: no pivoting).
        AD y[4]    = {zero, zero, zero, zero};
        y[j_local] = 1.;
        for (unsigned int p = 0; p < 4; ++p)
          for (unsigned int i = p + 1; i < 4; ++i)
          {
            const AD factor = mass[i][p] / mass[p][p];
            for (unsigned int k = p; k < 4; ++k)
              mass[i][k] -= factor * mass[p][k];
            y[i] -= factor * y[p];
          }
        for (unsigned int p = 4; p-- > 0;)
        {
          for (unsigned int k = p + 1; k < 4; ++k)
            y[p] -= mass[p][k] * y[k];
          y[p] /= mass[p][p];
        }
        for (unsigned int k = 0; k < 4; ++k)
          a[k] = theta * d_j * y[k] + (k == j_local ? 1. - theta : zero);
      }

      AD face_weight = zero;
      for (const Overlap &o : overlaps)
      {
        const auto &c = input.master_face[o.face];
        // The clip polygon is convex: a fan of triangles from its first
        // vertex.
        const Point &v_0 = o.polygon[0];
        for (unsigned int i = 1; i + 1 < o.n_vertices; ++i)
        {
          const Point &v_1  = o.polygon[i];
          const Point &v_2  = o.polygon[i + 1];
          const AD     area = 0.5 * ((v_1[0] - v_0[0]) * (v_2[1] - v_0[1]) -
                                 (v_1[1] - v_0[1]) * (v_2[0] - v_0[0]));
          if (area.val() <= 0)
            continue;
          for (const TrianglePoint &t : triangle_rule)
          {
            Point p;
            for (unsigned int d = 0; d < 2; ++d)
              p[d] = t.l[0] * v_0[d] + t.l[1] * v_1[d] + t.l[2] * v_2[d];
            AD xi_s[2], xi_m[2], N_s[4], N_m[4], dN[4][2];
            inverse_map(P, p, xi_s);
            inverse_map(o.master, p, xi_m);
            MasterFace<3>::shape(xi_s, N_s, dN);
            MasterFace<3>::shape(xi_m, N_m, dN);
            AD phi = zero;
            for (unsigned int k = 0; k < 4; ++k)
              phi += a[k] * N_s[k];
            const AD w_phi = t.weight * area * phi;
            for (unsigned int k = 0; k < 4; ++k)
            {
              D[q[k]] += w_phi * N_s[k];
              M[c[k]] += w_phi * N_m[k];
            }
            face_weight += w_phi;
          }
        }
      }
      normal_j = normal_j + scale(face_weight, n0);
    }

    return internal::finish_mortar<3>(slave,
                                      enforcement,
                                      D,
                                      xs,
                                      input.xs_old,
                                      n_s,
                                      M,
                                      xm,
                                      input.xm_old,
                                      n_m,
                                      normal_j,
                                      input.min_weight,
                                      n_displacements,
                                      R,
                                      K,
                                      paired,
                                      weighted_point);
  }



  bool
  mortar_input(const ContactPair<3>                 &pair,
               const unsigned int                    k,
               MortarInput3D                        &mortar,
               std::vector<unsigned int>            &stencil,
               std::vector<unsigned int>            &master_nodes,
               std::vector<types::global_dof_index> &dofs,
               std::string                          &too_large)
  {
    master_nodes.clear();
    const auto local =
      [](std::vector<unsigned int> &list, const unsigned int node)
    {
      const auto at = std::find(list.begin(), list.end(), node);
      if (at != list.end())
        return static_cast<unsigned int>(at - list.begin());
      list.push_back(node);
      return static_cast<unsigned int>(list.size() - 1);
    };
    const auto refuse = [&](const std::string &what)
    {
      const Vec3<double> &x = pair.slave_positions[k];
      if (too_large.empty())
        too_large = "contact pair <" + pair.description.text +
                    ">: the mortar element of the slave node at (" +
                    to_scientific(x[0]) + ", " + to_scientific(x[1]) + ", " +
                    to_scientific(x[2]) + ") " + what +
                    " (an iterate gone astray, or a master much finer than "
                    "the slave: make the finer side the slave)";
      return false;
    };
    pair.slave_stencil(k, stencil);
    if (stencil.size() > MortarInput3D::max_slave_nodes ||
        pair.slave->nodes()[k].faces.size() > MortarInput3D::max_slave_faces)
      return refuse("has more than " +
                    std::to_string(MortarInput3D::max_slave_faces) +
                    " slave faces");
    for (const unsigned int f : pair.slave->nodes()[k].faces)
    {
      auto &face = mortar.slave_face[mortar.n_slave_faces++];
      for (unsigned int v = 0; v < 4; ++v)
        face[v] = local(stencil, pair.slave->faces()[f].nodes[v]);
    }
    if (pair.mortar_faces[k].size() > max_mortar_master_nodes_3d)
      return refuse("overlaps more than " +
                    std::to_string(max_mortar_master_nodes_3d) +
                    " master faces");
    for (const unsigned int f : pair.mortar_faces[k])
    {
      std::array<unsigned int, 4> face;
      for (unsigned int v = 0; v < 4; ++v)
        face[v] = local(master_nodes, pair.master->faces()[f].nodes[v]);
      if (master_nodes.size() > max_mortar_master_nodes_3d)
        return refuse("overlaps more than " +
                      std::to_string(max_mortar_master_nodes_3d) +
                      " master nodes");
      mortar.master_face[mortar.n_master_faces++] = face;
    }

    mortar.n_slave_nodes = stencil.size();
    dofs.clear();
    for (unsigned int i = 0; i < stencil.size(); ++i)
    {
      mortar.xs[i]     = pair.slave_positions[stencil[i]];
      mortar.xs_old[i] = pair.old_slave_positions[stencil[i]];
      for (const auto dof : pair.slave->nodes()[stencil[i]].dofs)
        dofs.push_back(dof);
    }
    mortar.n_master_nodes = master_nodes.size();
    for (unsigned int l = 0; l < master_nodes.size(); ++l)
    {
      mortar.xm[l]     = pair.master_positions[master_nodes[l]];
      mortar.xm_old[l] = pair.old_master_positions[master_nodes[l]];
      for (const auto dof : pair.master->nodes()[master_nodes[l]].dofs)
        dofs.push_back(dof);
    }
    const unsigned int n = pair.enforcement->n_node_unknowns();
    for (unsigned int d = 0; d < n; ++d)
      dofs.push_back(pair.first_unknown + n * k + d);
    mortar.dual       = pair.dual_basis;
    mortar.min_weight = 1e-3 * pair.area[k];
    return true;
  }
} // namespace tribos
