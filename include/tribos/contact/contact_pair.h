#ifndef tribos_contact_contact_pair_h
#define tribos_contact_contact_pair_h

#include <tribos/contact/discretization/contact_discretization.h>
#include <tribos/contact/enforcement/enforcement.h>
#include <tribos/contact/search/contact_search.h>
#include <tribos/contact/state/node_state.h>
#include <tribos/contact/surface/contact_surface.h>
#include <tribos/contact/surface/rigid_surface.h>
#include <tribos/parameters/contact.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tribos
{
  using namespace dealii;

  /**
   * One contact pair: its identity and geometry (a slave surface, its
   * master: a deformable surface or a rigid one), its discretization and
   * enforcement, and per slave node its tributary area, its state (current
   * and committed) and positions. Built once by make_contact_pairs(); the
   * discretization (search and elements) writes the node states, the
   * enforcement only reads the pair, the output reads the states.
   */
  template <int dim>
  struct ContactPair
  {
    Parameters::ContactPair                 description;
    std::shared_ptr<ContactSurface<dim>>    slave;
    std::shared_ptr<ContactSurface<dim>>    master;
    std::shared_ptr<RigidSurface<dim>>      rigid;
    std::shared_ptr<const Enforcement<dim>> enforcement;
    /** The search and the elements (create_discretization()). */
    std::shared_ptr<ContactDiscretization<dim>> discretization;
    /**
     * The contact modulus E of the penalties 'k*E/h': the series modulus
     * E_s E_m / (E_s + E_m) of the two sides, E_s against a rigid surface
     * (its limit). It is continuous at that limit and, like Hertz's E*,
     * set by the softer side when the moduli differ much (a penalty on the
     * stiffer side's scale would make soft-on-hard contact
     * ill-conditioned).
     */
    double contact_modulus = 0;
    /** 1/2 with two passes and on a self-contact pair (each pass carries
     * half the area), else 1. */
    double area_factor = 1;
    /** The number of the first of the enforcement's unknowns (if any):
     * node k's are first_unknown + n_node_unknowns k + d. */
    types::global_dof_index first_unknown = 0;

    /** Per slave node: whether this process evaluates it (it owns its
     * dofs); whether it is excluded from its own constraint rows (see
     * make_contact_pairs()); its tributary area times area_factor, with
     * the areas of excluded nodes handed to the nodes that carry them. */
    std::vector<bool>   owned, excluded;
    std::vector<double> area;
    /** Per owned slave node: the seconds this process spent on its
     * element since the work was last taken (ContactHandler::take_work(),
     * the weights of a rebalanced partition). */
    std::vector<double> work;
    /**
     * Mortar with unknowns: per slave node, the hanging slave nodes whose
     * multiplier functions it carries, with its weight in their
     * constraints. A hanging node (3D, the middle of a coarse face's edge
     * on a refinement border) carries no multiplier of its own; the dual
     * basis is modified instead, Phi_p + c Phi_h for each parent p with
     * weight c (Wohlmuth's treatment of removed nodes, as at
     * crosspoints): the functions still sum to one, so uniform tractions
     * are still transmitted exactly.
     */
    std::vector<std::vector<std::pair<unsigned int, double>>> carried;

    /** Per slave node: the state at the last evaluation and at the last
     * converged increment. */
    std::vector<NodeState> current, committed;
    /** Node positions, now and at the last converged increment. */
    std::vector<Vec3<double>> slave_positions, old_slave_positions;
    std::vector<Vec3<double>> master_positions, old_master_positions;

    /**
     * The slave nodes whose positions this process reads: its own, and
     * the nodes of the elements it evaluates (mortar: their stencils).
     * Their dofs are ghosted; the positions of other slave nodes are not
     * kept up to date.
     */
    std::vector<unsigned int> read_slave_nodes;
    /** Deformable masters: the master nodes whose dofs this process owns
     * (it sends their positions to the processes that need them). */
    std::vector<unsigned int> owned_master_nodes;
    /**
     * Deformable masters, at the last search (MasterExchange): per master
     * node, whether master_positions and old_master_positions hold its
     * positions; per master face, whether its nodes (with a smoothed
     * master also the nodes beyond its ends) do; and the known faces, in
     * the search tree. Every face that can reach a slave node this process
     * evaluates is known, with its neighbours.
     */
    std::vector<bool>         master_known, face_known;
    std::vector<unsigned int> known_faces;

    /** The master's search tree over the known faces (deformable
     * masters). */
    ContactSearch<dim> search;
    /** (slave node, master face) pairs coupled in the sparsity pattern. */
    std::set<std::pair<unsigned int, unsigned int>> couplings;
    /** Whether a slave node within the search distance was ever met. */
    bool ever_near = false;

    unsigned int
    n_nodes() const
    {
      return owned.size();
    }

    /** Append the dofs of slave node @p k's unknowns (the enforcement's,
     * if any) to @p dofs. */
    void
    append_unknown_dofs(const unsigned int                    k,
                        std::vector<types::global_dof_index> &dofs) const
    {
      const unsigned int n = enforcement->n_node_unknowns();
      for (unsigned int d = 0; d < n; ++d)
        dofs.push_back(first_unknown + n * k + d);
    }
  };



  /**
   * The pairs of Contact/Pairs (two-pass: with the swapped ones), their
   * surfaces, moduli and enforcements, on @p dof_handler (the cells'
   * curved geometry @p curved_geometry, null if they are straight);
   * @p youngs_modulus gives each body's E. The enforcements' unknowns are
   * numbered from dof_handler.n_dofs() on; @p n_unknowns gets their number and
   * @p contact_dofs every dof of a contact surface.
   *
   * With unknowns per node (multipliers), a slave node whose rows would
   * depend on other rows carries none of its own (it is excluded, with a
   * Lambda = 0 row): a hanging node on a refinement border (its position
   * follows its parents), whose tributary area goes to its parents with
   * the constraint's weights (with mortar, its multiplier function goes
   * to its parents too: ContactPair::carried), and a node that an earlier
   * pair already
   * constrains against the same master (an edge shared by two slave
   * surfaces), whose area goes to that pair's node.
   */
  template <int dim>
  std::vector<ContactPair<dim>>
  make_contact_pairs(
    const Parameters::Contact                       &parameters,
    const DoFHandler<dim>                           &dof_handler,
    const std::function<double(types::material_id)> &youngs_modulus,
    const IndexSet                                  &locally_owned_dofs,
    const bool                                       axisymmetric,
    const Mapping<dim>                              *curved_geometry,
    types::global_dof_index                         &n_unknowns,
    IndexSet                                        &contact_dofs);

  /**
   * Warnings about @p pairs known after setup: a normal or tangential
   * penalty below 1e-3 E/h or above 1e8 E/h at some slave node (in the
   * mixed form below 1e-3 E/h only: a stiff penalty is no round-off
   * problem there).
   */
  template <int dim>
  std::vector<std::string>
  penalty_warnings(const std::vector<ContactPair<dim>> &pairs);

  /**
   * One line per pair for the log: enforcement, slave nodes, contact
   * modulus, range of element sizes and of the normal penalty.
   */
  template <int dim>
  std::vector<std::string>
  describe(const std::vector<ContactPair<dim>> &pairs);
} // namespace tribos

#endif
