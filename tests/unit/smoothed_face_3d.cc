// ctest: labels quick
/**
 * Unit test of the 3D smoothed master (SmoothedFace, NodeToSmoothedFace;
 * Contact/Master smoothing = averaged normals in 3D), on a warped 3 x 3
 * patch of bilinear quadrilaterals and on a fan of six triangles:
 *
 * 1. Continuity across a face edge (the reason for the smoothing): a slave
 *    point on the edge between two faces, sticking with a history
 *    committed on one of them, its element evaluated on either face gives
 *    the same gap and the same nodal forces (assembled onto the surface's
 *    nodes, friction included) to 1e-9 relative; the
 *    faceted element (NodeToSegment) jumps there by more than 0.1 %, so the
 *    check can fail.
 * 2. The tangent (Sacado AD) against central finite differences of the
 *    residual, each perturbed residual with a fresh smoothed projection:
 *    random positions, open, stick and slip, penalty and Lagrange
 *    multipliers; relative error below 1e-6.
 * 3. Objectivity: the patch, the slave and the committed state rotated
 *    rigidly (the committed traction too) give the rotated forces of the
 *    unrotated sticking element to 1e-9 (the committed traction turns with
 *    the normal and spins with the face).
 */

#include <tribos/contact/element/contact_element.h>
#include <tribos/contact/enforcement/lagrange_multiplier.h>
#include <tribos/contact/enforcement/penalty.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

using namespace tribos;

namespace
{
  /** A surface: node positions and faces (their vertices). */
  struct Surface
  {
    std::vector<Vec3<double>>              x;
    std::vector<std::vector<unsigned int>> faces;

    std::vector<std::vector<unsigned int>>
    node_faces() const
    {
      std::vector<std::vector<unsigned int>> result(x.size());
      for (unsigned int f = 0; f < faces.size(); ++f)
        for (const unsigned int v : faces[f])
          result[v].push_back(f);
      return result;
    }

    /** The other vertices of the faces that share a vertex with @p f. */
    std::vector<unsigned int>
    ring(const unsigned int f) const
    {
      std::vector<unsigned int> result;
      for (unsigned int g = 0; g < faces.size(); ++g)
      {
        bool shares = false;
        for (const unsigned int v : faces[g])
          for (const unsigned int w : faces[f])
            shares = shares || v == w;
        if (shares)
          for (const unsigned int v : faces[g])
          {
            bool known = false;
            for (const unsigned int w : faces[f])
              known = known || v == w;
            for (const unsigned int w : result)
              known = known || v == w;
            if (!known)
              result.push_back(v);
          }
      }
      return result;
    }
  };

