#include <tribos/base/exceptions.h>
#include <tribos/base/import_constraints.h>
#include <tribos/base/text.h>
#include <tribos/contact/contact_pair.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/affine_constraints.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace tribos
{
  namespace
  {
    /**
     * Exclude the slave nodes of @p pair whose rows would depend on other
     * rows, and hand their areas over (see make_contact_pairs()): hanging
     * nodes, and with @p earlier (the pairs made before) the nodes an
     * earlier pair already constrains.
     */
    template <int dim>
    void
    exclude_dependent_nodes(ContactPair<dim>                &pair,
                            std::vector<ContactPair<dim>>   *earlier,
                            const AffineConstraints<double> &hanging)
    {
      const auto        &nodes    = pair.slave->nodes();
      const unsigned int n_slaves = nodes.size();
      std::map<types::global_dof_index, unsigned int> node_of_dof;
      for (unsigned int k = 0; k < n_slaves; ++k)
        node_of_dof[nodes[k].dofs[0]] = k;

      // A hanging slave node: its row would be the combination of its
      // parents' rows. Its area goes to its parents with the constraint's
      // weights, so that the multipliers stay tractions.
      for (unsigned int k = 0; k < n_slaves; ++k)
      {
        const auto dof = nodes[k].dofs[0];
        if (!hanging.is_constrained(dof))
          continue;
        const auto *entries = hanging.get_constraint_entries(dof);
        if (entries == nullptr || entries->empty())
          continue;
        pair.excluded[k] = true;
        double moved     = 0;
        for (const auto &[parent_dof, weight] : *entries)
        {
          const auto parent = node_of_dof.find(parent_dof);
          if (parent != node_of_dof.end())
          {
            pair.area[parent->second] += weight * pair.area[k];
            pair.carried[parent->second].emplace_back(k, weight);
            moved += weight;
          }
        }
        AssertThrow(std::abs(moved - 1.) < 1e-8,
                    ExcMessage("Contact pair <" + pair.description.text +
                               ">: a hanging slave node whose parents are "
                               "not on the slave surface; refine the slave "
                               "surface as a whole."));
        pair.area[k] = 0;
      }

      // A node that an earlier pair with unknowns already constrains
      // against the same master would get a second, identical row. Writing
      // both surfaces as one ('3, 4 : plate') avoids the duplicate.
      if (earlier == nullptr)
        return;
      for (auto &other : *earlier)
      {
        if (other.enforcement->n_node_unknowns() == 0 ||
            other.description.rigid_surface != pair.description.rigid_surface ||
            other.description.master_boundary !=
              pair.description.master_boundary)
          continue;
        std::map<types::global_dof_index, unsigned int> other_node_of_dof;
        for (unsigned int j = 0; j < other.slave->nodes().size(); ++j)
          other_node_of_dof[other.slave->nodes()[j].dofs[0]] = j;
        for (unsigned int k = 0; k < n_slaves; ++k)
        {
          const auto j = other_node_of_dof.find(nodes[k].dofs[0]);
          if (j == other_node_of_dof.end() || pair.excluded[k])
            continue;
          pair.excluded[k] = true;
          if (!other.excluded[j->second])
            other.area[j->second] += pair.area[k];
          pair.area[k] = 0;
        }
      }
    }



    /**
     * The hanging node constraints of @p dof_handler on the locally
     * relevant dofs and the contact surfaces' @p surface_dofs: those of
     * every process (their cells may be elsewhere on a distributed mesh).
     */
    template <int dim>
    AffineConstraints<double>
    hanging_constraints(const DoFHandler<dim> &dof_handler,
                        const IndexSet        &surface_dofs,
                        const IndexSet        &locally_owned_dofs)
    {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      relevant.add_indices(surface_dofs);
      return hanging_node_constraints(
        dof_handler,
        relevant,
        Utilities::MPI::all_gather(
          dof_handler.get_triangulation().get_communicator(),
          locally_owned_dofs));
    }



    /**
     * The slave nodes of @p pair: which this process owns, their areas
     * and states, the dependent ones excluded (the pairs made before it:
     * @p earlier; @p hanging constraints; every hanging node with
     * @p carry_hanging_nodes), the nodes this process reads, and the
     * master nodes it owns.
     */
    template <int dim>
    void
    set_up_nodes(ContactPair<dim>                &pair,
                 std::vector<ContactPair<dim>>   &earlier,
                 const AffineConstraints<double> &hanging,
                 const IndexSet                  &locally_owned_dofs,
                 const bool                       carry_hanging_nodes)
    {
      const auto        &nodes    = pair.slave->nodes();
      const unsigned int n_slaves = nodes.size();
      pair.owned.resize(n_slaves);
      pair.work.assign(n_slaves, 0.);
      pair.area.resize(n_slaves);
      pair.excluded.assign(n_slaves, false);
      pair.carried.assign(n_slaves, {});
      pair.current.resize(n_slaves);
      for (unsigned int k = 0; k < n_slaves; ++k)
      {
        pair.owned[k]         = locally_owned_dofs.is_element(nodes[k].dofs[0]);
        pair.area[k]          = nodes[k].area * pair.area_factor;
        pair.current[k].point = nodes[k].reference;
        pair.slave_positions.push_back(nodes[k].reference);
      }
      // With unknowns, every dependent node; where the discretization has
      // the parents carry their hanging nodes' functions (mortar), those
      // too (a node of its own there would weigh the gap differently from
      // its neighbours and break the patch test: 1.4 % spread of a
      // uniform pressure).
      if (pair.enforcement->n_node_unknowns() > 0)
        exclude_dependent_nodes(pair, &earlier, hanging);
      else if (pair.discretization->parents_carry_hanging_nodes() ||
               carry_hanging_nodes)
        exclude_dependent_nodes<dim>(pair, nullptr, hanging);
      pair.discretization->initialize(pair);
      // The slave positions this process reads: its own nodes and the
      // stencils of the elements it evaluates.
      {
        std::vector<bool>         read(n_slaves, false);
        std::vector<unsigned int> stencil;
        for (unsigned int k = 0; k < n_slaves; ++k)
          if (pair.owned[k])
          {
            read[k] = true;
            if (!pair.excluded[k])
            {
              pair.discretization->stencil(pair, k, stencil);
              for (const unsigned int m : stencil)
                read[m] = true;
            }
          }
        for (unsigned int k = 0; k < n_slaves; ++k)
          if (read[k])
            pair.read_slave_nodes.push_back(k);
      }
      if (pair.master)
      {
        const auto &master_nodes = pair.master->nodes();
        for (unsigned int n = 0; n < master_nodes.size(); ++n)
          if (locally_owned_dofs.is_element(master_nodes[n].dofs[0]))
            pair.owned_master_nodes.push_back(n);
        pair.master_known.assign(master_nodes.size(), false);
        pair.face_known.assign(pair.master->faces().size(), false);
      }
    }
    /**
     * Slave and master meeting at an edge of one body: the nodes there sit
     * on the master with zero gap and the body turns inside out at them
     * (det F <= 0, with no hint at the pair). Refused, pointing to
     * self-contact.
     */
    template <int dim>
    void
    refuse_shared_nodes(const ContactPair<dim> &pair)
    {
      const auto                       &description = pair.description;
      std::set<types::global_dof_index> master_nodes;
      for (const auto &node : pair.master->nodes())
        master_nodes.insert(node.dofs[0]);
      for (const auto &node : pair.slave->nodes())
        AssertThrow(
          master_nodes.count(node.dofs[0]) == 0,
          ExcMessage(
            "Parameter <Contact/Pairs>: in pair <" + description.text +
            ">, the slave and master surfaces share nodes (they meet at an "
            "edge of one body, e.g. at the slave node at " +
            Text::join(std::vector<double>(node.reference.begin(),
                                           node.reference.begin() + dim)) +
            "). Boundaries of one body that meet each other are one "
            "surface for self-contact: give the same ids on both sides "
            "(e.g. <" +
            Text::join(description.slave_boundary) + ", " +
            Text::join(description.master_boundary) + " : " +
            Text::join(description.slave_boundary) + ", " +
            Text::join(description.master_boundary) + ">)."));
    }
  } // namespace



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
    IndexSet                                        &contact_dofs)
  {
    // The boundary ids of the faces of own cells (see Problem::make_grid).
    std::set<types::boundary_id> existing;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            existing.insert(face->boundary_id());
    existing = Utilities::MPI::compute_set_union(
      existing,
      dof_handler.get_triangulation().get_communicator());

    // Surfaces are shared between pairs (and passes).
    std::map<std::set<types::boundary_id>, std::shared_ptr<ContactSurface<dim>>>
               surfaces;
    const auto surface = [&](const std::set<unsigned int> &ids)
    {
      std::set<types::boundary_id> boundary_ids;
      for (const auto id : ids)
      {
        AssertThrow(existing.count(id) == 1,
                    ExcMessage("Parameter <Contact/Pairs> names boundary id " +
                               std::to_string(id) +
                               ", which the scene does not have. Its "
                               "boundary ids are " +
                               Text::join(existing) +
                               " (the README lists them per scene; a gmsh "
                               "mesh's are the physical group tags of its "
                               "boundary lines in 2D, surfaces in 3D)."));
        boundary_ids.insert(id);
      }
      auto &s = surfaces[boundary_ids];
      if (!s)
        s = std::make_shared<ContactSurface<dim>>(dof_handler,
                                                  boundary_ids,
                                                  axisymmetric,
                                                  curved_geometry);
      return s;
    };
    std::map<std::string, std::shared_ptr<RigidSurface<dim>>> rigid_surfaces;
    for (const auto &description : parameters.rigid_surfaces)
      rigid_surfaces[description.name] =
        std::make_shared<RigidSurface<dim>>(description);

    std::vector<Parameters::ContactPair> descriptions = parameters.pairs;
    if (parameters.two_pass)
      for (const auto &p : parameters.pairs)
        // A self pair is both passes already.
        if (p.rigid_surface.empty() && !p.self_contact())
        {
          auto swapped            = p;
          swapped.slave_boundary  = p.master_boundary;
          swapped.master_boundary = p.slave_boundary;
          swapped.text            = p.text + " (second pass)";
          descriptions.push_back(swapped);
        }

    // Every surface first (each is gathered from all processes, in the
    // same order everywhere).
    for (const auto &description : descriptions)
    {
      surface(description.slave_boundary);
      if (description.rigid_surface.empty())
        surface(description.master_boundary);
    }

    // The hanging slave nodes of every process (their cells may be
    // elsewhere on a distributed mesh).
    IndexSet surface_dofs(dof_handler.n_dofs());
    for (const auto &[ids, s] : surfaces)
      for (const auto &node : s->nodes())
        for (const auto dof : node.dofs)
          surface_dofs.add_index(dof);
    const AffineConstraints<double> hanging =
      hanging_constraints(dof_handler, surface_dofs, locally_owned_dofs);

    std::vector<ContactPair<dim>> pairs;
    n_unknowns = 0;
    for (const auto &description : descriptions)
    {
      ContactPair<dim> pair;
      pair.description = description;
      pair.enforcement = create_enforcement<dim>(description, parameters);
      const bool self  = description.self_contact();
      pair.slave       = surface(description.slave_boundary);
      double E_s       = std::numeric_limits<double>::max();
      for (const auto body : pair.slave->bodies())
        E_s = std::min(E_s, youngs_modulus(body));
      pair.contact_modulus = E_s;
      if (description.rigid_surface.empty())
      {
        pair.master = surface(description.master_boundary);
        if (!self)
          refuse_shared_nodes(pair);
        double E_m = std::numeric_limits<double>::max();
        for (const auto body : pair.master->bodies())
          E_m = std::min(E_m, youngs_modulus(body));
        pair.contact_modulus = E_s * E_m / (E_s + E_m);
        // Two passes (or a self pair, which is both): each carries half.
        // The penalty in mixed form too: each pass's node has its own
        // traction unknowns, whose rows g_N + t_N/eps_N = 0 have the
        // compliance 1/eps_N on their diagonal, so the two passes' rows on
        // one gap are not equal (multipliers, whose rows would be, are
        // refused on self pairs: Parameters::check_interfaces()).
        pair.area_factor = parameters.two_pass || self ? 0.5 : 1.;
      }
      else
        pair.rigid = rigid_surfaces.at(description.rigid_surface);
      pair.discretization =
        create_discretization<dim>(description, parameters, axisymmetric);
      AssertThrow(!self || pair.discretization->takes_self_contact(),
                  ExcMessage("Parameter <Contact/Pairs>: the self-contact "
                             "pair <" +
                             description.text + "> is discretized " +
                             pair.discretization->name() +
                             "; self-contact takes node to segment or "
                             "mortar, without Master smoothing."));

      set_up_nodes(pair,
                   pairs,
                   hanging,
                   locally_owned_dofs,
                   parameters.carry_hanging_nodes);
      pair.first_unknown = dof_handler.n_dofs() + n_unknowns;
      n_unknowns += pair.enforcement->n_node_unknowns() * pair.n_nodes();
      pair.committed           = pair.current;
      pair.old_slave_positions = pair.slave_positions;
      if (pair.master)
        for (const auto &node : pair.master->nodes())
          pair.master_positions.push_back(node.reference);
      pair.old_master_positions = pair.master_positions;
      pairs.push_back(std::move(pair));
    }

    contact_dofs = surface_dofs;
    contact_dofs.compress();
    return pairs;
  }



  template <int dim>
  std::vector<std::string>
  penalty_warnings(const std::vector<ContactPair<dim>> &pairs)
  {
    std::vector<std::string> warnings;
    for (const auto &pair : pairs)
    {
      for (const auto &w : pair.discretization->setup_warnings())
        warnings.push_back(w);
      // Exact multipliers have no penalty. The penalty law in mixed form
      // (Penalty formulation = mixed: the tractions as unknowns) has the
      // primal form's solution: a penalty too soft lets the bodies sink
      // through each other alike (1e-6 E/h: the block's whole stroke,
      // exit 0 and no word, where the primal form warned); a stiff one
      // only approaches exact contact, which its unknowns solve without
      // the primal form's round-off.
      if (!pair.enforcement->uses_normal_penalty())
        continue;
      const bool mixed = pair.enforcement->n_node_unknowns() > 0;
      const auto check = [&](const Parameters::PenaltyValue &penalty,
                             const std::string              &what,
                             const std::string              &entry)
      {
        // k = eps h / E at every slave node.
        double k_min = std::numeric_limits<double>::max(), k_max = 0;
        for (const auto &node : pair.slave->nodes())
        {
          const double k = penalty.resolve(pair.contact_modulus, node.size) *
                           node.size / pair.contact_modulus;
          k_min = std::min(k_min, k);
          k_max = std::max(k_max, k);
        }
        if (k_min < 1e-3 || (k_max > 1e8 && !mixed))
          warnings.push_back(
            "contact pair <" + pair.description.text + ">: the " + what +
            " is " + to_scientific(k_min) + " to " + to_scientific(k_max) +
            " E/h over its slave nodes, outside [1e-3, 1e8] E/h (E = " +
            to_scientific(pair.contact_modulus) + "): " +
            (k_min < 1e-3 ? "too soft to keep the bodies apart" :
                            "stiffer than round-off allows Newton to "
                            "resolve") +
            " (Contact/" + entry + " or the pair's option).");
      };
      check(pair.description.normal_penalty,
            "normal penalty",
            "Penalty factor");
      if (pair.description.friction_coefficient > 0)
        check(pair.description.tangential_penalty,
              "tangential penalty",
              "Tangential penalty factor");
    }
    return warnings;
  }



  template <int dim>
  std::vector<std::string>
  describe(const std::vector<ContactPair<dim>> &pairs)
  {
    std::vector<std::string> lines;
    for (const auto &pair : pairs)
    {
      double h_min = std::numeric_limits<double>::max(), h_max = 0;
      for (const auto &node : pair.slave->nodes())
      {
        h_min = std::min(h_min, node.size);
        h_max = std::max(h_max, node.size);
      }
      std::set<unsigned int> hanging;
      for (const auto &carried : pair.carried)
        for (const auto &entry : carried)
          hanging.insert(entry.first);
      const auto   n_hanging = hanging.size();
      const auto  &penalty   = pair.description.normal_penalty;
      const double E         = pair.contact_modulus;
      lines.push_back(
        "contact pair <" + pair.description.text +
        ">: " + pair.description.method +
        (pair.enforcement->formulation().empty() ?
           std::string() :
           " (" + pair.enforcement->formulation() + ")") +
        ", " + pair.discretization->name() + ", " +
        std::to_string(pair.n_nodes()) + " slave nodes" +
        (n_hanging > 0 ?
           " (" + std::to_string(n_hanging) + " hanging on others)" :
           std::string()) +
        ", contact modulus E = " + to_scientific(E) +
        ", h = " + to_scientific(h_min) + " to " + to_scientific(h_max) +
        (pair.enforcement->uses_normal_penalty() ?
           ", eps_N = " + to_scientific(penalty.resolve(E, h_max)) + " to " +
             to_scientific(penalty.resolve(E, h_min)) :
           std::string()));
    }
    return lines;
  }

  template struct ContactPair<2>;
  template struct ContactPair<3>;
  template std::vector<ContactPair<2>>
  make_contact_pairs(const Parameters::Contact &,
                     const DoFHandler<2> &,
                     const std::function<double(types::material_id)> &,
                     const IndexSet &,
                     const bool,
                     const Mapping<2> *,
                     types::global_dof_index &,
                     IndexSet &);
  template std::vector<ContactPair<3>>
  make_contact_pairs(const Parameters::Contact &,
                     const DoFHandler<3> &,
                     const std::function<double(types::material_id)> &,
                     const IndexSet &,
                     const bool,
                     const Mapping<3> *,
                     types::global_dof_index &,
                     IndexSet &);
  template std::vector<std::string>
  penalty_warnings(const std::vector<ContactPair<2>> &);
  template std::vector<std::string>
  penalty_warnings(const std::vector<ContactPair<3>> &);
  template std::vector<std::string>
  describe(const std::vector<ContactPair<2>> &);
  template std::vector<std::string>
  describe(const std::vector<ContactPair<3>> &);
} // namespace tribos
