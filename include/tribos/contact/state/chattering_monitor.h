#ifndef tribos_contact_chattering_monitor_h
#define tribos_contact_chattering_monitor_h

#include <tribos/contact/contact_pair.h>
#include <tribos/parameters/contact.h>

#include <deal.II/base/mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace tribos
{
  /**
   * Watches the contact status (open or closed) of every slave node between
   * the Newton iterations of an increment: a node whose status changes more
   * than a limit is chattering. The remedy Contact/Chattering remedy =
   * freeze holds such nodes closed for the rest of the increment (the
   * result is accepted only if none of them ends in tension; those that do
   * are released once and Newton goes on). Stick/slip
   * changes are the return map's business and converge: not counted. A
   * slipping node whose slip reverses (the tangential traction turning by
   * more than 90 degrees) in more than the limit of successive stalled
   * iterations is chattering in friction: Newton cycles between the two
   * slip directions
   * across the stick region between them (the 2D ironing with mortar, an
   * edge node of the contact zone with a small pressure). The remedy holds
   * it in stick; the result is accepted only if its traction is within the
   * Coulomb cone (else it is released once, as above).
   *
   * The policy (Contact/Chattering flips and Chattering remedy) acts
   * through after_iteration() and accept(), which Newton's hooks call;
   * track(), freeze() and the rest are its parts.
   */
  template <int dim>
  class ChatteringMonitor
  {
  public:
    ChatteringMonitor(const Parameters::Contact &parameters,
                      const MPI_Comm             mpi_communicator);

    /** Start counting for a new increment of @p pairs. */
    void
    begin_increment(const std::vector<ContactPair<dim>> &pairs);

    /**
     * After the assembly of Newton iteration @p iteration, whose free
     * residual is @p residual: count the status changes of @p pairs'
     * nodes while Newton makes no progress (the residual not below half
     * the best one of the increment after its first iteration: while the
     * residual falls, status changes are the active set converging) and
     * apply the remedy to the nodes past Contact/Chattering flips: cut the
     * increment (throws NonConvergence) or hold them (freeze; @p say tells
     * the user).
     */
    void
    after_iteration(const std::vector<ContactPair<dim>>            &pairs,
                    const unsigned int                              iteration,
                    const double                                    residual,
                    const std::function<void(const std::string &)> &say);

    /**
     * At an iterate that passed Newton's tests: whether it may be
     * accepted. Held nodes that ended in tension, off the master or beyond
     * the Coulomb cone are released once (false: Newton goes on from this
     * iterate); a second time the increment is cut (throws
     * NonConvergence).
     */
    bool
    accept(const std::vector<ContactPair<dim>>            &pairs,
           const std::function<void(const std::string &)> &say);

    /** The most chattering nodes seen in an iteration of the increment. */
    unsigned int
    most_chattering() const
    {
      return n_chattering_seen;
    }

    /**
     * Compare every owned slave node's status at the last evaluation with
     * the previous one, and @p count the changes or not (the caller counts
     * them while Newton stalls); returns the number of nodes (all
     * processes) with more than @p limit counted changes in the increment.
     */
    unsigned int
    track(const std::vector<ContactPair<dim>> &pairs,
          const unsigned int                   limit,
          const bool                           count);

    /** Hold every node with more than @p limit changes closed until the
     * increment ends; returns how many are held (all processes). */
    unsigned int
    freeze(const std::vector<ContactPair<dim>> &pairs,
           const unsigned int                   limit);

    /** Whether node @p k of pair @p p is held in stick. */
    bool
    frozen_stick(const unsigned int p, const unsigned int k) const
    {
      return p < held_stick.size() && k < held_stick[p].size() &&
             held_stick[p][k];
    }

    /** Whether node @p k of pair @p p is held closed. */
    bool
    frozen(const unsigned int p, const unsigned int k) const
    {
      return p < held.size() && k < held[p].size() && held[p][k];
    }

    /** Held nodes whose pressure is tensile or that lost their master
     * point, and nodes held in stick whose traction is beyond the Coulomb
     * cone (all processes). */
    unsigned int
    n_frozen_inadmissible(const std::vector<ContactPair<dim>> &pairs) const;

    /** Let the nodes of n_frozen_inadmissible() go, with their counts
     * reset; returns how many (all processes). */
    unsigned int
    release_inadmissible(const std::vector<ContactPair<dim>> &pairs);

  private:
    /** Node @p k of pair @p p is owned here and either held closed and
     * tensile or without a master point, or held in stick and open or
     * beyond the Coulomb cone. */
    bool
    held_inadmissible(const std::vector<ContactPair<dim>> &pairs,
                      const unsigned int                   p,
                      const unsigned int                   k) const
    {
      const auto &state = pairs[p].current[k];
      if (!pairs[p].owned[k])
        return false;
      if (frozen(p, k) && (state.result.pressure < 0 || !state.paired))
        return true;
      const double limit = pairs[p].description.friction_coefficient *
                           std::max(state.result.pressure, 0.);
      return frozen_stick(p, k) &&
             (!state.closed() ||
              norm(state.result.traction) > limit * (1. + 1e-6));
    }

    const Parameters::Contact &parameters;
    MPI_Comm                   mpi_communicator;
    /** The increment so far: the most chattering nodes of an iteration,
     * the smallest residual after the first iteration, the nodes held, and
     * whether held nodes were released. */
    unsigned int n_chattering_seen = 0;
    double       best_residual     = 0;
    unsigned int n_frozen          = 0;
    bool         released          = false;
    /** Per pair and node: status at the last evaluation (-1: none yet),
     * changes in the increment, held closed; the direction of the
     * tangential traction at the last evaluation if the node slipped
     * (else zero), successive reversals of the slip, held in stick. */
    std::vector<std::vector<int>>          status;
    std::vector<std::vector<unsigned int>> changes;
    std::vector<std::vector<bool>>         held;
    std::vector<std::vector<Vec3<double>>> slip_direction;
    std::vector<std::vector<unsigned int>> reversals;
    std::vector<std::vector<bool>>         held_stick;
  };
} // namespace tribos

#endif
