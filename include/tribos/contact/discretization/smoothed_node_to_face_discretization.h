#ifndef tribos_contact_smoothed_node_to_face_discretization_h
#define tribos_contact_smoothed_node_to_face_discretization_h

#include <tribos/contact/discretization/node_to_segment_discretization.h>

#include <string>
#include <vector>

namespace tribos
{
  /**
   * Node to segment against a 3D master (bilinear quadrilaterals or linear
   * triangles) whose normal field is smoothed by averaged nodal normals
   * (Contact/Master smoothing = averaged normals; SmoothedFace,
   * NodeToSmoothedFace): the projection, the gap and the normal are those
   * of the smoothed surface, and the element couples the vertices of the
   * faces around the face, on which its nodal normals depend.
   *
   * A node is paired with the face whose smoothed normal line through it
   * meets the face inside (the nearest such); the smoothed field is
   * continuous across face edges, so the faces that share an edge agree
   * there and no hysteresis between faces is needed. Where no face of the
   * candidates has the projection inside (a node at a free edge of the
   * master, or round-off at a shared edge), the face whose projection
   * lies least outside is taken if that is within the edge band.
   */
  class SmoothedNodeToFaceDiscretization : public NodeToSegmentDiscretization<3>
  {
  public:
    using NodeToSegmentDiscretization<3>::NodeToSegmentDiscretization;

    std::string
    name() const override
    {
      return faceted ? "node to segment" : "node to segment, smoothed master";
    }

    std::vector<std::string>
    setup_warnings() const override
    {
      auto warnings = NodeToSegmentDiscretization<3>::setup_warnings();
      if (faceted)
        warnings.push_back(fallback_warning);
      return warnings;
    }

    /** Not the smoothed master (its nodal normals assume a master apart
     * from the slave). */
    bool
    takes_self_contact() const override
    {
      return false;
    }

    void
    initialize(const ContactPair<3> &pair) override;

    /** The faces around each face (not once it fell back to the
     * faces). */
    bool
    needs_nodes_beyond() const override
    {
      return !faceted;
    }

    bool
    pair_node(ContactPair<3> &pair, const unsigned int k) override;

    void
    element_dofs(const ContactPair<3>                 &pair,
                 const unsigned int                    k,
                 const int                             face,
                 std::vector<types::global_dof_index> &dofs) const override;

    ElementOutcome
    evaluate(ContactPair<3>                       &pair,
             const unsigned int                    k,
             const SlaveInput                     &slave,
             double                               *R,
             double                               *K,
             std::vector<types::global_dof_index> &dofs,
             std::string                          &refusal) override;

    unsigned int
    max_element_dofs() const override
    {
      return NodeToSmoothedFace::max_dofs + 3;
    }

  private:
    /** Master smoothing = automatic met a master the smoothing cannot
     * take (initialize()): the pair is plain node to segment, and says
     * so (fallback_warning). */
    bool        faceted = false;
    std::string fallback_warning;

    /** Per master face: its SmoothedFace (the fans around its vertices in
     * stencil numbers) and the surface nodes of its stencil (its vertices,
     * then its ring). Built once, the surface's topology does not change. */
    std::vector<SmoothedFace>              shapes;
    std::vector<std::vector<unsigned int>> stencils;

    /** The positions of the stencil of @p face from @p positions. */
    void
    stencil_positions(const unsigned int               face,
                      const std::vector<Vec3<double>> &positions,
                      Vec3<double>                    *x) const;
  };
} // namespace tribos

#endif
