#include <tribos/contact/contact_element.h>

namespace tribos
{
  namespace
  {
    using AD = ContactAD;

    /**
     * The committed traction @p T (tangent to the committed normal
     * @p n_old) spun with the face about that normal: the in-plane angle
     * phi of the map F that takes the committed frame (the face's tangents
     * @p a_old at the committed coordinates and @p n_old) to the current
     * one (@p a, @p n at the same coordinates), after the rotation R1 that
     * takes n_old to n: tan phi = (G_21 - G_12)/(G_11 + G_22) with G =
     * R1^T F in an orthonormal frame of the old tangent plane. The frame
     * need not be orthogonal (a smoothed normal is not the face's): F is
     * built on its dual basis, so a rigid rotation Q gives F = Q and the
     * result R1 Spin(phi) T = Q T. Returned about @p n_old, still to be
     * turned to the current normal.
     */
    Vec3<AD>
    spin_with_face(const Vec3<double> *a_old,
                   const Vec3<double> &n_old,
                   const Vec3<AD>     *a,
                   const Vec3<AD>     &n,
                   const Vec3<double> &T)
    {
      const double       volume  = dot(a_old[0], cross(a_old[1], n_old));
      const Vec3<double> dual[3] = {scale(1. / volume, cross(a_old[1], n_old)),
                                    scale(1. / volume, cross(n_old, a_old[0])),
                                    scale(1. / volume,
                                          cross(a_old[0], a_old[1]))};
      const auto         F       = [&](const Vec3<double> &v)
      {
        return scale(dot(dual[0], v), a[0]) + scale(dot(dual[1], v), a[1]) +
               scale(dot(dual[2], v), n);
      };
      const Vec3<double> e1 =
        scale(1. / norm(a_old[0] - scale(dot(a_old[0], n_old), n_old)),
              a_old[0] - scale(dot(a_old[0], n_old), n_old));
      const Vec3<double> e2 = cross(n_old, e1);
      const Vec3<AD>     r1 = internal::turn(n_old, n, to<AD>(e1)),
                     r2     = internal::turn(n_old, n, to<AD>(e2));
      const Vec3<AD> f1 = F(e1), f2 = F(e2);
      const AD       c = dot(r1, f1) + dot(r2, f2);
      const AD       s = dot(r2, f1) - dot(r1, f2);
      const AD       r = sqrt(c * c + s * s);
      return scale(c / r, to<AD>(T)) + scale(s / r, to<AD>(cross(n_old, T)));
    }
  } // namespace



  ContactPointResult
  NodeToSmoothedFace::evaluate(const SlaveInput        &slave,
                               const SmoothedFaceInput &input,
                               const Enforcement<3>    &enforcement,
                               double                  *R,
                               double                  *K)
  {
    constexpr unsigned int dim  = 3;
    const SmoothedFace    &face = input.face;
    ContactPointResult     result;
    const unsigned int     n_nodes         = face.n_nodes;
    const unsigned int     n_displacements = dim * (1 + n_nodes);
    const unsigned int n_out = n_displacements + enforcement.n_node_unknowns();
    const Vec3<AD>     xs    = internal::seed<dim>(slave.position, 0, n_out);
    Vec3<AD>           xm[SmoothedFace::max_nodes];
    for (unsigned int k = 0; k < n_nodes; ++k)
      xm[k] = internal::seed<dim>(input.x[k], dim * (1 + k), n_out);

    // The nodal normals, differentiated (Tangent = paper: held fixed).
    Vec3<double> nodal0[4];
    face.nodal_normals(input.x, nodal0);
    Vec3<AD> nodal[4];
    if (slave.consistent)
      face.nodal_normals(xm, nodal);
    else
      for (unsigned int a = 0; a < face.n_vertices; ++a)
        nodal[a] = to<AD>(nodal0[a]);

    // xi: one Newton step in AD from the converged root of x_s = xbar(xi)
    // + g n(xi) is its implicit derivative.
    AD xi[2] = {AD(input.xi[0]), AD(input.xi[1])};
    {
      Vec3<double> xbar0, a0[2], n0, dn0[2];
      face.field(input.x, nodal0, input.xi, xbar0, a0, n0, dn0);
      double inverse[3][3];
      if (SmoothedFace::inverse_jacobian(a0, n0, dn0, input.g, inverse))
      {
        Vec3<AD> xbar, a[2], n, dn[2];
        face.field(xm, nodal, input.xi, xbar, a, n, dn);
        const Vec3<AD> r = xs - xbar - scale(input.g, n);
        for (unsigned int alpha = 0; alpha < 2; ++alpha)
          xi[alpha] -= inverse[alpha][0] * r[0] + inverse[alpha][1] * r[1] +
                       inverse[alpha][2] * r[2];
      }
    }
    Vec3<AD> xbar, a[2], field_normal, dn[2];
    face.field(xm, nodal, xi, xbar, a, field_normal, dn);
    const Vec3<AD> normal = scale(1. / norm(field_normal), field_normal);
    AD             N[4], dN[4][2];
    face.shape(xi, N, dN);

    PointKinematics kinematics;
    kinematics.gap    = dot(xs - xbar, normal);
    kinematics.normal = normal;
    Vec3<AD> moved    = {{AD(0.), AD(0.), AD(0.)}};
    for (unsigned int k = 0; k < face.n_vertices; ++k)
      moved = moved + scale(N[k], to<AD>(input.x_old[k]));
    const NodeState &committed = *slave.committed;
    kinematics.slip      = internal::slip_increment(moved, committed, normal);
    kinematics.committed = internal::committed_traction(committed, normal);
    if (input.same_face && committed.closed() &&
        value_of(dot(to<AD>(committed.result.normal), normal)) > 0)
    {
      // The face's frame at the committed coordinates, then and now.
      Vec3<double> nodal_old[4], xbar_old, a_old[2], n_old, dn_old[2];
      face.nodal_normals(input.x_old, nodal_old);
      face.field(input.x_old,
                 nodal_old,
                 committed.result.xi,
                 xbar_old,
                 a_old,
                 n_old,
                 dn_old);
      Vec3<AD> xbar_now, a_now[2], n_now, dn_now[2];
      face
        .field(xm, nodal, committed.result.xi, xbar_now, a_now, n_now, dn_now);
      n_now               = scale(1. / norm(n_now), n_now);
      const Vec3<AD> spun = spin_with_face(a_old,
                                           committed.result.normal,
                                           a_now,
                                           n_now,
                                           committed.result.traction);
      kinematics.committed =
        internal::turn(committed.result.normal, normal, spun);
    }

    AD weights[5];
    weights[0] = slave.area;
    for (unsigned int k = 0; k < face.n_vertices; ++k)
      weights[1 + k] = -slave.area * N[k];
    internal::finish_weighted<dim>(kinematics,
                                   weights,
                                   1 + face.n_vertices,
                                   n_displacements,
                                   AD(slave.area),
                                   slave,
                                   enforcement,
                                   R,
                                   K,
                                   result);
    result.xi[0] = value_of(xi[0]);
    result.xi[1] = value_of(xi[1]);
    return result;
  }
} // namespace tribos
