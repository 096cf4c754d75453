#ifndef tribos_postprocess_contact_output_h
#define tribos_postprocess_contact_output_h

#include <tribos/contact/contact_handler.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /** Totals of the contact state, summed over all processes. */
  struct ContactStatistics
  {
    /** Per pair: sum of A t_N, sum of A |T|, and the resultant force
     * on the slave body (x, y, z). */
    std::vector<std::array<double, 5>> pair_forces;
    double                             max_penetration = 0;
    unsigned int                       n_active        = 0;
    unsigned int                       n_stick         = 0;
    unsigned int                       n_slip          = 0;
  };

  /**
   * The contact results as output: totals for history.csv and the console,
   * contact-NNNNN.csv, and the nodal fields of the VTU. Reads the pairs'
   * current states (after a converged increment, the committed ones).
   */
  template <int dim>
  class ContactOutput
  {
  public:
    explicit ContactOutput(const ContactHandler<dim> &contact);

    /** Collective. */
    ContactStatistics
    statistics() const;

    /** Names of the history.csv columns that columns() fills. */
    std::vector<std::string>
    column_names() const;

    /** The statistics as a row matching column_names(). Collective. */
    std::vector<double>
    columns() const;

    /** Write contact-NNNNN.csv: one row per slave node and pair, sorted by
     * pair and node (rank 0 gathers). Collective. */
    void
    write_csv(const std::string &filename) const;

    /**
     * Nodal fields for the VTU: CPRESS, COPEN, CSLIP, CSTATUS on a scalar
     * Q1 numbering (@p scalar_dof: the scalar dof of the vertex whose
     * first displacement dof is the key, for the vertices of this
     * process's cells), CSHEAR on the displacement numbering; one physical
     * value per node where a node is a slave of several pairs (see the
     * source). Each process writes the nodes it owns into the owned
     * (non-ghosted) vectors, then compresses them. Collective.
     */
    void
    nodal_fields(const std::map<types::global_dof_index,
                                types::global_dof_index>      &scalar_dof,
                 std::array<TrilinosWrappers::MPI::Vector, 4> &scalars,
                 TrilinosWrappers::MPI::Vector                &shear) const;

  private:
    const ContactHandler<dim> &contact;

    /**
     * The state each slave node this process owns reports: its own, except
     * for a hanging node that carries no constraint of its own
     * (ContactPair::carried; with multipliers or mortar). Such a node
     * reports its parents' values interpolated with the constraint's
     * weights: with dual mortar exactly the coefficient of its basis
     * function in the multiplier field, which its parents carry; and the
     * status of the parent with the largest weighted pressure. Its own
     * result says open, which would show a hole in the contact zone.
     * Per pair, a copy of ContactPair::current. Collective: the parents
     * may belong to other processes.
     */
    std::vector<std::vector<NodeState>>
    reported_states() const;
  };
} // namespace tribos

#endif
