#ifndef tribos_contact_contact_element_h
#define tribos_contact_contact_element_h

#include <tribos/contact/enforcement/enforcement.h>
#include <tribos/contact/state/node_state.h>
#include <tribos/contact/surface/face_shape.h>
#include <tribos/contact/surface/master_face.h>
#include <tribos/contact/surface/rigid_surface.h>
#include <tribos/contact/surface/smoothed_face.h>
#include <tribos/contact/surface/smoothed_segment.h>

namespace tribos
{
  /**
   * What the contact elements need of one slave node: its position, its
   * committed state (the frame and traction of the last converged step),
   * the law's parameters and its tributary area; with an enforcement that
   * owns unknowns, their values (@p unknowns).
   */
  struct SlaveInput
  {
    Vec3<double>        position;
    const NodeState    *committed = nullptr;
    ContactLaw          law;
    double              area     = 0;
    const Vec3<double> *unknowns = nullptr;
    /** Tangent = consistent (else the paper's (29)-(31)). */
    bool consistent = true;
  };

  namespace internal
  {
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
     * R v for the rotation R of a face between the last converged step and
     * now at the same local coordinates, from its tangents and normal then
     * (@p a_old, @p n_old) and now (@p a, @p n): the rotation R1 that takes
     * n_old to n, after the spin phi about n_old that remains of the polar
     * decomposition of the face's in-plane deformation F_s (tan phi =
     * (G_21 - G_12)/(G_11 + G_22), G = R1^T F_s in an orthonormal frame of
     * the old tangent plane). F_s is built on the dual basis of the old
     * tangents, since a smoothed normal is not the face's own; Rodrigues'
     * formula, so @p v need not be tangent. A rigid rotation Q of the face
     * gives Q v. The committed traction's turn with a 3D master face,
     * faceted or smoothed.
     */
    template <typename Number>
    Vec3<Number>
    rotate_with_face(const Vec3<double> *a_old,
                     const Vec3<double> &n_old,
                     const Vec3<Number> *a,
                     const Vec3<Number> &n,
                     const Vec3<Number> &v)
    {
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
      const Vec3<Number> r1 = turn(n_old, n, to<Number>(e1)),
                         r2 = turn(n_old, n, to<Number>(e2));
      const Vec3<Number> f1 = F(e1), f2 = F(e2);
      const Number       c    = dot(r1, f1) + dot(r2, f2);
      const Number       s    = dot(r2, f1) - dot(r1, f2);
      const Number       r    = sqrt(c * c + s * s);
      const Vec3<Number> axis = to<Number>(n_old);
      const Vec3<Number> spun = scale(c / r, v) + scale(s / r, cross(axis, v)) +
                                scale((1. - c / r) * dot(axis, v), axis);
      return turn(n_old, n, spun);
    }

    /** @p n entries (dim of them from @p first on) of @p x seeded as
     * independent AD variables (constants if @p n is 0: a residual
     * only). */
    template <int dim>
    Vec3<ContactAD>
    seed(const Vec3<double> &x, const unsigned int first, const unsigned int n);

    /**
     * The slip increment of the step, written once for every element: the
     * tangential part (at the current @p normal) of @p moved - xbar_n,
     * @p moved being where the master material point under the slave's
     * contact point was at the last converged step and xbar_n the
     * committed contact point.
     */
    Vec3<ContactAD>
    slip_increment(const Vec3<ContactAD> &moved,
                   const NodeState       &committed,
                   const Vec3<ContactAD> &normal);

    /** The committed traction turned with the normal (zero if the node was
     * open, or if the normal turned over). */
    Vec3<ContactAD>
    committed_traction(const NodeState       &committed,
                       const Vec3<ContactAD> &normal);

