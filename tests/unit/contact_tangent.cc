// ctest: labels quick
/**
 * Unit test: the contact element's tangent (Sacado AD, Tangent =
 * consistent) against central finite differences of its residual, where
 * every perturbed residual is evaluated with a fresh closest-point
 * projection. Random configurations in 2D (segments) and 3D (warped
 * bilinear faces and the flat triangles of tetrahedra), open, stick and slip,
 * projections inside a face, clamped at its edge (a node beyond a convex
 * corner) and onto the face's extension (unclamped, as the handler keeps a face
 * within its edge band and at the free end of a master), and rigid plane,
 * sphere and cylinder; each with the penalty law and with the Lagrange
 * multiplier law (the element's rows and columns of the node's multipliers
 * included). Asserts a relative error below 1e-6, and that the `paper` tangent
 * differs (it drops the geometric terms). Then two iterates the semismooth
 * Newton meets: a tensile multiplier on the closed branch, whose Coulomb bound
 * must be mu max(0, t_N - c g_N), never negative; a node whose tangential
 * motion is fixed in both directions (on the axis of a symmetric model),
 * whose residual and tangent must be finite.
 */

#include <tribos/contact/element/contact_element.h>
#include <tribos/contact/enforcement/lagrange_multiplier.h>
#include <tribos/contact/enforcement/penalty.h>

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

using namespace tribos;

/** The enforcement of an element: multipliers (with @p unknowns) or
 * penalty. */
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

SlaveInput
slave_input(const Vec3<double> &x,
            const NodeState    &committed,
            const ContactLaw   &law,
            const double        area,
            const bool          consistent,
            const Vec3<double> *unknowns)
{
  SlaveInput slave;
  slave.position   = x;
  slave.committed  = &committed;
  slave.law        = law;
  slave.area       = area;
  slave.consistent = consistent;
  slave.unknowns   = unknowns;
  return slave;
}

template <int dim>
ContactPointResult
segment_element(const Vec3<double> &x,
                const Vec3<double> *master,
                const Projection   &projection,
                const Vec3<double> *master_old,
                const NodeState    &committed,
                const bool          same_face,
                const ContactLaw   &law,
                const double        area,
                const bool          consistent,
                double             *R,
                double             *K,
                const Vec3<double> *unknowns = nullptr,
                const bool          triangle = false)
{
  FaceInput<dim> face;
  for (unsigned int k = 0; k < MasterFace<dim>::n_nodes; ++k)
  {
    face.x[k]     = master[k];
    face.x_old[k] = master_old[k];
  }
  face.projection = projection;
  face.same_face  = same_face;
  face.shape =
    triangle ? FaceShape::of<Triangle3>() : FaceShape::of<LinearFace<dim>>();
  return NodeToSegment<dim>::evaluate(
    slave_input(x, committed, law, area, consistent, unknowns),
    face,
    enforcement<dim>(unknowns != nullptr),
    R,
    K);
}

ContactPointResult
smoothed_element(const Vec3<double> &x,
                 const Vec3<double> *master,
                 const bool         *has,
                 const double        xi,
                 const Vec3<double> *master_old,
                 const NodeState    &committed,
                 const ContactLaw   &law,
                 const double        area,
                 const bool          consistent,
                 double             *R,
                 double             *K,
                 const Vec3<double> *unknowns = nullptr)
{
  SmoothedInput segment;
  for (unsigned int k = 0; k < 4; ++k)
    segment.x[k] = master[k];
  segment.x_old[0] = master_old[0];
  segment.x_old[1] = master_old[1];
  segment.has[0]   = has[0];
  segment.has[1]   = has[1];
  segment.xi       = xi;
  return NodeToSmoothedSegment::evaluate(
    slave_input(x, committed, law, area, consistent, unknowns),
    segment,
    enforcement<2>(unknowns != nullptr),
    R,
    K);
}

template <int dim>
ContactPointResult
rigid_element(const Vec3<double>      &x,
              const RigidSurface<dim> &surface,
              const Vec3<double>      &shift,
              const Vec3<double>      &shift_old,
              const NodeState         &committed,
              const ContactLaw        &law,
              const double             area,
              const bool               consistent,
              double                  *R,
              double                  *K,
              const Vec3<double>      *unknowns = nullptr)
{
  RigidInput<dim> input;
  input.surface   = &surface;
  input.shift     = shift;
  input.shift_old = shift_old;
  return NodeToRigid<dim>::evaluate(
    slave_input(x, committed, law, area, consistent, unknowns),
    input,
    enforcement<dim>(unknowns != nullptr),
    R,
    K);
}