  /** A 4 x 4 grid of nodes on z = 0.15 sin(x) cos(y) plus noise, its 3 x 3
   * quadrilaterals (lexicographic vertices, normal +z). */
  Surface
  quad_patch(std::mt19937 &random, const double noise)
  {
    std::uniform_real_distribution<double> u(-1, 1);
    Surface                                s;
    for (unsigned int j = 0; j < 4; ++j)
      for (unsigned int i = 0; i < 4; ++i)
        s.x.push_back(
          {{i + noise * u(random),
            j + noise * u(random),
            0.3 * std::sin(1.3 * i) * std::cos(0.9 * j) + noise * u(random)}});
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int i = 0; i < 3; ++i)
        s.faces.push_back(
          {4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i, 4 * (j + 1) + i + 1});
    return s;
  }

  /** A hexagon of six triangles around a raised centre (node 0). */
  Surface
  triangle_fan(std::mt19937 &random, const double noise)
  {
    std::uniform_real_distribution<double> u(-1, 1);
    Surface                                s;
    s.x.push_back({{0, 0, 0.2 + noise * u(random)}});
    for (unsigned int k = 0; k < 6; ++k)
      s.x.push_back({{std::cos(k * M_PI / 3) + noise * u(random),
                      std::sin(k * M_PI / 3) + noise * u(random),
                      noise * u(random)}});
    for (unsigned int k = 0; k < 6; ++k)
      s.faces.push_back({0, 1 + k, 1 + (k + 1) % 6});
    return s;
  }

  template <int dim>
  const Enforcement<dim> &
  enforcement(const bool unknowns)
  {
    static const Parameters::Contact     parameters{};
    static const Penalty<dim>            penalty;
    static const LagrangeMultiplier<dim> multipliers(parameters);
    if (unknowns)
      return multipliers;
    return penalty;
  }

  /** Everything one evaluation of the element needs besides positions. */
  struct Setup
  {
    Surface                   surface;
    unsigned int              face = 0;
    SmoothedFace              shape;
    std::vector<unsigned int> stencil;
    std::vector<Vec3<double>> old;
    NodeState                 committed;
    ContactLaw                law;
    /** The face of the committed state (surface numbering), -1: none. */
    int committed_face = -1;
  };

  Setup
  make_setup(const Surface &surface, const unsigned int face)
  {
    Setup setup;
    setup.surface = surface;
    setup.face    = face;
    if (!SmoothedFace::make(surface.faces,
                            surface.node_faces(),
                            face,
                            surface.ring(face),
                            setup.shape,
                            setup.stencil))
      throw std::runtime_error("stencil too large");
    setup.old                      = surface.x;
    setup.law.normal_penalty       = 1e3;
    setup.law.tangential_penalty   = 5e2;
    setup.law.friction_coefficient = 0.3;
    return setup;
  }

  /**
   * The element of @p slave on the setup's face with the node positions
   * @p x (the surface's numbering); false if the smoothed projection
   * fails or lies outside the face by more than @p band. R, K in the
   * element's dof order (slave, stencil, multipliers).
   */
  bool
  evaluate(const Setup                     &setup,
           const Vec3<double>              &slave,
           const std::vector<Vec3<double>> &x,
           const Vec3<double>              *unknowns,
           double                          *R,
           double                          *K,
           ContactPointResult              &result,
           const double                     band = 0)
  {
    SmoothedFaceInput input;
    input.face = setup.shape;
    for (unsigned int i = 0; i < setup.stencil.size(); ++i)
      input.x[i] = x[setup.stencil[i]];
    for (unsigned int v = 0; v < setup.shape.n_vertices; ++v)
      input.x_old[v] = setup.old[setup.stencil[v]];
    if (!setup.shape.project(slave, input.x, input.xi, input.g) ||
        setup.shape.outside(input.xi) > band)
      return false;
    // The committed face's vertices in the stencil, as the discretization
    // finds them.
    if (setup.committed_face >= 0)
    {
      const auto &vertices = setup.surface.faces[setup.committed_face];
      bool        found    = true;
      for (unsigned int v = 0; v < vertices.size() && found; ++v)
      {
        const auto i =
          std::find(setup.stencil.begin(), setup.stencil.end(), vertices[v]);
        found                       = i != setup.stencil.end();
        input.committed_vertices[v] = i - setup.stencil.begin();
        input.committed_old[v]      = setup.old[vertices[v]];
      }
      input.n_committed_vertices = found ? vertices.size() : 0;
    }
    SlaveInput s;
    s.position   = slave;
    s.committed  = &setup.committed;
    s.law        = setup.law;
    s.area       = 0.7;
    s.consistent = true;
    s.unknowns   = unknowns;
    result       = NodeToSmoothedFace::evaluate(s,
                                          input,
                                          enforcement<3>(unknowns != nullptr),
                                          R,
                                          K);
    return true;
  }

  /** The nodal forces of an element assembled onto the surface's nodes
   * (3 per node, the slave's first). */
  std::vector<double>
  assembled(const Setup &setup, const std::vector<double> &R)
  {
    std::vector<double> forces(3 * (1 + setup.surface.x.size()), 0.);
    for (unsigned int d = 0; d < 3; ++d)
      forces[d] = R[d];
    for (unsigned int i = 0; i < setup.stencil.size(); ++i)
      for (unsigned int d = 0; d < 3; ++d)
        forces[3 * (1 + setup.stencil[i]) + d] += R[3 * (1 + i) + d];
    return forces;
  }

  double
  difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    double diff = 0, size = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
    {
      diff += std::pow(a[i] - b[i], 2);
      size += std::pow(a[i], 2);
    }
    return std::sqrt(diff / size);
  }

  /**
   * Part 1: a slave on the edge between faces @p f and @p g of @p surface
   * (at the point of that edge with parameter @p s, a little inside the
   * master), evaluated on either face. Returns the relative differences of
   * the smoothed (@p smoothed) and of the faceted forces.
   */
  void
  edge_continuity(const Surface     &surface,
                  const unsigned int f,
                  const unsigned int g,
                  const unsigned int a,
                  const unsigned int b,
                  const double       s,
                  double            &smoothed,
                  double            &faceted,
                  double            &gap_jump)
  {
    Setup on_f = make_setup(surface, f), on_g = make_setup(surface, g);
    // A point on the smoothed normal line through the edge point: the
    // smoothed projection puts it on the edge from both faces.
    Vec3<double> nodal[4];
    // The edge point and the interpolated normal there (from f's nodal
    // normals at a and b).
    Vec3<double> xm[SmoothedFace::max_nodes];
    for (unsigned int i = 0; i < on_f.stencil.size(); ++i)
      xm[i] = surface.x[on_f.stencil[i]];
    on_f.shape.nodal_normals(xm, nodal);
    unsigned int la = 0, lb = 0;
    for (unsigned int i = 0; i < on_f.shape.n_vertices; ++i)
    {
      if (on_f.stencil[i] == a)
        la = i;
      if (on_f.stencil[i] == b)
        lb = i;
    }
    const Vec3<double> point =
      scale(1 - s, surface.x[a]) + scale(s, surface.x[b]);
    const Vec3<double> normal = scale(1 - s, nodal[la]) + scale(s, nodal[lb]);
    const Vec3<double> slave  = point - scale(0.01 / norm(normal), normal);
    // A sticking history committed on face f: the surface has moved a
    // little since, the traction is tangent to the committed normal.
    for (Setup *setup : {&on_f, &on_g})
    {
      for (unsigned int k = 0; k < surface.x.size(); ++k)
        setup->old[k] =
          surface.x[k] + Vec3<double>{{0.004 * std::sin(3. * k + s),
                                       0.004 * std::cos(2. * k),
                                       0.003 * std::sin(5. * k)}};
      const Vec3<double> n           = scale(1. / norm(normal), normal);
      setup->committed.result.status = ContactStatus::stick;
      setup->committed.result.xi[0]  = 0.3;
      setup->committed.result.xi[1]  = -0.2;
      setup->committed.result.normal = n;
      setup->committed.point         = point + Vec3<double>{{0.003, -0.002, 0}};
      const Vec3<double> t{{1, 0.5, 0}};
      setup->committed.result.traction = scale(30., t - scale(dot(t, n), n));
      setup->committed_face            = f;
    }

    std::vector<double> Rf(3 * (1 + on_f.stencil.size())),
      Rg(3 * (1 + on_g.stencil.size()));
    ContactPointResult rf, rg;
    if (!evaluate(on_f,
                  slave,
                  surface.x,
                  nullptr,
                  Rf.data(),
                  nullptr,
                  rf,
                  1e-8) ||
        !evaluate(on_g,
                  slave,
                  surface.x,
                  nullptr,
                  Rg.data(),
                  nullptr,
                  rg,
                  1e-8))
      throw std::runtime_error("the edge point does not project");
    smoothed = difference(assembled(on_f, Rf), assembled(on_g, Rg));
    gap_jump = std::abs(rf.gap - rg.gap) / std::abs(rf.gap);

    // The faceted element at the same point, on either face.
    const auto faceted_forces = [&](const Setup &setup)
    {
      FaceInput<3> input;
      input.shape = setup.shape.triangle() ? FaceShape::of<Triangle3>() :
                                             FaceShape::of<Quadrilateral4>();
      for (unsigned int v = 0; v < setup.shape.n_vertices; ++v)
      {
        input.x[v]     = surface.x[setup.stencil[v]];
        input.x_old[v] = input.x[v];
      }
      input.projection = setup.shape.triangle() ?
                           project_triangle(slave, input.x, false) :
                           project<3>(slave, input.x, false);
      SlaveInput si;
      si.position  = slave;
      si.committed = &setup.committed;
      si.law       = setup.law;
      si.area      = 0.7;
      std::vector<double> R(3 * (1 + setup.shape.n_vertices));
      NodeToSegment<3>::evaluate(si,
                                 input,
                                 enforcement<3>(false),
                                 R.data(),
                                 nullptr);
      std::vector<double> forces(3 * (1 + surface.x.size()), 0.);
      for (unsigned int d = 0; d < 3; ++d)
        forces[d] = R[d];
      for (unsigned int v = 0; v < setup.shape.n_vertices; ++v)
        for (unsigned int d = 0; d < 3; ++d)
          forces[3 * (1 + setup.stencil[v]) + d] += R[3 * (1 + v) + d];
      return forces;
    };
    faceted = difference(faceted_forces(on_f), faceted_forces(on_g));
  }

  /** Part 2: tangent against central differences on face @p f. */
  void
  check_tangent(std::mt19937      &random,
                const Surface     &base,
                const unsigned int f,
                const bool         multipliers,
                unsigned int      *counts,
                double            &worst,
                bool              &ok)
  {
    std::uniform_real_distribution<double> u(-1, 1);
    Setup                                  setup   = make_setup(base, f);
    const unsigned int                     n_nodes = setup.stencil.size();
    const unsigned int                     n_displacements = 3 * (1 + n_nodes);
    const unsigned int n = n_displacements + (multipliers ? 3 : 0);
    for (unsigned int sample = 0; sample < 60; ++sample)
    {
      // A point over the face, slightly in or out.
      const double w[4] = {0.25 + 0.2 * u(random),
                           0.25 + 0.2 * u(random),
                           0.25 + 0.2 * u(random),
                           0.25 + 0.2 * u(random)};
      Vec3<double> centre{{0, 0, 0}}, normal{{0, 0, 0}};
      double       total = 0;
      for (unsigned int v = 0; v < setup.shape.n_vertices; ++v)
      {
        centre = centre + scale(w[v], base.x[setup.stencil[v]]);
        total += w[v];
      }
      centre = scale(1. / total, centre);
      {
        Vec3<double> xm[SmoothedFace::max_nodes], nodal[4];
        for (unsigned int i = 0; i < n_nodes; ++i)
          xm[i] = base.x[setup.stencil[i]];
        setup.shape.nodal_normals(xm, nodal);
        for (unsigned int v = 0; v < setup.shape.n_vertices; ++v)
          normal = normal + nodal[v];
        normal = scale(1. / norm(normal), normal);
      }
      const Vec3<double> slave =
        centre + scale(-0.03 + 0.04 * u(random), normal);
      // History: the old positions moved a little, a committed stick
      // state on this face (or another), a traction tangent to its normal.
      for (unsigned int i = 0; i < base.x.size(); ++i)
        for (unsigned int d = 0; d < 3; ++d)
          setup.old[i][d] = base.x[i][d] + 0.01 * u(random);
      setup.committed_face          = sample % 2 == 0 ? int(f) : -1;
      setup.committed               = NodeState();
      setup.committed.result.status = ContactStatus::stick;
      setup.committed.result.xi[0]  = 0.3 * u(random);
      setup.committed.result.xi[1]  = 0.3 * u(random);
      setup.committed.result.normal = normal;
      setup.committed.point =
        centre + scale(0.02, Vec3<double>{{u(random), u(random), 0}});
      const Vec3<double> traction{{3 * u(random), 3 * u(random), 0}};
      setup.committed.result.traction =
        traction - scale(dot(traction, normal), normal);
      setup.law.tangential_penalty = 5e2 * (1 + 0.5 * u(random));
      Vec3<double> lambda{{3 * u(random), 3 * u(random), 0}};
      lambda = lambda - scale(10 * (1 + 0.5 * u(random)), normal);

      const auto residual = [&](const std::vector<double> &dx,
                                double                    *R,
                                double                    *K,
                                ContactPointResult        &result)
      {
        Vec3<double>              s = slave, l = lambda;
        std::vector<Vec3<double>> x = base.x;
        for (unsigned int d = 0; d < 3; ++d)
        {
          s[d] += dx[d];
          for (unsigned int i = 0; i < n_nodes; ++i)
            x[setup.stencil[i]][d] += dx[3 * (1 + i) + d];
          if (multipliers)
            l[d] += dx[n_displacements + d];
        }
        return evaluate(setup, s, x, multipliers ? &l : nullptr, R, K, result);
      };
      std::vector<double> zero(n, 0.), R(n), K(n * n);
      ContactPointResult  result;
      if (!residual(zero, R.data(), K.data(), result))
        continue;
      const double        h     = 1e-7;
      double              error = 0, size = 0;
      bool                comparable = true;
      std::vector<double> Rp(n), Rm(n);
      for (unsigned int j = 0; j < n && comparable; ++j)
      {
        std::vector<double> plus(n, 0.), minus(n, 0.);
        plus[j]  = h;
        minus[j] = -h;
        ContactPointResult rp, rm;
        comparable = residual(plus, Rp.data(), nullptr, rp) &&
                     residual(minus, Rm.data(), nullptr, rm) &&
                     rp.status == result.status && rm.status == result.status;
        for (unsigned int i = 0; i < n && comparable; ++i)
        {
          const double fd = (Rp[i] - Rm[i]) / (2 * h);
          error += std::pow(K[i * n + j] - fd, 2);
          size += std::pow(K[i * n + j], 2);
        }
      }
      if (!comparable)
        continue;
      ++counts[int(result.status)];
      if (size > 0)
      {
        worst = std::max(worst, std::sqrt(error / size));
        if (std::sqrt(error / size) > 1e-6)
          ok = false;
      }
    }
  }

  /** Part 3: rigid rotation Q of a sticking element. Returns the relative
   * difference between Q times the forces and the rotated element's. */
  double
  rotation_error(std::mt19937 &random, const Surface &base, const unsigned f)
  {
    std::uniform_real_distribution<double> u(-1, 1);
    // Rodrigues about a random axis by a random angle.
    Vec3<double> axis{{u(random), u(random), u(random)}};
    axis               = scale(1. / norm(axis), axis);
    const double angle = 1.2 * u(random);
    const auto   Q     = [&](const Vec3<double> &v)
    {
      return scale(std::cos(angle), v) +
             scale(std::sin(angle), cross(axis, v)) +
             scale((1 - std::cos(angle)) * dot(axis, v), axis);
    };
    Setup setup = make_setup(base, f);
    // The last converged state: the surface a little moved, a sticking
    // node; now (this increment) the surface moved on a little more.
    for (unsigned int i = 0; i < base.x.size(); ++i)
      for (unsigned int d = 0; d < 3; ++d)
        setup.old[i][d] = base.x[i][d] + 0.005 * u(random);
    Vec3<double> centre{{0, 0, 0}};
    for (unsigned int v = 0; v < setup.shape.n_vertices; ++v)
      centre =
        centre + scale(1. / setup.shape.n_vertices, base.x[setup.stencil[v]]);
    Vec3<double> xm[SmoothedFace::max_nodes] = {}, nodal[4];
    for (unsigned int i = 0; i < setup.stencil.size(); ++i)
      xm[i] = setup.old[setup.stencil[i]];
    double             xi[2], g;
    const Vec3<double> slave = centre + Vec3<double>{{0.01, -0.02, -0.01}};
    setup.shape.project(slave, xm, xi, g);
    Vec3<double> xbar, a[2], n, dn[2];
    setup.shape.nodal_normals(xm, nodal);
    setup.shape.field(xm, nodal, xi, xbar, a, n, dn);
    n                               = scale(1. / norm(n), n);
    setup.committed.result.status   = ContactStatus::stick;
    setup.committed.result.xi[0]    = xi[0];
    setup.committed.result.xi[1]    = xi[1];
    setup.committed.result.normal   = n;
    setup.committed.point           = xbar;
    setup.committed.result.traction = scale(2., a[0] - scale(dot(a[0], n), n));
    setup.committed_face            = f;

    std::vector<double> R(3 * (1 + setup.stencil.size()));
    ContactPointResult  result;
    evaluate(setup, slave, base.x, nullptr, R.data(), nullptr, result, 0.5);

    Setup rotated = setup;
    for (auto &x : rotated.old)
      x = Q(x);
    std::vector<Vec3<double>> x = base.x;
    for (auto &y : x)
      y = Q(y);
    rotated.committed.result.normal   = Q(n);
    rotated.committed.point           = Q(xbar);
    rotated.committed.result.traction = Q(setup.committed.result.traction);
    std::vector<double> Rr(R.size());
    ContactPointResult  result_rotated;
    evaluate(rotated,
             Q(slave),
             x,
             nullptr,
             Rr.data(),
             nullptr,
             result_rotated,
             0.5);
    std::vector<double> expected(R.size());
    for (unsigned int i = 0; i < R.size(); i += 3)
    {
      const Vec3<double> f = Q(Vec3<double>{{R[i], R[i + 1], R[i + 2]}});
      for (unsigned int d = 0; d < 3; ++d)
        expected[i + d] = f[d];
    }
    return difference(expected, Rr);
  }
} // namespace



