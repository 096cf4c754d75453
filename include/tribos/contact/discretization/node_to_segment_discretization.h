#ifndef tribos_contact_node_to_segment_discretization_h
#define tribos_contact_node_to_segment_discretization_h

#include <tribos/contact/discretization/contact_discretization.h>
#include <tribos/contact/search/self_contact_search.h>
#include <tribos/parameters/contact.h>

#include <string>
#include <vector>

namespace tribos
{
  /**
   * Node to segment against a faceted deformable master (the paper's
   * contact element: 2D segments, 3D bilinear faces; NodeToSegment): each
   * slave node is projected onto the closest master face (a CGAL search,
   * then the exact projection onto that face and its neighbours) and its
   * element couples the node with the face's nodes.
   *
   * A node keeps the face of its last evaluation while it projects onto
   * it or onto its extension within a band of 0.1 in local coordinates:
   * over a master vertex (a concave kink of the deformed master) the
   * closest face would otherwise flip between iterations and Newton would
   * cycle between two smooth residuals. Near a free end of the master a
   * node sees the end face's extension within the band; farther out it
   * has slid off.
   */
  template <int dim>
  class NodeToSegmentDiscretization : public ContactDiscretization<dim>
  {
  public:
    explicit NodeToSegmentDiscretization(const Parameters::Contact &parameters);

    std::string
    name() const override
    {
      return "node to segment";
    }

    void
    initialize(const ContactPair<dim> &pair) override;

    bool
    pair_node(ContactPair<dim> &pair, const unsigned int k) override;

    bool
    takes_self_contact() const override
    {
      return true;
    }

    std::vector<std::string>
    setup_warnings() const override
    {
      return self_search.warnings();
    }

    ElementOutcome
    evaluate(ContactPair<dim>                     &pair,
             const unsigned int                    k,
             const SlaveInput                     &slave,
             double                               *R,
             double                               *K,
             std::vector<types::global_dof_index> &dofs,
             std::string                          &refusal) override;

    unsigned int
    max_element_dofs() const override
    {
      return NodeToSegment<dim>::n_dofs + dim;
    }

  protected:
    /**
     * Width, in local coordinates, of the band beyond the end of a master
     * surface in which a slave node still sees the end face's extension.
     */
    static constexpr double edge_band = 0.1;

    /**
     * The faces near slave point @p x: the closest face (CGAL search) and
     * its known neighbours; empty if the master is farther than Search
     * distance. Sets @p state.distance.
     */
    std::vector<unsigned int>
    candidate_faces(const ContactPair<dim> &pair,
                    const Vec3<double>     &x,
                    NodeState              &state) const;

    /** Register the couplings of slave node @p k with its face (if it has
     * one and it is new); returns whether it was new. */
    static bool
    couple_face(ContactPair<dim> &pair, const unsigned int k);

    const Parameters::Contact &parameters;

  private:
    /**
     * Self-contact (the slave surface is its own master): the faces near
     * slave node @p k at @p x that may touch it: not a face of the node
     * or one sharing a node with those (its own neighbourhood), facing it
     * (the node's normal against the face's below -0.5), the node not
     * behind it by more than half its element size (else it is the other
     * side of the node's own body), within the reach (doubled until one
     * is found, up to the largest). The closest such and
     * its admissible neighbours; empty if none. Sets @p state.distance.
     */
    std::vector<unsigned int>
    self_candidate_faces(const ContactPair<dim> &pair,
                         const unsigned int      k,
                         const Vec3<double>     &x,
                         NodeState              &state) const;

    /** The projection of @p x onto face @p f (clamped to the face if
     * @p clamp), with the face's unit outward normal and point there; the
     * face where it was at the last converged increment if @p old. */
    Projection
    project(const ContactPair<dim> &pair,
            const unsigned int      f,
            const Vec3<double>     &x,
            const bool              clamp,
            Vec3<double>           *normal = nullptr,
            Vec3<double>           *point  = nullptr,
            const bool              old    = false) const;

    /** Self-contact: the unit normal of slave node @p k, the mean of its
     * known faces' normals there. */
    Vec3<double>
    node_normal(const ContactPair<dim> &pair, const unsigned int k) const;

    /** Self-contact: each node's own neighbourhood and the reach. */
    SelfContactSearch<dim> self_search;
  };
} // namespace tribos

#endif