struct Tally
{
  unsigned int n[4]        = {0, 0, 0, 0};
  unsigned int n_clamped   = 0;
  double       worst       = 0;
  double       paper_error = 0;
};



/**
 * Compares the tangent @p K (and the `paper` tangent @p Kp, if given) of
 * an element with @p n dofs, assembled at the dof vector 0 where the
 * status is @p status, with central differences of @p residual. That
 * functor writes R at a perturbed dof vector and returns whether the
 * evaluation is comparable (same status, a valid projection); if not, a
 * kink lies within +-h, there is no derivative to compare, and the sample
 * is skipped (returns false). Otherwise the sample is counted in @p tally
 * and @p ok is cleared above a relative error of 1e-6.
 */
template <typename Residual>
bool
compare_with_differences(const unsigned int         n,
                         const ContactStatus        status,
                         const std::vector<double> &K,
                         const std::vector<double> *Kp,
                         const Residual            &residual,
                         Tally                     &tally,
                         bool                      &ok)
{
  const double        h     = 1e-7;
  double              error = 0, size = 0, paper = 0;
  std::vector<double> Rp(n), Rm(n);
  for (unsigned int j = 0; j < n; ++j)
  {
    std::vector<double> plus(n, 0.), minus(n, 0.);
    plus[j] += h;
    minus[j] -= h;
    if (!residual(plus, Rp.data()) || !residual(minus, Rm.data()))
      return false;
    for (unsigned int i = 0; i < n; ++i)
    {
      const double fd = (Rp[i] - Rm[i]) / (2 * h);
      error += std::pow(K[i * n + j] - fd, 2);
      if (Kp)
        paper += std::pow((*Kp)[i * n + j] - fd, 2);
      size += std::pow(K[i * n + j], 2);
    }
  }
  ++tally.n[int(status)];
  if (size > 0)
  {
    const double relative = std::sqrt(error / size);
    tally.worst           = std::max(tally.worst, relative);
    tally.paper_error = std::max(tally.paper_error, std::sqrt(paper / size));
    if (relative > 1e-6)
      ok = false;
  }
  else if (status != ContactStatus::open)
    ok = false;
  return true;
}



/** A random multiplier (traction on the slave): mostly compressive along
 * -@p normal, with a tangential part. */
Vec3<double>
random_multiplier(std::mt19937 &random, const unsigned int dim)
{
  std::uniform_real_distribution<double> u(-1, 1);
  Vec3<double> lambda{{3 * u(random), 3 * u(random), 3 * u(random)}};
  lambda[dim - 1] = -10 * (1 + 0.5 * u(random));
  if (dim == 2)
    lambda[2] = 0;
  return lambda;
}



/**
 * @p multipliers: the Lagrange multiplier element (dim more dofs). With
 * @p extended the slave is projected onto the face's extension (not
 * clamped), as for a node kept within the edge band or at a free end.
 * With @p triangle (3D) the master face is the triangle of a tetrahedron
 * (TriangleFace), clamped at one of its three edges or at a corner.
 */
