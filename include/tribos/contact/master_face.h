#ifndef tribos_contact_master_face_h
#define tribos_contact_master_face_h

#include <tribos/contact/vec3.h>

#include <algorithm>
#include <cmath>

namespace tribos
{
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
      XiNumber N[n_nodes], dN[n_nodes][2];
      shape(xi, N, dN);
      for (unsigned int d = 0; d < 3; ++d)
      {
        xbar[d] = 0.;
        for (unsigned int alpha = 0; alpha < n_coords; ++alpha)
          a[alpha][d] = 0.;
        for (unsigned int k = 0; k < n_nodes; ++k)
        {
          xbar[d] += N[k] * x[k][d];
          for (unsigned int alpha = 0; alpha < n_coords; ++alpha)
            a[alpha][d] += dN[k][alpha] * x[k][d];
        }
      }
      if constexpr (dim == 2)
      {
        const Vec3<Number> ez{{Number(0.), Number(0.), Number(1.)}};
        normal = cross(ez, a[0]);
      }
      else
        normal = cross(a[0], a[1]);
      normal = scale(1. / norm(normal), normal);
    }
  };



  /** Result of the closest-point projection onto one master face. */
  struct Projection
  {
    double xi[2] = {0, 0};
    /** Whether a coordinate was clamped to the face boundary (-1 or 1). */
    int clamped[2] = {0, 0};
    /** Distance between the point and xbar(xi). */
    double distance = 0;
    bool
    inside() const
    {
      return clamped[0] == 0 && clamped[1] == 0;
    }
  };



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
} // namespace tribos

#endif
