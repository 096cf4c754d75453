#include <tribos/contact/surface/face_shape.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

namespace tribos
{
  using namespace dealii;

  FaceShape
  FaceShape::for_cells(const int          dim,
                       const bool         hyper_cubes,
                       const unsigned int degree)
  {
    AssertThrow(degree == 1 || degree == 2,
                ExcMessage("Contact surfaces are built for Finite element/"
                           "Polynomial degree = 1 or 2; this mesh has "
                           "degree " +
                           std::to_string(degree) + "."));
    if (dim == 2)
      return degree == 1 ? of<Segment2>() : of<Segment3>();
    if (hyper_cubes)
      return degree == 1 ? of<Quadrilateral4>() : of<Quadrilateral9>();
    return degree == 1 ? of<Triangle3>() : of<Triangle6>();
  }



  std::string
  FaceShape::name() const
  {
    const char *names[] = {"two-node segment",
                           "three-node segment",
                           "four-node quadrilateral",
                           "three-node triangle",
                           "six-node triangle",
                           "nine-node quadrilateral"};
    static_assert(std::variant_size_v<Kind> == 6);
    return names[kind.index()];
  }



  namespace
  {
    using Add = std::function<void(unsigned int, double, double)>;

    /**
     * A face's integrals by Gauss points on the chord or flat patch through
     * its vertices (@p Linear), with the functions of @p K: linear faces,
     * and the straight quadratic segment (h/6, 2h/3, h/6).
     */
    template <class K>
    void
    integrate_on_vertices(const Vec3<double> *x,
                          const bool          axisymmetric,
                          const Add          &add)
    {
      using Linear                    = typename K::Linear;
      constexpr unsigned int n_coords = K::n_coords;
      const QGauss<n_coords> quadrature(K::degree + 1);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        double xi[2] = {0, 0};
        for (unsigned int c = 0; c < n_coords; ++c)
          xi[c] = 2 * quadrature.point(q)[c] - 1;
        double N[K::n_nodes];
        K::values(xi, N);
        Vec3<double> xbar, a[2], normal;
        Linear::geometry(x, xi, xbar, a, normal);
        const double jacobian =
          (n_coords == 1 ? norm(a[0]) : norm(cross(a[0], a[1])));
        // Weights of [0,1]^(dim-1) times 2^(dim-1) for [-1,1].
        const double weight = quadrature.weight(q) * (n_coords == 1 ? 2. : 4.);
        const double ring   = axisymmetric ? 2 * numbers::PI * xbar[0] : 1.;
        for (unsigned int v = 0; v < K::n_nodes; ++v)
          add(v, N[v] * jacobian * weight * ring, jacobian * weight);
      }
    }

    /**
     * A flat triangle: each vertex's function integrates to a third of its
     * area. On the six-node triangle the vertex functions integrate to
     * zero: the areas are those of the modified basis of the mortar element
     * (Mortar3D), 2 A / 15 and A / 5.
     */
    template <class K>
    void
    integrate_flat_triangle(const Vec3<double> *x, const Add &add)
    {
      const double area  = 0.5 * norm(cross(x[1] - x[0], x[2] - x[0]));
      const double alpha = TriangleFace::modified_basis_alpha;
      for (unsigned int v = 0; v < K::n_nodes; ++v)
      {
        const double share = K::n_middles == 0 ? 1. / 3. :
                             v < 3             ? 2. * alpha / 3. :
                                                 (1. - 2. * alpha) / 3.;
        add(v, share * area, area);
      }
    }

    const QGauss<1> &
    line_rule()
    {
      static const QGauss<1> rule(4);
      return rule;
    }

    const QGauss<2> &
    square_rule()
    {
      static const QGauss<2> rule(4);
      return rule;
    }

    const QGaussSimplex<2> &
    triangle_rule()
    {
      static const QGaussSimplex<2> rule(4);
      return rule;
    }