template <int dim>
void
check_segment(std::mt19937 &random,
              Tally        &tally,
              bool         &ok,
              const bool    multipliers = false,
              const bool    extended    = false,
              const bool    triangle    = false)
{
  const unsigned int n_master        = triangle ? 3 : MasterFace<dim>::n_nodes;
  const unsigned int n_displacements = dim * (1 + n_master);
  const unsigned int n = n_displacements + (multipliers ? dim : 0);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto                             project_onto =
    [&](const Vec3<double> &x, const Vec3<double> *m, const bool clamp)
  {
    if (triangle)
      return project_triangle(x, m, clamp);
    return project<dim>(x, m, clamp);
  };

  for (unsigned int sample = 0; sample < 300; ++sample)
  {
    // A warped face around the unit square/segment, normal about +y/+z
    // (a triangle: its half below the diagonal).
    Vec3<double> master[4] = {};
    for (unsigned int k = 0; k < n_master; ++k)
    {
      master[k]    = {{0, 0, 0}};
      master[k][0] = (k % 2) + 0.1 * u(random);
      if (dim == 3)
        master[k][1] = (k / 2) + 0.1 * u(random);
      master[k][dim - 1] = 0.15 * u(random);
    }
    // Slave mostly above the face's interior, sometimes beyond an edge.
    const bool   beyond = (sample % 4 == 0);
    const double centre = triangle ? 0.33 : 0.5, spread = triangle ? 0.2 : 0.4;
    Vec3<double> slave{
      {centre + spread * u(random) + (beyond ? 0.7 : 0.), 0, 0}};
    if (dim == 3)
      slave[1] = centre + spread * u(random) - (triangle && sample % 8 == 4);
    slave[dim - 1] = -0.05 + 0.1 * u(random);

    ContactLaw law;
    law.normal_penalty       = 1e3;
    law.tangential_penalty   = 5e2 * (1 + 0.5 * u(random));
    law.friction_coefficient = 0.3;
    // Positions at the last converged step: a tangential history.
    Vec3<double> master_old[4] = {};
    for (unsigned int k = 0; k < n_master; ++k)
    {
      master_old[k] = master[k];
      for (unsigned int d = 0; d < dim; ++d)
        master_old[k][d] += 0.01 * u(random);
    }
    // The committed state: on this face (at other coordinates) or on
    // another one, its traction tangent to the committed normal.
    NodeState history;
    history.result.status = ContactStatus::stick;
    {
      // Near where the slave projects on the old face: small slips.
      const Projection old = project_onto(slave, master_old, false);
      history.result.xi[0] = old.xi[0] + 0.05 * u(random);
      history.result.xi[1] = dim == 3 ? old.xi[1] + 0.05 * u(random) : 0.;
    }
    const bool same = sample % 2 == 0;
    history.face    = same ? 0 : 1;
    {
      Vec3<double> a[2];
      if constexpr (dim == 3)
        if (triangle)
          TriangleFace::geometry(master_old,
                                 history.result.xi,
                                 history.point,
                                 a,
                                 history.result.normal);
      if (!triangle)
        MasterFace<dim>::geometry(master_old,
                                  history.result.xi,
                                  history.point,
                                  a,
                                  history.result.normal);
    }
    const Vec3<double> traction{{3 * u(random), 3 * u(random), 3 * u(random)}};
    history.result.traction =
      traction -
      scale(dot(traction, history.result.normal), history.result.normal);
    if (dim == 2)
      history.result.traction[2] = 0;
    const Vec3<double> lambda = random_multiplier(random, dim);

    const auto residual = [&](const std::vector<double> &x, double *R)
    {
      Vec3<double> s = slave, m[4] = {}, l = lambda;
      for (unsigned int k = 0; k < n_master; ++k)
        m[k] = master[k];
      for (unsigned int d = 0; d < dim; ++d)
      {
        s[d] += x[d];
        for (unsigned int k = 0; k < n_master; ++k)
          m[k][d] += x[dim * (1 + k) + d];
        if (multipliers)
          l[d] += x[n_displacements + d];
      }
      const Projection p = project_onto(s, m, !extended);
      return segment_element<dim>(s,
                                  m,
                                  p,
                                  master_old,
                                  history,
                                  same,
                                  law,
                                  0.7,
                                  true,
                                  R,
                                  nullptr,
                                  multipliers ? &l : nullptr,
                                  triangle);
    };

    std::vector<double> R(n), K(n * n), Kp(n * n);
    const Projection    p      = project_onto(slave, master, !extended);
    const auto          result = segment_element<dim>(slave,
                                             master,
                                             p,
                                             master_old,
                                             history,
                                             same,
                                             law,
                                             0.7,
                                             true,
                                             R.data(),
                                             K.data(),
                                             multipliers ? &lambda : nullptr,
                                             triangle);
    segment_element<dim>(slave,
                         master,
                         p,
                         master_old,
                         history,
                         same,
                         law,
                         0.7,
                         false,
                         R.data(),
                         Kp.data(),
                         multipliers ? &lambda : nullptr,
                         triangle);

    const bool compared = compare_with_differences(
      n,
      result.status,
      K,
      &Kp,
      [&](const std::vector<double> &x, double *R_x)
      { return residual(x, R_x).status == result.status; },
      tally,
      ok);
    // Beyond the face: clamped, or on its extension (|xi| > 1).
    bool outside = !p.inside();
    if (triangle)
      outside = outside || !TriangleFace::within(p.xi, 0.);
    else
      for (unsigned int c = 0; c < dim - 1; ++c)
        outside = outside || std::abs(p.xi[c]) > 1;
    if (compared && outside && result.status != ContactStatus::open)
      ++tally.n_clamped;
  }
}



