/**
 * Unit test: the contact element's tangent (Sacado AD, Tangent =
 * consistent) against central finite differences of its residual, where
 * every perturbed residual is evaluated with a fresh closest-point
 * projection. Random configurations in 2D (segments) and 3D (warped
 * bilinear faces), open, stick and slip, projections inside a face and
 * clamped at its edge (a node beyond a convex corner), and rigid plane,
 * sphere and cylinder. Asserts a relative error below 1e-6, and that the
 * `paper` tangent differs (it drops the geometric terms).
 */

#include <tribos/contact/contact_element.h>

#include <iostream>
#include <random>
#include <vector>

using namespace tribos;

struct Tally
{
  unsigned int n[3]        = {0, 0, 0};
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



template <int dim>
void
check_segment(std::mt19937 &random, Tally &tally, bool &ok)
{
  using Element                            = NodeToSegment<dim>;
  constexpr unsigned int                 n = Element::n_dofs;
  std::uniform_real_distribution<double> u(-1, 1);

  for (unsigned int sample = 0; sample < 300; ++sample)
  {
    // A warped face around the unit square/segment, normal about +y/+z.
    Vec3<double> master[4];
    for (unsigned int k = 0; k < MasterFace<dim>::n_nodes; ++k)
    {
      master[k]    = {{0, 0, 0}};
      master[k][0] = (k % 2) + 0.1 * u(random);
      if (dim == 3)
        master[k][1] = (k / 2) + 0.1 * u(random);
      master[k][dim - 1] = 0.15 * u(random);
    }
    // Slave mostly above the face's interior, sometimes beyond an edge.
    const bool   beyond = (sample % 4 == 0);
    Vec3<double> slave{{0.5 + 0.4 * u(random) + (beyond ? 0.7 : 0.), 0, 0}};
    if (dim == 3)
      slave[1] = 0.5 + 0.4 * u(random);
    slave[dim - 1] = -0.05 + 0.1 * u(random);

    ContactLaw law;
    law.normal_penalty       = 1e3;
    law.tangential_penalty   = 5e2 * (1 + 0.5 * u(random));
    law.friction_coefficient = 0.3;
    // Positions at the last converged step: a tangential history.
    Vec3<double> slave_old = slave, master_old[4];
    for (unsigned int d = 0; d < dim; ++d)
      slave_old[d] += 0.03 * u(random);
    for (unsigned int k = 0; k < MasterFace<dim>::n_nodes; ++k)
    {
      master_old[k] = master[k];
      for (unsigned int d = 0; d < dim; ++d)
        master_old[k][d] += 0.01 * u(random);
    }
    Vec3<double> traction{{3 * u(random), 3 * u(random), 0}};
    if (dim == 2)
      traction[1] = 0;

    const auto residual = [&](const std::vector<double> &x, double *R)
    {
      Vec3<double> s = slave, m[4];
      for (unsigned int k = 0; k < MasterFace<dim>::n_nodes; ++k)
        m[k] = master[k];
      for (unsigned int d = 0; d < dim; ++d)
      {
        s[d] += x[d];
        for (unsigned int k = 0; k < MasterFace<dim>::n_nodes; ++k)
          m[k][d] += x[dim * (1 + k) + d];
      }
      const Projection p = project<dim>(s, m);
      return Element::evaluate(s,
                               m,
                               p,
                               slave_old,
                               master_old,
                               traction,
                               law,
                               0.7,
                               true,
                               R,
                               nullptr);
    };

    std::vector<double> R(n), K(n * n), Kp(n * n);
    const Projection    p      = project<dim>(slave, master);
    const auto          result = Element::evaluate(slave,
                                          master,
                                          p,
                                          slave_old,
                                          master_old,
                                          traction,
                                          law,
                                          0.7,
                                          true,
                                          R.data(),
                                          K.data());
    Element::evaluate(slave,
                      master,
                      p,
                      slave_old,
                      master_old,
                      traction,
                      law,
                      0.7,
                      false,
                      R.data(),
                      Kp.data());

    const bool compared = compare_with_differences(
      n,
      result.status,
      K,
      &Kp,
      [&](const std::vector<double> &x, double *R_x)
      { return residual(x, R_x).status == result.status; },
      tally,
      ok);
    if (compared && !p.inside() && result.status != ContactStatus::open)
      ++tally.n_clamped;
  }
}



/**
 * The 2D element on a smoothed master (averaged nodal normals): a segment
 * with a kinked neighbour on each side (or a free end), the slave above
 * the segment; every perturbed residual with a fresh smoothed projection.
 */
void
check_smoothed(std::mt19937 &random, Tally &tally, bool &ok)
{
  using Element = NodeToSmoothedSegment;
  std::uniform_real_distribution<double> u(-1, 1);

  for (unsigned int sample = 0; sample < 300; ++sample)
  {
    // x_0, x_1, node before, node after; kinks up to about 20 degrees.
    Vec3<double>       master[4] = {{{0, 0.1 * u(random), 0}},
                                    {{1, 0.1 * u(random), 0}},
                                    {{-1, 0.35 * u(random), 0}},
                                    {{2, 0.35 * u(random), 0}}};
    const bool         has[2]    = {sample % 5 != 1, sample % 7 != 2};
    const unsigned int n         = 2 * (3 + has[0] + has[1]);
    Vec3<double> slave{{0.5 + 0.45 * u(random), -0.05 + 0.1 * u(random), 0}};

    ContactLaw law;
    law.normal_penalty       = 1e3;
    law.tangential_penalty   = 5e2 * (1 + 0.5 * u(random));
    law.friction_coefficient = 0.3;
    Vec3<double> slave_old   = slave, master_old[4];
    for (unsigned int d = 0; d < 2; ++d)
      slave_old[d] += 0.03 * u(random);
    for (unsigned int k = 0; k < 4; ++k)
    {
      master_old[k] = master[k];
      for (unsigned int d = 0; d < 2; ++d)
        master_old[k][d] += 0.01 * u(random);
    }
    const Vec3<double> traction{{3 * u(random), 0, 0}};

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
      Vec3<double> s, m[4];
      positions(x, s, m);
      double xi = 0;
      projected = SmoothedSegment::project(s, m, has, xi) && std::abs(xi) <= 1;
      return Element::evaluate(s,
                               m,
                               has,
                               xi,
                               slave_old,
                               master_old,
                               traction,
                               law,
                               0.7,
                               consistent,
                               R,
                               K);
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
            bool              &ok)
{
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
    Vec3<double> traction{{u(random), u(random), dim == 3 ? u(random) : 0.}};
    ContactLaw   law;
    law.normal_penalty       = 1e3;
    law.tangential_penalty   = 1e3;
    law.friction_coefficient = 0.2;

    const auto evaluate = [&](const Vec3<double> &x, double *R, double *K)
    {
      return NodeToRigid<dim>::evaluate(x,
                                        surface,
                                        shift,
                                        shift_old,
                                        slave_old,
                                        traction,
                                        law,
                                        1.3,
                                        true,
                                        R,
                                        K);
    };
    std::vector<double> R(dim), K(dim * dim);
    const auto          result = evaluate(slave, R.data(), K.data());
    compare_with_differences(
      dim,
      result.status,
      K,
      nullptr,
      [&](const std::vector<double> &x, double *R_x)
      {
        Vec3<double> moved = slave;
        for (unsigned int d = 0; d < dim; ++d)
          moved[d] += x[d];
        return evaluate(moved, R_x, nullptr).status == result.status;
      },
      tally,
      ok);
  }
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
  return all_ok ? 0 : 1;
}