    /** The rule of integrate_on_face<K>: 4-point Gauss on segments and per
     * direction on quadrilaterals, the 4-point-per-direction simplex rule
     * on triangles. */
    template <class K>
    const Quadrature<K::n_coords> &
    face_rule()
    {
      if constexpr (K::n_coords == 1)
        return line_rule();
      else if constexpr (std::is_same_v<typename K::Linear, Triangle3>)
        return triangle_rule();
      else
        return square_rule();
    }

    /**
     * A quadratic face on its own geometry through all its nodes: at the
     * points of face_rule<K>(), the nodes' functions (the six-node
     * triangle's modified basis) times the face's measure.
     */
    template <class K>
    void
    integrate_on_face(const Vec3<double> *x,
                      const bool          axisymmetric,
                      const Add          &add)
    {
      const auto &rule = face_rule<K>();
      for (unsigned int q = 0; q < rule.size(); ++q)
      {
        double xi[2] = {0, 0};
        for (unsigned int c = 0; c < K::n_coords; ++c)
          xi[c] = std::is_same_v<K, Triangle6> ? rule.point(q)[c] :
                                                 2 * rule.point(q)[c] - 1;
        double N[K::n_nodes], dN[K::n_nodes][2] = {};
        K::shape(xi, N, dN);
        const double weight = std::is_same_v<K, Triangle6> ?
                                rule.weight(q) :
                                (K::n_coords == 1 ? 2 : 4) * rule.weight(q);
        Vec3<double> xq{{0, 0, 0}};
        Vec3<double> a[2] = {{{0, 0, 0}}, {{0, 0, 0}}};
        for (unsigned int i = 0; i < K::n_nodes; ++i)
        {
          xq = xq + scale(N[i], x[i]);
          for (unsigned int k = 0; k < 2; ++k)
            a[k] = a[k] + scale(dN[i][k], x[i]);
        }
        if constexpr (std::is_same_v<K, Triangle6>)
        {
          // The modified basis: a vertex takes alpha of both its edges'
          // middle functions.
          const double alpha = TriangleFace::modified_basis_alpha;
          double       P2[6];
          std::copy(N, N + 6, P2);
          for (unsigned int v = 0; v < 3; ++v)
            N[v] = P2[v] + alpha * (P2[3 + v] + P2[3 + (v + 2) % 3]);
          for (unsigned int e = 0; e < 3; ++e)
            N[3 + e] = (1 - 2 * alpha) * P2[3 + e];
        }
        const double measure =
          weight * (K::n_coords == 1 ? norm(a[0]) : norm(cross(a[0], a[1])));
        const double ring = axisymmetric ? 2 * numbers::PI * xq[0] : 1.;
        for (unsigned int v = 0; v < K::n_nodes; ++v)
          add(v, N[v] * measure * ring, measure);
      }
    }

    /** The integrals of a face of kind @p K: a nine-node quadrilateral on
     * its own geometry, other quadratic faces too where they are curved,
     * flat triangles in closed form, the rest by Gauss points on their
     * vertices. */
    template <class K>
    void
    integrate_kind(const Vec3<double> *x,
                   const bool          axisymmetric,
                   const bool          curved,
                   const Add          &add)
    {
      if constexpr (std::is_same_v<K, Quadrilateral9>)
        integrate_on_face<K>(x, axisymmetric, add);
      else
      {
        if constexpr (K::degree == 2)
          if (curved)
          {
            integrate_on_face<K>(x, axisymmetric, add);
            return;
          }
        if constexpr (std::is_same_v<typename K::Linear, Triangle3>)
          integrate_flat_triangle<K>(x, add);
        else
          integrate_on_vertices<K>(x, axisymmetric, add);
      }
    }
  } // namespace



  void
  FaceShape::integrate(
    const Vec3<double>                                      *x,
    const bool                                               axisymmetric,
    const bool                                               curved,
    const std::function<void(unsigned int, double, double)> &add) const
  {
    std::visit([&](auto k)
               { integrate_kind<decltype(k)>(x, axisymmetric, curved, add); },
               kind);
  }
} // namespace tribos
