#include <tribos/contact/contact_element.h>

#include <Sacado.hpp>

namespace tribos
{
  namespace
  {
    /** Forward AD number with at most 15 derivatives (3D: 5 nodes x 3). */
    using AD = Sacado::Fad::SLFad<double, 15>;

    double
    value(const AD &x)
    {
      return x.val();
    }

    /**
     * The interface law shared by both element types: normal penalty and
     * Coulomb return mapping. Fills @p force = T - t_N n (the residual of
     * the slave per unit area) and the reported values.
     */
    template <typename Number>
    void
    interface_law(const Number       &gap,
                  const Vec3<Number> &normal,
                  const Vec3<Number> &slip_increment,
                  const Vec3<double> &previous_traction,
                  const ContactLaw   &law,
                  Vec3<Number>       &force,
                  ContactPointResult &result)
    {
      result.gap = value(gap);
      for (unsigned int d = 0; d < 3; ++d)
        result.normal[d] = value(normal[d]);

      force = {{Number(0.), Number(0.), Number(0.)}};
      // Closed for lambda - eps_N g_N >= 0 (g_N <= 0 for pure penalty): a
      // node that just touches carries no pressure but gives the Newton
      // matrix its contact stiffness, so that the first iteration of a step
      // does not push it deep into the master.
      if (law.multiplier - law.normal_penalty * value(gap) < 0)
        return;

      const Number pressure = law.multiplier - law.normal_penalty * gap;
      result.pressure       = value(pressure);
      result.status         = ContactStatus::stick;
      force                 = scale(-pressure, normal);

      if (law.friction_coefficient > 0)
      {
        // Stick trial (16): the committed traction, kept tangent to the
        // current surface, plus the elastic part of the slip increment.
        const Vec3<Number> old_traction = to<Number>(previous_traction);
        const Vec3<Number> trial =
          (old_traction - scale(dot(old_traction, normal), normal)) +
          scale(law.tangential_penalty, slip_increment);
        const Number magnitude = norm(trial);
        const Number limit     = law.friction_coefficient * pressure;
        Vec3<Number> traction  = trial;
        // Slip indicator (17) and return mapping (18)-(19). At equality
        // the node sticks: a node that slipped in the last step starts
        // the next one on the stick branch (paper, Table 1).
        if (value(magnitude) > value(limit))
        {
          traction      = scale(limit / magnitude, trial);
          result.status = ContactStatus::slip;
          result.slip_increment =
            value((magnitude - limit) / law.tangential_penalty);
        }
        force = force + traction;
        for (unsigned int d = 0; d < 3; ++d)
          result.traction[d] = value(traction[d]);
      }
    }



    /** Seed @p n_values entries of @p x as independent AD variables. */
    template <int dim>
    Vec3<AD>
    seed(const Vec3<double> &x, const unsigned int first, const unsigned int n)
    {
      Vec3<AD> result;
      for (unsigned int d = 0; d < 3; ++d)
        result[d] = (d < dim ? AD(n, first + d, x[d]) : AD(x[d]));
      return result;
    }
  } // namespace



