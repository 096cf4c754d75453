#ifndef tribos_contact_pairing_h
#define tribos_contact_pairing_h

#include <tribos/contact/contact_pair.h>
#include <tribos/parameters/contact.h>

#include <deal.II/lac/trilinos_vector.h>

#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * The contact search, independent of the enforcement: reads the
   * positions of the slave nodes a process reads (and the enforcement's
   * unknowns), makes the master faces that can reach them known on this
   * process and builds their CGAL AABB tree (exchange_master_nodes(),
   * ContactSearch), then lets the pair's discretization pair every owned
   * slave node with the master (ContactDiscretization::pair_node(): the
   * closest face and its neighbours for node to segment, the overlapping
   * faces for mortar; a rigid master needs no search).
   */
  template <int dim>
  class Pairing
  {
  public:
    Pairing(const Parameters::Contact &parameters, const MPI_Comm communicator);

    /**
     * Read the positions of the slave nodes this process reads (and, with
     * unknowns, the multipliers) from @p solution, make the master faces
     * that can reach them known (exchange_master_nodes()), and pair every
     * owned slave node that is not excluded. Registers new (slave node,
     * master face) couplings; returns whether one was new. Collective.
     */
    bool
    update(ContactPair<dim>                    &pair,
           const TrilinosWrappers::MPI::Vector &solution);

    /**
     * What the master exchanges of update() took since the last call: the
     * values this process received from the others, and the seconds
     * (collective, so partly waiting for the other processes, not this
     * process's own contact work).
     */
    struct Exchanged
    {
      std::size_t values  = 0;
      double      seconds = 0;
    };
    Exchanged
    take_exchanged()
    {
      return std::exchange(exchanged, Exchanged());
    }

  private:
    const Parameters::Contact &parameters;
    MPI_Comm                   communicator;
    Exchanged                  exchanged;
  };
} // namespace tribos

#endif
