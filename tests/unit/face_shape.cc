// ctest: labels quick
/**
 * The six kinds of contact face (include/tribos/contact/surface/
 * face_kinds.h) and their run-time handle FaceShape: per kind, the
 * functions are 1 at their own node and 0 at the others, sum to one, and
 * their gradients are those of central differences; values() and shape()
 * agree; the tables (edges of the linear face, middles of edges, the
 * flip that turns the normal over) agree with the support points; the
 * tributary integrals on flat faces are the closed forms (h/2; h/6, 2h/3,
 * h/6; A/4; A/3; the six-node triangle's modified basis 2A/15 and A/5;
 * A/36, A/9, 4A/9), by both paths where a kind has two (straight and
 * curved), and the ring of an axisymmetric segment; for_cells() picks the
 * kind of every mesh and refuses a cubic one with its message.
 */

#include <tribos/contact/surface/face_shape.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace tribos;

namespace
{
  unsigned int n_failed = 0;

  std::string
  sci(const double value)
  {
    std::ostringstream out;
    out << std::scientific << std::setprecision(1) << value;
    return out.str();
  }

  void
  check(const bool condition, const std::string &message)
  {
    std::cout << (condition ? "ok      " : "FAILED  ") << message << '\n';
    if (!condition)
      ++n_failed;
  }

  /** The node's function at the support points, their sum, and the
   * gradients against central differences. */
  template <class K>
  void
  check_functions(const std::string &name)
  {
    constexpr unsigned int n           = K::n_nodes;
    double                 worst_delta = 0, worst_sum = 0, worst_values = 0;
    for (unsigned int j = 0; j < n; ++j)
    {
      double N[n], dN[n][2];
      K::shape(K::support_points[j], N, dN);
      for (unsigned int i = 0; i < n; ++i)
        worst_delta =
          std::max(worst_delta, std::abs(N[i] - (i == j ? 1. : 0.)));
    }
    double worst_gradient = 0;
    // Points inside every kind's reference face.
    const double points[3][2] = {{0.1, 0.2}, {0.3, 0.05}, {0.25, 0.6}};
    for (const auto &xi : points)
    {
      double N[n], dN[n][2], values[n];
      K::shape(xi, N, dN);
      K::values(xi, values);
      double sum = 0, gradient_sum[2] = {0, 0};
      for (unsigned int i = 0; i < n; ++i)
      {
        sum += N[i];
        worst_values = std::max(worst_values, std::abs(values[i] - N[i]));
        for (unsigned int c = 0; c < K::n_coords; ++c)
          gradient_sum[c] += dN[i][c];
      }
      worst_sum      = std::max({worst_sum,
                                 std::abs(sum - 1.),
                                 std::abs(gradient_sum[0]),
                                 std::abs(gradient_sum[1])});
      const double h = 1e-6;
      for (unsigned int c = 0; c < K::n_coords; ++c)
      {
        double plus[2] = {xi[0], xi[1]}, minus[2] = {xi[0], xi[1]};
        plus[c] += h;
        minus[c] -= h;
        double N_plus[n], N_minus[n];
        K::values(plus, N_plus);
        K::values(minus, N_minus);
        for (unsigned int i = 0; i < n; ++i)
          worst_gradient =
            std::max(worst_gradient,
                     std::abs((N_plus[i] - N_minus[i]) / (2 * h) - dN[i][c]));
      }
    }
    check(worst_delta < 1e-15 && worst_sum < 1e-14 && worst_values == 0. &&
            worst_gradient < 1e-8,
          name + ": N_i(x_j) = delta_ij to " + sci(worst_delta) +
            ", sum N = 1 and sum dN = 0 to " + sci(worst_sum) +
            ", values() = shape() exactly, dN against central differences "
            "to " +
            sci(worst_gradient));
  }

