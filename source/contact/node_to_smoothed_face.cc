#include <tribos/contact/contact_element.h>

namespace tribos
{
  namespace
  {
    using AD = ContactAD;

    /**
     * R v for the rotation R that takes the unit vector @p from to the unit
     * vector @p onto (internal::turn() with both of the number type).
     */
    Vec3<AD>
    turn(const Vec3<AD> &from, const Vec3<AD> &onto, const Vec3<AD> &v)
    {
      const AD       c = dot(from, onto);
      const Vec3<AD> w = cross(from, onto);
      return scale(c, v) + cross(w, v) + scale(dot(w, v) / (1. + c), w);
    }

    /**
     * The rotation of a face between the last converged step and now at
     * local coordinates @p xi, applied to @p v: the rotation R1 that takes
     * the face's normal then (@p x_old) to its normal now (@p x), after
     * the spin phi about the old normal that remains of the polar
     * decomposition of the face's in-plane deformation (tan phi = (G_21 -
     * G_12)/(G_11 + G_22), G = R1^T F_s in an orthonormal frame of the old
     * tangent plane; Rodrigues' formula, so v need not be tangent). A
     * rigid rotation Q of the face gives Q v.
     */
    template <class Face>
    Vec3<AD>
    rotate_with_face(const Vec3<double> *x_old,
                     const Vec3<AD>     *x,
                     const double       *xi,
                     const Vec3<AD>     &v)
    {
      Vec3<double> xbar_old, a_old[2], n_old;
      Face::geometry(x_old, xi, xbar_old, a_old, n_old);
      Vec3<AD> xbar, a[2], n;
      Face::geometry(x, xi, xbar, a, n);
      // Dual basis of the old tangents (in the old tangent plane).
      const double m11 = dot(a_old[0], a_old[0]), m12 = dot(a_old[0], a_old[1]),
                   m22           = dot(a_old[1], a_old[1]);
      const double       det     = m11 * m22 - m12 * m12;
      const Vec3<double> dual[2] = {
        scale(1. / det, scale(m22, a_old[0]) - scale(m12, a_old[1])),
        scale(1. / det, scale(m11, a_old[1]) - scale(m12, a_old[0]))};
      const auto F = [&](const Vec3<double> &w)
      {
        return scale(dot(dual[0], w), a[0]) + scale(dot(dual[1], w), a[1]);
      };
      const Vec3<double> e1 = scale(1. / norm(a_old[0]), a_old[0]);
      const Vec3<double> e2 = cross(n_old, e1);
      const Vec3<AD>     r1 = internal::turn(n_old, n, to<AD>(e1)),
                     r2     = internal::turn(n_old, n, to<AD>(e2));
      const Vec3<AD> f1 = F(e1), f2 = F(e2);
      const AD       c    = dot(r1, f1) + dot(r2, f2);
      const AD       s    = dot(r2, f1) - dot(r1, f2);
      const AD       r    = sqrt(c * c + s * s);
      const Vec3<AD> axis = to<AD>(n_old);
      const Vec3<AD> spun = scale(c / r, v) + scale(s / r, cross(axis, v)) +
                            scale((1. - c / r) * dot(axis, v), axis);
      return internal::turn(n_old, n, spun);
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
    if (input.n_committed_vertices > 0 && committed.closed() &&
        value_of(dot(to<AD>(committed.result.normal), normal)) > 0)
    {
      // The committed traction and normal rotated with the face the node
      // was on at the last converged step, at its committed coordinates
      // (a rigid rotation of the bodies rotates the sticking traction
      // exactly), then turned to the normal now. The face is the
      // committed one whichever face the node is on now, so the residual
      // does not jump when the node crosses an edge within the increment.
      Vec3<AD> x_committed[4];
      for (unsigned int v = 0; v < input.n_committed_vertices; ++v)
        x_committed[v] = xm[input.committed_vertices[v]];
      const auto rotate = [&](const Vec3<double> &w)
      {
        if (input.n_committed_vertices == 3)
          return rotate_with_face<TriangleFace>(input.committed_old,
                                                x_committed,
                                                committed.result.xi,
                                                to<AD>(w));
        return rotate_with_face<MasterFace<3>>(input.committed_old,
                                               x_committed,
                                               committed.result.xi,
                                               to<AD>(w));
      };
      kinematics.committed = turn(rotate(committed.result.normal),
                                  normal,
                                  rotate(committed.result.traction));
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
