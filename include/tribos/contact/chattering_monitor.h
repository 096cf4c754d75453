#ifndef tribos_contact_chattering_monitor_h
#define tribos_contact_chattering_monitor_h

#include <tribos/contact/contact_pair.h>

#include <deal.II/base/mpi.h>

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
   * changes are the return map's business and converge: not counted.
   */
  template <int dim>
  class ChatteringMonitor
  {
  public:
    explicit ChatteringMonitor(const MPI_Comm mpi_communicator);

    /** Start counting for a new increment of @p pairs. */
    void
    begin_increment(const std::vector<ContactPair<dim>> &pairs);

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

    /** Whether node @p k of pair @p p is held closed. */
    bool
    frozen(const unsigned int p, const unsigned int k) const
    {
      return p < held.size() && k < held[p].size() && held[p][k];
    }

    /** Held nodes whose pressure is tensile or that lost their master
     * point (all processes). */
    unsigned int
    n_frozen_in_tension(const std::vector<ContactPair<dim>> &pairs) const;

    /** Let the held nodes in tension (see n_frozen_in_tension()) go, with
     * their change counts reset; returns how many (all processes). */
    unsigned int
    release_in_tension(const std::vector<ContactPair<dim>> &pairs);

  private:
    /** Node @p k of pair @p p is held, owned here, and tensile or without
     * a master point. */
    bool
    held_in_tension(const std::vector<ContactPair<dim>> &pairs,
                    const unsigned int                   p,
                    const unsigned int                   k) const
    {
      const auto &state = pairs[p].current[k];
      return frozen(p, k) && pairs[p].owned[k] &&
             (state.result.pressure < 0 || !state.paired);
    }

    MPI_Comm mpi_communicator;
    /** Per pair and node: status at the last evaluation (-1: none yet),
     * changes in the increment, held closed. */
    std::vector<std::vector<int>>          status;
    std::vector<std::vector<unsigned int>> changes;
    std::vector<std::vector<bool>>         held;
  };
} // namespace tribos

#endif
