#include <tribos/contact/element/contact_element.h>

namespace tribos
{
  namespace internal
  {
    using AD = ContactAD;

    /** Seed @p n_values entries of @p x as independent AD variables. */
    template <int dim>
    Vec3<ContactAD>
    seed(const Vec3<double> &x, const unsigned int first, const unsigned int n)
    {
      Vec3<AD> result;
      for (unsigned int d = 0; d < 3; ++d)
        result[d] = (d < dim && n > 0 ? AD(n, first + d, x[d]) : AD(x[d]));
      return result;
    }



    /**
     * The slip increment of the step, written once for every element: the
     * tangential part (at the current @p normal) of @p moved - xbar_n,
     * @p moved being where the master material point under the slave's
     * projection point was at the last converged step (a face: sum N_a(xi)
     * x_a,n; a rigid surface: the projection point less the surface's
     * translation in the step) and xbar_n the committed projection point.
     */
    Vec3<AD>
    slip_increment(const Vec3<AD>  &moved,
                   const NodeState &committed,
                   const Vec3<AD>  &normal)
    {
      const Vec3<AD> relative = moved - to<AD>(committed.point);
      return relative - scale(dot(relative, normal), normal);
    }



    /** The committed traction turned with the normal (zero if the node was
     * open, or if the normal turned over). */
    Vec3<AD>
    committed_traction(const NodeState &committed, const Vec3<AD> &normal)
    {
      Vec3<AD> turned = {{AD(0.), AD(0.), AD(0.)}};
      if (committed.closed() &&
          value_of(dot(to<AD>(committed.result.normal), normal)) > 0)
        turned = turn(committed.result.normal,
                      normal,
                      to<AD>(committed.result.traction));
      return turned;
    }



    template <int dim>
    void
    finish_weighted(const PointKinematics  &kinematics,
                    const ContactAD        *weights,
                    const unsigned int      n_force_nodes,
                    const unsigned int      n_displacements,
                    const ContactAD        &row_area,
                    const SlaveInput       &slave,
                    const Enforcement<dim> &enforcement,
                    double                 *R,
                    double                 *K,
                    ContactPointResult     &result)
    {
      result.gap = value_of(kinematics.gap);
      for (unsigned int d = 0; d < 3; ++d)
        result.normal[d] = value_of(kinematics.normal[d]);

      const unsigned int n_unknowns = enforcement.n_node_unknowns();
      const unsigned int n_out      = n_displacements + n_unknowns;
      Vec3<AD>           unknowns, force, constraint;
      if (n_unknowns > 0)
        unknowns =
          seed<dim>(*slave.unknowns, n_displacements, K != nullptr ? n_out : 0);
      enforcement.local_law(kinematics,
                            slave.law,
                            n_unknowns > 0 ? &unknowns : nullptr,
                            force,
                            constraint,
                            result);
      result.area = value_of(row_area);

      for (unsigned int i = 0; i < n_out; ++i)
      {
        AD residual = 0.;
        if (i < dim * n_force_nodes)
          residual = weights[i / dim] * force[i % dim];
        else if (i >= n_displacements)
          residual = row_area * constraint[i - n_displacements];
        R[i] = residual.val();
        if (K != nullptr)
          for (unsigned int j = 0; j < n_out; ++j)
            K[i * n_out + j] = residual.dx(j);
      }
    }

    template Vec3<ContactAD>
    seed<2>(const Vec3<double> &, const unsigned int, const unsigned int);
    template Vec3<ContactAD>
    seed<3>(const Vec3<double> &, const unsigned int, const unsigned int);
    template void
    finish_weighted<2>(const PointKinematics &,
                       const ContactAD *,
                       const unsigned int,
                       const unsigned int,
                       const ContactAD &,
                       const SlaveInput &,
                       const Enforcement<2> &,
                       double *,
                       double *,
                       ContactPointResult &);
    template void
    finish_weighted<3>(const PointKinematics &,
                       const ContactAD *,
                       const unsigned int,
                       const unsigned int,
                       const ContactAD &,
                       const SlaveInput &,
                       const Enforcement<3> &,
                       double *,
                       double *,
                       ContactPointResult &);
  } // namespace internal

  namespace
  {
    using AD = ContactAD;
    using internal::committed_traction;
    using internal::seed;
    using internal::slip_increment;
    using internal::turn;

    /**
     * The committed traction @p T (tangent to the committed face) turned with
     * the face: in 2D with its normal, in 3D also spun with its in-plane
     * deformation (internal::rotate_with_face()).
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
        return internal::rotate_with_face(a_old, n_old, a, n, to<Number>(T));
    }



    /**
     * Every node-to-surface element ends here: the residual is A force on
     * the slave's dim rows, -N_a A force on the rows of the
     * @p n_master_nodes master nodes that carry it, A times the conditions
     * on the unknowns' rows (internal::finish_weighted()).
     */
    template <int dim>
    void
    finish(const PointKinematics  &kinematics,
           const AD               *N,
           const unsigned int      n_master_nodes,
           const unsigned int      n_displacements,
           const SlaveInput       &slave,
           const Enforcement<dim> &enforcement,
           double                 *R,
           double                 *K,
           ContactPointResult     &result)
    {
      AD weights[5];
      weights[0] = slave.area;
      for (unsigned int a = 0; a < n_master_nodes; ++a)
        weights[1 + a] = -slave.area * N[a];
      internal::finish_weighted<dim>(kinematics,
                                     weights,
                                     1 + n_master_nodes,
                                     n_displacements,
                                     AD(slave.area),
                                     slave,
                                     enforcement,
                                     R,
                                     K,
                                     result);
    }
  } // namespace



