#include <tribos/contact/contact_element.h>

#include <Sacado.hpp>

namespace tribos
{
  namespace
  {
    /**
     * Forward AD number with at most 18 derivatives (3D: 5 nodes x 3 plus
     * the slave's 3 multipliers).
     */
    using AD = Sacado::Fad::SLFad<double, 18>;

    double
    value(const AD &x)
    {
      return x.val();
    }

    /**
     * |v|, with a zero derivative at v = 0 instead of the NaN of d sqrt(x)
     * at 0 (a node whose tangential motion is fixed in every direction,
     * e.g. on the axis of a symmetric model, has a zero trial traction).
     */
    template <typename Number>
    Number
    safe_norm(const Vec3<Number> &v)
    {
      if (value(dot(v, v)) == 0)
        return Number(0.);
      return norm(v);
    }

    /**
     * The slip indicator |T_trial| > mu t_N, with equality to round-off
     * (relative 1e-12) counted as stick.
     */
    template <typename Number>
    bool
    slips(const Number &magnitude, const Number &limit)
    {
      return value(magnitude) > value(limit) * (1. + 1e-12);
    }

    /** max(0, x) with the derivative of the branch taken. */
    template <typename Number>
    Number
    positive_part(const Number &x)
    {
      return value(x) > 0 ? x : Number(0.);
    }

