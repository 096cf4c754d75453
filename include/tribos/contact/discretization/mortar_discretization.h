#ifndef tribos_contact_mortar_discretization_h
#define tribos_contact_mortar_discretization_h

#include <tribos/contact/discretization/contact_discretization.h>
#include <tribos/contact/element/mortar_element.h>
#include <tribos/contact/element/mortar_element_3d.h>
#include <tribos/contact/search/self_contact_search.h>
#include <tribos/parameters/contact.h>

#include <string>
#include <type_traits>
#include <vector>

namespace tribos
{
  /**
   * Segment-to-segment mortar with dual (or standard) multiplier
   * functions (Contact/Discretization = mortar; doc/mortar.md): the
   * element of slave node j integrates its function Phi_j against the
   * master faces that overlap its slave faces (Mortar2D on 2D Q1 and Q2
   * segments, Mortar3D on 3D bilinear faces), and gives the node a
   * weighted gap, slip and nodal normal for the pair's enforcement.
   *
   * The search finds, for each slave segment or face of a node, the
   * master faces that overlap it in its projection and face it, from the
   * faces closest to its corners and middle through their overlapping
   * neighbours (see pair_node()). A hanging slave node (a refinement
   * border in 3D) has no element of its own: its function goes to its
   * parents (ContactPair::carried), whose elements take its faces too.
   *
   * Owns the master faces each node's element integrates (found by the
   * search) and, in 3D, the cache of the overlaps integrated in one
   * assembly (each overlap serves the four nodes of its slave face).
   */
  template <int dim>
  class MortarDiscretization : public ContactDiscretization<dim>
  {
  public:
    /**
     * With the @p dual basis (else the standard one), the master's
     * averaged nodal normals for the nodal normal (@p smoothed_master, 2D
     * Q1), integrals over the surface of revolution (@p axisymmetric).
     */
    MortarDiscretization(const Parameters::Contact &parameters,
                         const bool                 dual,
                         const bool                 smoothed_master,
                         const bool                 axisymmetric);

    std::string
    name() const override;

    void
    initialize(const ContactPair<dim> &pair) override;

    /** Not with the master's averaged normals. */
    bool
    takes_self_contact() const override
    {
      return !smoothed_master;
    }

    std::vector<std::string>
    setup_warnings() const override
    {
      return self_search.warnings();
    }

    bool
    parents_carry_hanging_nodes() const override
    {
      return true;
    }

    void
    stencil(const ContactPair<dim>    &pair,
            const unsigned int         k,
            std::vector<unsigned int> &nodes) const override;

    double
    exchange_reach(const ContactPair<dim> &pair,
                   const unsigned int      k) const override;

    bool
    needs_nodes_beyond() const override
    {
      return smoothed_master;
    }

    bool
    pair_node(ContactPair<dim> &pair, const unsigned int k) override;

    void
    add_couplings(const ContactPair<dim>          &pair,
                  const AffineConstraints<double> &constraints,
                  DynamicSparsityPattern          &dsp) const override;

    void
    used_couplings(
      const ContactPair<dim>                          &pair,
      const unsigned int                               k,
      std::set<std::pair<unsigned int, unsigned int>> &into) const override;

    void
    element_dofs(const ContactPair<dim>               &pair,
                 const unsigned int                    k,
                 const int                             face,
                 std::vector<types::global_dof_index> &dofs) const override;

    void
    begin_assembly(const ContactPair<dim> &pair,
                   const double            time,
                   const double            committed_time) override;

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
      return dim == 2 ?
               2 * (MortarInput::max_slave_nodes + max_mortar_master_nodes) +
                 2 :
               3 * (MortarInput3D::max_slave_nodes +
                    max_mortar_master_nodes_3d) +
                 3;
    }

    /** The master faces of slave node @p k's element at the last search:
     * its own and those of the hanging nodes it carries, each once. */
    void
    element_master_faces(const ContactPair<dim>    &pair,
                         const unsigned int         k,
                         std::vector<unsigned int> &faces) const;

  private:
    using Input = std::conditional_t<dim == 2, MortarInput, MortarInput3D>;

    /**
     * The master faces that overlap one of slave @p k's segments or faces
     * in the orthogonal projection onto its line (3D: clipped in the
     * face's auxiliary plane), face it (2D: normals more than 75 degrees
     * apart) and, for a node open at the last converged step, do not lie
     * wholly more than the segment's length behind it (a closed one keeps
     * faces at any depth); found from the faces closest to the segment's
     * ends and middle through their overlapping neighbours. Paired if one
     * of them lies within reach along the normal (a gap below Search
     * distance and the segment's length); the element then integrates all
     * of them, however far, since a face taken or dropped by its distance
     * would change the weighted gap by a jump.
     */
    void
    find_faces(ContactPair<dim> &pair, const unsigned int k);

    /** The slave nodes of slave node @p k's faces, @p k first. */
    void
    slave_stencil(const ContactPair<dim>    &pair,
                  const unsigned int         k,
                  std::vector<unsigned int> &nodes) const;

    /** The slave faces of slave node @p k's element, its own and those of
     * the hanging nodes it carries, each once. */
    void
    element_slave_faces(const ContactPair<dim>    &pair,
                        const unsigned int         k,
                        std::vector<unsigned int> &faces) const;

    /**
     * The input of slave node @p k's element: its slave stencil and faces,
     * the master nodes and faces the search found, now and at the last
     * converged step; @p dofs gets the element's dofs (slave stencil,
     * master nodes, the node's unknowns). Returns false, with the reason
     * in @p refusal (the first one met), if the element couples more
     * master nodes or faces than the AD number holds.
     */
    bool
    make_input(const ContactPair<dim>               &pair,
               const unsigned int                    k,
               Input                                &input,
               std::vector<types::global_dof_index> &dofs,
               std::string                          &refusal);

    /** The positions of the stencil and the master nodes (now and at the
     * last converged step), the dofs, and the weight below which the node
     * has no master, into @p input. */
    void
    set_positions(const ContactPair<dim>               &pair,
                  const unsigned int                    k,
                  Input                                &input,
                  std::vector<types::global_dof_index> &dofs) const;

    const Parameters::Contact &parameters;
    const bool                 dual;
    const bool                 smoothed_master;
    const bool                 axisymmetric;
    /** Per slave node, the master faces that overlap its slave faces at the
     * last search (the first one is also NodeState::face). */
    std::vector<std::vector<unsigned int>> faces_of_node;
    /** 3D: each overlap integrated once per assembly. */
    MortarOverlapCache overlap_cache;
    /** Self-contact: each node's own neighbourhood and the reach. */
    SelfContactSearch<dim> self_search;
    /** Buffers of make_input(), reused between nodes. */
    std::vector<unsigned int> stencil_buffer, master_buffer;
  };
} // namespace tribos

#endif
