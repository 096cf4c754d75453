#ifndef tribos_contact_smoothed_face_h
#define tribos_contact_smoothed_face_h

#include <tribos/contact/surface/face_shape.h>
#include <tribos/contact/surface/master_face.h>
#include <tribos/contact/surface/vec3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace tribos
{
  /**
   * A 3D master face (bilinear quadrilateral or linear triangle) whose
   * normal field is interpolated between averaged nodal normals, the 3D
   * counterpart of SmoothedSegment: n(xi) = sum_a N_a(xi) n_a, with n_a
   * the normalized sum of the unit normals that the faces around vertex a
   * have at a (their corner normals). The point of the face that a slave
   * point x_s sees is the one whose normal line passes through it,
   *
   *   x_s = xbar(xi) + g n(xi),
   *
   * three equations for xi_1, xi_2 and g (Popp, Gee and Wall 2009 use the
   * same projection along interpolated nodal normals for their mortar
   * slave side); the gap is (x_s - xbar(xi)) . n(xi)/|n(xi)|.
   *
   * Why: with bilinear faces the normal jumps across every face edge, so
   * the node-to-segment gap and force of a slave node change
   * discontinuously as it slides across an edge of a bent master, and
   * Newton stalls there however small the increment (the 3D ironing). On
   * an edge shared by two faces both interpolate the same two nodal
   * normals with the same functions, so the projection, the gap and the
   * force are continuous across it.
   *
   * The stencil: the face's vertices are nodes 0 .. n_vertices - 1 of the
   * position array (MasterFace<3> or TriangleFace order), the other
   * vertices of the faces around them follow; fan[v] lists the faces
   * around vertex v as indices into that array.
   */
  struct SmoothedFace
  {
    /** The most nodes of a stencil and faces around one vertex. */
    static constexpr unsigned int max_nodes = 40;
    static constexpr unsigned int max_fan   = 12;

    /** One face around a vertex: its vertices (stencil indices, in its
     * own MasterFace<3> or TriangleFace order) and which of them is the
     * vertex. */
    struct Corner
    {
      unsigned int n_vertices = 4;
      unsigned int nodes[4]   = {0, 0, 0, 0};
      unsigned int corner     = 0;
    };

    /** The face's kind: Quadrilateral4 or Triangle3. */
    FaceShape    kind       = FaceShape::of<Quadrilateral4>();
    unsigned int n_vertices = 4;
    unsigned int n_nodes    = 4;
    Corner       fan[4][max_fan];
    unsigned int n_fan[4] = {0, 0, 0, 0};

    /**
     * The smoothed face of face @p f of a surface whose faces have the
     * vertices @p face_vertices (3 or 4 node numbers each, in
     * MasterFace<3> or TriangleFace order) and whose nodes belong to the
     * faces @p node_faces; @p ring: the other vertices of the faces that
     * share a vertex with f. @p stencil gets the node numbers of the
     * stencil (f's vertices, then @p ring). Returns false if the stencil
     * exceeds max_nodes or a fan max_fan.
     */
    static bool
    make(const std::vector<std::vector<unsigned int>> &face_vertices,
         const std::vector<std::vector<unsigned int>> &node_faces,
         const unsigned int                            f,
         const std::vector<unsigned int>              &ring,
         SmoothedFace                                 &shape,
         std::vector<unsigned int>                    &stencil)
    {
      const auto &vertices = face_vertices[f];
      stencil              = vertices;
      stencil.insert(stencil.end(), ring.begin(), ring.end());
      if (stencil.size() > max_nodes)
        return false;
      std::map<unsigned int, unsigned int> local;
      for (unsigned int i = 0; i < stencil.size(); ++i)
        local[stencil[i]] = i;
      shape.n_vertices = vertices.size();
      shape.kind       = shape.n_vertices == 3 ? FaceShape::of<Triangle3>() :
                                                 FaceShape::of<Quadrilateral4>();
      shape.n_nodes    = stencil.size();
      for (unsigned int a = 0; a < vertices.size(); ++a)
      {
        const auto &fan = node_faces[vertices[a]];
        if (fan.size() > max_fan)
          return false;
        shape.n_fan[a] = fan.size();
        for (unsigned int i = 0; i < fan.size(); ++i)
        {
          const auto &other  = face_vertices[fan[i]];
          Corner     &corner = shape.fan[a][i];
          corner.n_vertices  = other.size();
          for (unsigned int v = 0; v < other.size(); ++v)
          {
            corner.nodes[v] = local.at(other[v]);
            if (other[v] == vertices[a])
              corner.corner = v;
          }
        }
      }
      return true;
    }

    /** Whether the face is a triangle. */
    bool
    triangle() const
    {
      return kind.triangle();
    }

    /**
     * The unit normal of face @p c at its vertex c.corner: the cross
     * product of its two edges there (a triangle: of any two edges).
     */
    template <typename Number>
    static Vec3<Number>
    corner_normal(const Vec3<Number> *x, const Corner &c)
    {
      const unsigned int *v = c.nodes;
      Vec3<Number>        e1, e2;
      if (c.n_vertices == 3)
      {
        e1 = x[v[1]] - x[v[0]];
        e2 = x[v[2]] - x[v[0]];
      }
      else
      {
        // Lexicographic vertices: xi_1 runs 0 -> 1 and 2 -> 3, xi_2 runs
        // 0 -> 2 and 1 -> 3; at a corner the edges from it along each.
        const unsigned int i = c.corner;
        e1                   = (i < 2) ? x[v[1]] - x[v[0]] : x[v[3]] - x[v[2]];
        e2 = (i % 2 == 0) ? x[v[2]] - x[v[0]] : x[v[3]] - x[v[1]];
      }
      const Vec3<Number> n = cross(e1, e2);
      return scale(1. / norm(n), n);
    }

    /** The averaged nodal normals of the face's vertices (unit). */
    template <typename Number>
    void
    nodal_normals(const Vec3<Number> *x, Vec3<Number> *n) const
    {
      for (unsigned int a = 0; a < n_vertices; ++a)
      {
        Vec3<Number> sum{{Number(0.), Number(0.), Number(0.)}};
        for (unsigned int i = 0; i < n_fan[a]; ++i)
          sum = sum + corner_normal(x, fan[a][i]);
        n[a] = scale(1. / norm(sum), sum);
      }
    }

    /** Shape values and derivatives of the face at @p xi. */
    template <typename Number>
    void
    shape(const Number *xi, Number *N, Number (*dN)[2]) const
    {
      kind.visit_linear<3>([&](auto k) { decltype(k)::shape(xi, N, dN); });
    }

    /**
     * At @p xi: the point xbar, its tangents a_alpha, the interpolated
     * normal n(xi) (not normalized) and its derivatives dn/dxi_alpha, from
     * the positions @p x and the nodal normals @p nodal.
     */
    template <typename Number, typename XiNumber>
    void
    field(const Vec3<Number> *x,
          const Vec3<Number> *nodal,
          const XiNumber     *xi,
          Vec3<Number>       &xbar,
          Vec3<Number>       *a,
          Vec3<Number>       &n,
          Vec3<Number>       *dn) const
    {
      XiNumber N[4], dN[4][2];
      shape(xi, N, dN);
      for (unsigned int d = 0; d < 3; ++d)
      {
        xbar[d] = 0.;
        n[d]    = 0.;
        for (unsigned int alpha = 0; alpha < 2; ++alpha)
        {
          a[alpha][d]  = 0.;
          dn[alpha][d] = 0.;
        }
        for (unsigned int k = 0; k < n_vertices; ++k)
        {
          xbar[d] += N[k] * x[k][d];
          n[d] += N[k] * nodal[k][d];
          for (unsigned int alpha = 0; alpha < 2; ++alpha)
          {
            a[alpha][d] += dN[k][alpha] * x[k][d];
            dn[alpha][d] += dN[k][alpha] * nodal[k][d];
          }
        }
      }
    }

    /**
     * The 3 x 3 matrix J = d r / d(xi_1, xi_2, g) of the projection
     * condition r = x_s - xbar(xi) - g n(xi) = 0 (columns -a_alpha - g
     * dn/dxi_alpha and -n), and its inverse in @p inverse. Returns false if
     * it is singular.
     */
    static bool
    inverse_jacobian(const Vec3<double> *a,
                     const Vec3<double> &n,
                     const Vec3<double> *dn,
                     const double        g,
                     double (&inverse)[3][3])
    {
      const Vec3<double> c[3] = {scale(-1., a[0] + scale(g, dn[0])),
                                 scale(-1., a[1] + scale(g, dn[1])),
                                 scale(-1., n)};
      // The inverse of the matrix with columns c_j has rows (c_k x c_l)/det.
      const double det = dot(c[0], cross(c[1], c[2]));
      if (!(std::abs(det) > 1e-300) || !std::isfinite(det))
        return false;
      const Vec3<double> rows[3] = {cross(c[1], c[2]),
                                    cross(c[2], c[0]),
                                    cross(c[0], c[1])};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          inverse[i][j] = rows[i][j] / det;
      return true;
    }

    /**
     * Local coordinates @p xi and normal distance @p g of the point of the
     * face (or its extension) whose interpolated normal line passes
     * through @p point: Newton on the projection condition from the
     * closest point of the faceted face. Returns false where it does not
     * converge (far on the concave side, where the normal lines do not
     * reach). The result is not clamped.
     */
    bool
    project(const Vec3<double> &point,
            const Vec3<double> *x,
            double             *xi,
            double             &g) const
    {
      Vec3<double> nodal[4];
      nodal_normals(x, nodal);
      const Projection start = kind.visit_linear<3>(
        [&](auto k) { return decltype(k)::project(point, x, false); });
      xi[0] = start.xi[0];
      xi[1] = start.xi[1];
      Vec3<double> xbar, a[2], n, dn[2];
      field(x, nodal, xi, xbar, a, n, dn);
      g = dot(point - xbar, n) / dot(n, n);
      // Converged once the step is at the round-off of the coordinates:
      // a fixed 1e-14 of the face size is below it where the coordinates
      // are large against the face (12 against 0.3 on the ironing's
      // foundation), the iteration then ran out and the projection was
      // lost, and the node's force jumped between Newton iterates.
      double size = 0, magnitude = norm(point);
      for (unsigned int k = 0; k < n_vertices; ++k)
      {
        size      = std::max(size, norm(x[k] - x[0]));
        magnitude = std::max(magnitude, norm(x[k]));
      }
      const double round_off =
        64 * std::numeric_limits<double>::epsilon() * magnitude;
      double last = std::numeric_limits<double>::infinity();
      for (unsigned int iteration = 0; iteration < 30; ++iteration)
      {
        field(x, nodal, xi, xbar, a, n, dn);
        const Vec3<double> r = point - xbar - scale(g, n);
        double             inverse[3][3];
        if (!inverse_jacobian(a, n, dn, g, inverse))
          return false;
        double step[3];
        for (unsigned int i = 0; i < 3; ++i)
          step[i] = -(inverse[i][0] * r[0] + inverse[i][1] * r[1] +
                      inverse[i][2] * r[2]);
        xi[0] += step[0];
        xi[1] += step[1];
        g += step[2];
        if (!std::isfinite(g) || std::abs(xi[0]) > 10 || std::abs(xi[1]) > 10)
          return false;
        // The step in length units (xi spans the face's size over 2).
        last = std::max(0.5 * size * (std::abs(step[0]) + std::abs(step[1])),
                        std::abs(step[2]));
        if (last <= std::max(1e-14 * size, round_off))
          return true;
      }
      // Round-off that the test above does not see ends the iteration
      // here; a projection that still moves is none.
      return last <= 1e-10 * size;
    }

    /** Whether @p xi lies on the face or its extension by @p band. */
    bool
    within(const double *xi, const double band) const
    {
      return kind.visit_linear<3>([&](auto k)
                                  { return decltype(k)::within(xi, band); });
    }

    /** How far @p xi lies outside the face (0 inside), in the units of
     * MasterFace::within()'s band. */
    double
    outside(const double *xi) const
    {
      return kind.visit_linear<3>([&](auto k)
                                  { return decltype(k)::outside(xi); });
    }
  };
} // namespace tribos

#endif