  template <int dim>
  ContactPointResult
  NodeToSegment<dim>::evaluate(const Vec3<double> &slave,
                               const Vec3<double> *master,
                               const Projection   &projection,
                               const Vec3<double> &slave_old,
                               const Vec3<double> *master_old,
                               const Vec3<double> &previous_traction,
                               const ContactLaw   &law,
                               const double        area,
                               const bool          consistent,
                               double             *R,
                               double             *K)
  {
    using Face = MasterFace<dim>;
    ContactPointResult result;
    result.face  = -1;
    result.xi[0] = projection.xi[0];
    result.xi[1] = projection.xi[1];

    Vec3<AD> xs = seed<dim>(slave, 0, n_dofs);
    Vec3<AD> xm[n_nodes];
    for (unsigned int k = 0; k < n_nodes; ++k)
      xm[k] = seed<dim>(master[k], dim * (1 + k), n_dofs);

    // Geometry at the converged projection, in double, for the update.
    Vec3<double> xbar0, a0[2], n0;
    Face::geometry(master, projection.xi, xbar0, a0, n0);

    // xi as a function of the positions (see the class documentation).
    AD xi[2] = {AD(projection.xi[0]), AD(projection.xi[1])};
    {
      Vec3<AD> xbar_fixed_xi, a_ad[2], n_ad;
      Face::geometry(xm, projection.xi, xbar_fixed_xi, a_ad, n_ad);
      const Vec3<AD> r = xs - xbar_fixed_xi;
      AD             residual[2];
      double         J[2][2] = {{0, 0}, {0, 0}};
      for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
      {
        residual[alpha] =
          consistent ? dot(r, a_ad[alpha]) : dot(r, to<AD>(a0[alpha]));
        for (unsigned int beta = 0; beta < Face::n_coords; ++beta)
          J[alpha][beta] = dot(a0[alpha], a0[beta]);
      }
      if constexpr (dim == 3)
        if (consistent)
        {
          Vec3<double> a12{{0, 0, 0}};
          for (unsigned int k = 0; k < 4; ++k)
            a12 = a12 + scale(Face::mixed_derivative(k), master[k]);
          const double curvature = dot(slave - xbar0, a12);
          J[0][1] -= curvature;
          J[1][0] -= curvature;
        }
      if (projection.inside())
      {
        if constexpr (dim == 2)
          xi[0] += residual[0] / J[0][0];
        else
        {
          const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
          xi[0] += (J[1][1] * residual[0] - J[0][1] * residual[1]) / det;
          xi[1] += (J[0][0] * residual[1] - J[1][0] * residual[0]) / det;
        }
      }
      else
        for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
          if (projection.clamped[alpha] == 0)
            xi[alpha] += residual[alpha] / J[alpha][alpha];
    }

    Vec3<AD> xbar, a[2], normal;
    Face::geometry(xm, xi, xbar, a, normal);
    if (!consistent)
    {
      normal = to<AD>(n0);
      for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
        a[alpha] = to<AD>(a0[alpha]);
    }
    const AD gap = dot(xs - xbar, normal);

    AD N[n_nodes], dN[n_nodes][2];
    Face::shape(xi, N, dN);

    // Relative motion of the slave and the master material point under it
    // during the step, tangential part.
    Vec3<AD> relative = xs - to<AD>(slave_old);
    for (unsigned int k = 0; k < n_nodes; ++k)
      relative = relative - scale(N[k], xm[k] - to<AD>(master_old[k]));
    const Vec3<AD> slip = relative - scale(dot(relative, normal), normal);

    Vec3<AD> force;
    interface_law(gap, normal, slip, previous_traction, law, force, result);

    AD residual[n_dofs];
    for (unsigned int d = 0; d < dim; ++d)
    {
      residual[d] = area * force[d];
      for (unsigned int k = 0; k < n_nodes; ++k)
        residual[dim * (1 + k) + d] = -area * N[k] * force[d];
    }
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      R[i] = residual[i].val();
      if (K != nullptr)
        for (unsigned int j = 0; j < n_dofs; ++j)
          K[i * n_dofs + j] = residual[i].dx(j);
    }
    result.xi[0] = value(xi[0]);
    result.xi[1] = value(xi[1]);
    return result;
  }



  template <int dim>
  ContactPointResult
  NodeToRigid<dim>::evaluate(const Vec3<double>      &slave,
                             const RigidSurface<dim> &surface,
                             const Vec3<double>      &shift,
                             const Vec3<double>      &shift_old,
                             const Vec3<double>      &slave_old,
                             const Vec3<double>      &previous_traction,
                             const ContactLaw        &law,
                             const double             area,
                             const bool               consistent,
                             double                  *R,
                             double                  *K)
  {
    ContactPointResult result;
    const Vec3<AD>     xs = seed<dim>(slave, 0, n_dofs);

    Vec3<AD> xbar, normal;
    AD       gap;
    surface.closest_point(xs, shift, xbar, normal, gap);
    if (!consistent)
    {
      // Hold the closest point's normal fixed: the small-deformation
      // linearization.
      Vec3<double> n0, xbar0;
      for (unsigned int d = 0; d < 3; ++d)
      {
        n0[d]    = normal[d].val();
        xbar0[d] = xbar[d].val();
      }
      normal = to<AD>(n0);
      gap    = dot(xs - to<AD>(xbar0), normal);
      xbar   = xs - scale(gap, normal);
    }

    // Slip: the tangential part of the slave's motion relative to the
    // surface during the step.
    const Vec3<AD> relative =
      (xs - to<AD>(slave_old)) - to<AD>(shift - shift_old);
    const Vec3<AD> slip = relative - scale(dot(relative, normal), normal);

    Vec3<AD> force;
    interface_law(gap, normal, slip, previous_traction, law, force, result);

    for (unsigned int i = 0; i < dim; ++i)
    {
      const AD residual = area * force[i];
      R[i]              = residual.val();
      if (K != nullptr)
        for (unsigned int j = 0; j < dim; ++j)
          K[i * dim + j] = residual.dx(j);
    }
    return result;
  }

  template struct NodeToSegment<2>;
  template struct NodeToSegment<3>;
  template struct NodeToRigid<2>;
  template struct NodeToRigid<3>;
} // namespace tribos
