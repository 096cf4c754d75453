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
   * The contact search: pairs every owned slave node of a pair with a
   * master point at the current positions, independent of the enforcement.
   * A deformable master's faces go into a CGAL AABB tree (ContactSearch);
   * each slave node queries the closest face and projects exactly onto it
   * and its neighbours. A node keeps the face of its last evaluation while
   * it projects onto it or onto its extension within a band (no
   * flip-flop over master vertices); near a free end of the master it sees
   * the end face's extension within the band; farther out it has slid off.
   * With a smoothed master the projection is the smoothed one
   * (SmoothedSegment). Rigid masters need no search.
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
     * owned slave node. Registers new (slave node, master face) couplings;
     * returns whether one was new. Collective.
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
    /**
     * The faces near slave point @p x: the closest face (CGAL search) and
     * its neighbours; empty if the master is farther than Search distance.
     * Sets @p state.distance.
     */
    std::vector<unsigned int>
    candidate_faces(const ContactPair<dim> &pair,
                    const Vec3<double>     &x,
                    NodeState              &state) const;

    /**
     * Pair slave @p k with the faceted master: keep the face of the last
     * evaluation while the node projects onto it (or its extension within
     * the edge band), else the closest projection inside a candidate face
     * (else the closest clamped one); near a free end of the master, the
     * end face's extension within the edge band.
     */
    void
    pair_faceted(ContactPair<dim> &pair, const unsigned int k) const;

    /**
     * Pair slave @p k with the smoothed master: the face whose smoothed
     * normal line through the node has xi in [-1, 1] (the nearest such);
     * near a free end of the master, the end face's extension within the
     * edge band. Unpaired otherwise.
     */
    void
    pair_smoothed(ContactPair<dim> &pair, const unsigned int k) const;

    /**
     * Mortar: the master faces that overlap one of slave @p k's segments
     * or faces in the orthogonal projection onto its line (3D: clipped in
     * the face's auxiliary plane), face it (2D: normals more than 75
     * degrees apart) and, for a node open at the last converged step, do
     * not lie wholly more than the segment's length behind it (a closed
     * one keeps faces at any depth); found from the faces closest to the
     * segment's ends and middle through their overlapping neighbours.
     * Paired if one of them lies within reach along the normal (a gap
     * below Search distance and the segment's length); the element then
     * integrates all of them, however far, since a face taken or dropped
     * by its distance would change the weighted gap by a jump.
     */
    void
    pair_mortar(ContactPair<dim> &pair, const unsigned int k) const;

    const Parameters::Contact &parameters;
    MPI_Comm                   communicator;
    Exchanged                  exchanged;
  };



  /**
   * The nodes of master @p face for SmoothedSegment (the segment, the node
   * before, the node after) at @p positions, and which neighbours exist.
   */
  template <int dim>
  void
  smoothed_stencil(const ContactPair<dim>          &pair,
                   const unsigned int               face,
                   const std::vector<Vec3<double>> &positions,
                   Vec3<double>                    *x,
                   bool                            *has);
} // namespace tribos

#endif