  /** The linear face's tables against its support points. */
  template <class K>
  void
  check_tables(const std::string &name)
  {
    using Linear = typename K::Linear;
    bool edges   = Linear::n_vertices == K::n_vertices;
    for (unsigned int c = 0; c < Linear::n_edge_coordinates; ++c)
      for (unsigned int side = 0; side < 2; ++side)
        for (const int v : Linear::edge_nodes[c][side])
          if (v >= 0)
          {
            const double *x = Linear::support_points[v];
            // Coordinate c at side -1 or +1, on a triangle xi_c = 0 or
            // (entry 2) xi_1 + xi_2 = 1.
            const double value = c == 2 ? x[0] + x[1] : x[c];
            const double edge  = std::is_same_v<Linear, Triangle3> ?
                                   (side == 0 ? 0. : 1.) :
                                   (side == 0 ? -1. : 1.);
            edges              = edges && value == edge;
          }
    // Swapping the flip's vertices turns the normal at the centre over.
    Vec3<double> x[4];
    for (unsigned int v = 0; v < Linear::n_vertices; ++v)
      x[v] = {{Linear::support_points[v][0],
               Linear::support_points[v][1] + 0.1 * v * v,
               0.}};
    if constexpr (K::n_coords == 2)
      for (unsigned int v = 0; v < Linear::n_vertices; ++v)
        x[v] = {{Linear::support_points[v][0],
                 Linear::support_points[v][1],
                 0.05 * v}};
    Vec3<double> xbar, a[2], normal, flipped_normal;
    Linear::geometry(x, Linear::centre, xbar, a, normal);
    std::swap(x[Linear::flip[0]], x[Linear::flip[1]]);
    Linear::geometry(x, Linear::centre, xbar, a, flipped_normal);
    const bool flip    = std::abs(dot(normal, flipped_normal) + 1.) < 1e-14;
    bool       middles = true;
    if constexpr (K::n_middles > 0)
    {
      for (unsigned int e = 0; e < std::size(K::middle_edges); ++e)
        for (unsigned int c = 0; c < 2; ++c)
          middles =
            middles && K::support_points[K::n_vertices + e][c] ==
                         0.5 * (K::support_points[K::middle_edges[e][0]][c] +
                                K::support_points[K::middle_edges[e][1]][c]);
      middles = middles && K::n_middles == std::size(K::middle_edges) +
                                             (K::has_centre ? 1 : 0);
      if constexpr (K::has_centre)
        middles = middles && K::support_points[K::n_nodes - 1][0] == 0. &&
                  K::support_points[K::n_nodes - 1][1] == 0.;
    }
    check(edges && flip && middles,
          name + ": edge nodes on their edges, the flip turns the normal "
                 "over, the middles at their edges' midpoints");
  }

  /** The integrals of the kind's functions over the flat face with nodes
   * at (2 xi, 3 xi') (@p curved: by its curved path); their sum and the
   * measure. */
  std::vector<double>
  integrals(const FaceShape &shape, const bool curved, double &measure)
  {
    std::vector<Vec3<double>> x(shape.n_nodes());
    const auto                place = [&](auto kind)
    {
      for (unsigned int v = 0; v < shape.n_nodes(); ++v)
        x[v] = {{2 * decltype(kind)::support_points[v][0],
                 3 * decltype(kind)::support_points[v][1],
                 0.}};
    };
    if (shape.dim() == 2)
      shape.visit<2>(place);
    else
      shape.visit<3>(place);
    std::vector<double> area(shape.n_nodes(), 0.);
    measure = 0;
    shape.integrate(x.data(),
                    false,
                    curved,
                    [&](const unsigned int v, const double a, const double m)
                    {
                      area[v] += a;
                      if (v == 0)
                        measure += m;
                    });
    return area;
  }
} // namespace



