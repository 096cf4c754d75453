#ifndef tribos_contact_master_face_h
#define tribos_contact_master_face_h

#include <tribos/contact/surface/vec3.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribos
{
  namespace internal
  {
    /**
     * Point xbar(xi), covariant tangents a_alpha = dxbar/dxi_alpha and unit
     * normal (2D: e_z x a_1, 3D: a_1 x a_2) at @p xi of the face of shape
     * @p Face with nodes @p x.
     */
    template <class Face, typename Number, typename XiNumber>
    void
    face_geometry(const Vec3<Number> *x,
                  const XiNumber     *xi,
                  Vec3<Number>       &xbar,
                  Vec3<Number>       *a,
                  Vec3<Number>       &normal)
    {
      XiNumber N[Face::n_nodes], dN[Face::n_nodes][2];
      Face::shape(xi, N, dN);
      for (unsigned int d = 0; d < 3; ++d)
      {
        xbar[d] = 0.;
        for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
          a[alpha][d] = 0.;
        for (unsigned int k = 0; k < Face::n_nodes; ++k)
        {
          xbar[d] += N[k] * x[k][d];
          for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
            a[alpha][d] += dN[k][alpha] * x[k][d];
        }
      }
      if constexpr (Face::n_coords == 1)
      {
        const Vec3<Number> ez{{Number(0.), Number(0.), Number(1.)}};
        normal = cross(ez, a[0]);
      }
      else
        normal = cross(a[0], a[1]);
      normal = scale(1. / norm(normal), normal);
    }
  } // namespace internal



  /**
   * The shape functions of the quadratic segment on xi in [-1, 1] and
   * their derivatives: its ends (xi = -1, +1), then its middle (xi = 0).
   * The 2D Q2 and P2 contact faces are this segment; the nine-node
   * quadrilateral's functions are products of two.
   */
  template <typename Number>
  void
  quadratic_segment_shape(const Number &xi, Number *N, Number *dN)
  {
    N[0]  = 0.5 * xi * (xi - 1.);
    N[1]  = 0.5 * xi * (xi + 1.);
    N[2]  = 1. - xi * xi;
    dN[0] = xi - 0.5;
    dN[1] = xi + 0.5;
    dN[2] = -2. * xi;
  }



  /**
   * Geometry of a master face: a 2-node segment in 2D, a 4-node bilinear
   * quadrilateral in 3D (deal.II's lexicographic vertex order), with local
   * coordinates xi in [-1, 1]^(dim-1). The vertex order is chosen by the
   * surface builder so that the normal n = a_1 x a_2 / |a_1 x a_2| (3D) or
   * n = e_z x a_1 / |a_1| (2D) points out of the master body.
   */
  template <int dim>
  struct MasterFace
  {
    static constexpr unsigned int n_nodes  = (dim == 2 ? 2 : 4);
    static constexpr unsigned int n_coords = dim - 1;

    /** Shape values N_a and derivatives dN_a/dxi_alpha at @p xi. */
    template <typename Number>
    static void
    shape(const Number *xi, Number *N, Number (*dN)[2])
    {
      if constexpr (dim == 2)
      {
        N[0]     = 0.5 * (1. - xi[0]);
        N[1]     = 0.5 * (1. + xi[0]);
        dN[0][0] = -0.5;
        dN[1][0] = 0.5;
      }
      else
      {
        const double s[4][2] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
        for (unsigned int a = 0; a < 4; ++a)
        {
          N[a]     = 0.25 * (1. + s[a][0] * xi[0]) * (1. + s[a][1] * xi[1]);
          dN[a][0] = 0.25 * s[a][0] * (1. + s[a][1] * xi[1]);
          dN[a][1] = 0.25 * s[a][1] * (1. + s[a][0] * xi[0]);
        }
      }
    }

    /** Mixed second derivative d^2 N_a / dxi_1 dxi_2 (bilinear only). */
    static double
    mixed_derivative(const unsigned int a)
    {
      const double s[4][2] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
      return 0.25 * s[a][0] * s[a][1];
    }

    /**
     * Point xbar(xi), covariant tangents a_alpha and unit normal at @p xi
     * of the face with nodes @p x.
     */
    template <typename Number, typename XiNumber>
    static void
    geometry(const Vec3<Number> *x,
             const XiNumber     *xi,
             Vec3<Number>       &xbar,
             Vec3<Number>       *a,
             Vec3<Number>       &normal)
    {
      internal::face_geometry<MasterFace<dim>>(x, xi, xbar, a, normal);
    }

    /** Whether @p xi lies on the face or its extension by @p band (in
     * local coordinates) beyond each edge. */
    static bool
    within(const double *xi, const double band)
    {
      bool near = true;
      for (unsigned int c = 0; c < n_coords; ++c)
        near = near && std::abs(xi[c]) <= 1. + band;
      return near;
    }
  };



  /**
   * Geometry of a linear triangle, the face of a P1 tetrahedron: nodes 0,
   * 1, 2 (deal.II's vertex order, swapped by the surface builder so that
   * n = a_1 x a_2 / |a_1 x a_2| points out of the body) and local
   * coordinates in the unit triangle xi_1, xi_2 >= 0, xi_1 + xi_2 <= 1,
   * N_0 = 1 - xi_1 - xi_2, N_1 = xi_1, N_2 = xi_2. The same interface as
   * MasterFace<3>: the contact elements take either as a template.
   *
   * Its edges in the terms of Projection::clamped: xi_1 = 0 (entry 0,
   * side -1), xi_2 = 0 (entry 1, side -1) and xi_1 + xi_2 = 1 (entry 2,
   * side +1), the edge opposite node 1, 2 and 0 respectively.
   */
  struct TriangleFace
  {
    static constexpr unsigned int n_nodes  = 3;
    static constexpr unsigned int n_coords = 2;

    /**
     * The six-node triangle of a P2 tetrahedron in contact: its vertex
     * functions integrate to zero over a flat face, so contact works in the
     * modified basis Ntilde_v = N_v + alpha (N of the middles of v's two
     * edges), Ntilde_m = (1 - 2 alpha) N_m with this alpha (Popp, Wohlmuth,
     * Gee and Wall 2012): a partition of unity whose functions integrate to
     * 2 A / 15 (vertex) and A / 5 (middle) over a face of area A. The same
     * displacement has the coefficients u_v at a vertex and
     * (u_m - alpha (u_a + u_b)) / (1 - 2 alpha) at the middle of edge a-b.
     */
    static constexpr double modified_basis_alpha = 0.2;

    template <typename Number>
    static void
    shape(const Number *xi, Number *N, Number (*dN)[2])
    {
      N[0]     = 1. - xi[0] - xi[1];
      N[1]     = xi[0];
      N[2]     = xi[1];
      dN[0][0] = -1.;
      dN[0][1] = -1.;
      dN[1][0] = 1.;
      dN[1][1] = 0.;
      dN[2][0] = 0.;
      dN[2][1] = 1.;
    }

    /** The face is flat: no second derivatives. */
    static double
    mixed_derivative(const unsigned int)
    {
      return 0.;
    }

    template <typename Number, typename XiNumber>
    static void
    geometry(const Vec3<Number> *x,
             const XiNumber     *xi,
             Vec3<Number>       &xbar,
             Vec3<Number>       *a,
             Vec3<Number>       &normal)
    {
      internal::face_geometry<TriangleFace>(x, xi, xbar, a, normal);
    }

    /** As MasterFace::within(); the band is measured as on a
     * quadrilateral, whose local coordinates span 2, not 1. */
    static bool
    within(const double *xi, const double band)
    {
      const double b = 0.5 * band;
      return xi[0] >= -b && xi[1] >= -b && xi[0] + xi[1] <= 1. + b;
    }
  };



  /** Result of the closest-point projection onto one master face. */
  struct Projection
  {
    double xi[2] = {0, 0};
    /**
     * Whether a coordinate was clamped to the face boundary (-1 or 1);
     * on a triangle entry 2 stands for xi_1 + xi_2 (clamped to 1: +1). At
     * a corner two entries are set.
     */
    int clamped[3] = {0, 0, 0};
    /** Explicit, so that every byte of a Projection is defined: a
     * NodeState, which holds one, is written to checkpoints as bytes, and
     * the compiler's padding here would carry whatever a copy left. */
    int padding = 0;
    /** Distance between the point and xbar(xi). */
    double distance = 0;
    bool
    inside() const
    {
      return clamped[0] == 0 && clamped[1] == 0 && clamped[2] == 0;
    }

    /**
     * With exactly one edge clamped: the direction in local coordinates
     * along that edge, in which the projection still moves (returns
     * true); with none or two (a corner): false.
     */
    bool
    free_direction(double (&t)[2]) const
    {
      const int n_clamped =
        (clamped[0] != 0) + (clamped[1] != 0) + (clamped[2] != 0);
      if (n_clamped != 1)
        return false;
      if (clamped[0] != 0)
        t[0] = 0, t[1] = 1;
      else if (clamped[1] != 0)
        t[0] = 1, t[1] = 0;
      else
        t[0] = 1, t[1] = -1;
      return true;
    }
  };
  static_assert(sizeof(Projection) == 40,
                "Projection has no padding (it is written to checkpoints)");



  /**
   * Closest-point projection (1) of @p point onto the face with nodes
   * @p x: Newton on r_alpha = (x - xbar(xi)) . a_alpha = 0 with the full
   * matrix (including the curvature term of the bilinear patch); a
   * coordinate that leaves [-1, 1] is clamped and the others are solved
   * again along that edge, which gives the closest point of the face in
   * every case, deterministically. With @p clamp false the coordinates of
   * the projection onto the face's extension are returned (within +-3).
   */
  template <int dim>
  Projection
  project(const Vec3<double> &point,
          const Vec3<double> *x,
          const bool          clamp = true)
  {
    using Face = MasterFace<dim>;
    Projection   p;
    Vec3<double> xbar, a[2], n;

    for (unsigned int pass = 0; pass < 3; ++pass)
    {
      for (unsigned int iteration = 0; iteration < 25; ++iteration)
      {
        Face::geometry(x, p.xi, xbar, a, n);
        const Vec3<double> r           = point - xbar;
        double             residual[2] = {0, 0}, J[2][2] = {{0, 0}, {0, 0}};
        for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
        {
          residual[alpha] = dot(r, a[alpha]);
          for (unsigned int beta = 0; beta < Face::n_coords; ++beta)
            J[alpha][beta] = dot(a[alpha], a[beta]);
        }
        if constexpr (dim == 3)
        {
          Vec3<double> a12{{0, 0, 0}};
          for (unsigned int k = 0; k < 4; ++k)
            a12 = a12 + scale(Face::mixed_derivative(k), x[k]);
          J[0][1] -= dot(r, a12);
          J[1][0] -= dot(r, a12);
        }
        // Solve J dxi = residual on the free coordinates.
        double dxi[2] = {0, 0};
        if (dim == 2 || (p.clamped[0] == 0 && p.clamped[1] == 0))
        {
          if constexpr (dim == 2)
            dxi[0] = residual[0] / J[0][0];
          else
          {
            const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
            dxi[0] = (J[1][1] * residual[0] - J[0][1] * residual[1]) / det;
            dxi[1] = (J[0][0] * residual[1] - J[1][0] * residual[0]) / det;
          }
        }
        else
          for (unsigned int alpha = 0; alpha < 2; ++alpha)
            if (p.clamped[alpha] == 0)
              dxi[alpha] = residual[alpha] / J[alpha][alpha];

        double change = 0;
        for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
          if (p.clamped[alpha] == 0)
          {
            // Keep the iterate bounded: a projection far outside is
            // clamped anyway.
            p.xi[alpha] = std::clamp(p.xi[alpha] + dxi[alpha], -3., 3.);
            change      = std::max(change, std::abs(dxi[alpha]));
          }
        if (change < 1e-14)
          break;
      }

      // Clamp coordinates outside the face; redo if anything changed.
      bool changed = false;
      if (!clamp)
        break;
      for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
        if (p.clamped[alpha] == 0 && std::abs(p.xi[alpha]) > 1. + 1e-12)
        {
          p.clamped[alpha] = (p.xi[alpha] > 0 ? 1 : -1);
          p.xi[alpha]      = p.clamped[alpha];
          changed          = true;
        }
      if (!changed)
        break;
    }
    Face::geometry(x, p.xi, xbar, a, n);
    p.distance = norm(point - xbar);
    return p;
  }



  /**
   * Closest-point projection of @p point onto the flat triangle with
   * nodes @p x (TriangleFace): the projection onto its plane, exact in
   * one solve; outside the triangle, the closest point of its three
   * edges, with the edge (or at a corner, both edges) marked clamped.
   * With @p clamp false the coordinates of the projection onto the plane.
   */
  inline Projection
  project_triangle(const Vec3<double> &point,
                   const Vec3<double> *x,
                   const bool          clamp = true)
  {
    Projection         p;
    const Vec3<double> a1 = x[1] - x[0], a2 = x[2] - x[0], r = point - x[0];
    const double       m11 = dot(a1, a1), m12 = dot(a1, a2), m22 = dot(a2, a2),
                 det = m11 * m22 - m12 * m12;
    const double r1 = dot(r, a1), r2 = dot(r, a2);
    p.xi[0]                = (m22 * r1 - m12 * r2) / det;
    p.xi[1]                = (m11 * r2 - m12 * r1) / det;
    const double tolerance = 1e-12;
    if (clamp && !(p.xi[0] >= -tolerance && p.xi[1] >= -tolerance &&
                   p.xi[0] + p.xi[1] <= 1. + tolerance))
    {
      // The edges as (from, to) in local coordinates, and the entries of
      // Projection::clamped that an interior point of each sets.
      const double edges[3][2][2] = {{{0, 0}, {0, 1}},  // xi_1 = 0
                                     {{0, 0}, {1, 0}},  // xi_2 = 0
                                     {{1, 0}, {0, 1}}}; // xi_1 + xi_2 = 1
      const int    sides[3]       = {-1, -1, 1};
      double       best           = std::numeric_limits<double>::max();
      for (unsigned int e = 0; e < 3; ++e)
      {
        const double *from = edges[e][0], *to = edges[e][1];
        Vec3<double>  y0 = x[0], y1 = x[0];
        for (unsigned int d = 0; d < 3; ++d)
        {
          y0[d] += from[0] * a1[d] + from[1] * a2[d];
          y1[d] += to[0] * a1[d] + to[1] * a2[d];
        }
        const Vec3<double> edge = y1 - y0;
        const double       t =
          std::clamp(dot(point - y0, edge) / dot(edge, edge), 0., 1.);
        const double distance = norm(point - (y0 + scale(t, edge)));
        if (distance < best)
        {
          best = distance;
          for (unsigned int c = 0; c < 2; ++c)
            p.xi[c] = from[c] + t * (to[c] - from[c]);
          // A corner of the triangle lies on two edges.
          p.clamped[0] = (p.xi[0] == 0. ? -1 : 0);
          p.clamped[1] = (p.xi[1] == 0. ? -1 : 0);
          p.clamped[2] = (p.xi[0] + p.xi[1] == 1. ? 1 : 0);
          p.clamped[e] = sides[e];
        }
      }
    }
    Vec3<double> xbar, a[2], n;
    TriangleFace::geometry(x, p.xi, xbar, a, n);
    p.distance = norm(point - xbar);
    return p;
  }
} // namespace tribos

#endif