    /**
     * Every element type ends here: the enforcement's local law at the
     * point of @p kinematics gives the force on the slave (per unit area)
     * and, with unknowns, the node's conditions. The residual of node i of
     * the @p n_force_nodes that carry the force is @p weights[i] times the
     * force (node-to-segment: A on the slave, -N_a A on the master nodes;
     * mortar: D on the slave nodes, -M on the master nodes), the
     * unknowns' rows after the @p n_displacements displacement rows are
     * @p row_area times the conditions, and the AD derivative is the
     * tangent.
     */
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
                    ContactPointResult     &result);
  } // namespace internal



  /** A face of a deformable master: its nodes now and at the last
   * converged step, the slave's projection onto it, and whether the
   * committed state lies on this face. */
  template <int dim>
  struct FaceInput
  {
    Vec3<double> x[4], x_old[4];
    Projection   projection;
    bool         same_face = false;
    /** The face's kind, a linear one (nodes x[0..n_vertices)). */
    FaceShape shape = FaceShape::of<LinearFace<dim>>();
  };

  /** A segment of a smoothed 2D master: x_0, x_1, the node before, the
   * node after (SmoothedSegment), which neighbours exist, the segment's
   * nodes at the last converged step, and the slave's smoothed projection
   * coordinate. */
  struct SmoothedInput
  {
    Vec3<double> x[4], x_old[2];
    bool         has[2] = {false, false};
    double       xi     = 0;
  };

  /** A face of a smoothed 3D master: the stencil (SmoothedFace: the
   * face's vertices, then the other vertices of the faces around them),
   * its nodes now and (the face's vertices) at the last converged step,
   * the slave's smoothed projection, and the face the committed state lies
   * on: its vertices in the stencil (n_committed_vertices = 0 if it has
   * none or they are not all in the stencil) and at the last converged
   * step. */
  struct SmoothedFaceInput
  {
    SmoothedFace face;
    Vec3<double> x[SmoothedFace::max_nodes], x_old[4];
    double       xi[2]                 = {0, 0};
    double       g                     = 0;
    unsigned int n_committed_vertices  = 0;
    unsigned int committed_vertices[4] = {0, 0, 0, 0};
    Vec3<double> committed_old[4];
  };

  /** A rigid surface and its translation now and at the last converged
   * step. */
  template <int dim>
  struct RigidInput
  {
    const RigidSurface<dim> *surface = nullptr;
    Vec3<double>             shift, shift_old;
  };

  /**
   * The residual of one contact element and its derivative. The residual
   * of a slave node k with tributary area A_k is (paper (24)-(27), written
   * for the penalty law (14) and the Coulomb return mapping (16)-(19))
   *
   *   R_slave    =  A_k (T - t_N n),
   *   R_master_a = -N_a(xi) A_k (T - t_N n),
   *
   * with t_N = eps_N <-g_N>, the trial tangential traction
   * T_trial = Q T_n + eps_T dg_T, and T = T_trial (stick) or
   * mu t_N T_trial / |T_trial| (slip). Both parts are objective: a rigid
   * rotation of the bodies in contact changes neither.
   *
   * The slip increment of the step is the motion of the slave's projection
   * point relative to the master material point it left,
   *   dg_T = P_T [ sum_a N_a(xi) x_a,n - xbar_n ],
   * with xbar_n the committed projection point and x_a,n the master nodes
   * at the last converged step: the paper's a_alpha dxi^alpha of (16),
   * measured on the master as it was and tangential to it as it is. It
   * vanishes under a rigid motion whatever the penetration (the relative
   * motion of the slave node itself would see the penetration g_N n turn
   * with the bodies: a spurious slip g_N dtheta per step), and it holds for
   * a node that crosses to another master face within a step.
   *
   * Q turns the committed traction with the surface: the rotation taking
   * the committed normal to the current one, times (3D, same master face
   * as at the last step) the spin of the face about its normal, the
   * rotation of the polar decomposition of the face's in-plane
   * deformation at the committed local coordinates. A rigid rotation is
   * reproduced exactly; the paper's covariant components t_alpha = T .
   * a_alpha do the same to first order.
   *
   * The residual is templated on the number type and differentiated by
   * Sacado forward AD: with Tangent = consistent the local coordinates xi
   * carry their exact derivative (one Newton step of the projection in AD
   * from the converged value equals the implicit derivative), and the
   * normal and tangents are differentiated too, so the tangent is the
   * exact derivative of what is assembled. With Tangent = paper, xi moves
   * with the small-deformation update xi + M^-1 (x - xbar) . a_beta
   * (metric M = a_a . a_b, curvature term dropped) and n, a_alpha are held
   * fixed: the linearization (29)-(31).
   */
  template <int dim>
  struct NodeToSegment
  {
    /** The most master nodes and dofs (a triangle face has 3 nodes, and
     * 3 fewer dofs). */
    static constexpr unsigned int n_nodes = MasterFace<dim>::n_nodes;
    static constexpr unsigned int n_dofs  = dim * (1 + n_nodes);

    /**
     * Evaluate the element of @p slave against @p face with the law of
     * @p enforcement. R gets n_dofs entries (slave dofs first, then master
     * node by node) plus the enforcement's unknowns per node (rows: the
     * node's conditions); K, if not null, their square (row-major, K_ij =
     * dR_i/du_j).
     */
    static ContactPointResult
    evaluate(const SlaveInput       &slave,
             const FaceInput<dim>   &face,
             const Enforcement<dim> &enforcement,
             double                 *R,
             double                 *K);
  };



  /**
   * The 2D element against a master whose normal field is smoothed by
   * averaged nodal normals (SmoothedSegment, Contact/Master smoothing): the
   * same interface laws, with the projection, the gap and the normal of
   * the smoothed surface. The force acts on the slave and on the two nodes
   * of the segment (-N_a(xi) times it); the neighbour nodes get no force,
   * but the normal depends on them, so their columns are part of the
   * (exact, AD) tangent. Dofs: slave, x_0, x_1, then the node before x_0
   * and the node after x_1 where @p has says they exist, then the
   * multiplier.
   */
  struct NodeToSmoothedSegment
  {
    /** Displacement dofs at most: slave and four master nodes. */
    static constexpr unsigned int max_dofs = 2 * 5;

    /** As NodeToSegment::evaluate(); dofs: slave, x_0, x_1, then the
     * existing neighbours, then the enforcement's unknowns. */
    static ContactPointResult
    evaluate(const SlaveInput     &slave,
             const SmoothedInput  &segment,
             const Enforcement<2> &enforcement,
             double               *R,
             double               *K);
  };



  /**
   * The 3D element against a master whose normal field is smoothed by
   * averaged nodal normals (SmoothedFace, Contact/Master smoothing): the
   * interface laws of NodeToSegment with the projection, the gap and the
   * normal of the smoothed surface. The force acts on the slave and on the
   * face's vertices (-N_a(xi) times it); the other nodes of the stencil
   * get no force, but the nodal normals depend on them, so their columns
   * are part of the (exact, AD) tangent. The committed traction rotates
   * with the face it was committed on (its normal's turn and its in-plane
   * spin) and then turns to the current normal, so that a rigid rotation
   * leaves a sticking traction as it was in the co-rotating frame, and the
   * residual stays continuous when the node crosses to another face.
   */
  struct NodeToSmoothedFace
  {
    /** Displacement dofs at most: the slave and a full stencil. */
    static constexpr unsigned int max_dofs = 3 * (1 + SmoothedFace::max_nodes);

    /** As NodeToSegment::evaluate(); dofs: slave, the stencil's nodes,
     * then the enforcement's unknowns. */
    static ContactPointResult
    evaluate(const SlaveInput        &slave,
             const SmoothedFaceInput &input,
             const Enforcement<3>    &enforcement,
             double                  *R,
             double                  *K);
  };



  /** The same element against a rigid surface: only the slave's dofs. */
  template <int dim>
  struct NodeToRigid
  {
    static constexpr unsigned int n_dofs = dim;

    /** As NodeToSegment::evaluate(); dofs: the slave's, then the
     * enforcement's unknowns. */
    static ContactPointResult
    evaluate(const SlaveInput       &slave,
             const RigidInput<dim>  &surface,
             const Enforcement<dim> &enforcement,
             double                 *R,
             double                 *K);
  };
} // namespace tribos

#endif
