#ifndef tribos_contact_node_state_h
#define tribos_contact_node_state_h

#include <tribos/contact/surface/master_face.h>
#include <tribos/contact/surface/vec3.h>

#include <limits>

namespace tribos
{
  /**
   * The interface law's parameters at one slave node (paper section 2.2),
   * resolved by the pair's enforcement (Enforcement::law()).
   */
  struct ContactLaw
  {
    /** Normal penalty eps_N (14); with multipliers the complementarity
     * parameter c of the normal condition. */
    double normal_penalty = 0;
    /** Tangential penalty eps_T of the stick trial (16); with multipliers
     * the complementarity parameter c_T. */
    double tangential_penalty = 0;
    /** Coulomb coefficient mu (17); 0 means frictionless. */
    double friction_coefficient = 0;
    /**
     * Gaps up to this count as touching: contact is active from g_N = touch
     * on, t_N = eps_N (touch - g_N). A node of a body that rests on a
     * master at g_N = 0 (a scene with Gap = 0) must close in the first
     * iteration whatever the round-off of its position, or a body held only
     * by contact is singular there; 1e-12 of the element size is below any
     * physical gap and above the round-off of the positions.
     */
    double touch = 0;
    /**
     * Augmented Lagrangian multiplier lambda of the node (a pressure):
     * t_N = <lambda - eps_N g_N>. Zero for pure penalty.
     */
    double multiplier = 0;
    /**
     * Penalty formulation = mixed: 1/eps_N and 1/eps_T, the compliances
     * that regularize the multiplier conditions into the penalty law
     * (zero: exact contact).
     */
    double normal_compliance     = 0;
    double tangential_compliance = 0;
    /**
     * Lagrange multipliers only: bit d set if the slave node's displacement
     * component d is fixed (Dirichlet or a symmetry plane). A stick
     * condition along a tangent in which the slave cannot move would make
     * the saddle-point system singular (e.g. on a symmetry plane); there
     * the tangential multiplier is set to zero instead, which is what
     * symmetry implies.
     */
    unsigned int fixed_components = 0;
    /**
     * Chattering remedy: the node is held closed for the rest of the
     * increment whatever its gap or pressure (the converged state is
     * accepted only if its pressure is not tensile).
     */
    bool frozen_closed = false;
    /**
     * Chattering remedy for friction: the node is held in stick for the
     * rest of the increment (its slip direction kept reversing while
     * Newton stalled); the converged state is accepted only if its
     * traction is within the Coulomb cone.
     */
    bool frozen_stick = false;
  };



  /**
   * Contact status of a slave node, as written to CSTATUS: open, closed and
   * sticking, closed and slipping (Abaqus' numbers), or closed on a
   * frictionless interface (no tangential state to stick or slip).
   */
  enum class ContactStatus : int
  {
    open   = 0,
    stick  = 1,
    slip   = 2,
    closed = 3
  };



  /** What the evaluation of one contact point reports (values only). */
  struct ContactPointResult
  {
    ContactStatus status = ContactStatus::open;
    /** Normal gap g_N (2); negative is penetration. */
    double gap = 0;
    /** Normal pressure t_N. */
    double pressure = 0;
    /** Tangential traction vector T (acts on the master; -T on the slave). */
    Vec3<double> traction{{0, 0, 0}};
    Vec3<double> normal{{0, 0, 0}};
    /** Slip increment of the return mapping (|T_trial| - mu t_N over
     * eps_T), or (multipliers) of the node's tangential motion. */
    double slip_increment = 0;
    /** Local coordinates of the projection (deformable master). */
    double xi[2] = {0, 0};
    /** The area the traction acts on: node to surface, the node's
     * tributary area in the reference configuration; mortar, its weight
     * w_j in the current one. */
    double area = 0;
  };



  /**
   * Everything the contact algorithm knows about one slave node of one pair:
   * its pairing with the master (the search's answer), the result of its
   * last evaluation, where it was on the master (projection point, normal,
   * face, local coordinates: the frame of the next step's trial traction
   * and slip), its accumulated slip and its enforcement's values (the
   * augmented Lagrangian's multiplier; the Lagrange multiplier, a copy of
   * its unknowns). A pair keeps one current and one committed copy per
   * node: committing a converged increment is `committed = current`,
   * restoring a failed one `current = committed` (the pairing included),
   * like the plastic history of the bulk.
   */
  struct NodeState
  {
    /* Pairing. */
    /** Whether the node has a master point (face, or rigid surface). */
    bool       paired = false;
    int        face   = -1;
    Projection projection;
    /** Distance to the closest point of the master surface (also for a
     * node that slid off its end: its gap then); NaN if unknown. */
    double distance = std::numeric_limits<double>::quiet_NaN();

    /* The last evaluation. */
    ContactPointResult result;
    /** The projection point on the master (the node itself if unpaired). */
    Vec3<double> point{{0, 0, 0}};
    /** Accumulated slip, this increment's included. */
    double slip = 0;

    /* Enforcement. */
    /** Augmented Lagrangian multiplier (a pressure). */
    double multiplier = 0;
    /** Lagrange multiplier (the node's traction vector), read from the
     * system's unknowns. */
    Vec3<double> lambda{{0, 0, 0}};

    /** Whether the node was closed at this state. */
    bool
    closed() const
    {
      return result.status != ContactStatus::open;
    }
  };
} // namespace tribos

#endif