  namespace
  {
    /** NodeToSegment::evaluate() on a master face of the linear kind
     * @p Face (face_kinds.h). */
    template <int dim, class Face>
    ContactPointResult
    evaluate_on_face(const SlaveInput       &slave,
                     const FaceInput<dim>   &face,
                     const Enforcement<dim> &enforcement,
                     double                 *R,
                     double                 *K)
    {
      constexpr unsigned int n_nodes = Face::n_nodes;
      constexpr unsigned int n_dofs  = dim * (1 + n_nodes);
      ContactPointResult     result;
      const unsigned int     n_out = n_dofs + enforcement.n_node_unknowns();
      Vec3<AD>               xs    = seed<dim>(slave.position, 0, n_out);
      Vec3<AD>               xm[n_nodes];
      for (unsigned int k = 0; k < n_nodes; ++k)
        xm[k] = seed<dim>(face.x[k], dim * (1 + k), n_out);

      // Geometry at the converged projection, in double, for the update.
      Vec3<double> xbar0, a0[2], n0;
      Face::geometry(face.x, face.projection.xi, xbar0, a0, n0);

      // xi as a function of the positions (see the class documentation).
      AD xi[2] = {AD(face.projection.xi[0]), AD(face.projection.xi[1])};
      {
        Vec3<AD> xbar_fixed_xi, a_ad[2], n_ad;
        Face::geometry(xm, face.projection.xi, xbar_fixed_xi, a_ad, n_ad);
        const Vec3<AD> r = xs - xbar_fixed_xi;
        AD             residual[2];
        double         J[2][2] = {{0, 0}, {0, 0}};
        for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
        {
          residual[alpha] =
            slave.consistent ? dot(r, a_ad[alpha]) : dot(r, to<AD>(a0[alpha]));
          for (unsigned int beta = 0; beta < Face::n_coords; ++beta)
            J[alpha][beta] = dot(a0[alpha], a0[beta]);
        }
        if constexpr (dim == 3)
          if (slave.consistent)
          {
            Vec3<double> a12{{0, 0, 0}};
            for (unsigned int k = 0; k < n_nodes; ++k)
              a12 = a12 + scale(Face::mixed_derivative(k), face.x[k]);
            const double curvature = dot(slave.position - xbar0, a12);
            J[0][1] -= curvature;
            J[1][0] -= curvature;
          }
        double t[2];
        if (face.projection.inside())
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
        else if (dim == 3 && face.projection.free_direction(t))
        {
          // Clamped to one edge: the projection moves along it.
          const AD     along     = t[0] * residual[0] + t[1] * residual[1];
          const double stiffness = t[0] * (J[0][0] * t[0] + J[0][1] * t[1]) +
                                   t[1] * (J[1][0] * t[0] + J[1][1] * t[1]);
          xi[0] += t[0] * along / stiffness;
          xi[1] += t[1] * along / stiffness;
        }
      }

      Vec3<AD> xbar, a[2], normal;
      Face::geometry(xm, xi, xbar, a, normal);
      if (!slave.consistent)
      {
        normal = to<AD>(n0);
        for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
          a[alpha] = to<AD>(a0[alpha]);
      }
      const AD gap = dot(xs - xbar, normal);

      AD N[n_nodes], dN[n_nodes][2];
      Face::shape(xi, N, dN);

      PointKinematics kinematics;
      kinematics.gap    = gap;
      kinematics.normal = normal;
      // Slip: the projection point's motion relative to the master material
      // point it left, measured on the master as it was.
      Vec3<AD> moved = {{AD(0.), AD(0.), AD(0.)}};
      for (unsigned int k = 0; k < n_nodes; ++k)
        moved = moved + scale(N[k], to<AD>(face.x_old[k]));
      const NodeState &committed = *slave.committed;
      kinematics.slip            = slip_increment(moved, committed, normal);

      // The committed traction turned with the face (on the same face, at
      // the committed coordinates: its spin about the normal too), else with
      // the normal.
      kinematics.committed = committed_traction(committed, normal);
      if (face.same_face && committed.closed() &&
          dot(committed.result.normal, n0) > 0)
      {
        Vec3<double> xbar_old, a_old[2], n_old;
        Face::geometry(face.x_old, committed.result.xi, xbar_old, a_old, n_old);
        Vec3<AD> xbar_now, a_now[2], n_now;
        if (slave.consistent)
          Face::geometry(xm, committed.result.xi, xbar_now, a_now, n_now);
        else
        {
          Vec3<double> x_value, a_value[2], n_value;
          Face::geometry(face.x,
                         committed.result.xi,
                         x_value,
                         a_value,
                         n_value);
          n_now = to<AD>(n_value);
          for (unsigned int alpha = 0; alpha < Face::n_coords; ++alpha)
            a_now[alpha] = to<AD>(a_value[alpha]);
        }
        kinematics.committed = turn_with_face<dim>(a_old,
                                                   n_old,
                                                   a_now,
                                                   n_now,
                                                   committed.result.traction);
      }

      finish<dim>(kinematics,
                  N,
                  n_nodes,
                  n_dofs,
                  slave,
                  enforcement,
                  R,
                  K,
                  result);
      result.xi[0] = value_of(xi[0]);
      result.xi[1] = value_of(xi[1]);
      return result;
    }
  } // namespace



