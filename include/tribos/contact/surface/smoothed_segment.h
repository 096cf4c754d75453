#ifndef tribos_contact_smoothed_segment_h
#define tribos_contact_smoothed_segment_h

#include <tribos/contact/surface/master_face.h>
#include <tribos/contact/surface/vec3.h>

#include <cmath>

namespace tribos
{
  /**
   * A 2D master segment whose normal field is smoothed by averaged nodal
   * normals: n(xi) = N_0(xi) n_0 + N_1(xi) n_1, with n_a the normalized sum
   * of the unit normals of the two segments that meet at node a (the
   * segment's own normal where the surface ends). The point of the segment
   * that a slave point x_s sees is the one whose normal line passes through
   * it, (x_s - xbar(xi)) x n(xi) = 0, and the gap is
   * g = (x_s - xbar(xi)) . n(xi)/|n(xi)|.
   *
   * Why: on a faceted master the normal jumps at every vertex. A slave node
   * over a concave vertex then projects onto both segments, over a convex
   * one onto none, and the contact force changes direction (and, with a
   * penalty, magnitude) discontinuously when the node crosses the vertex.
   * Newton then cycles between the two sides, which is what stopped the
   * ironing with the punch's nodes sliding over the foundation's coarser
   * segments. With averaged normals both segments that share a vertex give
   * the same normal and the same projection there, so the projection, the
   * gap and the force are continuous along the whole surface.
   *
   * Nodes: x[0], x[1] the segment (oriented as MasterFace<2>, normal out
   * of the master), x[2] the node before x[0] and x[3] the node after x[1]
   * along the surface, used only where @p has[0], @p has[1].
   */
  struct SmoothedSegment
  {
    /** Unit normal e_z x (q - p)/|q - p| of the segment from p to q. */
    template <typename Number>
    static Vec3<Number>
    segment_normal(const Vec3<Number> &p, const Vec3<Number> &q)
    {
      const Vec3<Number> a = q - p;
      const Vec3<Number> n{{Number(-a[1]), Number(a[0]), Number(0.)}};
      return scale(1. / norm(n), n);
    }

    /** The averaged nodal normals n_0, n_1 (unit). */
    template <typename Number>
    static void
    nodal_normals(const Vec3<Number> *x,
                  const bool         *has,
                  Vec3<Number>       &n0,
                  Vec3<Number>       &n1)
    {
      const Vec3<Number> own = segment_normal(x[0], x[1]);
      n0                     = own;
      n1                     = own;
      if (has[0])
      {
        n0 = own + segment_normal(x[2], x[0]);
        n0 = scale(1. / norm(n0), n0);
      }
      if (has[1])
      {
        n1 = own + segment_normal(x[1], x[3]);
        n1 = scale(1. / norm(n1), n1);
      }
    }

    /** 2D cross product a x b (the z component). */
    template <typename Number>
    static Number
    cross2(const Vec3<Number> &a, const Vec3<Number> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /**
     * Local coordinate xi of the point of the (extended) segment whose
     * smoothed normal line passes through @p point, in double. The
     * condition is quadratic in s = (1 + xi)/2; of its roots the one
     * nearest the segment is taken. Returns false if there is none (a
     * point far on the concave side, where the normal lines do not reach)
     * or if the root is degenerate. The result is not clamped.
     */
    static bool
    project(const Vec3<double> &point,
            const Vec3<double> *x,
            const bool         *has,
            double             &xi)
    {
      Vec3<double> n0, n1;
      nodal_normals(x, has, n0, n1);
      const Vec3<double> r0 = point - x[0];
      const Vec3<double> d  = x[1] - x[0];
      const Vec3<double> m  = n1 - n0;
      // c2 s^2 + c1 s + c0 = 0
      const double c0    = cross2(r0, n0);
      const double c1    = cross2(r0, m) - cross2(d, n0);
      const double c2    = -cross2(d, m);
      const double scale = std::abs(c1) + std::abs(c0) + 1e-300;
      double       s     = 0;
      if (std::abs(c2) * 1e8 <= scale)
      {
        if (c1 == 0.)
          return false;
        s = -c0 / c1;
      }
      else
      {
        const double discriminant = c1 * c1 - 4 * c2 * c0;
        if (discriminant < 0)
          return false;
        // Stable roots: q = -(c1 + sign(c1) sqrt(D))/2, s = q/c2, c0/q.
        const double q =
          -0.5 * (c1 + std::copysign(std::sqrt(discriminant), c1));
        const double s1 = q / c2;
        const double s2 = (q != 0. ? c0 / q : s1);
        s               = (std::abs(s1 - 0.5) <= std::abs(s2 - 0.5) ? s1 : s2);
      }
      xi = 2 * s - 1;
      return std::isfinite(xi) && c1 + 2 * c2 * s != 0.;
    }

    /**
     * d/dxi of the projection condition (x_s - xbar(xi)) x n(xi) at @p xi,
     * for the implicit derivative of xi: -xbar_xi x n + (x_s - xbar) x
     * n_xi with xbar_xi = (x_1 - x_0)/2, n_xi = (n_1 - n_0)/2.
     */
    static double
    condition_derivative(const Vec3<double> &point,
                         const Vec3<double> *x,
                         const bool         *has,
                         const double        xi)
    {
      Vec3<double> n0, n1;
      nodal_normals(x, has, n0, n1);
      const double       N0 = 0.5 * (1 - xi), N1 = 0.5 * (1 + xi);
      const Vec3<double> xbar   = scale(N0, x[0]) + scale(N1, x[1]);
      const Vec3<double> normal = scale(N0, n0) + scale(N1, n1);
      return 0.5 *
             (cross2(x[0] - x[1], normal) + cross2(point - xbar, n1 - n0));
    }
  };
} // namespace tribos

#endif