/**
 * The 2D element on a smoothed master (averaged nodal normals): a segment
 * with a kinked neighbour on each side (or a free end), the slave above
 * the segment; every perturbed residual with a fresh smoothed projection.
 */
void
check_smoothed(std::mt19937 &random,
               Tally        &tally,
               bool         &ok,
               const bool    multipliers = false)
{
  using Element = NodeToSmoothedSegment;
  std::uniform_real_distribution<double> u(-1, 1);

  for (unsigned int sample = 0; sample < 300; ++sample)
  {
    // x_0, x_1, node before, node after; kinks up to about 20 degrees.
    Vec3<double>       master[4]       = {{{0, 0.1 * u(random), 0}},
                                          {{1, 0.1 * u(random), 0}},
                                          {{-1, 0.35 * u(random), 0}},
                                          {{2, 0.35 * u(random), 0}}};
    const bool         has[2]          = {sample % 5 != 1, sample % 7 != 2};
    const unsigned int n_displacements = 2 * (3 + has[0] + has[1]);
    const unsigned int n      = n_displacements + (multipliers ? 2 : 0);
    const Vec3<double> lambda = random_multiplier(random, 2);
    Vec3<double> slave{{0.5 + 0.45 * u(random), -0.05 + 0.1 * u(random), 0}};

    ContactLaw law;
    law.normal_penalty       = 1e3;
    law.tangential_penalty   = 5e2 * (1 + 0.5 * u(random));
    law.friction_coefficient = 0.3;
    Vec3<double> master_old[4];
    for (unsigned int k = 0; k < 4; ++k)
    {
      master_old[k] = master[k];
      for (unsigned int d = 0; d < 2; ++d)
        master_old[k][d] += 0.01 * u(random);
    }
    // Committed: a point of the old segment, its chord normal, a
    // tangential traction.
    NodeState history;
    history.result.status = ContactStatus::stick;
    const double xi_old   = 2 * (slave[0] - 0.5) + 0.05 * u(random);
    history.point         = scale(0.5 * (1 - xi_old), master_old[0]) +
                    scale(0.5 * (1 + xi_old), master_old[1]);
    const Vec3<double> chord = master_old[1] - master_old[0];
    history.result.normal =
      scale(1. / norm(chord), Vec3<double>{{-chord[1], chord[0], 0}});
    history.result.traction = scale(3 * u(random) / norm(chord), chord);

    // Positions from the element's dof vector (absent neighbours skipped).
    const auto positions =
      [&](const std::vector<double> &x, Vec3<double> &s, Vec3<double> *m)
    {
      s = slave;
      for (unsigned int k = 0; k < 4; ++k)
        m[k] = master[k];
      unsigned int next = 2;
      for (unsigned int d = 0; d < 2; ++d)
        s[d] += x[d];
      for (unsigned int k = 0; k < 4; ++k)
        if (k < 2 || has[k - 2])
        {
          for (unsigned int d = 0; d < 2; ++d)
            m[k][d] += x[next + d];
          next += 2;
        }
    };
    const auto evaluate = [&](const std::vector<double> &x,
                              double                    *R,
                              double                    *K,
                              const bool                 consistent,
                              bool                      &projected)
    {
      Vec3<double> s, m[4], l = lambda;
      positions(x, s, m);
      if (multipliers)
        for (unsigned int d = 0; d < 2; ++d)
          l[d] += x[n_displacements + d];
      double xi = 0;
      projected = SmoothedSegment::project(s, m, has, xi) && std::abs(xi) <= 1;
      return smoothed_element(s,
                              m,
                              has,
                              xi,
                              master_old,
                              history,
                              law,
                              0.7,
                              consistent,
                              R,
                              K,
                              multipliers ? &l : nullptr);
    };

    std::vector<double> zero(n, 0.), R(n), K(n * n), Kp(n * n);
    bool                projected;
    const auto result = evaluate(zero, R.data(), K.data(), true, projected);
    if (!projected)
      continue;
    evaluate(zero, R.data(), Kp.data(), false, projected);

    compare_with_differences(
      n,
      result.status,
      K,
      &Kp,
      [&](const std::vector<double> &x, double *R_x)
      {
        bool inside;
        return evaluate(x, R_x, nullptr, true, inside).status ==
                 result.status &&
               inside;
      },
      tally,
      ok);
  }
}



