#include <tribos/contact/element/contact_element.h>

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
     * The rotation of a face between the last converged step (vertices
     * @p x_old) and now (@p x) at local coordinates @p xi, applied to @p v
     * (internal::rotate_with_face()).
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
      return internal::rotate_with_face(a_old, n_old, a, n, v);
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
        // The committed face is of the surface's one kind.
        return input.face.kind.visit_linear<3>(
          [&](auto kind)
          {
            return rotate_with_face<decltype(kind)>(input.committed_old,
                                                    x_committed,
                                                    committed.result.xi,
                                                    to<AD>(w));
          });
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
