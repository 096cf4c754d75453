#ifndef tribos_contact_contact_point_h
#define tribos_contact_contact_point_h

#include <tribos/contact/vec3.h>

namespace tribos
{
  /** Interface law of one contact pair (paper section 2.2). */
  struct ContactLaw
  {
    /** Normal penalty eps_N (14). */
    double normal_penalty = 0;
    /** Tangential penalty eps_T of the stick trial (16). */
    double tangential_penalty = 0;
    /** Coulomb coefficient mu (17); 0 means frictionless. */
    double friction_coefficient = 0;
    /**
     * Augmented Lagrangian multiplier lambda of the node (a pressure):
     * t_N = <lambda - eps_N g_N>. Zero for pure penalty.
     */
    double multiplier = 0;
    /**
     * Lagrange multiplier method only: bit d set if the slave node's
     * displacement component d is fixed (Dirichlet or a symmetry plane).
     * A stick condition along a tangent in which the slave cannot move
     * would make the saddle-point system singular (e.g. on a symmetry
     * plane); there the tangential multiplier is set to zero instead,
     * which is what symmetry implies.
     */
    unsigned int fixed_components = 0;
    /**
     * Chattering remedy: the node is held closed for the rest of the
     * increment whatever its gap or pressure (the converged state is
     * accepted only if its pressure is not tensile).
     */
    bool frozen_closed = false;
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

  /**
   * History of one slave node, committed only when a step converges (like
   * plastic history): whether it was in contact, its tangential traction
   * vector T_n, the accumulated slip, and where it was: the projection
   * point and normal on the master (the slave's own position and a zero
   * normal if it was not paired), the master face and its local
   * coordinates. The frame lets the next step's trial traction turn with
   * the surface and measure the slip against the master material point
   * it left, so that a rigid motion of the bodies in contact changes
   * neither (objectivity). (The nodes' positions at the last converged
   * step are kept per surface.)
   */
  struct SlaveHistory
  {
    bool         active = false;
    Vec3<double> traction{{0, 0, 0}};
    double       slip = 0;
    Vec3<double> point{{0, 0, 0}};
    Vec3<double> normal{{0, 0, 0}};
    int          face  = -1;
    double       xi[2] = {0, 0};
  };

  /** What the evaluation of one contact point reports (values only). */
  struct ContactPointResult
  {
    ContactStatus status = ContactStatus::open;
    /** Normal gap g_N (2); negative is penetration. */
    double gap = 0;
    /** Normal pressure t_N >= 0. */
    double pressure = 0;
    /** Tangential traction vector T (acts on the master; -T on the slave). */
    Vec3<double> traction{{0, 0, 0}};
    Vec3<double> normal{{0, 0, 0}};
    /** Slip increment of the return mapping, |T_trial| - mu t_N over eps_T. */
    double slip_increment = 0;
    /** Master face and local coordinates of the projection (deformable). */
    int    face  = -1;
    double xi[2] = {0, 0};
  };
} // namespace tribos

#endif