template <int dim>
void
check_rigid(const std::string &type,
            std::mt19937      &random,
            Tally             &tally,
            bool              &ok,
            const bool         multipliers = false)
{
  const unsigned int                     n = dim + (multipliers ? dim : 0);
  std::uniform_real_distribution<double> u(-1, 1);
  Parameters::RigidSurface               description;
  description.name      = type;
  description.type      = type;
  description.point     = {0.1, 0.2, dim == 3 ? 0.3 : 0.};
  description.radius    = 1;
  description.direction = type == "plane" ?
                            std::vector<double>{0.2, 1, dim == 3 ? 0.3 : 0.} :
                            std::vector<double>{0.3, 0.1, 1};
  description.motion    = std::vector<std::string>(dim, "0.1*t");
  const RigidSurface<dim> surface(description);
  const Vec3<double>      shift     = surface.translation(0.5);
  const Vec3<double>      shift_old = surface.translation(0.497);

  for (unsigned int sample = 0; sample < 200; ++sample)
  {
    Vec3<double> slave{{u(random), u(random), dim == 3 ? u(random) : 0.}};
    // Put the slave slightly inside the surface.
    Vec3<double> xbar, normal;
    double       gap;
    surface.closest_point(slave, shift, xbar, normal, gap);
    slave = xbar + scale(-0.02 * (1 + u(random)), normal);
    const Vec3<double> slave_old =
      slave +
      Vec3<double>{
        {3e-4 * u(random), 3e-4 * u(random), dim == 3 ? 3e-4 * u(random) : 0.}};
    // Committed: the closest point at the last step, its normal, a
    // tangential traction.
    NodeState history;
    history.result.status = ContactStatus::stick;
    {
      double old_gap;
      surface.closest_point(slave_old,
                            shift_old,
                            history.point,
                            history.result.normal,
                            old_gap);
    }
    const Vec3<double> traction{
      {u(random), u(random), dim == 3 ? u(random) : 0.}};
    history.result.traction =
      traction -
      scale(dot(traction, history.result.normal), history.result.normal);
    ContactLaw law;
    law.normal_penalty       = 1e3;
    law.tangential_penalty   = 1e3;
    law.friction_coefficient = 0.2;
    // A traction on the slave: compressive along the surface's normal.
    Vec3<double> lambda = scale(-10 * (1 + 0.5 * u(random)), normal);
    for (unsigned int d = 0; d < dim; ++d)
      lambda[d] += 4 * u(random);

    const auto evaluate =
      [&](const Vec3<double> &x, const Vec3<double> &l, double *R, double *K)
    {
      return rigid_element<dim>(x,
                                surface,
                                shift,
                                shift_old,
                                history,
                                law,
                                1.3,
                                true,
                                R,
                                K,
                                multipliers ? &l : nullptr);
    };
    std::vector<double> R(n), K(n * n);
    const auto          result = evaluate(slave, lambda, R.data(), K.data());
    compare_with_differences(
      n,
      result.status,
      K,
      nullptr,
      [&](const std::vector<double> &x, double *R_x)
      {
        Vec3<double> moved = slave, l = lambda;
        for (unsigned int d = 0; d < dim; ++d)
        {
          moved[d] += x[d];
          if (multipliers)
            l[d] += x[dim + d];
        }
        return evaluate(moved, l, R_x, nullptr).status == result.status;
      },
      tally,
      ok);
  }
}