int
main()
{
  check_functions<Segment2>("two-node segment");
  check_functions<Segment3>("three-node segment");
  check_functions<Quadrilateral4>("four-node quadrilateral");
  check_functions<Triangle3>("three-node triangle");
  check_functions<Triangle6>("six-node triangle");
  check_functions<Quadrilateral9>("nine-node quadrilateral");
  check_tables<Segment2>("two-node segment");
  check_tables<Segment3>("three-node segment");
  check_tables<Quadrilateral4>("four-node quadrilateral");
  check_tables<Triangle3>("three-node triangle");
  check_tables<Triangle6>("six-node triangle");
  check_tables<Quadrilateral9>("nine-node quadrilateral");

  // Tributary integrals on flat faces, as fractions of the face's measure
  // (2D: length 4; 3D: 24 on the quadrilaterals, 3 on the triangles).
  struct Expected
  {
    FaceShape           shape;
    std::vector<double> fractions;
    double              measure;
  };
  const std::vector<Expected> expected = {
    {FaceShape::of<Segment2>(), {0.5, 0.5}, 4},
    {FaceShape::of<Segment3>(), {1. / 6, 1. / 6, 2. / 3}, 4},
    {FaceShape::of<Quadrilateral4>(), {0.25, 0.25, 0.25, 0.25}, 24},
    {FaceShape::of<Triangle3>(), {1. / 3, 1. / 3, 1. / 3}, 3},
    {FaceShape::of<Triangle6>(), {2. / 15, 2. / 15, 2. / 15, .2, .2, .2}, 3},
    {FaceShape::of<Quadrilateral9>(),
     {1. / 36,
      1. / 36,
      1. / 36,
      1. / 36,
      1. / 9,
      1. / 9,
      1. / 9,
      1. / 9,
      4. / 9},
     24}};
  for (const auto &e : expected)
    for (const bool curved : {false, true})
    {
      double     measure = 0;
      const auto area    = integrals(e.shape, curved, measure);
      double     worst   = std::abs(measure / e.measure - 1);
      for (unsigned int v = 0; v < area.size(); ++v)
        worst =
          std::max(worst,
                   std::abs(area[v] - e.fractions[v] * e.measure) / e.measure);
      check(worst < 1e-14,
            e.shape.name() + (curved ? " (curved path)" : " (straight path)") +
              ": tributary integrals and measure of a flat face to " +
              sci(worst));
    }

  // The ring of a segment from r = 1 to r = 2: 2 pi int N r dr.
  {
    const Vec3<double> x[2]    = {{{1, 0, 0}}, {{2, 0, 0}}};
    double             area[2] = {0, 0};
    FaceShape::of<Segment2>().integrate(x,
                                        true,
                                        false,
                                        [&](const unsigned int v,
                                            const double       a,
                                            const double) { area[v] += a; });
    const double error = std::max(std::abs(area[0] / (4 * M_PI / 3) - 1),
                                  std::abs(area[1] / (5 * M_PI / 3) - 1));
    check(error < 1e-14,
          "axisymmetric segment from r = 1 to 2: 4 pi / 3 and 5 pi / 3 to " +
            sci(error));
  }

  // The kind of each mesh.
  const bool picks =
    FaceShape::for_cells(2, true, 1) == FaceShape::of<Segment2>() &&
    FaceShape::for_cells(2, false, 1) == FaceShape::of<Segment2>() &&
    FaceShape::for_cells(2, true, 2) == FaceShape::of<Segment3>() &&
    FaceShape::for_cells(2, false, 2) == FaceShape::of<Segment3>() &&
    FaceShape::for_cells(3, true, 1) == FaceShape::of<Quadrilateral4>() &&
    FaceShape::for_cells(3, true, 2) == FaceShape::of<Quadrilateral9>() &&
    FaceShape::for_cells(3, false, 1) == FaceShape::of<Triangle3>() &&
    FaceShape::for_cells(3, false, 2) == FaceShape::of<Triangle6>();
  const FaceShape tri6 = FaceShape::of<Triangle6>();
  const bool      queries =
    tri6.n_vertices() == 3 && tri6.n_middles() == 3 && tri6.n_nodes() == 6 &&
    tri6.degree() == 2 && tri6.dim() == 3 &&
    tri6.linear() == FaceShape::of<Triangle3>() && tri6.triangle() &&
    !FaceShape::of<Quadrilateral9>().triangle() &&
    FaceShape::of<Quadrilateral9>().linear() == FaceShape::of<Quadrilateral4>();
  check(picks && queries,
        "for_cells() picks the kind of every mesh; the counts and the "
        "linear face");
  std::string message;
  try
  {
    FaceShape::for_cells(3, true, 3);
  }
  catch (const std::exception &error)
  {
    message = error.what();
  }
  // deal.II wraps the message's lines.
  check(message.find("Finite element/Polynomial degree = 1 or") !=
            std::string::npos &&
          message.find("this mesh has degree 3.") != std::string::npos,
        "a cubic mesh is refused with its message");
  bool refused = false;
  try
  {
    tri6.visit<2>([](auto) {});
  }
  catch (const std::exception &)
  {
    refused = true;
  }
  check(refused, "visiting a 3D kind as a 2D one is an internal error");

  std::cout << (n_failed == 0 ? "OK" : "FAILED") << std::endl;
  return n_failed == 0 ? 0 : 1;
}
