#ifndef tribos_contact_mortar_element_h
#define tribos_contact_mortar_element_h

#include <tribos/contact/element/contact_element.h>

#include <deal.II/base/types.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace tribos
{
  /**
   * What the 2D mortar element of one slave node j needs: the slave nodes
   * of its segments (j first, then its neighbours), now and at the last
   * converged step, the segments as lists of those local numbers (ends
   * ordered so that the MasterFace normal points out of the slave body,
   * then the middle node of a quadratic segment), and the master nodes and
   * segments that the search found facing them.
   */
  struct MortarInput
  {
    /** A vertex of Q2: its two segments' ends and middles. */
    static constexpr unsigned int max_slave_nodes = 5;

    unsigned int n_slave_nodes = 0;
    Vec3<double> xs[max_slave_nodes], xs_old[max_slave_nodes];
    unsigned int n_slave_segments = 0;
    unsigned int slave_segment[2][3];

    unsigned int n_master_nodes = 0;
    Vec3<double> xm[max_mortar_master_nodes], xm_old[max_mortar_master_nodes];
    unsigned int n_master_segments = 0;
    std::array<unsigned int, 3> master_segment[max_mortar_master_nodes];

    /** The segments' kind, slave and master: Segment2 (Q1, P1) or
     * Segment3 (Q2, P2: the ends, then the middle). */
    FaceShape shape = FaceShape::of<Segment2>();

    /** Mortar basis = dual (else standard). */
    bool dual = true;
    /** Integrate over the surface of revolution (x = r, weight 2 pi r). */
    bool axisymmetric = false;
    /** A node whose weight w_j (below) is below this has no master (its
     * segments barely overlap the master). */
    double min_weight = 0;
    /** The share of the contact this element carries (ContactPair::
     * area_factor: one half for each side of a self-contact pair with
     * penalty): its forces and the area it reports are scaled by it. */
    double area_factor = 1;
    /**
     * Contact/Master smoothing = averaged normals (Q1): the nodal normal
     * n_j from the master's averaged nodal normals instead of the slave's
     * segments (see Mortar2D).
     */
    bool smoothed_master = false;
    /** With smoothed_master: per master segment, the local numbers of the
     * master nodes before its first and after its second node along the
     * surface (MasterFace::beyond), -1 at the surface's ends; the
     * segment's averaged end normals are SmoothedSegment's. */
    int master_beyond[max_mortar_master_nodes][2];
  };



  /**
   * The mortar (segment-to-segment) element of slave node j in 2D, after
   * Yang, Laursen and Meng (2005) and Popp, Gee and Wall (2009): the
   * node's multiplier function Phi_j weights the gap and the traction over
   * the overlap of its slave segments with the master segments.
   *
   * On each slave segment [x_a, x_b] (coordinate s in [0, 1]) the master
   * segments that face it are projected orthogonally onto its line; the
   * overlap is clipped to [0, 1] and integrated by 2-point Gauss, which is
   * exact: along the overlap the master coordinate is an affine function of
   * s, so every integrand is quadratic. With it
   *
   *   D_jk = int Phi_j N_k,   M_jl = int Phi_j N_l(chi(s)),
   *   w_j  = sum_k D_jk = sum_l M_jl  (the overlap's weight),
   *
   * and the node's point quantities for the enforcement are
   *
   *   g_j = n_j . (sum_l M_jl y_l - sum_k D_jk x_k) / w_j  (weighted gap),
   *   dg_T = P_T [ (sum_l M_jl y_l,n - sum_k D_jk x_k,n) / w_j
   *                - (xbar_n - x_j,n) ]
   *
   * with n_j the slave's nodal normal (the unit normals of its segments
   * weighted by their share of w_j, so that a segment leaving the master
   * fades out of it continuously), y_l,n and x_k,n the nodes at the last
   * converged step and xbar_n - x_j,n the committed offset of the weighted
   * master point: like node to segment, the slip is the change of where the
   * slave sits on the master as it was, so a rigid motion of both bodies slips
   * nothing. Force on slave node k: D_jk f, on master node l: -M_jl f, for the
   * traction f of the enforcement's local law (penalty, multipliers or
   * augmented, with the Coulomb return map); the unknowns' rows are w_j
   * times the conditions. Everything, D and M included, is Sacado AD of
   * the positions: the tangent is the exact derivative of the residual.
   *
   * Dual basis: Phi_a = 2 N_a - N_b on a segment, biorthogonal to the
   * slave's shape functions, so D is diagonal where the segment is fully
   * overlapped and the traction of node j acts on node j. On a segment
   * the master covers only in part (the master's end) the dual functions
   * can have a negative weight over the covered part; there they are
   * blended continuously towards the standard functions (theta = 2 c - 1
   * for a covered fraction c in [1/2, 1]), which keeps the weights
   * positive and the residual continuous (still a partition of unity, so
   * a uniform traction is still transmitted exactly).
   *
   * For a flat interface and a uniform traction p, the forces are p int
   * N_k on the slave and p int N_l on the master nodes: the contact patch
   * test holds to round-off, with either side as slave.
   *
   * With MortarInput::smoothed_master (Contact/Master smoothing = averaged
   * normals, Q1) the nodal normal is instead the master's smoothed normal
   * field n_m(chi) = N_c n_c + N_d n_d (n_c, n_d the averaged normals of a
   * master segment's ends, as SmoothedSegment) integrated against N_j over
   * the overlaps and normalized: n_j = -int N_j n_m / |int N_j n_m|.
   * Why: the slave's nodal normal at the edge of the contact zone is
   * tilted by the slave segment beyond it, half the angle between the two
   * segments; a coarse curved slave (a punch on a flat block) then presses
   * the master at that angle, and with friction the imbalance between the
   * zone's two edges tilts the resultant (the ironing's horizontal force
   * 7 % high, doc/mortar.md). The master's normal field does not depend
   * on which slave segments touch. The weights N_j are positive, so n_j
   * lies between the master normals it averages (the dual functions, in
   * part negative, could carry it beyond them). The element then couples
   * the master nodes beyond the ends of its segments as well. Where n_j
   * would point into the slave (averaged normals at a sharp master corner
   * the slave slides off), the slave's normal is kept.
   */
  struct Mortar2D
  {
    /**
     * Evaluate the element of slave node j (@p input) with the law of
     * @p enforcement. Dofs: the slave nodes of input (2 each), the master
     * nodes (2 each), then the enforcement's unknowns; R and K as in
     * NodeToSegment::evaluate(). @p paired is set to whether the node's
     * weight reaches input.min_weight; if not, R and K are untouched.
     * @p weighted_point gets x_j + (weighted master point - weighted slave
     * point), the node's contact point.
     */
    static ContactPointResult
    evaluate(const SlaveInput     &slave,
             const MortarInput    &input,
             const Enforcement<2> &enforcement,
             double               *R,
             double               *K,
             bool                 &paired,
             Vec3<double>         &weighted_point);
  };

  namespace internal
  {
    /**
     * The weight theta of the dual functions in a slave segment's (or
     * face's) basis, blended with the standard ones: 1 where the master
     * covers the @p covered fraction 1 of it, 0 at half or less (or if
     * not @p dual), 2 covered - 1 in between. The switch at the master's
     * end is continuous, so a segment whose end lines up with the master's
     * (a symmetry plane) is not flipped between the two bases by round-off,
     * and the weights stay positive.
     */
    inline ContactAD
    dual_weight(const bool dual, const ContactAD &covered)
    {
      if (!dual || covered.val() <= 0.5)
        return ContactAD(0.);
      if (covered.val() >= 1.)
        return ContactAD(1.);
      return 2. * covered - 1.;
    }

    /**
     * The integrals of Mortar2D::evaluate() on quadratic segments (Q2,
     * input.shape Segment3): the node's weights @p D on the slave
     * nodes and @p M on the master nodes and its unnormalized normal
     * @p normal_j, from the positions @p xs, @p xm (seeded AD numbers;
     * D, M and normal_j start at zero). Slave and master are the curves x(xi) =
     * sum N_a(xi) x_a of the segments' three nodes. A master segment's
     * overlap with a slave segment runs between the closest-point
     * projections of its ends onto the slave curve; at each Gauss point
     * xi of the overlap the master point is where the slave's normal line
     * at xi meets the master curve (so the overlap's ends map to the
     * master's ends). Both projections are Newton iterations in double,
     * then one Newton step in AD numbers, which gives their exact first
     * derivatives (implicit function theorem). 5-point Gauss per overlap:
     * exact on straight segments (the integrands are then polynomials of
     * degree 4), and the mass matrix of the dual functions likewise.
     *
     * Dual basis: Phi = A N with A = D_e M_e^-1 of the segment's quadratic
     * shape functions, biorthogonal to them (on a straight segment the
     * weights int Phi_j = int N_j are h/6, 2h/3, h/6: positive, so the
     * quadratic dual basis is usable in 2D as it is, without the
     * basis transformation 3D quadratic faces would need). Blended towards
     * the standard functions on partly covered segments as on Q1. The
     * dual functions still sum to one, so a uniform traction is
     * transmitted exactly: the patch test holds for Q2.
     */
    void
    integrate_quadratic(const MortarInput     &input,
                        const Vec3<ContactAD> *xs,
                        const Vec3<ContactAD> *xm,
                        ContactAD             *D,
                        ContactAD             *M,
                        Vec3<ContactAD>       &normal_j);

    /** The position of @p node in @p list, appended if it is not there:
     * an element's local number of a node. */
    inline unsigned int
    local_number(std::vector<unsigned int> &list, const unsigned int node)
    {
      const auto at = std::find(list.begin(), list.end(), node);
      if (at != list.end())
        return static_cast<unsigned int>(at - list.begin());
      list.push_back(node);
      return static_cast<unsigned int>(list.size() - 1);
    }

  } // namespace internal
} // namespace tribos

#endif