/**
 * A closed node whose multiplier is tensile (t_N = -Lambda . n < 0 but
 * t_N - c g_N >= 0: penetrating), slipping, on a rigid plane y = 0: the
 * tangential row must use the Coulomb bound mu max(0, t_N - c g_N) >= 0;
 * the raw mu t_N < 0 would turn the friction force against the slip.
 */
bool
check_tensile_multiplier()
{
  Parameters::RigidSurface description;
  description.name      = "plane";
  description.type      = "plane";
  description.point     = {0, 0, 0};
  description.direction = {0, 1, 0};
  description.motion    = {"0", "0"};
  const RigidSurface<2> plane(description);
  const Vec3<double>    zero{{0, 0, 0}};

  ContactLaw law;
  law.normal_penalty       = 100;
  law.tangential_penalty   = 50;
  law.friction_coefficient = 0.3;
  const double       t_N = -0.5, gap = 3 * t_N / law.normal_penalty;
  const Vec3<double> lambda{{0.2, -t_N, 0}}; // Lambda . n = -t_N
  const Vec3<double> slave{{0, gap, 0}};
  NodeState          history; // was at x = -0.01 on the plane, open
  history.point = {{-0.01, 0, 0}};
  double     R[4], K[16];
  const auto result = rigid_element<
    2>(slave, plane, zero, zero, history, law, 1., true, R, K, &lambda);
  // trial = T + c_T dg_T = 0.2 + 50 * 0.01 = 0.7 along +x; the bound is
  // mu (t_N - c g_N) = 0.3 * (-0.5 + 1.5) = 0.3.
  const double trial = 0.2 + 50 * 0.01, bound = 0.3 * (t_N - 100 * gap);
  const double expected = lambda[0] - bound; // tangent t_0 = (-n_y, n_x)
  bool         ok       = result.status == ContactStatus::slip &&
            std::abs(std::abs(R[3]) - std::abs(expected)) < 1e-12 &&
            trial > bound;
  for (const double k : K)
    ok = ok && std::isfinite(k);
  std::cout << "tensile multiplier on the closed branch: tangential row "
            << R[3] << ", expected +-" << expected
            << " (bound mu max(0, t_N - c g_N) = " << bound << ")"
            << (ok ? "  ok" : "  FAILED") << std::endl;
  return ok;
}



/**
 * A node on the axis of a symmetric 3D model (x and y fixed), pressed on
 * a rigid plane z = 0 with friction, with penalty and multipliers, also
 * held closed in tension (the chattering remedy): finite residual and
 * tangent, and no slip where it cannot move.
 */
bool
check_fixed_tangents()
{
  Parameters::RigidSurface description;
  description.name      = "plate";
  description.type      = "plane";
  description.point     = {0, 0, 0};
  description.direction = {0, 0, 1};
  description.motion    = {"0", "0", "0"};
  const RigidSurface<3> plate(description);
  const Vec3<double>    zero{{0, 0, 0}};
  bool                  ok = true;
  for (const bool multipliers : {false, true})
    for (const double pressure : {2., -2.})
    {
      ContactLaw law;
      law.normal_penalty       = 100;
      law.tangential_penalty   = 50;
      law.friction_coefficient = 0.5;
      law.fixed_components     = multipliers ? 3u : 0u;
      law.frozen_closed        = pressure < 0;
      const Vec3<double> slave{{0, 0, -pressure / 100}},
        lambda{{0, 0, pressure}};
      double    R[6], K[36];
      NodeState history;
      history.point     = {{0, 0, 0}};
      const auto result = rigid_element<3>(slave,
                                           plate,
                                           zero,
                                           zero,
                                           history,
                                           law,
                                           1.,
                                           true,
                                           R,
                                           K,
                                           multipliers ? &lambda : nullptr);
      bool       finite = true;
      for (unsigned int i = 0; i < (multipliers ? 6u : 3u); ++i)
        finite = finite && std::isfinite(R[i]);
      for (unsigned int i = 0; i < (multipliers ? 36u : 9u); ++i)
        finite = finite && std::isfinite(K[i]);
      const bool sticks = result.status == ContactStatus::stick;
      std::cout << "axis node, " << (multipliers ? "multipliers" : "penalty")
                << ", pressure " << pressure << ": status "
                << int(result.status)
                << (finite && sticks ? "  ok" : "  FAILED") << std::endl;
      ok = ok && finite && sticks;
    }
  return ok;
}