int
main()
{
  std::mt19937 random(20261128);
  bool         ok = true;

  // 1. Continuity across edges: quadrilaterals (central face 4 and its
  // neighbour 5 share nodes 6 and 10; 4 and 7 share 9 and 10) and
  // triangles (faces 0 and 1 share nodes 0 and 2).
  double worst_smoothed = 0, least_faceted = 1e300, worst_gap = 0;
  for (unsigned int sample = 0; sample < 20; ++sample)
  {
    const Surface quads = quad_patch(random, 0.1);
    const Surface fan   = triangle_fan(random, 0.05);
    const double  s     = 0.2 + 0.6 * (sample + 0.5) / 20;
    double        smoothed, faceted, gap;
    edge_continuity(quads, 4, 5, 6, 10, s, smoothed, faceted, gap);
    worst_smoothed = std::max(worst_smoothed, smoothed);
    worst_gap      = std::max(worst_gap, gap);
    least_faceted  = std::min(least_faceted, faceted);
    edge_continuity(quads, 4, 7, 9, 10, s, smoothed, faceted, gap);
    worst_smoothed = std::max(worst_smoothed, smoothed);
    worst_gap      = std::max(worst_gap, gap);
    least_faceted  = std::min(least_faceted, faceted);
    edge_continuity(fan, 0, 1, 0, 2, s, smoothed, faceted, gap);
    worst_smoothed = std::max(worst_smoothed, smoothed);
    worst_gap      = std::max(worst_gap, gap);
    least_faceted  = std::min(least_faceted, faceted);
  }
  std::cout << "edge continuity: smoothed forces differ by " << worst_smoothed
            << " (gap " << worst_gap << "), faceted by at least "
            << least_faceted << std::endl;
  if (!(worst_smoothed < 1e-9 && worst_gap < 1e-9 && least_faceted > 1e-3))
    ok = false;

  // 2. Tangent against finite differences.
  for (const bool multipliers : {false, true})
  {
    unsigned int counts[4] = {0, 0, 0, 0};
    double       worst     = 0;
    for (unsigned int patch = 0; patch < 6; ++patch)
    {
      check_tangent(random,
                    quad_patch(random, 0.1),
                    4,
                    multipliers,
                    counts,
                    worst,
                    ok);
      check_tangent(random,
                    triangle_fan(random, 0.05),
                    patch % 6,
                    multipliers,
                    counts,
                    worst,
                    ok);
    }
    std::cout << (multipliers ? "multipliers" : "penalty")
              << ": tangent vs finite differences, worst relative error "
              << worst << " (open " << counts[0] << ", stick " << counts[1]
              << ", slip " << counts[2] << ")" << std::endl;
    if (counts[0] == 0 || counts[1] == 0 || counts[2] == 0)
      ok = false;
  }

  // 3. Objectivity of a sticking node.
  double worst_rotation = 0;
  for (unsigned int sample = 0; sample < 20; ++sample)
  {
    worst_rotation =
      std::max(worst_rotation,
               rotation_error(random, quad_patch(random, 0.1), 4));
    worst_rotation =
      std::max(worst_rotation,
               rotation_error(random, triangle_fan(random, 0.05), sample % 6));
  }
  std::cout << "rigid rotation: forces differ from the rotated ones by "
            << worst_rotation << std::endl;
  if (!(worst_rotation < 1e-9))
    ok = false;

  std::cout << (ok ? "OK" : "FAILED") << std::endl;
  return ok ? 0 : 1;
}
