// The plane geometry of the 3D mortar element (Mortar3D): polygon
// clipping, polygon areas and the overlap test in a slave face's auxiliary
// plane, shared by the element and the mortar search.

#include <tribos/contact/element/mortar_element_3d.h>

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
        Q[k] = plane.project(Y[clockwise(n_m, k)]);
      if (polygon_area(Q, n_m) <= 0)
        return false;
      const unsigned int n =
        clip_polygon(Q, n_m, plane.P_ccw, plane.n, clipped);
      return n >= 3 && polygon_area(clipped, n) > 1e-12 * plane.area;
    }
  } // namespace internal
} // namespace tribos
