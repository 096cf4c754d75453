#ifndef tribos_contact_self_contact_roles_h
#define tribos_contact_self_contact_roles_h

#include <deal.II/base/mpi.h>

#include <vector>

namespace tribos
{
  using namespace dealii;

  template <int dim>
  struct ContactPair;

  /**
   * Self-contact with Lagrange multipliers: which side of each contact is
   * the slave. With penalty and the augmented Lagrangian a self-contact
   * surface is its own slave and master in both passes with half weights;
   * multipliers cannot do that (a node and the node opposite it would
   * both constrain the same gap: two equal rows, a singular system), so
   * each contact needs one slave side, and which side that is follows
   * from where the surface folds, not from the input.
   *
   * The rule (4C colours its self-contact elements alike): the graph
   * whose edges join each paired node near its faces (closer than twice
   * its element size, or behind a face) to those faces' nodes
   * (@p targets: per node, empty if it is not near; node to segment's
   * one face, a mortar element's faces) is coloured with two colours, component
   * by component, breadth first from a seed; the seed's colour is slave, its
   * neighbours' master, theirs slave, and so on, so that whole sides of a fold
   * are slaves and the opposite sides masters. The seed is the component's
   * smallest paired node that was a slave at the last converged
   * increment (@p was_slave: closed, or paired near, as the
   * discretization judges), else its smallest paired node:
   * the sides keep their roles from increment to increment, through a
   * restart (the committed states are in the checkpoint) and a change of
   * the mesh (the contact status is carried over). Which side that is
   * the first time is arbitrary (the smaller node numbers), as the
   * choice of slave of a one-pass pair is the user's. A component
   * that cannot be coloured (three patches touching each other) falls
   * back to the mutual rule: a node is a master if a node of its face has
   * it in its own face and a smaller index. The graph is gathered from
   * every process and coloured alike everywhere, so the roles do not
   * depend on the partition.
   *
   * A master node loses its pairing (its multiplier's row then says
   * Lambda = 0) where a slave holds the contact (it is a node of one of
   * a slave's faces); slaves keep theirs. Collective.
   */
  template <int dim>
  void
  assign_self_contact_roles(
    ContactPair<dim>                             &pair,
    const std::vector<std::vector<unsigned int>> &targets,
    const std::vector<bool>                      &was_slave,
    const MPI_Comm                                communicator);
} // namespace tribos

#endif