  template <int dim>
  ContactPointResult
  NodeToSegment<dim>::evaluate(const SlaveInput       &slave,
                               const FaceInput<dim>   &face,
                               const Enforcement<dim> &enforcement,
                               double                 *R,
                               double                 *K)
  {
    return face.shape.template visit_linear<dim>(
      [&](auto kind)
      {
        return evaluate_on_face<dim, decltype(kind)>(slave,
                                                     face,
                                                     enforcement,
                                                     R,
                                                     K);
      });
  }



  template <int dim>
  ContactPointResult
  NodeToRigid<dim>::evaluate(const SlaveInput       &slave,
                             const RigidInput<dim>  &surface,
                             const Enforcement<dim> &enforcement,
                             double                 *R,
                             double                 *K)
  {
    ContactPointResult result;
    const unsigned int n_out = n_dofs + enforcement.n_node_unknowns();
    const Vec3<AD>     xs    = seed<dim>(slave.position, 0, n_out);

    Vec3<AD> xbar, normal;
    AD       gap;
    surface.surface->closest_point(xs, surface.shift, xbar, normal, gap);
    if (!slave.consistent)
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

    PointKinematics kinematics;
    kinematics.gap    = gap;
    kinematics.normal = normal;
    // Slip: the projection point's motion relative to the surface, which
    // translates; the committed traction turned with the normal (a curved
    // surface).
    kinematics.slip =
      slip_increment(xbar - to<AD>(surface.shift - surface.shift_old),
                     *slave.committed,
                     normal);
    kinematics.committed = committed_traction(*slave.committed, normal);

    finish<dim>(kinematics,
                nullptr,
                0,
                n_dofs,
                slave,
                enforcement,
                R,
                K,
                result);
    return result;
  }



  ContactPointResult
  NodeToSmoothedSegment::evaluate(const SlaveInput     &slave,
                                  const SmoothedInput  &segment,
                                  const Enforcement<2> &enforcement,
                                  double               *R,
                                  double               *K)
  {
    constexpr unsigned int dim = 2;
    ContactPointResult     result;
    const double           xi_value = segment.xi;

    // Seed the present nodes: slave, x_0, x_1, then the neighbours.
    const unsigned int n_displacements =
      dim * (3 + (segment.has[0] ? 1 : 0) + (segment.has[1] ? 1 : 0));
    const unsigned int n_out = n_displacements + enforcement.n_node_unknowns();
    const Vec3<AD>     xs    = seed<dim>(slave.position, 0, n_out);
    Vec3<AD>           xm[4];
    unsigned int       next = dim;
    for (unsigned int k = 0; k < 4; ++k)
      if (k < 2 || segment.has[k - 2])
      {
        xm[k] = seed<dim>(segment.x[k], next, n_out);
        next += dim;
      }
      else
        xm[k] = to<AD>(segment.x[k]);

    Vec3<AD> n0, n1;
    if (slave.consistent)
      SmoothedSegment::nodal_normals(xm, segment.has, n0, n1);
    else
    {
      // Paper tangent: the normal field held fixed.
      Vec3<double> m0, m1;
      SmoothedSegment::nodal_normals(segment.x, segment.has, m0, m1);
      n0 = to<AD>(m0);
      n1 = to<AD>(m1);
    }

    // xi: one Newton step in AD from the converged root is the implicit
    // derivative of the projection condition.
    const double derivative =
      SmoothedSegment::condition_derivative(slave.position,
                                            segment.x,
                                            segment.has,
                                            xi_value);
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
    PointKinematics kinematics;
    kinematics.gap    = gap;
    kinematics.normal = normal;
    Vec3<AD> moved    = {{AD(0.), AD(0.), AD(0.)}};
    for (unsigned int k = 0; k < 2; ++k)
      moved = moved + scale(N[k], to<AD>(segment.x_old[k]));
    kinematics.slip      = slip_increment(moved, *slave.committed, normal);
    kinematics.committed = committed_traction(*slave.committed, normal);

    finish<dim>(kinematics,
                N,
                2,
                n_displacements,
                slave,
                enforcement,
                R,
                K,
                result);
    result.xi[0] = value_of(xi);
    return result;
  }

  template struct NodeToSegment<2>;
  template struct NodeToSegment<3>;
  template struct NodeToRigid<2>;
  template struct NodeToRigid<3>;
} // namespace tribos