int
main()
{
  std::mt19937 random(7);
  bool         all_ok = true;
  const auto   report = [&](const std::string &name, const Tally &t, bool ok)
  {
    std::cout << name << ": open " << t.n[0] << ", stick " << t.n[1]
              << ", slip " << t.n[2] << ", clamped " << t.n_clamped
              << "; max relative error " << t.worst;
    if (t.paper_error > 0)
      std::cout << " (paper tangent: " << t.paper_error << ")";
    const bool covered = t.n[1] > 5 && t.n[2] > 5;
    std::cout << ((ok && covered) ? "  ok" : "  FAILED") << std::endl;
    all_ok = all_ok && ok && covered;
  };
  {
    Tally t;
    bool  ok = true;
    check_segment<2>(random, t, ok);
    ok = ok && t.n_clamped > 5 && t.paper_error > 1e-3;
    report("2D node-to-segment", t, ok);
  }
  {
    Tally t;
    bool  ok = true;
    check_segment<3>(random, t, ok);
    ok = ok && t.n_clamped > 5 && t.paper_error > 1e-3;
    report("3D node-to-face", t, ok);
  }
  {
    Tally t;
    bool  ok = true;
    check_smoothed(random, t, ok);
    ok = ok && t.paper_error > 1e-3;
    report("2D node-to-segment, smoothed master", t, ok);
  }
  for (const std::string type : {"plane", "sphere", "cylinder"})
  {
    Tally t2, t3;
    bool  ok2 = true, ok3 = true;
    check_rigid<2>(type, random, t2, ok2);
    check_rigid<3>(type, random, t3, ok3);
    report("2D rigid " + type, t2, ok2);
    report("3D rigid " + type, t3, ok3);
  }

  // The same elements on their extended faces and with multipliers.
  for (const bool multipliers : {false, true})
  {
    const std::string law = multipliers ? ", multipliers" : "";
    {
      Tally t;
      bool  ok = true;
      check_segment<2>(random, t, ok, multipliers, true);
      ok = ok && t.n_clamped > 5;
      report("2D node-to-segment, extended faces" + law, t, ok);
    }
    {
      Tally t;
      bool  ok = true;
      check_segment<3>(random, t, ok, multipliers, true);
      ok = ok && t.n_clamped > 5;
      report("3D node-to-face, extended faces" + law, t, ok);
    }
    if (!multipliers)
      continue;
    {
      Tally t;
      bool  ok = true;
      check_segment<2>(random, t, ok, true);
      ok = ok && t.n_clamped > 5;
      report("2D node-to-segment" + law, t, ok);
    }
    {
      Tally t;
      bool  ok = true;
      check_segment<3>(random, t, ok, true);
      ok = ok && t.n_clamped > 5;
      report("3D node-to-face" + law, t, ok);
    }
    {
      Tally t;
      bool  ok = true;
      check_smoothed(random, t, ok, true);
      report("2D node-to-segment, smoothed master" + law, t, ok);
    }
    for (const std::string type : {"plane", "sphere", "cylinder"})
    {
      Tally t2, t3;
      bool  ok2 = true, ok3 = true;
      check_rigid<2>(type, random, t2, ok2, true);
      check_rigid<3>(type, random, t3, ok3, true);
      report("2D rigid " + type + law, t2, ok2);
      report("3D rigid " + type + law, t3, ok3);
    }
  }

  // The triangle faces of tetrahedra: clamped to an edge, at a corner, on
  // the extension; penalty and multipliers.
  for (const bool multipliers : {false, true})
    for (const bool extended : {false, true})
    {
      Tally t;
      bool  ok = true;
      check_segment<3>(random, t, ok, multipliers, extended, true);
      ok = ok && t.n_clamped > 5 && (multipliers || t.paper_error > 1e-3);
      report(std::string("3D node-to-triangle") +
               (extended ? ", extended faces" : "") +
               (multipliers ? ", multipliers" : ""),
             t,
             ok);
    }

  all_ok = check_tensile_multiplier() && all_ok;
  all_ok = check_fixed_tangents() && all_ok;
  return all_ok ? 0 : 1;
}
