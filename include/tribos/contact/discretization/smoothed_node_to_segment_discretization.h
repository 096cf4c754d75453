#ifndef tribos_contact_smoothed_node_to_segment_discretization_h
#define tribos_contact_smoothed_node_to_segment_discretization_h

#include <tribos/contact/discretization/node_to_segment_discretization.h>

namespace tribos
{
  /**
   * Node to segment against a 2D master whose normal field is smoothed by
   * averaged nodal normals (Contact/Master smoothing = averaged normals;
   * SmoothedSegment, NodeToSmoothedSegment): the projection, the gap and
   * the normal are those of the smoothed surface, and the element couples
   * the nodes beyond the segment's ends, on which the normal depends.
   * A node is paired with the face whose smoothed normal line through it
   * has xi in [-1, 1] (the nearest such); near a free end of the master,
   * with the end face's extension within the edge band.
   */
  class SmoothedNodeToSegmentDiscretization
    : public NodeToSegmentDiscretization<2>
  {
  public:
    using NodeToSegmentDiscretization<2>::NodeToSegmentDiscretization;

    std::string
    name() const override
    {
      return "node to segment, smoothed master";
    }

    /** Not the smoothed master (its nodal normals assume a master apart
     * from the slave). */
    bool
    takes_self_contact() const override
    {
      return false;
    }

    bool
    needs_nodes_beyond() const override
    {
      return true;
    }

    bool
    pair_node(ContactPair<2> &pair, const unsigned int k) override;

    void
    element_dofs(const ContactPair<2>                 &pair,
                 const unsigned int                    k,
                 const int                             face,
                 std::vector<types::global_dof_index> &dofs) const override;

    ElementOutcome
    evaluate(ContactPair<2>                       &pair,
             const unsigned int                    k,
             const SlaveInput                     &slave,
             double                               *R,
             double                               *K,
             std::vector<types::global_dof_index> &dofs,
             std::string                          &refusal) override;

    unsigned int
    max_element_dofs() const override
    {
      return NodeToSmoothedSegment::max_dofs + 2;
    }

  private:
    /**
     * The nodes of master @p face for SmoothedSegment (the segment, the
     * node before, the node after) at @p positions, and which neighbours
     * exist.
     */
    static void
    stencil_of(const ContactPair<2>            &pair,
               const unsigned int               face,
               const std::vector<Vec3<double>> &positions,
               Vec3<double>                    *x,
               bool                            *has);
  };
} // namespace tribos

#endif
