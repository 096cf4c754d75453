#ifndef tribos_contact_master_exchange_h
#define tribos_contact_master_exchange_h

#include <tribos/contact/contact_pair.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cstddef>

namespace tribos
{
  using namespace dealii;

  /**
   * The distributed half of the contact search of a deformable master: makes
   * known on this process the master faces that can reach the slave nodes
   * it reads (ContactPair::read_slave_nodes), and builds its search tree
   * over them. Collective.
   *
   * The processes all-gather the bounding boxes of the slave nodes they
   * read (current positions) and the largest master face diameter h now.
   * Each process then sends to each other one the positions (now and at
   * the last commit) of the master nodes whose dofs it owns and that lie
   * within Search distance + 3 h of that process's box: a face within
   * the search distance of a slave node has its nodes within the distance
   * plus h, its neighbours' nodes within plus 2 h, and the nodes beyond
   * those neighbours' ends (smoothed masters) within plus 3 h. So every
   * face a slave node can pair with, every neighbour the projection looks
   * at and every node its element reads are known, and the node-to-segment
   * pairing is the one of a search over the whole surface. A mortar
   * element integrates every overlapping face that faces it, however far,
   * once one is within the search distance: mortar boxes reach 5 slave
   * face sizes farther (a master rising at up to 75 degrees over a slave
   * face). Beyond that reach (steeper masters, or an iterate that pushes
   * a closed mortar node deeper than the reach) a process would miss faces
   * a search over the whole surface sees. The volume sent per search
   * scales with the contact interface of each process, not with the mesh
   * nor the whole surface. With Search distance = 0 (no limit) every
   * process receives every master node.
   *
   * Sets ContactPair::master_positions, old_master_positions,
   * master_known, face_known and known_faces, and builds ContactPair::search.
   * Returns the number of values this process received.
   */
  template <int dim>
  std::size_t
  exchange_master_nodes(ContactPair<dim>                    &pair,
                        const TrilinosWrappers::MPI::Vector &solution,
                        const double                         search_distance,
                        const MPI_Comm                       communicator);
} // namespace tribos

#endif
