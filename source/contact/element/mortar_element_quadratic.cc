#include <tribos/contact/element/mortar_element.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tribos
{
  namespace
  {
    using AD = ContactAD;

    /** 5-point Gauss on [-1, 1]: exact to degree 9. */
    constexpr unsigned int n_gauss           = 5;
    constexpr double       gauss_x[n_gauss]  = {-0.9061798459386640,
                                                -0.5384693101056831,
                                                0.,
                                                0.5384693101056831,
                                                0.9061798459386640};
    constexpr double       gauss_w[n_gauss]  = {0.2369268850561891,
                                                0.4786286704993665,
                                                0.5688888888888889,
                                                0.4786286704993665,
                                                0.2369268850561891};
    constexpr double       d2N[3]            = {1., 1., -2.};
    constexpr double       projection_limit  = 3.;
    constexpr unsigned int newton_iterations = 30;

    /** Point and tangent dx/dxi of the curve through @p x at @p xi. */
    template <typename Number, typename XiNumber>
    void
    curve(const Vec3<Number> *const *x,
          const XiNumber            &xi,
          Vec3<Number>              &point,
          Vec3<Number>              &tangent)
    {
      XiNumber N[3], dN[3];
      quadratic_segment_shape(xi, N, dN);
      for (unsigned int d = 0; d < 3; ++d)
      {
        point[d] = N[0] * (*x[0])[d] + N[1] * (*x[1])[d] + N[2] * (*x[2])[d];
        tangent[d] =
          dN[0] * (*x[0])[d] + dN[1] * (*x[1])[d] + dN[2] * (*x[2])[d];
      }
    }

    /** The second derivative of the curve (constant). */
    Vec3<double>
    curvature(const Vec3<double> *const *x)
    {
      Vec3<double> c;
      for (unsigned int d = 0; d < 3; ++d)
        c[d] = d2N[0] * (*x[0])[d] + d2N[1] * (*x[1])[d] + d2N[2] * (*x[2])[d];
      return c;
    }

    /**
     * Where the closest point of the curve through @p x to @p y lies: -1
     * before its start, +1 beyond its end (as seen along the tangent at
     * that end), 0 inside, with @p xi the root of r(xi) = (y - x(xi)) .
     * x'(xi) in (-1, 1), by Newton kept inside the bracket where r changes
     * sign (bisection if a step leaves it), and @p slope = r'(xi) there.
     * Outside, where the point lies does not matter: the overlap is
     * clipped to the segment.
     */
    int
    closest_point(const Vec3<double> *const *x,
                  const Vec3<double>        &y,
                  double                    &xi,
                  double                    &slope)
    {
      const Vec3<double> c        = curvature(x);
      const auto         residual = [&](const double at, double &derivative)
      {
        Vec3<double> p, t;
        curve(x, at, p, t);
        derivative = -dot(t, t) + dot(y - p, c);
        return dot(y - p, t);
      };
      const double r_start = residual(-1., slope);
      if (r_start <= 0)
        return -1;
      const double r_end = residual(1., slope);
      if (r_end >= 0)
        return 1;
      double low = -1., high = 1.;
      xi = std::clamp(xi, -1., 1.);
      for (unsigned int i = 0; i < 100; ++i)
      {
        const double r = residual(xi, slope);
        if (r > 0)
          low = xi;
        else
          high = xi;
        double next = slope < 0 ? xi - r / slope : 0.5 * (low + high);
        if (next <= low || next >= high)
          next = 0.5 * (low + high);
        const double step = std::abs(next - xi);
        xi                = next;
        if (step < 1e-14 || high - low < 1e-14)
          break;
      }
      residual(xi, slope);
      return 0;
    }

    /**
     * Where the line through @p p along the normal of the tangent @p t
     * meets the curve through @p x: eta with (x(eta) - p) . t = 0, by
     * Newton from @p eta, and @p slope = x'(eta) . t there. Returns false
     * if it does not converge within +-3.
     */
    bool
    along_normal(const Vec3<double> *const *x,
                 const Vec3<double>        &p,
                 const Vec3<double>        &t,
                 double                    &eta,
                 double                    &slope)
    {
      Vec3<double> y, a;
      for (unsigned int i = 0; i < newton_iterations; ++i)
      {
        curve(x, eta, y, a);
        slope = dot(a, t);
        if (slope == 0)
          return false;
        const double step = dot(y - p, t) / slope;
        eta -= step;
        if (std::abs(eta) > projection_limit)
          return false;
        // Converged at round-off: (y - p) . t carries the rounding of the
        // coordinates' size |p|, a step of about eps |p| / |x'| (a fixed
        // 1e-14 was not reached on segments below about h = 1/100 of the
        // coordinates, and the Gauss point was dropped: a jump in the
        // residual that stalled Newton on a refined Q2 patch test).
        const double floor =
          1e-14 + 64 * std::numeric_limits<double>::epsilon() * norm(p) /
                    std::max(norm(a), std::numeric_limits<double>::min());
        if (std::abs(step) < floor)
        {
          curve(x, eta, y, a);
          slope = dot(a, t);
          return true;
        }
      }
      return false;
    }

    /** The inverse of the symmetric 3 x 3 matrix @p m (row @p j only). */
    void
    inverse_row(const AD (&m)[3][3], const unsigned int j, AD *row)
    {
      AD cof[3][3];
      for (unsigned int r = 0; r < 3; ++r)
        for (unsigned int c = 0; c < 3; ++c)
        {
          const unsigned int r1 = (r + 1) % 3, r2 = (r + 2) % 3;
          const unsigned int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
          cof[r][c] = m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1];
        }
      const AD det =
        m[0][0] * cof[0][0] + m[0][1] * cof[0][1] + m[0][2] * cof[0][2];
      // (M^-1)_jk = cof_kj / det = cof_jk / det (M symmetric).
      for (unsigned int k = 0; k < 3; ++k)
        row[k] = cof[j][k] / det;
    }

    /** The unit vector out of the plane: ez x a segment's chord is its
     * normal. */
    const Vec3<double> ez{{0., 0., 1.}};

    /** A master segment's overlap with a slave segment. */
    struct Overlap
    {
      unsigned int m;
      /** The overlap in the slave segment's coordinate. */
      AD lo, hi;
    };

    /**
     * The overlap @p o of master segment @p m of @p input (its nodes'
     * positions @p xm in AD numbers) with the slave segment through @p x
     * (@p x_ad in AD numbers, its chord @p chord and the chord's normal
     * @p n_s): the closest-point projections of the master's ends onto the
     * slave curve, clipped to the segment. False if there is none (the
     * master faces the same way, or the overlap is empty). One master
     * segment at a time, apart from integrate_quadratic()'s loop over them
     * that adds up the covered fraction.
     */
    bool
    master_overlap(const MortarInput         &input,
                   const Vec3<AD>            *xm,
                   const unsigned int         m,
                   const Vec3<double> *const *x,
                   const Vec3<AD> *const     *x_ad,
                   const Vec3<double>        &chord,
                   const Vec3<double>        &n_s,
                   Overlap                   &o)
    {
      const auto         &ms   = input.master_segment[m];
      const Vec3<double> *y[3] = {&input.xm[ms[0]],
                                  &input.xm[ms[1]],
                                  &input.xm[ms[2]]};
      if (dot(cross(ez, *y[1] - *y[0]), n_s) >= 0)
        return false;
      o.m = m;
      // The master's ends on the slave curve: in double, then one
      // Newton step in AD numbers for the derivatives.
      double          ends[2];
      AD              ends_ad[2];
      const Vec3<AD> *y_ad[2] = {&xm[ms[0]], &xm[ms[1]]};
      for (unsigned int e = 0; e < 2; ++e)
      {
        ends[e] = 2. * dot(*y[e] - *x[0], chord) / dot(chord, chord) - 1.;
        double    slope;
        const int where = closest_point(x, *y[e], ends[e], slope);
        if (where != 0)
        {
          // Before or beyond the segment: clipped, no derivative.
          ends[e]    = 2. * where;
          ends_ad[e] = ends[e];
          continue;
        }
        Vec3<AD> p_ad, t_ad;
        curve(x_ad, AD(ends[e]), p_ad, t_ad);
        ends_ad[e] = ends[e] - dot(*y_ad[e] - p_ad, t_ad) / slope;
      }
      if (std::abs(ends[0] - ends[1]) < 1e-12)
        return false;
      const bool c_low = ends[0] < ends[1];
      const AD  &low   = c_low ? ends_ad[0] : ends_ad[1];
      const AD  &high  = c_low ? ends_ad[1] : ends_ad[0];
      o.lo             = low.val() > -1. ? low : AD(-1.);
      o.hi             = high.val() < 1. ? high : AD(1.);
      if (o.hi.val() <= o.lo.val())
        return false;
      return true;
    }

    /**
     * The coefficients c_k of the dual function Phi_j = sum_k c_k N_k of
     * node j (@p j_local in the segment) on the slave segment through
     * @p x_ad, of which the master covers the fraction @p covered. Apart
     * from the overlaps: it needs only the segment and the covered
     * fraction.
     */
    std::array<AD, 3>
    dual_coefficients(const MortarInput     &input,
                      const Vec3<AD> *const *x_ad,
                      const unsigned int     j_local,
                      const AD              &covered)
    {
      const AD zero(0.);

      // The dual functions of the segment as on Q1 (blended towards the
      // standard ones where the master covers it in part): Phi_j = sum_k
      // c_k N_k.
      const AD          theta = internal::dual_weight(input.dual, covered);
      std::array<AD, 3> c     = {{zero, zero, zero}};
      c[j_local]              = 1.;
      if (theta.val() > 0)
      {
        AD mass[3][3];
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int k = 0; k < 3; ++k)
            mass[i][k] = zero;
        for (unsigned int q = 0; q < n_gauss; ++q)
        {
          const double xi = gauss_x[q];
          double       N[3], dN[3];
          quadratic_segment_shape(xi, N, dN);
          Vec3<AD> p, t;
          curve(x_ad, AD(xi), p, t);
          AD weight = gauss_w[q] * norm(t);
          if (input.axisymmetric)
            weight *= p[0];
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int k = 0; k < 3; ++k)
              mass[i][k] += weight * N[i] * N[k];
        }
        AD inverse[3];
        inverse_row(mass, j_local, inverse);
        const AD d_j = mass[j_local][0] + mass[j_local][1] + mass[j_local][2];
        for (unsigned int k = 0; k < 3; ++k)
          c[k] = theta * d_j * inverse[k] + (1. - theta) * c[k];
      }
      return c;
    }
  } // namespace



  namespace internal
  {
    void
    integrate_quadratic(const MortarInput     &input,
                        const Vec3<ContactAD> *xs,
                        const Vec3<ContactAD> *xm,
                        ContactAD             *D,
                        ContactAD             *M,
                        Vec3<ContactAD>       &normal_j)
    {
      const Vec3<AD> ez_ad = to<AD>(ez);
      const AD       zero(0.);

      for (unsigned int s = 0; s < input.n_slave_segments; ++s)
      {
        const unsigned int *segment = input.slave_segment[s];
        const Vec3<double> *x[3]    = {&input.xs[segment[0]],
                                       &input.xs[segment[1]],
                                       &input.xs[segment[2]]};
        const Vec3<AD>     *x_ad[3] = {&xs[segment[0]],
                                       &xs[segment[1]],
                                       &xs[segment[2]]};
        // Node j's place in the segment: 0, 1 (ends) or 2 (middle).
        const unsigned int j_local =
          segment[0] == 0 ? 0 : (segment[1] == 0 ? 1 : 2);
        const Vec3<double> chord = *x[1] - *x[0];
        const Vec3<double> n_s   = cross(ez, chord);

        Overlap      overlaps[max_mortar_master_nodes];
        unsigned int n_overlaps = 0;
        AD           covered    = zero;
        for (unsigned int m = 0; m < input.n_master_segments; ++m)
        {
          Overlap o;
          if (!master_overlap(input, xm, m, x, x_ad, chord, n_s, o))
            continue;
          covered += 0.5 * (o.hi - o.lo);
          overlaps[n_overlaps++] = o;
        }

        const std::array<AD, 3> c =
          dual_coefficients(input, x_ad, j_local, covered);

        for (unsigned int i = 0; i < n_overlaps; ++i)
        {
          const Overlap      &o       = overlaps[i];
          const auto         &ms      = input.master_segment[o.m];
          const Vec3<double> *y[3]    = {&input.xm[ms[0]],
                                         &input.xm[ms[1]],
                                         &input.xm[ms[2]]};
          const Vec3<AD>     *y_ad[3] = {&xm[ms[0]], &xm[ms[1]], &xm[ms[2]]};
          for (unsigned int q = 0; q < n_gauss; ++q)
          {
            const AD xi =
              0.5 * (o.lo + o.hi) + 0.5 * (o.hi - o.lo) * gauss_x[q];
            Vec3<AD> p, t;
            curve(x_ad, xi, p, t);
            // The master point on the slave's normal line at xi, from the
            // projection onto the master's chord.
            Vec3<double> p_value, t_value;
            for (unsigned int d = 0; d < 3; ++d)
            {
              p_value[d] = p[d].val();
              t_value[d] = t[d].val();
            }
            const Vec3<double> master_chord = *y[1] - *y[0];
            double             eta = 2. * dot(p_value - *y[0], master_chord) /
                           dot(master_chord, master_chord) -
                         1.;
            double slope;
            if (!along_normal(y, p_value, t_value, eta, slope))
              continue;
            Vec3<AD> y_point, a;
            curve(y_ad, AD(eta), y_point, a);
            const AD eta_ad = eta - dot(y_point - p, t) / slope;

            const AD length = norm(t);
            AD       weight = 0.5 * (o.hi - o.lo) * gauss_w[q] * length;
            if (input.axisymmetric)
              weight *= 2. * M_PI * p[0];
            AD N[3], dN[3], N_m[3], dN_m[3];
            quadratic_segment_shape(xi, N, dN);
            quadratic_segment_shape(eta_ad, N_m, dN_m);
            const AD phi   = c[0] * N[0] + c[1] * N[1] + c[2] * N[2];
            const AD w_phi = weight * phi;
            for (unsigned int a_node = 0; a_node < 3; ++a_node)
            {
              D[segment[a_node]] += w_phi * N[a_node];
              M[ms[a_node]] += w_phi * N_m[a_node];
            }
            normal_j = normal_j + scale(w_phi / length, cross(ez_ad, t));
          }
        }
      }
    }
  } // namespace internal
} // namespace tribos