    /**
     * The interface law shared by all element types: normal penalty and
     * Coulomb return mapping. @p committed is the committed traction T_n
     * turned with the surface (Q T_n). Fills @p force = T - t_N n (the
     * residual of the slave per unit area) and the reported values.
     */
    template <typename Number>
    void
    interface_law(const Number       &gap,
                  const Vec3<Number> &normal,
                  const Vec3<Number> &slip_increment,
                  const Vec3<Number> &committed,
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
      if (!law.frozen_closed &&
          law.multiplier - law.normal_penalty * value(gap) < 0)
        return;

      const Number pressure = law.multiplier - law.normal_penalty * gap;
      result.pressure       = value(pressure);
      result.status         = ContactStatus::closed;
      force                 = scale(-pressure, normal);

      if (law.friction_coefficient > 0)
      {
        result.status = ContactStatus::stick;
        // Stick trial (16): the committed traction, turned with the
        // surface (tangent to it), plus the elastic part of the slip
        // increment.
        const Vec3<Number> trial =
          committed + scale(law.tangential_penalty, slip_increment);
        const Number magnitude = safe_norm(trial);
        // A node held closed by the chattering remedy may carry a tensile
        // pressure: the Coulomb bound is never negative.
        const Number limit = law.friction_coefficient * positive_part(pressure);
        Vec3<Number> traction = trial;
        // Slip indicator (17) and return mapping (18)-(19). At equality
        // the node sticks: a node that slipped in the last step starts
        // the next one on the stick branch (paper, Table 1). Equality to
        // round-off: its trial is then its committed traction, mu t_N up
        // to the last digit, and the last digit must not decide.
        if (slips(magnitude, limit))
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



    /**
     * An orthonormal tangent frame of the unit normal @p n: t_0 from the
     * coordinate axis least aligned with n (fixed while n varies, so the
     * frame is differentiable), t_1 = n x t_0. In 2D (n in the plane
     * z = 0) t_0 lies in the plane and t_1 = +-e_z is unused.
     */
    template <typename Number>
    void
    tangent_frame(const Vec3<Number> &n, Vec3<Number> (&t)[2])
    {
      unsigned int axis = 0;
      for (unsigned int d = 1; d < 3; ++d)
        if (std::abs(value(n[d])) < std::abs(value(n[axis])))
          axis = d;
      if (value(n[2]) == 0 && axis == 2)
      {
        // 2D: the in-plane tangent.
        t[0] = {{Number(-n[1]), Number(n[0]), Number(0.)}};
        t[1] = {{Number(0.), Number(0.), Number(1.)}};
        return;
      }
      Vec3<Number> e = {{Number(0.), Number(0.), Number(0.)}};
      e[axis]        = 1.;
      t[0]           = e - scale(n[axis], n);
      t[0]           = scale(1. / norm(t[0]), t[0]);
      t[1]           = cross(n, t[0]);
    }



    /**
     * R v for the rotation R that takes the unit vector @p from to the unit
     * vector @p to about their common normal (from x to): R v = c v + w x v
     * + (w . v) w / (1 + c), w = from x to, c = from . to. The committed
     * traction's turn with the surface's normal.
     */
    template <typename Number>
    Vec3<Number>
    turn(const Vec3<double> &from,
         const Vec3<Number> &onto,
         const Vec3<Number> &v)
    {
      const Vec3<Number> f = to<Number>(from);
      const Number       c = dot(f, onto);
      const Vec3<Number> w = cross(f, onto);
      return scale(c, v) + cross(w, v) + scale(dot(w, v) / (1. + c), w);
    }

    /**
     * The committed traction @p T (tangent to the committed face) turned with
     * the face: the rotation of the polar decomposition of the map F_s =
     * a_alpha (x) a^alpha_o + n (x) n_o, which takes the committed tangents
     * @p a_old and normal @p n_old to the current @p a and @p n at the same
     * local coordinates: the rotation taking n_o to n, then about n_o the
     * angle phi of the in-plane rest G = R1^T F_s (2 x 2 in an orthonormal
     * frame e_1, e_2 of the old tangent plane): tan phi = (G_21 - G_12) /
     * (G_11 + G_22). In 2D phi = 0.
     */
    template <int dim, typename Number>
    Vec3<Number>
    turn_with_face(const Vec3<double> *a_old,
                   const Vec3<double> &n_old,
                   const Vec3<Number> *a,
                   const Vec3<Number> &n,
                   const Vec3<double> &T)
    {
      if constexpr (dim == 2)
        return turn(n_old, n, to<Number>(T));
      else
      {
        // Dual basis of the old tangents.
        const double m11           = dot(a_old[0], a_old[0]),
                     m12           = dot(a_old[0], a_old[1]),
                     m22           = dot(a_old[1], a_old[1]);
        const double       det     = m11 * m22 - m12 * m12;
        const Vec3<double> dual[2] = {
          scale(1. / det, scale(m22, a_old[0]) - scale(m12, a_old[1])),
          scale(1. / det, scale(m11, a_old[1]) - scale(m12, a_old[0]))};
        const auto F = [&](const Vec3<double> &v)
        {
          return scale(dot(dual[0], v), a[0]) + scale(dot(dual[1], v), a[1]) +
                 scale(dot(n_old, v), n);
        };
        const Vec3<double> e1 = scale(1. / norm(a_old[0]), a_old[0]);
        const Vec3<double> e2 = cross(n_old, e1);
        // G_ij = (R1 e_i) . (F_s e_j).
        const Vec3<Number> r1 = turn(n_old, n, to<Number>(e1)),
                           r2 = turn(n_old, n, to<Number>(e2));
        const Vec3<Number> f1 = F(e1), f2 = F(e2);
        const Number       c = dot(r1, f1) + dot(r2, f2);
        const Number       s = dot(r2, f1) - dot(r1, f2);
        const Number       r = sqrt(c * c + s * s);
        // Rotation by phi about n_old of T (tangent to the old face).
        const Vec3<Number> spun = scale(c / r, to<Number>(T)) +
                                  scale(s / r, to<Number>(cross(n_old, T)));
        return turn(n_old, n, spun);
      }
    }



    /**
     * The Lagrange multiplier form of the same interface law. The unknown
     * @p multiplier is the slave's contact traction vector Lambda (force per
     * unit area on the slave, so t_N = -Lambda . n and T = P_T Lambda), and
     * @p constraint receives the node's equations: while open the
     * multiplier itself, while closed the normal condition (component 0)
     * and the tangential one in the frame t_1, t_2 (components 1, 2):
     *
     *   open  (t_N - c g_N < 0):    C = Lambda                 (no traction)
     *   closed, normal:             C_0 = c g_N                (g_N = 0)
     *   frictionless:               C_a = t_a . T              (T = 0)
     *   stick (|T + c_T dg_T| <= mu t_N):  C_a = t_a . c_T dg_T  (no slip)
     *   slip:   C_a = t_a . (T - mu t_N (T + c_T dg_T)/|T + c_T dg_T|)  (22)
     *
     * This is the primal-dual active set strategy written as a semismooth
     * Newton method (Alart and Curnier's augmented form): the contact and
     * stick/slip status follow from the current multipliers and gaps at
     * every evaluation, so the active set is updated inside Newton, and the
     * derivative of C is the generalized Jacobian on each branch. The slip
     * branch couples T to the normal multiplier non-symmetrically, as in
     * the paper's (22) and (35). c = eps_N and c_T (Contact/Friction
     * complementarity parameter, by default E / h of the node) change the
     * iterates (which branch a node takes) and the row scaling only, never
     * the converged solution. c_T must not be much stiffer than the body:
     * with c_T = 1000 E a slip of 1e-6 h already decides the branch, and
     * the iteration cycled between stick and slip on the 3D upsetting.
     */
    template <typename Number>
    void
    multiplier_law(const Number       &gap,
                   const Vec3<Number> &normal,
                   const Vec3<Number> &slip_increment,
                   const Vec3<Number> &multiplier,
                   const ContactLaw   &law,
                   Vec3<Number>       &force,
                   Vec3<Number>       &constraint,
                   ContactPointResult &result)
    {
      result.gap = value(gap);
      for (unsigned int d = 0; d < 3; ++d)
        result.normal[d] = value(normal[d]);

      force                       = multiplier;
      const Number       pressure = -dot(multiplier, normal);
      const Vec3<Number> tau      = multiplier + scale(pressure, normal);
      if (!law.frozen_closed &&
          value(pressure) - law.normal_penalty * value(gap) < 0)
      {
        constraint    = multiplier;
        result.status = ContactStatus::open;
        return;
      }
      result.pressure = value(pressure);
      result.status   = law.friction_coefficient > 0 ? ContactStatus::stick :
                                                       ContactStatus::closed;

      // Tangents in which the slave cannot move (symmetry planes,
      // Dirichlet): there the condition is T . t = 0 (what symmetry
      // implies); a stick condition would be singular. The friction law
      // acts in the remaining tangent directions.
      Vec3<Number> fixed[2];
      unsigned int n_fixed = 0;
      for (unsigned int d = 0; d < 3 && n_fixed < 2; ++d)
        if (law.fixed_components & (1u << d))
        {
          Vec3<Number> t = {{Number(0.), Number(0.), Number(0.)}};
          t[d]           = 1.;
          t              = t - scale(normal[d], normal);
          for (unsigned int i = 0; i < n_fixed; ++i)
            t = t - scale(dot(t, fixed[i]), fixed[i]);
          const Number length = norm(t);
          if (value(length) >= 0.5)
            fixed[n_fixed++] = scale(1. / length, t);
        }
      const auto free_part = [&](const Vec3<Number> &v)
      {
        Vec3<Number> result = v;
        for (unsigned int i = 0; i < n_fixed; ++i)
          result = result - scale(dot(v, fixed[i]), fixed[i]);
        return result;
      };
      const Vec3<Number> tau_free = free_part(tau);

      Vec3<Number> tangential = tau_free;
      if (law.friction_coefficient > 0)
      {
        const Vec3<Number> slip = free_part(slip_increment);
        const Vec3<Number> trial =
          tau_free + scale(law.tangential_penalty, slip);
        const Number magnitude = safe_norm(trial);
        // The Coulomb bound of the augmented (Alart-Curnier) form, on
        // max(0, t_N - c g_N): never negative, also in iterates whose
        // multiplier is tensile; equal to mu t_N at convergence (g_N = 0).
        const Number limit =
          law.friction_coefficient *
          positive_part(Number(pressure - law.normal_penalty * gap));
        if (slips(magnitude, limit))
        {
          tangential            = tau_free - scale(limit / magnitude, trial);
          result.status         = ContactStatus::slip;
          result.slip_increment = value(norm(slip));
        }
        else
          tangential = scale(law.tangential_penalty, slip);
      }
      tangential = tangential + (tau - tau_free);

      // Rows in the local frame (n, t_1, t_2): the normal row must not
      // see the tangential rows' geometry. (As one global vector
      // c g n + P_T C, the term c g dn/du of a penetrating node would put
      // spurious tangential forces into every iterate.)
      Vec3<Number> t[2];
      tangent_frame(normal, t);
      constraint[0] = law.normal_penalty * gap;
      constraint[1] = dot(tangential, t[0]);
      constraint[2] = dot(tangential, t[1]);
      for (unsigned int d = 0; d < 3; ++d)
        result.traction[d] = value(tau[d]);
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

    /**
     * The interface law at one slave node (penalty form, or the multiplier
     * form with @p multiplier) and the element residual it gives, with its
     * AD derivative: A force on the slave's dim rows, -N_a A force on the
     * rows of the @p n_master_nodes master nodes that carry it, and A times
     * the constraint on the dim multiplier rows after the @p
     * n_displacements displacement rows. Every element type ends with this
     * (a rigid master carries no nodes).
     */
    template <int dim>
    void
    apply_law(const AD           &gap,
              const Vec3<AD>     &normal,
              const Vec3<AD>     &slip,
              const AD           *N,
              const unsigned int  n_master_nodes,
              const unsigned int  n_displacements,
              const Vec3<double> *multiplier,
              const Vec3<AD>     &committed,
              const ContactLaw   &law,
              const double        area,
              double             *R,
              double             *K,
              ContactPointResult &result)
    {
      const unsigned int n_out = n_displacements + (multiplier ? dim : 0);
      Vec3<AD>           force, constraint;
      if (multiplier)
        multiplier_law(gap,
                       normal,
                       slip,
                       seed<dim>(*multiplier, n_displacements, n_out),
                       law,
                       force,
                       constraint,
                       result);
      else
        interface_law(gap, normal, slip, committed, law, force, result);

      for (unsigned int i = 0; i < n_out; ++i)
      {
        AD residual = 0.;
        if (i < dim)
          residual = area * force[i];
        else if (i < dim * (1 + n_master_nodes))
          residual = -area * N[i / dim - 1] * force[i % dim];
        else if (i >= n_displacements)
          residual = area * constraint[i - n_displacements];
        R[i] = residual.val();
        if (K != nullptr)
          for (unsigned int j = 0; j < n_out; ++j)
            K[i * n_out + j] = residual.dx(j);
      }
    }
  } // namespace



  template <int dim>
  ContactPointResult
  NodeToSegment<dim>::evaluate(const Vec3<double> &slave,
                               const Vec3<double> *master,
                               const Projection   &projection,
                               const Vec3<double> *master_old,
                               const SlaveHistory &history,
                               const bool          same_face,
                               const ContactLaw   &law,
                               const double        area,
                               const bool          consistent,
                               double             *R,
                               double             *K,
                               const Vec3<double> *multiplier)
  {
    using Face = MasterFace<dim>;
    ContactPointResult result;
    result.face  = -1;
    result.xi[0] = projection.xi[0];
    result.xi[1] = projection.xi[1];

    const unsigned int n_out = n_dofs + (multiplier ? dim : 0);
    Vec3<AD>           xs    = seed<dim>(slave, 0, n_out);
    Vec3<AD>           xm[n_nodes];
    for (unsigned int k = 0; k < n_nodes; ++k)
      xm[k] = seed<dim>(master[k], dim * (1 + k), n_out);

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

    // Slip: the projection point's motion relative to the master material
    // point it left, measured on the master as it was.
    Vec3<AD> relative = to<AD>(scale(-1., history.point));
    for (unsigned int k = 0; k < n_nodes; ++k)
      relative = relative + scale(N[k], to<AD>(master_old[k]));
    const Vec3<AD> slip = relative - scale(dot(relative, normal), normal);

    // The committed traction turned with the face (the same face at the
    // committed coordinates: its spin too), else with the normal.
    Vec3<AD> committed = {{AD(0.), AD(0.), AD(0.)}};
    if (history.active && dot(history.normal, n0) > 0)
    {
      if (same_face)
      {
        Vec3<double> xbar_old, a_old[2], n_old;
        Face::geometry(master_old, history.xi, xbar_old, a_old, n_old);
        Vec3<AD> xbar_now, a_now[2], n_now;
        if (consistent)
          Face::geometry(xm, history.xi, xbar_now, a_now, n_now);
        else
        {
          Vec3<double> x_value, a_value[2], n_value;
          Face::geometry(master, history.xi, x_value, a_value, n_value);
          n_now = to<AD>(n_value);
          for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
            a_now[alpha] = to<AD>(a_value[alpha]);
        }
        committed =
          turn_with_face<dim>(a_old, n_old, a_now, n_now, history.traction);
      }
      else
        committed = turn(history.normal, normal, to<AD>(history.traction));
    }

    apply_law<dim>(gap,
                   normal,
                   slip,
                   N,
                   n_nodes,
                   n_dofs,
                   multiplier,
                   committed,
                   law,
                   area,
                   R,
                   K,
                   result);
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
                             const SlaveHistory      &history,
                             const ContactLaw        &law,
                             const double             area,
                             const bool               consistent,
                             double                  *R,
                             double                  *K,
                             const Vec3<double>      *multiplier)
  {
    ContactPointResult result;
    const unsigned int n_out = n_dofs + (multiplier ? dim : 0);
    const Vec3<AD>     xs    = seed<dim>(slave, 0, n_out);

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

    // Slip: the projection point's motion relative to the surface (which
    // translates) during the step, tangential part.
    const Vec3<AD> relative =
      (xbar - to<AD>(history.point)) - to<AD>(shift - shift_old);
    const Vec3<AD> slip = relative - scale(dot(relative, normal), normal);
    // The committed traction turned with the normal (a curved surface).
    Vec3<AD> committed = {{AD(0.), AD(0.), AD(0.)}};
    if (history.active && value(dot(to<AD>(history.normal), normal)) > 0)
      committed = turn(history.normal, normal, to<AD>(history.traction));

    apply_law<dim>(gap,
                   normal,
                   slip,
                   nullptr,
                   0,
                   n_dofs,
                   multiplier,
                   committed,
                   law,
                   area,
                   R,
                   K,
                   result);
    return result;
  }

  ContactPointResult
  NodeToSmoothedSegment::evaluate(const Vec3<double> &slave,
                                  const Vec3<double> *master,
                                  const bool         *has,
                                  const double        xi_value,
                                  const Vec3<double> *master_old,
                                  const SlaveHistory &history,
                                  const ContactLaw   &law,
                                  const double        area,
                                  const bool          consistent,
                                  double             *R,
                                  double             *K,
                                  const Vec3<double> *multiplier)
  {
    constexpr unsigned int dim = 2;
    ContactPointResult     result;
    result.face = -1;

    // Seed the present nodes: slave, x_0, x_1, then the neighbours.
    const unsigned int n_displacements =
      dim * (3 + (has[0] ? 1 : 0) + (has[1] ? 1 : 0));
    const unsigned int n_out = n_displacements + (multiplier ? dim : 0);
    const Vec3<AD>     xs    = seed<dim>(slave, 0, n_out);
    Vec3<AD>           xm[4];
    unsigned int       next = dim;
    for (unsigned int k = 0; k < 4; ++k)
      if (k < 2 || has[k - 2])
      {
        xm[k] = seed<dim>(master[k], next, n_out);
        next += dim;
      }
      else
        xm[k] = to<AD>(master[k]);

    Vec3<AD> n0, n1;
    if (consistent)
      SmoothedSegment::nodal_normals(xm, has, n0, n1);
    else
    {
      // Paper tangent: the normal field held fixed.
      Vec3<double> m0, m1;
      SmoothedSegment::nodal_normals(master, has, m0, m1);
      n0 = to<AD>(m0);
      n1 = to<AD>(m1);
    }

    // xi: one Newton step in AD from the converged root is the implicit
    // derivative of the projection condition.
    const double derivative =
      SmoothedSegment::condition_derivative(slave, master, has, xi_value);
    AD xi = xi_value;
    {
      const AD       N0 = 0.5 * (1. - xi_value), N1 = 0.5 * (1. + xi_value);
      const Vec3<AD> xbar   = scale(N0, xm[0]) + scale(N1, xm[1]);
      const Vec3<AD> normal = scale(N0, n0) + scale(N1, n1);
      xi -= SmoothedSegment::cross2(xs - xbar, normal) / derivative;
    }
    const AD       N[2]   = {0.5 * (1. - xi), 0.5 * (1. + xi)};
    const Vec3<AD> xbar   = scale(N[0], xm[0]) + scale(N[1], xm[1]);
    Vec3<AD>       normal = scale(N[0], n0) + scale(N[1], n1);
    normal                = scale(1. / norm(normal), normal);
    const AD gap          = dot(xs - xbar, normal);

    // Slip and committed traction as for NodeToSegment (2D: the turn with
    // the normal is the whole rotation).
    Vec3<AD> relative = to<AD>(scale(-1., history.point));
    for (unsigned int k = 0; k < 2; ++k)
      relative = relative + scale(N[k], to<AD>(master_old[k]));
    const Vec3<AD> slip      = relative - scale(dot(relative, normal), normal);
    Vec3<AD>       committed = {{AD(0.), AD(0.), AD(0.)}};
    if (history.active && value(dot(to<AD>(history.normal), normal)) > 0)
      committed = turn(history.normal, normal, to<AD>(history.traction));

    apply_law<dim>(gap,
                   normal,
                   slip,
                   N,
                   2,
                   n_displacements,
                   multiplier,
                   committed,
                   law,
                   area,
                   R,
                   K,
                   result);
    result.xi[0] = value(xi);
    return result;
  }

  template struct NodeToSegment<2>;
  template struct NodeToSegment<3>;
  template struct NodeToRigid<2>;
  template struct NodeToRigid<3>;
} // namespace tribos
